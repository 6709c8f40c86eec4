#!/usr/bin/env bash
# Checks rastersim.core (FuseSoC CAPI2; FuseSoC itself is not packaged for Debian here) and
# rtl/rastersim.f without FuseSoC: the YAML parses; every file named exists; every target's filesets
# and parameters are declared; rastersim_top's parameters are all declared (vlogparam, in its
# order) and lint and synth take each; the sim target's plusargs are those the vector testbench
# reads; the .f file lists the rtl fileset's files in the same order. Then each named target runs
# as FuseSoC's tool (edalize) would run it:
#   lint      Verilator -Wall with the waivers
#   sim       Icarus (a .scr command file with the defines and include folders, the user files
#             copied where `copyto` puts them, vvp with the plusargs): the default package, another
#             package chosen by RASTERSIM_VECTORS_PARAMS and package (both must pass), the two
#             naming different packages (must fail) and a folder without .hex files (refused)
#   synth     yosys synth_ice40 of rastersim_top at the target's parameters: the frame memory in block
#             RAM and the logic within an HX8K's 7,680 LUTs
#   selftest  Icarus: the board self-test must print "selftest: PASS"
#   hx8k      yosys synth_ice40, nextpnr-ice40 (the target's options, the pin file), icepack: the
#             self-test must place and route on the HX8K; prints its logic cells, block RAMs and Fmax
# Usage: scripts/check-fusesoc-core.sh [TARGET...]   (default: lint sim synth selftest)
# Exit 0 when all pass, 1 on the first problem (named), 2 on bad usage.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
for target in "$@"; do
  case "$target" in
    lint | sim | synth | selftest | hx8k) ;;
    *)
      echo "usage: scripts/check-fusesoc-core.sh [lint|sim|synth|selftest|hx8k ...]: no target '$target'" >&2
      exit 2
      ;;
  esac
done
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
python3 - "$root" "$work" "${@:-lint sim synth selftest}" <<'PY'
import os, re, shutil, subprocess, sys
import yaml

root, work = sys.argv[1], sys.argv[2]
wanted = " ".join(sys.argv[3:]).split()
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
parameters = core.get("parameters", {})
for name, p in parameters.items():
    if p.get("datatype") not in ("bool", "file", "int", "real", "str"):
        fail(f"rastersim.core: parameter {name}: datatype {p.get('datatype')} is not a CAPI2 datatype")
    if p.get("paramtype") not in ("cmdlinearg", "generic", "plusarg", "vlogdefine", "vlogparam"):
        fail(f"rastersim.core: parameter {name}: paramtype {p.get('paramtype')} is not a CAPI2 paramtype")
targets = core.get("targets", {})
for target in ("default", "lint", "sim", "synth", "selftest", "hx8k"):
    if target not in targets:
        fail(f"rastersim.core: no target {target}")
for name, target in targets.items():
    for fs in target.get("filesets", []):
        if fs not in filesets:
            fail(f"rastersim.core: target {name}: no fileset {fs}")
    for parameter in target.get("parameters", []):
        if parameter.split("=")[0] not in parameters:
            fail(f"rastersim.core: target {name}: parameter {parameter} is not declared")
    if not target.get("toplevel"):
        fail(f"rastersim.core: target {name}: no toplevel")

# Every build parameter of rastersim_top (the core's, declared in rastersim_core_parameters.vh),
# declared in its order and taken by lint and synth.
top_text = open(os.path.join(root, "rtl", "rastersim_top.sv")).read()
header = top_text[top_text.index("module rastersim_top"):top_text.index(") (")]
if "`RASTERSIM_CORE_PARAMETERS" in header:
    header += open(os.path.join(root, "rtl", "rastersim_core_parameters.vh")).read()
top_parameters = re.findall(r"parameter integer (\w+)", header)
vlogparams = [n for n, p in parameters.items() if p["paramtype"] == "vlogparam"]
if vlogparams != top_parameters:
    fail(f"rastersim.core: the vlogparam parameters {vlogparams} are not rastersim_top's {top_parameters}")
for name in ("lint", "synth"):
    listed = [p.split("=")[0] for p in targets[name].get("parameters", [])]
    if listed != top_parameters:
        fail(f"rastersim.core: target {name} does not take every rastersim_top parameter in order: {listed}")

# The sim target's plusargs are exactly the ones the vector testbench reads.
tb_text = open(os.path.join(root, "testbench", "vectors", "rastersim_vectors_tb.v")).read()
read_plusargs = set(re.findall(r'\$(?:value|test)\$plusargs\("(\w+)', tb_text))
sim_plusargs = {p.split("=")[0] for p in targets["sim"].get("parameters", [])
                if parameters[p.split("=")[0]]["paramtype"] == "plusarg"}
if sim_plusargs != read_plusargs:
    fail(f"rastersim.core: the sim target's plusargs {sorted(sim_plusargs)} are not the testbench's {sorted(read_plusargs)}")

def sources(target):
    files, includes, waivers, copies, pins = [], [], [], [], []
    for fs in targets[target]["filesets"]:
        for path, attrs in entries(filesets[fs]):
            full = os.path.join(root, path)
            if attrs.get("is_include_file"):
                includes.append(os.path.dirname(full))
            elif attrs["file_type"] == "vlt":
                waivers.append(full)
            elif attrs["file_type"] == "user":
                copies.append((full, attrs.get("copyto", os.path.basename(path))))
            elif attrs["file_type"] == "PCF":
                pins.append(full)
            else:
                files.append(full)
    return files, sorted(set(includes)), waivers, copies, pins

def run(what, command, cwd=None):
    result = subprocess.run(command, cwd=cwd, capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"{what} failed:\n" + (result.stdout + result.stderr)[-3000:])
    return result.stdout + result.stderr

def target_folder(name):
    """A fresh work root for a target run, holding the fileset's copyto files (as FuseSoC does)."""
    folder = os.path.join(work, name)
    os.makedirs(folder)
    for src, dst in sources(name.split(".")[0])[3]:
        shutil.copy(src, os.path.join(folder, dst))
    return folder

def icarus(target, folder, defines=None, plusargs=None):
    """edalize's icarus backend: a .scr command file, iverilog -c, then vvp with the plusargs."""
    files, includes, _, _, _ = sources(target)
    with open(os.path.join(folder, "rastersim.scr"), "w") as scr:
        for key, value in (defines or {}).items():
            scr.write(f"+define+{key}={value}\n")
        for include in includes:
            scr.write(f"+incdir+{include}\n")
        for f in files:
            scr.write(f + "\n")
    options = targets[target]["tools"]["icarus"].get("iverilog_options", [])
    run(f"{target} (iverilog)", ["iverilog", "-s" + targets[target]["toplevel"], "-c", "rastersim.scr", "-o",
                                  "rastersim", *options], cwd=folder)
    args = [f"+{k}={int(v) if isinstance(v, bool) else v}" for k, v in (plusargs or {}).items()]
    result = subprocess.run(["vvp", "-n", "-M.", "-l", "icarus.log", "rastersim", "-fst", *args], cwd=folder,
                            capture_output=True, text=True)
    return result.stdout + result.stderr

def yosys_synth(target, folder, params, extra):
    """edalize's yosys backend: read the files with the include folders, chparam, synth_ice40."""
    files, includes, _, _, _ = sources(target)
    top = targets[target]["toplevel"]
    chparams = "".join(f"chparam -set {k} {v} {top}\n" for k, v in params.items())
    with open(os.path.join(folder, "rastersim.ys"), "w") as ys:
        ys.write(f"read_verilog -sv {' '.join('-I' + i for i in includes)} {' '.join(files)}\n{chparams}"
                 f"synth_ice40 -top {top}\nwrite_json rastersim.json\n{extra}")
    return run(f"{target} (yosys)", ["yosys", "-q", "-l", "yosys.log", "rastersim.ys"], cwd=folder)

def fixed_parameters(target):
    return dict(p.split("=") for p in targets[target].get("parameters", []) if "=" in p)

# The .f file: the same RTL files in the same order.
listed = [line.strip() for line in open(os.path.join(root, "rtl", "rastersim.f"))
          if line.strip() and not line.startswith("//") and not line.startswith("+")]
rtl_files = [p for p, a in entries(filesets["rtl"]) if not a.get("is_include_file")]
if ["rtl/" + f for f in listed] != rtl_files:
    fail("rtl/rastersim.f does not list the rtl fileset's files in its order")
summary = ["files, parameters"]

if "lint" in wanted:
    files, includes, waivers, _, _ = sources("lint")
    run("lint (verilator -Wall)", ["verilator", "--lint-only", "-Wall", *waivers, *["-I" + i for i in includes],
                                   *files, "--top-module", targets["lint"]["toplevel"]])
    run("verilator -F rtl/rastersim.f", ["verilator", "--lint-only", "-Wall", *waivers, "-F",
                                         os.path.join(root, "rtl", "rastersim.f"), "--top-module", "rastersim_top"])
    run("iverilog -c rastersim.f", ["iverilog", "-g2012", "-c", "rastersim.f", "-s", "rastersim_top",
                                    "-o", os.path.join(work, "f.vvp")], cwd=os.path.join(root, "rtl"))
    summary.append("lint")

if "sim" in wanted:
    verdict = re.compile(r"^(\d+) passed, 0 failed", re.M)
    log = icarus("sim", target_folder("sim"))
    if not verdict.search(log):
        fail("sim: the default package did not pass:\n" + log[-2000:])
    # Another package, as `--RASTERSIM_VECTORS_PARAMS='"..."' --package=DIR --functional` passes it.
    other = os.path.join(root, "vectors", "depth-lequal")
    chosen = {"RASTERSIM_VECTORS_PARAMS": '"' + os.path.join(other, "rastersim_vectors_params.vh") + '"'}
    other_log = icarus("sim", target_folder("sim.other"), chosen, {"package": other, "functional": True, "max_shown": 5})
    if not verdict.search(other_log) or verdict.search(other_log).group(0) == verdict.search(log).group(0):
        fail("sim: vectors/depth-lequal chosen by RASTERSIM_VECTORS_PARAMS and package did not run:\n" + other_log[-2000:])
    mixed_log = icarus("sim", target_folder("sim.mixed"), chosen,
                       {"package": os.path.join(root, "vectors", "depth-equal")})
    if verdict.search(mixed_log) or not re.search(r"^\d+ passed, [1-9]\d* failed", mixed_log, re.M):
        fail("sim: a parameter file and .hex files of different packages did not fail:\n" + mixed_log[-2000:])
    missing_log = icarus("sim", target_folder("sim.missing"), chosen, {"package": os.path.join(work, "no-package")})
    if "no-package/frame.hex: no such file" not in missing_log:
        fail("sim: a package folder without .hex files was not refused:\n" + missing_log[-2000:])
    summary.append(f"sim (scene-default {verdict.search(log).group(0)}, depth-lequal "
                   f"{verdict.search(other_log).group(0)})")

def count(pattern, text):
    found = re.findall(pattern, text)
    return int(found[-1]) if found else 0

if "synth" in wanted:
    folder = target_folder("synth")
    yosys_synth("synth", folder, fixed_parameters("synth"), "tee -q -o stat.txt stat\n")
    stat = open(os.path.join(folder, "stat.txt")).read()
    luts, brams = count(r"SB_LUT4\s+(\d+)", stat), count(r"SB_RAM40_4K\s+(\d+)", stat)
    ffs = sum(int(n) for n in re.findall(r"SB_DFF\w*\s+(\d+)", stat))
    if brams == 0 or count(r"Number of memories:\s+(\d+)", stat) != 0:
        fail("synth: the frame memory is not in block RAM:\n" + stat)
    if luts > 7680:
        fail(f"synth: rastersim_top takes {luts} LUTs, more than an HX8K's 7,680")
    summary.append(f"synth ({luts} LUTs, {ffs} FFs, {brams} SB_RAM40_4K)")

if "selftest" in wanted:
    log = icarus("selftest", target_folder("selftest"))
    if not re.search(r"^selftest: PASS$", log, re.M):
        fail("selftest: the board self-test did not pass:\n" + log[-2000:])
    summary.append("selftest (PASS)")

if "hx8k" in wanted:
    folder = target_folder("hx8k")
    yosys_synth("hx8k", folder, {}, "")
    options = [str(o) for o in targets["hx8k"]["tools"]["icestorm"].get("nextpnr_options", [])]
    pins = sources("hx8k")[4]
    if len(pins) != 1:
        fail("hx8k: the target needs exactly one pin file (file_type PCF)")
    run("hx8k (nextpnr-ice40: the self-test does not fit or route)",
        ["nextpnr-ice40", "-l", "next.log", *options, "--pcf", pins[0], "--json", "rastersim.json",
         "--asc", "rastersim.asc"], cwd=folder)
    run("hx8k (icepack)", ["icepack", "rastersim.asc", "rastersim.bin"], cwd=folder)
    log = open(os.path.join(folder, "next.log")).read()
    cells = re.findall(r"ICESTORM_LC:\s+(\d+)/\s*(\d+)", log)[-1]
    rams = re.findall(r"ICESTORM_RAM:\s+(\d+)/\s*(\d+)", log)[-1]
    mhz = re.findall(r"Max frequency for clock .*?: ([\d.]+) MHz", log)[-1]
    summary.append(f"hx8k (placed and routed: {cells[0]} of {cells[1]} logic cells, {rams[0]} of {rams[1]} "
                   f"block RAMs, {mhz} MHz)")

print("check-fusesoc-core: rastersim.core and rtl/rastersim.f check out: " + ", ".join(summary))
PY
