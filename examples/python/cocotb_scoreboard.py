"""How a cocotb test would use the model as its scoreboard (docs/library.md). Not run by the test
suite (cocotb is not a Debian package); examples/python/scoreboard.py and python/tests run the same
calls. The DUT is rastersim_top (or your own design with the same command and fragment ports); the
model predicts every fragment, in order, with the cycle the z-buffer accepts it."""
import cocotb
from cocotb.clock import Clock
from cocotb.triggers import FallingEdge, RisingEdge

import rastersim

PROFILE = '{"width": 64, "height": 48, "setup_interval": 2, "memory_latency": 3}'
TRIANGLES = [  # snapped: x, y in 1/16 pixels, z as a 24-bit integer, r, g, b
    [(56, 36, 4194304, 255, 0, 0), (640, 168, 8388608, 0, 255, 0), (204, 480, 12582912, 0, 0, 255)],
]


@cocotb.test()
async def fragments_match_the_model(dut):
    model = rastersim.Pipeline(PROFILE)
    for vertices in TRIANGLES:
        model.submit_snapped(vertices)
    expected = model.fragments()  # (n, 9): tri, x, y, z, pass, r, g, b, cycle
    cocotb.start_soon(Clock(dut.clk, 10, units="ns").start())
    dut.rst.value = 1
    for _ in range(4):
        await RisingEdge(dut.clk)
    dut.rst.value = 0
    cycle, seen, offered = -1, 0, 0
    while seen < len(expected):
        if offered < len(TRIANGLES):  # offer triangles back to back, as the model assumes
            for k, (x, y, z, r, g, b) in enumerate(TRIANGLES[offered]):
                getattr(dut, f"cmd_x{k}").value = x & 0xFFFF
                getattr(dut, f"cmd_y{k}").value = y & 0xFFFF
                getattr(dut, f"cmd_z{k}").value = z
                getattr(dut, f"cmd_rgb{k}").value = (r << 16) | (g << 8) | b
        dut.cmd_valid.value = offered < len(TRIANGLES)
        await FallingEdge(dut.clk)
        if cycle < 0 and dut.frame_ready.value:
            cycle = 0
        if cycle >= 0:
            if dut.cmd_valid.value and dut.cmd_ready.value:
                offered += 1
            if dut.trace_frag_valid.value and dut.trace_frag_ready.value:
                tri, x, y, z, _, r, g, b, at = (int(v) for v in expected[seen])
                got = (int(dut.trace_frag_x.value), int(dut.trace_frag_y.value), int(dut.trace_frag_z.value),
                       int(dut.trace_frag_rgb.value), cycle)
                assert got == (x, y, z, (r << 16) | (g << 8) | b, at), \
                    f"triangle {tri}, pixel ({x}, {y}): rtl {got}, model {(x, y, z, (r << 16) | (g << 8) | b, at)}"
                seen += 1
            cycle += 1
        await RisingEdge(dut.clk)
    assert cycle <= model.frame_cycles()
