// The z-buffer's interface (docs/verification.md "Checking one unit: cosim --unit"): `rastersim
// cosim --unit zbuffer --dut LIST --top NAME` checks a z-buffer (depth test and the buffers it
// writes) behind these ports against the model's. Copy this module, keep its parameters and
// ports, and put your unit inside. As it stands it never takes a fragment (cosim reports the
// stall on frag_ready).
//
// All ports are synchronous to the rising edge of clk; a handshake happens in a cycle where valid
// and ready are both high; the result port has no ready: the harness takes every cycle's output.
module rastersim_zbuffer_unit_template #(
  parameter integer WIDTH = 640,        /// screen, pixels (the profile's width), 1..4096
  parameter integer HEIGHT = 480,       /// the profile's height
  parameter integer SUBPIXEL_BITS = 4,  /// S (given to every unit)
  parameter integer Z_BITS = 24,        /// N: the depth word
  parameter integer FRACTION_BITS = 9   /// F (given to every unit)
) (
  input  wire clk,
  input  wire rst,                      /// high for 4 cycles before the frame; cfg_* are steady from then on
  input  wire [2:0]  cfg_depth_func,    /// 0 never, 1 less, 2 equal, 3 lequal, 4 greater, 5 notequal, 6 gequal, 7 always
  input  wire        cfg_depth_write,   /// 1: a passing fragment writes its depth
  input  wire [Z_BITS-1:0] cfg_depth_clear,  /// the depth buffer's value after reset (the colour buffer's is 0)
  // Fragments: one per handshake, in the order the model's walker made them.
  input  wire        frag_valid,
  output wire        frag_ready,
  input  wire [15:0] frag_x, frag_y,    /// its pixel
  input  wire [Z_BITS-1:0] frag_z,      /// its depth word
  input  wire [23:0] frag_rgb,          /// its colour {r, g, b}
  // Results: one per fragment, in fragment order.
  output wire        res_valid,
  output wire        res_pass,          /// 1: the depth test passed (colour written, depth too with cfg_depth_write)
  // High when every accepted fragment has its result out and its writes in the buffers.
  output wire        frame_done,
  // Read-back after the frame: the words of address rb_addr (y * WIDTH + x) the cycle after.
  input  wire [31:0] rb_addr,
  output wire [Z_BITS-1:0] rb_depth,
  output wire [23:0] rb_rgb
);
  assign frag_ready = 1'b0;
  assign {res_valid, res_pass} = '0;
  assign frame_done = 1'b1;
  assign {rb_depth, rb_rgb} = '0;
endmodule
