// rastersim's own z-buffer and its memory behind the z-buffer's interface
// (rastersim_zbuffer_unit.sv). Paths are relative to this file.
+incdir+../../rtl
../../rtl/zbuffer.sv
../../rtl/zbuffer_memory.sv
rastersim_zbuffer_unit.sv
