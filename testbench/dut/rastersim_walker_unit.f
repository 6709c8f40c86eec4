// rastersim's own walker and Z adder behind the walker's interface (rastersim_walker_unit.sv). Paths
// are relative to this file.
+incdir+../../rtl
../../rtl/plane_register.sv
../../rtl/scanline_walker.sv
../../rtl/scanline_walker_entry.sv
../../rtl/span_bounds.sv
../../rtl/z_adder.sv
rastersim_walker_unit.sv
