// The setup unit's interface (docs/verification.md "Checking one unit: cosim --unit"): `rastersim
// cosim --unit setup --dut LIST --top NAME` checks a setup unit behind these ports against the
// model's setup. Copy this module, keep its parameters and ports, and put your unit inside; the
// harness verilates rastersim_unit_pkg.sv (setup_record_t) before your files. As it stands it
// never takes a triangle (cosim reports the stall on cmd_ready).
//
// All ports are synchronous to the rising edge of clk; a handshake happens in a cycle where valid
// and ready are both high; the output ports have no ready: the harness takes every cycle's output.
module rastersim_setup_unit_template #(
  parameter integer WIDTH = 640,        /// screen, pixels (the profile's width), 1..4096
  parameter integer HEIGHT = 480,       /// the profile's height
  parameter integer SUBPIXEL_BITS = 4,  /// S: fraction bits of the command's x and y
  parameter integer Z_BITS = 24,        /// N: the depth word
  parameter integer FRACTION_BITS = 9   /// F: fraction bits of the plane registers (docs/widths.md)
) (
  input  wire clk,
  input  wire rst,                      /// high for 4 cycles before the frame; cfg_* are steady from then on
  input  wire [1:0]  cfg_cull,          /// 0 none, 1 back, 2 front
  input  wire        cfg_front_face,    /// 0 counter-clockwise, 1 clockwise (as seen on the screen, y down)
  // Commands: one triangle per handshake, in order; the k-th accepted is triangle k.
  input  wire        cmd_valid,
  output wire        cmd_ready,
  input  wire [31:0] cmd_x0, cmd_y0, cmd_x1, cmd_y1, cmd_x2, cmd_y2,  /// snapped, two's complement, S fraction bits
  input  wire [Z_BITS-1:0] cmd_z0, cmd_z1, cmd_z2,                    /// depth words, 0 near
  input  wire [23:0] cmd_rgb0, cmd_rgb1, cmd_rgb2,                    /// {r, g, b}
  // Decisions: one per triangle, in triangle order.
  output wire        dec_valid,
  output wire [2:0]  dec_status,        /// 0 drawn, 1 degenerate, 2 culled, 3 offscreen, 4 no pixel centre
  // Records: one per drawn triangle, in triangle order (the k-th is the k-th drawn triangle's).
  output wire        rec_valid,
  output rastersim_unit_pkg::setup_record_t rec,
  // High when every accepted triangle has its decision and, drawn, its record out.
  output wire        frame_done
);
  assign cmd_ready = 1'b0;
  assign {dec_valid, dec_status} = '0;
  assign rec_valid = 1'b0;
  assign rec = '0;
  assign frame_done = 1'b1;
endmodule
