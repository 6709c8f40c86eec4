#!/usr/bin/env bash
# Checks rastersim.core (FuseSoC CAPI2; FuseSoC itself is not packaged for Debian here) and
# rtl/rastersim.f without FuseSoC: the YAML parses; every file named exists; every target's filesets
# and parameters are declared; the .f file lists the rtl fileset's files in the same order; and each
# target does what FuseSoC would have its tool do: lint (Verilator -Wall, with the waivers), sim
# (Icarus, the package's files copied where `copyto` puts them, the run must pass) and synth (yosys
# elaborates the top at the target's parameters). Exit 1 on the first problem, naming it.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
python3 - "$root" "$work" <<'PY'
import os, re, shutil, subprocess, sys
import yaml

root, work = sys.argv[1], sys.argv[2]
core_path = os.path.join(root, "rastersim.core")

def fail(message):
    print("check-fusesoc-core: " + message)
    sys.exit(1)

text = open(core_path).read()
if not text.startswith("CAPI=2:\n"):
    fail("rastersim.core: line 1 must be 'CAPI=2:'")
core = yaml.safe_load(text)
if not re.fullmatch(r"[\w.-]+:[\w.-]+:[\w.-]+:\d+\.\d+\.\d+", core.get("name", "")):
    fail("rastersim.core: name must be vendor:library:name:version")

def entries(fileset):
    """(path, attributes) of each file of a fileset, with the fileset's file_type as default."""
    out = []
    for item in fileset.get("files", []):
        path, attrs = (next(iter(item.items())) if isinstance(item, dict) else (item, {}))
        attrs = dict(attrs or {})
        attrs.setdefault("file_type", fileset.get("file_type"))
        out.append((path, attrs))
    return out

filesets = core.get("filesets", {})
for name, fileset in filesets.items():
    for path, attrs in entries(fileset):
        if not os.path.isfile(os.path.join(root, path)):
            fail(f"rastersim.core: fileset {name}: {path} does not exist")
        if not attrs.get("file_type"):
            fail(f"rastersim.core: fileset {name}: {path} has no file_type")
declared = set(core.get("parameters", {}))
targets = core.get("targets", {})
for target in ("default", "lint", "sim", "synth"):
    if target not in targets:
        fail(f"rastersim.core: no target {target}")
for name, target in targets.items():
    for fs in target.get("filesets", []):
        if fs not in filesets:
            fail(f"rastersim.core: target {name}: no fileset {fs}")
    for parameter in target.get("parameters", []):
        if parameter.split("=")[0] not in declared:
            fail(f"rastersim.core: target {name}: parameter {parameter} is not declared")
    if not target.get("toplevel"):
        fail(f"rastersim.core: target {name}: no toplevel")

def sources(target):
    files, includes, waivers, copies = [], [], [], []
    for fs in targets[target]["filesets"]:
        for path, attrs in entries(filesets[fs]):
            full = os.path.join(root, path)
            if attrs.get("is_include_file"):
                includes.append(os.path.dirname(full))
            elif attrs["file_type"] == "vlt":
                waivers.append(full)
            elif attrs["file_type"] == "user":
                copies.append((full, attrs.get("copyto", os.path.basename(path))))
            else:
                files.append(full)
    return files, sorted(set(includes)), waivers, copies

def run(what, command, cwd=None):
    result = subprocess.run(command, cwd=cwd, capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"{what} failed:\n" + (result.stdout + result.stderr)[-3000:])
    return result.stdout + result.stderr

# The .f file: the same RTL files in the same order.
listed = [line.strip() for line in open(os.path.join(root, "rtl", "rastersim.f"))
          if line.strip() and not line.startswith("//") and not line.startswith("+")]
rtl_files = [p for p, a in entries(filesets["rtl"]) if not a.get("is_include_file")]
if ["rtl/" + f for f in listed] != rtl_files:
    fail("rtl/rastersim.f does not list the rtl fileset's files in its order")

# lint: Verilator -Wall with the waivers, at the default parameters.
files, includes, waivers, _ = sources("lint")
run("lint (verilator -Wall)", ["verilator", "--lint-only", "-Wall", *waivers, *["-I" + i for i in includes],
                               *files, "--top-module", targets["lint"]["toplevel"]])
run("verilator -F rtl/rastersim.f", ["verilator", "--lint-only", "-Wall", *waivers, "-F",
                                     os.path.join(root, "rtl", "rastersim.f"), "--top-module", "rastersim_top"])
run("iverilog -c rastersim.f", ["iverilog", "-g2012", "-c", "rastersim.f", "-s", "rastersim_top",
                                "-o", os.path.join(work, "f.vvp")], cwd=os.path.join(root, "rtl"))

# sim: Icarus in a folder holding the copied vectors; the package's verdict must be a pass.
files, includes, _, copies = sources("sim")
for src, dst in copies:
    shutil.copy(src, os.path.join(work, dst))
run("sim (iverilog)", ["iverilog", *targets["sim"]["tools"]["icarus"].get("iverilog_options", []),
                       *["-I" + i for i in includes], "-s", targets["sim"]["toplevel"], "-o",
                       os.path.join(work, "sim.vvp"), *files])
log = run("sim (vvp)", ["vvp", "-n", os.path.join(work, "sim.vvp")], cwd=work)
if not re.search(r"^\d+ passed, 0 failed", log, re.M):
    fail("sim: the package did not pass:\n" + log[-2000:])

# synth: yosys elaborates the top at the target's parameters (synthesis itself is rtl-yosys.sh's).
files, includes, _, _ = sources("synth")
chparams = "; ".join(f"chparam -set {p.split('=')[0]} {p.split('=')[1]} {targets['synth']['toplevel']}"
                     for p in targets["synth"].get("parameters", []) if "=" in p)
run("synth (yosys)", ["yosys", "-q", "-p", f"read_verilog -sv {' '.join('-I' + i for i in includes)} {' '.join(files)}; "
                      f"{chparams}; hierarchy -check -top {targets['synth']['toplevel']}"])
print("check-fusesoc-core: rastersim.core and rtl/rastersim.f check out: files, lint, sim (" +
      re.search(r"^\d+ passed, 0 failed", log, re.M).group(0) + "), synth elaboration")
PY
