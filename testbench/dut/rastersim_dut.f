// rastersim's own core behind the verification interface (rastersim_dut.sv): `rastersim cosim
// --dut testbench/dut/rastersim_dut.f --top rastersim_dut`, or with the memory port (the harness's
// memory behind it): `--top rastersim_dut_memory`. Paths are relative to this file.
-F ../../rtl/rastersim.f
rastersim_dut_memory.sv
rastersim_dut.sv
