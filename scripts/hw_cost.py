#!/usr/bin/env python3
"""Hardware cost of the RTL on an iCE40 (docs/performance.md): yosys synth_ice40 LUT / FF / BRAM
counts and nextpnr-ice40 Fmax per unit and for the top, at one profile. Run through
scripts/hw-cost.sh; writes hw-cost.csv and hw-cost.json into --out.

- Counts are those of the unit alone (synth_ice40, flattened), as it is in rtl/: no part of a
  unit is cut out. yosys's `check` must report no problems (undriven nets, driver conflicts,
  logic loops); a row where it does says UNRELIABLE in the note column.
- Fmax is that of the unit inside a registered wrapper: every input comes from a shift register
  fed by one pin and every output is captured into a loadable shift register read out on one pin,
  so that no unit needs more pins than the package has and every timing path starts and ends at a
  flip-flop. The wrapper's own cells are placed too but not counted.
- The frame memory (W x H depth and colour words and their written-bit maps) is zbuffer_memory;
  the z-buffer reaches it through its memory port. rastersim_core is the top without it (the
  memory is an external SRAM on its mem_* ports); rastersim_top is the core with zbuffer_memory.
  zbuffer_memory and rastersim_top are synthesized only when the frame memory fits the device's
  block RAM (or with --synthesize-memory); otherwise their row says that it does not fit and
  gives the memory's bits (14.7 Mbit at 640 x 480).
- plane_register has no profile parameters of its own: it is synthesized with the widths the
  profile gives the depth plane (the widest plane register).
- Results are kept per unit in the work folder (--work) with a key of the RTL sources, the
  profile and the tool scripts: a second run with the same --work reuses them.
"""
import argparse
import csv
import hashlib
import json
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RTL = os.path.join(ROOT, "rtl")  # --rtl-dir
# What each unit's row covers (the "contents" column).
UNITS = {
    "plane_register": "one plane register at the depth plane's widths",
    "triangle_setup": "setup unit",
    "scanline_walker_entry": "the walker's entry stage before the record FIFO (first row's span, second row's DDA)",
    "scanline_walker": "scanline walker (registers' side; its entry comes through the record FIFO)",
    "z_adder": "Z adder (depth and colour plane registers)",
    "depth_bias": "bias unit: a triangle's depth bias from its record's depth steps (7 stages) and its FIFO",
    "zbuffer": "z-buffer control and in-flight ring; frame memory outside (memory port)",
    "zbuffer_memory": "frame memory on chip (depth/colour words; written bitmaps; read-back)",
    "texture_divide": "texture unit's perspective divide: u, v from S, T, Q (29 stages, one fragment per clock)",
    "texture_address": "texture unit's address stages (3): texel columns, rows and bilinear weights from u, v",
    "texture_filter": "texture unit's filter stages (6): blend and modulate, 3 channels",
    "rastersim_core": "TOP WITHOUT FRAME MEMORY: setup + walker + Z adder + z-buffer; "
                      "memory port to an external SRAM",
    "rastersim_top": "TOP WITH FRAME MEMORY ON CHIP: rastersim_core + zbuffer_memory",
}


def core_parameter_defaults(rtl):
    """rastersim_core's build parameters in declaration order with their defaults, read from where
    they are declared once (rtl/rastersim_core_parameters.vh)."""
    text = open(os.path.join(rtl, "rastersim_core_parameters.vh")).read()
    return {name: int(value) for name, value in re.findall(r"parameter integer (\w+) = (-?\d+)", text)}


# The flags' defaults where they are not the core's: the smallest record FIFO.
FLAG_DEFAULTS = {"MAX_SETUP_FIFO_DEPTH": 1}
DEVICES = {"hx8k": ("--hx8k", "ct256", 7680, 32), "up5k": ("--up5k", "sg48", 5280, 30), "hx1k": ("--hx1k", "tq144", 1280, 16)}
DEVICE_DSPS = {"hx8k": 0, "up5k": 8, "hx1k": 0}  # SB_MAC16 blocks
BRAM_BITS = 4096  # SB_RAM40_4K
MEMORY_UNITS = {"zbuffer_memory", "rastersim_top"}  # the units that hold the frame memory


def frame_memory_bits(width, height, z_bits):
    """zbuffer_memory's bits: W H depth (z_bits) and colour (24) words and two written-bit maps of
    ceil(W H / 64) rows of 64 bits (rtl/zbuffer_memory.sv)."""
    words = width * height
    return words * (z_bits + 24) + 2 * ((words + 63) // 64) * 64


# synth_ice40 of yosys 0.23 with its `coarse` step spelled out (the passes its log shows without
# -dsp; tests/hw_cost checks that they are the same) and one change: `share` leaves memory reads ($memrd) alone. The z-buffer reads its
# in-flight ring at every age (the hazard check); share enumerates the activation patterns of
# those reads, 2^age of them (128 at latency 8; at latency 64 yosys used 17 GB and was killed),
# and none of them can be merged since all are active in the same cycle. Other cells are shared as
# by synth_ice40. `rest` is the label range after coarse: "map_ram:check" stops before the check
# step (its autoname pass takes longer than synthesizing the full-size setup unit).
# With dsp, the passes of synth_ice40 -dsp that map multipliers of 2 x 2 bits or more (with a result
# of 11 bits or more) to SB_MAC16 blocks (the iCE40 UP5K has eight).
def synth_ice40(top, rest, options="", dsp=False):
    dsp_passes = ["memory_dff", "wreduce t:$mul", "techmap -map +/mul2dsp.v -map +/ice40/dsp_map.v -D DSP_A_MAXWIDTH=16 -D DSP_B_MAXWIDTH=16 "
                  "-D DSP_A_MINWIDTH=2 -D DSP_B_MINWIDTH=2 -D DSP_Y_MINWIDTH=11 -D DSP_NAME=$__MUL16X16",
                  "select a:mul2dsp", "setattr -unset mul2dsp", "opt_expr -fine", "wreduce", "select -clear",
                  "ice40_dsp", "chtype -set $mul t:$__soft_mul"] if dsp else []
    return "\n".join([
        f"synth_ice40 -top {top} -run :coarse",
        "opt_expr", "opt_clean", "check", "opt -nodffe -nosdff", "fsm", "opt", "wreduce", "peepopt", "opt_clean",
        "share t:$memrd %n",
        "techmap -map +/cmp2lut.v -D LUT_WIDTH=4", "opt_expr", "opt_clean", *dsp_passes, "alumacc", "opt",
        "memory -nomap", "opt_clean",
        f"synth_ice40 -top {top} -run {rest} {options}{' -dsp' if dsp else ''}".rstrip()]) + "\n"


# The unit without profile parameters, at the widths the profile gives the depth plane.
SHIMS = {
    "plane_register": """
`include "rastersim_pkg.sv"
module hwcost_plane_register #(
  parameter integer WIDTH = 640, parameter integer HEIGHT = 480, parameter integer SUBPIXEL_BITS = 4,
  parameter integer Z_BITS = 24, parameter integer Z_GUARD_BITS = 0, parameter integer MAX_MEMORY_LATENCY = 64
) (clk, load, step_x, next_row, row_enter, enter_left, enter_slot, left_carry, start, step_x_in, step_y_in,
     left_start, left_step, out);
`include "rastersim_widths.vh"
  localparam integer F = rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS);
  localparam integer Z_REG_BITS = Z_BITS + F + 1;
  input wire clk, load, step_x, next_row, row_enter, enter_left, enter_slot;
  input wire [1:0] left_carry;
  input wire [Z_REG_BITS-1:0] start, step_x_in, step_y_in;
  input wire [2*Z_REG_BITS-1:0] left_start, left_step;
  output wire [Z_BITS-1:0] out;
  plane_register #(.REG_BITS(Z_REG_BITS), .GUARD_BITS(F), .OUT_BITS(Z_BITS)) unit (
    .clk(clk), .load(load), .step_x(step_x), .next_row(next_row), .row_enter(row_enter),
    .enter_left(enter_left), .enter_slot(enter_slot), .left_carry(left_carry),
    .start(start), .step_x_in(step_x_in), .step_y_in(step_y_in), .left_start(left_start), .left_step(left_step),
    .out(out));
endmodule
""",
}


def run(command, log, cwd):
    with open(log, "w") as out:
        result = subprocess.run(command, stdout=out, stderr=subprocess.STDOUT, cwd=cwd)
    if result.returncode != 0:
        with open(log) as f:
            tail = f.read()[-3000:]
        raise RuntimeError(f"{command[0]} failed (log {log}):\n{tail}")


def yosys(script, log, cwd):
    path = log.replace(".log", ".ys")
    with open(path, "w") as f:
        f.write(script)
    run(["yosys", "-q", "-l", log, "-s", path], log + ".out", cwd)


def rtl_sources():
    return " ".join(os.path.join(RTL, f) for f in sorted(os.listdir(RTL)) if f.endswith(".sv"))


def module_parameters(unit):
    text = open(os.path.join(RTL, unit + ".sv")).read()
    if "`RASTERSIM_CORE_PARAMETERS" in text:  # rastersim_core, rastersim_top: every core parameter
        text += open(os.path.join(RTL, "rastersim_core_parameters.vh")).read()
    return [p for p in core_parameter_defaults(RTL) if re.search(r"parameter\s+integer\s+" + p + r"\b", text)]


def unit_parameters(unit, profile):
    """The parameters a unit of rtl/ is synthesized with: the core's parameters it declares."""
    return {p: profile[p] for p in module_parameters(unit)}


def yosys_ports(work, top, read, chparams):
    """The ports of `top` after elaboration: [(name, direction, width)] in declaration order."""
    chparam = " ".join(f"-set {k} {v}" for k, v in chparams.items() if v is not None)
    script = f"read_verilog -sv -I{RTL} {rtl_sources()} {read}\n"
    if chparam:
        script += f"chparam {chparam} {top}\n"
    script += f"hierarchy -top {top}\nproc\nwrite_json {top}.ports.json\n"
    yosys(script, os.path.join(work, top + ".ports.log"), work)
    module = json.load(open(os.path.join(work, top + ".ports.json")))["modules"][top]
    return [(name, p["direction"], len(p["bits"])) for name, p in module["ports"].items()]


def wrapper(top, instance_parameters, ports):
    """A registered wrapper: inputs from a shift chain on pin `serial_in`, outputs into a loadable
    shift chain read on pin `serial_out` (`capture` loads it)."""
    inputs = [(n, w) for n, d, w in ports if d == "input" and n != "clk"]
    outputs = [(n, w) for n, d, w in ports if d == "output"]
    in_bits = sum(w for _, w in inputs) or 1
    out_bits = sum(w for _, w in outputs) or 1
    lines = ["module hwcost_wrapper (input wire clk, input wire serial_in, input wire capture, output wire serial_out);",
             f"  reg [{in_bits - 1}:0] in_chain;",
             f"  always @(posedge clk) in_chain <= {{in_chain[{max(in_bits - 2, 0)}:0], serial_in}};" if in_bits > 1
             else "  always @(posedge clk) in_chain <= serial_in;",
             f"  wire [{out_bits - 1}:0] out_bits;",
             f"  reg [{out_bits - 1}:0] out_chain;",
             f"  always @(posedge clk) out_chain <= capture ? out_bits : {{out_chain[{max(out_bits - 2, 0)}:0], 1'b0}};"
             if out_bits > 1 else "  always @(posedge clk) out_chain <= out_bits;",
             f"  assign serial_out = out_chain[{out_bits - 1}];"]
    connections, at = [], 0
    if any(n == "clk" for n, _, _ in ports):
        connections.append(".clk(clk)")
    for name, width in inputs:
        connections.append(f".{name}(in_chain[{at + width - 1}:{at}])")
        at += width
    at = 0
    for name, width in outputs:
        connections.append(f".{name}(out_bits[{at + width - 1}:{at}])")
        at += width
    params = ", ".join(f".{k}({v})" for k, v in instance_parameters.items())
    lines.append(f"  {top} {'#(' + params + ') ' if params else ''}unit (" + ", ".join(connections) + ");")
    lines.append("endmodule")
    return "\n".join(lines) + "\n"


def cell_counts(stat_json, top):
    cells = json.load(open(stat_json))["modules"]["\\" + top]["num_cells_by_type"]
    luts = cells.get("SB_LUT4", 0)
    ffs = sum(n for t, n in cells.items() if t.startswith("SB_DFF"))
    brams = sum(n for t, n in cells.items() if t.startswith("SB_RAM"))
    carries = cells.get("SB_CARRY", 0)
    dsps = cells.get("SB_MAC16", 0)
    return luts, ffs, brams, carries, dsps


def ecp5_counts(stat_json, top):
    """LUT4s, flip-flops, 18x18 multipliers, carry cells (two bits each) and block RAMs of synth_ecp5."""
    cells = json.load(open(stat_json))["modules"]["\\" + top]["num_cells_by_type"]
    return {"ecp5_lut4": cells.get("LUT4", 0), "ecp5_ffs": cells.get("TRELLIS_FF", 0),
            "ecp5_mult18": cells.get("MULT18X18D", 0), "ecp5_ccu2c": cells.get("CCU2C", 0),
            "ecp5_dp16kd": cells.get("DP16KD", 0)}


def check_problems(log):
    """The problems yosys's `check` passes found (undriven nets, conflicting drivers, logic loops):
    their total and the first few warning lines."""
    text = open(log).read()
    total = sum(int(n) for n in re.findall(r"Found and reported (\d+) problems", text))
    lines = [line for line in text.splitlines()
             if line.startswith("Warning:") and ("no driver" in line or "conflict" in line or "logic loop" in line)]
    return total, lines[:5]


def pnr_failure(log, device, error):
    """Why nextpnr failed: "does not fit" with its logic-cell utilisation when it ran out of cells
    (a LUT and a flip-flop share a cell, so a unit under the LUT count can still overflow), else
    its first error line."""
    text = open(log).read() if os.path.exists(log) else error
    used = re.search(r"ICESTORM_LC:\s*(\d+)/\s*(\d+)", text)
    if "no BELs remaining" in text and used:
        ratio = int(used.group(1)) / int(used.group(2))
        return f"does not fit ({ratio:.1f} x the {device}'s logic cells; wrapper included): placement failed"
    errors = [line for line in text.splitlines() if line.startswith("ERROR")]
    return "place and route failed: " + (errors[0] if errors else error.splitlines()[-1])[:120]


def cache_key(*parts):
    """A digest of the RTL sources (names and contents) and the given texts (scripts, profile)."""
    digest = hashlib.sha256()
    for f in sorted(os.listdir(RTL)):
        if f.endswith((".sv", ".vh")):
            digest.update(f.encode() + b"\0" + open(os.path.join(RTL, f), "rb").read() + b"\0")
    for part in parts:
        digest.update(str(part).encode() + b"\0")
    return digest.hexdigest()


def cached(path, key, compute):
    """compute()'s result, or the one stored in `path` under the same key (then said on stderr)."""
    if os.path.exists(path):
        stored = json.load(open(path))
        if stored.get("key") == key:
            print(f"hw-cost: reusing {path}", file=sys.stderr, flush=True)
            return stored["result"]
    result = compute()
    with open(path, "w") as f:
        json.dump({"key": key, "result": result}, f, indent=2)
    return result


def cost_unit(unit, args, profile, work):
    """The row of one unit: counts, check problems, Fmax (or why none), tool times."""
    device_flag, package, device_luts, device_brams = DEVICES[args.device]
    read = ""
    if unit in SHIMS:
        top = "hwcost_" + unit
        read = os.path.join(work, top + ".v")
        with open(read, "w") as f:
            f.write(SHIMS[unit])
        parameters = {p: profile[p] for p in core_parameter_defaults(RTL)
                      if re.search(r"parameter\s+integer\s+" + p + r"\b", SHIMS[unit])}
    else:
        top = unit
        parameters = unit_parameters(unit, profile)
    unit_dir = os.path.join(work, unit)
    os.makedirs(unit_dir, exist_ok=True)
    frame_bits = frame_memory_bits(profile["WIDTH"], profile["HEIGHT"], profile["Z_BITS"])
    memory_bits = frame_bits if unit in MEMORY_UNITS else 0
    row = {"unit": unit, "contents": UNITS[unit], "device": args.device, **{p.lower(): v for p, v in profile.items()},
           "memory_bits": memory_bits, "luts": None, "ffs": None, "brams": None, "carries": None,
           "check_problems": None, "fmax_mhz": None, "fmax_seeds_mhz": None, "note": "", "synth_s": None, "pnr_s": None}
    if args.dsp:
        row["dsps"] = None
    if args.ecp5:
        row.update({"ecp5_lut4": None, "ecp5_ffs": None, "ecp5_mult18": None, "ecp5_ccu2c": None,
                    "ecp5_dp16kd": None, "ecp5_synth_s": None})
    memory_fits = memory_bits <= device_brams * BRAM_BITS
    if not memory_fits and not args.synthesize_memory:
        row["note"] = (f"not synthesized: does not fit (frame memory {memory_bits} bits = "
                       f"{memory_bits / (device_brams * BRAM_BITS):.1f} x the {args.device}'s block RAM of "
                       f"{device_brams} x {BRAM_BITS} bits)")
        return row

    # Counts: synth_ice40 up to its `check` step, then that step's checks and the statistics.
    chparam = " ".join(f"-set {k} {v}" for k, v in parameters.items())
    synth = (f"read_verilog -sv -I{RTL} {rtl_sources()} {read}\nchparam {chparam} {top}\nhierarchy -top {top}\n"
             f"{synth_ice40(top, 'map_ram:check', dsp=args.dsp)}hierarchy -check\ncheck -noinit\n"
             f"tee -q -o stat.json stat -json\n")

    def synthesize():
        start = time.monotonic()
        yosys(synth, os.path.join(unit_dir, "synth.log"), unit_dir)
        luts, ffs, brams, carries, dsps = cell_counts(os.path.join(unit_dir, "stat.json"), top)
        problems, lines = check_problems(os.path.join(unit_dir, "synth.log"))
        return {"luts": luts, "ffs": ffs, "brams": brams, "carries": carries, "dsps": dsps, "check_problems": problems,
                "problem_lines": lines, "synth_s": round(time.monotonic() - start)}
    counts = cached(os.path.join(unit_dir, "synth.json"), cache_key(unit, read and SHIMS[unit], synth), synthesize)
    row.update({k: v for k, v in counts.items() if k in row})
    notes = []
    if counts["check_problems"]:
        notes.append(f"UNRELIABLE: yosys check found {counts['check_problems']} problems "
                     f"({' | '.join(counts['problem_lines'])})")
    if memory_bits:
        notes.append("memory on chip" if memory_fits
                     else "memory synthesized beyond the block RAM (--synthesize-memory)")
    elif unit == "rastersim_core":
        notes.append(f"frame memory ({frame_bits} bits) not included: external behind the memory port")
    if args.ecp5:
        # The same unit through synth_ecp5 (LUT4s and MULT18X18D multipliers; no ECP5 place and route
        # is installed here).
        ecp5 = (f"read_verilog -sv -I{RTL} {rtl_sources()} {read}\nchparam {chparam} {top}\nhierarchy -top {top}\n"
                f"synth_ecp5 -top {top}\ntee -q -o stat_ecp5.json stat -json\n")

        def synthesize_ecp5():
            start = time.monotonic()
            yosys(ecp5, os.path.join(unit_dir, "synth_ecp5.log"), unit_dir)
            result = ecp5_counts(os.path.join(unit_dir, "stat_ecp5.json"), top)
            result["ecp5_synth_s"] = round(time.monotonic() - start)
            return result
        row.update(cached(os.path.join(unit_dir, "synth_ecp5.json"), cache_key(unit, read and SHIMS[unit], ecp5),
                          synthesize_ecp5))
    if not args.no_pnr:
        if args.dsp and counts["dsps"] > DEVICE_DSPS[args.device]:
            notes.append(f"does not fit ({counts['dsps']} SB_MAC16; the {args.device} has "
                         f"{DEVICE_DSPS[args.device]}): no place and route")
        elif row["luts"] > device_luts or row["brams"] > device_brams:
            lut_ratio, bram_ratio = row["luts"] / device_luts, row["brams"] / device_brams
            what = "LUTs" if lut_ratio >= bram_ratio else "block RAMs"
            notes.append(f"does not fit ({max(lut_ratio, bram_ratio):.1f} x the {args.device}'s {what}): "
                         "no place and route")
        else:
            wrap = (f"read_verilog -sv -I{RTL} {rtl_sources()} {read} wrapper.v\n"
                    f"hierarchy -top hwcost_wrapper\n{synth_ice40('hwcost_wrapper', 'map_ram:', '-json wrapped.json', dsp=args.dsp)}")
            pnr = ["nextpnr-ice40", device_flag, "--package", package, "--json", "wrapped.json", "--freq", "100",
                   "--timing-allow-fail"]

            def place_and_route(seed):
                start = time.monotonic()
                ports = yosys_ports(unit_dir, top, read, parameters)
                with open(os.path.join(unit_dir, "wrapper.v"), "w") as f:
                    f.write(wrapper(top, parameters, ports))
                result = {"fmax_mhz": None, "failure": ""}
                report, log = f"pnr-seed{seed}.json", os.path.join(unit_dir, f"pnr-seed{seed}.log")
                try:
                    yosys(wrap, os.path.join(unit_dir, "wrap.log"), unit_dir)
                    run(pnr + ["--report", report, "--seed", str(seed)], log, unit_dir)
                    fmax = json.load(open(os.path.join(unit_dir, report)))["fmax"]
                    result["fmax_mhz"] = round(min(v["achieved"] for v in fmax.values()), 1)
                except RuntimeError as e:
                    result["failure"] = pnr_failure(log, args.device, str(e))
                result["pnr_s"] = round(time.monotonic() - start)
                return result
            # Each placement seed's result is kept on its own; the row's Fmax is the worst seed's.
            placements = [cached(os.path.join(unit_dir, f"pnr-seed{seed}-result.json"),
                                 cache_key(unit, read and SHIMS[unit], parameters, wrap, " ".join(pnr), seed),
                                 lambda seed=seed: place_and_route(seed))
                          for seed in range(1, args.seeds + 1)]
            failures = [p["failure"] for p in placements if p["failure"]]
            if failures:
                notes.append(failures[0])
            else:
                fmax = [p["fmax_mhz"] for p in placements]
                row["fmax_mhz"] = min(fmax)
                row["fmax_seeds_mhz"] = "/".join(f"{f:.1f}" for f in fmax)
            row["pnr_s"] = sum(p["pnr_s"] for p in placements)
    row["note"] = "; ".join(notes).replace(",", ";")  # scripts/performance.sh splits the CSV at commas
    return row


def main():
    global RTL
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    for p, default in core_parameter_defaults(RTL).items():
        default = FLAG_DEFAULTS.get(p, default)
        parser.add_argument("--" + p.lower().replace("_", "-"), type=int, default=default, dest=p,
                            help=f"rastersim_core's {p} (default {default})")
    parser.add_argument("--device", choices=sorted(DEVICES), default="hx8k")
    parser.add_argument("--units", default=" ".join(UNITS), help="space-separated units (default: all)")
    parser.add_argument("--synthesize-memory", action="store_true",
                        help="synthesize zbuffer_memory and rastersim_top even when the frame memory exceeds the "
                             "device's block RAM (small profiles only: yosys builds what does not map to block RAM "
                             "from flip-flops)")
    parser.add_argument("--no-pnr", action="store_true", help="counts only, no nextpnr (no Fmax)")
    parser.add_argument("--seeds", type=int, default=1,
                        help="place and route each unit at nextpnr seeds 1..N: fmax_mhz is the worst seed's, "
                             "fmax_seeds_mhz lists every seed's (default 1)")
    parser.add_argument("--dsp", action="store_true",
                        help="synth_ice40 -dsp: multipliers onto SB_MAC16 blocks, counted in the dsps column "
                             "(needs --device up5k, the iCE40 with DSP blocks)")
    parser.add_argument("--ecp5", action="store_true",
                        help="also synthesize each unit with yosys synth_ecp5: LUT4, flip-flop, MULT18X18D, CCU2C "
                             "and DP16KD counts in the ecp5_* columns (no ECP5 place and route)")
    parser.add_argument("--rtl-dir", default=RTL, help="RTL sources (default: the source tree's rtl/)")
    parser.add_argument("--out", default=".", help="folder for hw-cost.csv and hw-cost.json")
    parser.add_argument("--work", default="", help="folder for the tools' files and the per-unit results that a "
                                                   "second run reuses (default: a new temporary one)")
    args = parser.parse_args()
    RTL = os.path.abspath(args.rtl_dir)
    profile = {p: getattr(args, p) for p in core_parameter_defaults(RTL)}
    if args.seeds < 1:
        print("hw-cost: --seeds must be 1 or more", file=sys.stderr)
        sys.exit(2)
    if args.dsp and args.device != "up5k":
        print(f"hw-cost: --dsp needs --device up5k (the {args.device} has no SB_MAC16 blocks)", file=sys.stderr)
        sys.exit(2)
    units = args.units.split()
    for u in units:
        if u not in UNITS:
            print(f"hw-cost: unknown unit '{u}' (units: {' '.join(UNITS)})", file=sys.stderr)
            sys.exit(2)
    work = os.path.abspath(args.work) if args.work else tempfile.mkdtemp(prefix="rastersim-hw-cost-")
    os.makedirs(work, exist_ok=True)
    os.makedirs(args.out, exist_ok=True)

    rows = []
    for unit in units:
        print(f"hw-cost: {unit} ...", file=sys.stderr, flush=True)
        row = cost_unit(unit, args, profile, work)
        rows.append(row)
        fmax = f"{row['fmax_mhz']} MHz" + (f" (seeds {row['fmax_seeds_mhz']})" if args.seeds > 1 else "")
        counts = (f"{row['luts']} LUT, {row['ffs']} FF, {row['brams']} BRAM, "
                  f"{str(row['dsps']) + ' SB_MAC16, ' if args.dsp else ''}Fmax {fmax}, "
                  f"yosys {row['synth_s']} s, wrapper + nextpnr {row['pnr_s']} s" if row["luts"] is not None else "")
        if args.ecp5 and row["ecp5_lut4"] is not None:
            counts += (f"; ECP5: {row['ecp5_lut4']} LUT4, {row['ecp5_ffs']} FF, {row['ecp5_mult18']} MULT18X18D, "
                       f"{row['ecp5_ccu2c']} CCU2C, {row['ecp5_dp16kd']} DP16KD (yosys {row['ecp5_synth_s']} s)")
        print(f"hw-cost: {unit} [{row['contents']}]: {counts}{'; ' if counts and row['note'] else ''}{row['note']}",
              file=sys.stderr, flush=True)

    with open(os.path.join(args.out, "hw-cost.json"), "w") as f:
        json.dump({"profile": profile, "device": args.device, "package": DEVICES[args.device][1], "units": rows}, f,
                  indent=2)
    with open(os.path.join(args.out, "hw-cost.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    print(f"hw-cost: wrote {os.path.join(args.out, 'hw-cost.csv')} and hw-cost.json (work files in {work})", file=sys.stderr)


if __name__ == "__main__":
    main()
