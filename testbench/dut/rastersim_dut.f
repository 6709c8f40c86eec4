// rastersim's own core behind the verification interface (rastersim_dut.sv): `rastersim cosim
// --dut testbench/dut/rastersim_dut.f --top rastersim_dut`. Paths are relative to this file.
-F ../../rtl/rastersim.f
rastersim_dut.sv
