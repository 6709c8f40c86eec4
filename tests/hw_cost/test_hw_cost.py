#!/usr/bin/env python3
"""scripts/hw-cost.sh (scripts/hw_cost.py) at tiny profiles, counts only (no nextpnr): the frame
memory is not synthesized where it cannot fit, a unit's row says UNRELIABLE when yosys's check
finds an undriven net, a second run reuses the per-unit results unless the RTL changed, and the
script's spelled-out synth_ice40 runs the same passes as yosys's own."""
import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import hw_cost  # noqa: E402  (scripts/ is not a package)
SCRIPT = os.path.join(ROOT, "scripts", "hw-cost.sh")
TINY = ["--width", "16", "--height", "8", "--max-memory-latency", "4", "--no-pnr"]


def run_hw_cost(*args):
    """(rows by unit, stderr) of one run."""
    out = tempfile.mkdtemp(prefix="hw-cost-test-out-")
    result = subprocess.run([SCRIPT, "--out", out, *args], capture_output=True, text=True)
    if result.returncode != 0:
        raise AssertionError(f"hw-cost.sh failed:\n{result.stderr}")
    with open(os.path.join(out, "hw-cost.csv")) as f:
        rows = {row["unit"]: row for row in csv.DictReader(f)}
    shutil.rmtree(out)
    return rows, result.stderr


class HwCost(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.mkdtemp(prefix="hw-cost-test-work-")

    def tearDown(self):
        shutil.rmtree(self.work)

    def test_every_core_parameter_reaches_the_units_that_declare_it(self):
        defaults = hw_cost.core_parameter_defaults(hw_cost.RTL)
        # Read from rtl/rastersim_core_parameters.vh: rastersim_core's whole list, in its order.
        self.assertEqual(list(defaults)[:4], ["WIDTH", "HEIGHT", "SUBPIXEL_BITS", "Z_BITS"])
        self.assertEqual(len(defaults), 16)
        profile = {**defaults, "WIDTH": 16, "HEIGHT": 8, "MAX_MEMORY_LATENCY": 4, "MAX_SETUP_FIFO_DEPTH": 1,
                   "TEXTURE": 1, "MAX_TEXTURE_LATENCY": 8, "DEPTH_EXPONENT_BITS": 3, "DEPTH_BIAS": 1, "PIXEL_CENTER": 1,
                   "FILL_RULE": 3, "DEPTH_ROUNDING": 1, "COLOR_ROUNDING": 1}
        self.assertEqual(hw_cost.unit_parameters("rastersim_core", profile), profile)
        self.assertEqual(hw_cost.unit_parameters("rastersim_top", profile), profile)
        self.assertEqual((hw_cost.unit_parameters("triangle_setup", profile).get("PIXEL_CENTER"),
                          hw_cost.unit_parameters("triangle_setup", profile).get("FILL_RULE")), (1, 3))
        z_adder = hw_cost.unit_parameters("z_adder", profile)
        self.assertEqual((z_adder.get("DEPTH_EXPONENT_BITS"), z_adder.get("DEPTH_BIAS")), (3, 1))
        self.assertNotIn("SETUP_INTERVAL", z_adder)  # declared by the core, not by the Z adder
        self.assertNotIn("TEXTURE", hw_cost.unit_parameters("zbuffer", profile))

    def test_default_profile_frame_memory_is_not_synthesized(self):
        rows, _ = run_hw_cost("--units", "zbuffer_memory rastersim_top", "--work", self.work)
        # 640 x 480 words of 24 depth and 24 colour bits, two written bitmaps of 4800 rows of 64.
        bits = 640 * 480 * (24 + 24) + 2 * 4800 * 64
        for unit in ("zbuffer_memory", "rastersim_top"):
            self.assertEqual(int(rows[unit]["memory_bits"]), bits)
            self.assertEqual(rows[unit]["luts"], "")
            self.assertIn("not synthesized: does not fit (frame memory 15360000 bits = 117.2 x the hx8k's block RAM",
                          rows[unit]["note"])
        self.assertFalse(os.path.exists(os.path.join(self.work, "zbuffer_memory", "synth.log")))

    def test_undriven_net_is_reported_and_results_are_reused_until_the_rtl_changes(self):
        rows, _ = run_hw_cost(*TINY, "--units", "zbuffer", "--work", self.work)
        clean = rows["zbuffer"]
        self.assertEqual(clean["check_problems"], "0")
        self.assertEqual(clean["note"], "")
        self.assertGreater(int(clean["luts"]), 0)
        self.assertEqual(clean["memory_bits"], "0")

        again, stderr = run_hw_cost(*TINY, "--units", "zbuffer", "--work", self.work)
        self.assertIn("reusing", stderr)
        self.assertEqual(again["zbuffer"], clean)

        # A copy of the RTL whose z-buffer leaves issue (a read goes out) undriven.
        rtl = os.path.join(self.work, "rtl")
        shutil.copytree(os.path.join(ROOT, "rtl"), rtl)
        path = os.path.join(rtl, "zbuffer.sv")
        with open(path) as f:
            text = f.read()
        broken = text.replace("wire issue = mem_rd_valid && mem_rd_ready;", "wire issue;")
        self.assertNotEqual(broken, text)
        with open(path, "w") as f:
            f.write(broken)
        rows, stderr = run_hw_cost(*TINY, "--units", "zbuffer", "--work", self.work, "--rtl-dir", rtl)
        self.assertNotIn("reusing", stderr)
        self.assertGreater(int(rows["zbuffer"]["check_problems"]), 0)
        self.assertTrue(rows["zbuffer"]["note"].startswith("UNRELIABLE"), rows["zbuffer"]["note"])
        self.assertIn("issue", rows["zbuffer"]["note"])

    def test_nextpnr_out_of_cells_reads_as_does_not_fit(self):
        log = os.path.join(self.work, "pnr.log")
        with open(log, "w") as f:
            f.write("Info: Device utilisation:\nInfo: \t         ICESTORM_LC: 10459/ 7680   136%\n"
                    "ERROR: Unable to place cell 'x', no BELs remaining to implement cell type 'ICESTORM_LC'\n"
                    "1 warning, 1 error\n")
        self.assertEqual(hw_cost.pnr_failure(log, "hx8k", "nextpnr-ice40 failed"),
                         "does not fit (1.4 x the hx8k's logic cells; wrapper included): placement failed")
        with open(log, "w") as f:
            f.write("Info: reading\nERROR: something else\n1 error\n")
        self.assertEqual(hw_cost.pnr_failure(log, "hx8k", "nextpnr-ice40 failed"),
                         "place and route failed: ERROR: something else")

    def passes_and_cells(self, read, synth_by_name):
        """Per yosys script (the same `read` then each synthesis): the passes run, in order, and the
        cell counts of the result."""
        results = {}
        for name, synth in synth_by_name.items():
            script, log = os.path.join(self.work, name + ".ys"), os.path.join(self.work, name + ".log")
            with open(script, "w") as f:
                f.write(read + synth + "stat\n")
            subprocess.run(["yosys", "-q", "-l", log, "-s", script], check=True, capture_output=True)
            with open(log) as f:
                text = f.read()
            passes = [p for p in re.findall(r"^[0-9.]+ Executing (.*)$", text, re.M) if p != "SYNTH_ICE40 pass."]
            results[name] = (passes, dict(re.findall(r"^ +(SB_\w+) +(\d+)$", text, re.M)))
        return results

    def test_spelled_out_synth_ice40_runs_the_same_passes_as_yosys(self):
        """On a unit without memory reads (where the restricted share changes nothing), the script's
        synth_ice40 and yosys's own run the same passes in the same order and give the same cells."""
        rtl = os.path.join(ROOT, "rtl")
        read = (f"read_verilog -sv -I{rtl} {os.path.join(rtl, 'plane_register.sv')} {os.path.join(rtl, 'z_adder.sv')}\n"
                "chparam -set WIDTH 16 -set HEIGHT 8 -set Z_BITS 16 z_adder\nhierarchy -top z_adder\n")
        r = self.passes_and_cells(read, {"yosys": "synth_ice40 -top z_adder -run :check\n",
                                         "script": hw_cost.synth_ice40("z_adder", "map_ram:check")})
        self.assertIn("SHARE pass (SAT-based resource sharing).", r["yosys"][0])
        self.assertTrue(r["yosys"][1])
        self.assertEqual(r["script"], r["yosys"])

    def test_spelled_out_synth_ice40_dsp_runs_the_same_passes_as_yosys(self):
        """With -dsp too: the texture filter's products become SB_MAC16 blocks, the same passes and
        cells as yosys's own synth_ice40 -dsp."""
        rtl = os.path.join(ROOT, "rtl")
        read = f"read_verilog -sv -I{rtl} {os.path.join(rtl, 'texture_filter.sv')}\nhierarchy -top texture_filter\n"
        r = self.passes_and_cells(read, {"yosys": "synth_ice40 -dsp -top texture_filter -run :check\n",
                                         "script": hw_cost.synth_ice40("texture_filter", "map_ram:check", dsp=True)})
        self.assertGreater(int(r["yosys"][1].get("SB_MAC16", "0")), 0)
        self.assertEqual(r["script"], r["yosys"])

    def test_dsp_blocks_are_counted_and_more_than_the_device_has_do_not_fit(self):
        rows, _ = run_hw_cost("--device", "up5k", "--dsp", "--units", "texture_filter", "--work", self.work)
        row = rows["texture_filter"]
        self.assertGreater(int(row["dsps"]), 8)  # the three channels' bilinear products
        self.assertIn(f"does not fit ({row['dsps']} SB_MAC16; the up5k has 8)", row["note"])
        self.assertEqual(row["fmax_mhz"], "")

    def test_dsp_needs_the_up5k_and_seeds_at_least_one(self):
        for args in (["--dsp"], ["--dsp", "--device", "hx8k"], ["--seeds", "0"]):
            result = subprocess.run([SCRIPT, "--out", self.work, "--units", "z_adder", *TINY, *args],
                                    capture_output=True, text=True)
            self.assertEqual(result.returncode, 2, args)
            self.assertIn("hw-cost:", result.stderr)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
