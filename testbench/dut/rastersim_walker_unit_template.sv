// The walker's interface (docs/verification.md "Checking one unit: cosim --unit"): `rastersim
// cosim --unit walker --dut LIST --top NAME` checks a walker (traversal and attribute
// interpolation) behind these ports against the model's. Copy this module, keep its parameters
// and ports, and put your unit inside; the harness verilates rastersim_unit_pkg.sv
// (setup_record_t) before your files. As it stands it never takes a record (cosim reports the
// stall on rec_ready).
//
// All ports are synchronous to the rising edge of clk; a handshake happens in a cycle where valid
// and ready are both high.
module rastersim_walker_unit_template #(
  parameter integer WIDTH = 640,        /// screen, pixels (the profile's width), 1..4096
  parameter integer HEIGHT = 480,       /// the profile's height
  parameter integer SUBPIXEL_BITS = 4,  /// S: fraction bits of the edge values (2S)
  parameter integer Z_BITS = 24,        /// N: the depth word
  parameter integer FRACTION_BITS = 9,  /// F: fraction bits of the plane registers (docs/widths.md)
  parameter integer AUX_BITS = 1        /// the width of rec_aux
) (
  input  wire clk,
  input  wire rst,                      /// high for 4 cycles before the frame; cfg_* are steady from then on
  input  wire        cfg_shading,       /// 0 flat (rec.flat_rgb), 1 Gouraud (the colour planes)
  // Records: one drawn triangle per handshake, in triangle order.
  input  wire        rec_valid,
  output wire        rec_ready,
  input  wire [31:0] rec_index,         /// its triangle
  input  rastersim_unit_pkg::setup_record_t rec,
  /* verilator lint_off UNUSEDSIGNAL */
  input  wire [AUX_BITS-1:0] rec_aux,   /// rastersim's own walker's record (docs/verification.md); may be ignored
  /* verilator lint_on UNUSEDSIGNAL */
  // Fragments: one per covered pixel; the harness takes one in a cycle with frag_ready high.
  output wire        frag_valid,
  input  wire        frag_ready,
  output wire [31:0] frag_index,        /// its triangle (rec_index of its record)
  output wire [15:0] frag_x, frag_y,    /// its pixel
  output wire [Z_BITS-1:0] frag_z,      /// its depth word
  output wire [23:0] frag_rgb,          /// its colour {r, g, b}
  // High when every accepted record's fragments are out.
  output wire        frame_done
);
  assign rec_ready = 1'b0;
  assign {frag_valid, frag_index, frag_x, frag_y, frag_z, frag_rgb} = '0;
  assign frame_done = 1'b1;
endmodule
