// rastersim's own setup unit behind the setup unit's interface (rastersim_setup_unit.sv). Paths
// are relative to this file.
+incdir+../../rtl
../../rtl/triangle_setup.sv
../../rtl/triangle_setup_serial.sv
../../rtl/triangle_setup_pipelined.sv
rastersim_setup_unit.sv
