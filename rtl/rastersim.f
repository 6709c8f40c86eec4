// The pipeline's files for tools without FuseSoC (rastersim.core lists the same), relative to this
// folder: `verilator -F rtl/rastersim.f --top-module rastersim_top` from anywhere (-F reads paths
// relative to the file), or `iverilog -g2012 -c rastersim.f -s rastersim_top` from rtl/. In this
// order: with rastersim_core after the units, Verilator 5.006's lint reports the width functions of
// rastersim_widths.vh as hiding themselves (rtl/lint_waivers.vlt covers the order below).
+incdir+.
rastersim_pkg.sv
depth_bias.sv
depth_word.sv
plane_register.sv
rastersim_core.sv
rastersim_top.sv
scanline_walker.sv
scanline_walker_entry.sv
setup_fifo.sv
span_bounds.sv
texture_address.sv
texture_divide.sv
texture_filter.sv
texture_memory.sv
texture_unit.sv
triangle_setup.sv
triangle_setup_pipelined.sv
triangle_setup_serial.sv
z_adder.sv
zbuffer.sv
zbuffer_memory.sv
