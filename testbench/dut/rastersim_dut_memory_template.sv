// The verification interface of rastersim with the memory port (docs/verification.md "The memory
// port"): the ports of a design whose frame buffers are in an external memory, which the harness
// of `rastersim cosim --dut LIST --top NAME` provides. Copy this module, keep its parameters and
// ports, and put your rasterizer inside. As it stands it never takes a triangle (cosim reports the
// stall on cmd_ready). A design that keeps its buffers: rastersim_dut_template.sv.
//
// All ports are synchronous to the rising edge of clk. A handshake happens in a cycle where valid
// and ready are both high; the retire ports have no ready: the harness takes every cycle's output.
module rastersim_dut_memory_template #(
  parameter integer WIDTH = 640,        /// screen, pixels (the profile's width), 1..4096
  parameter integer HEIGHT = 480,       /// the profile's height
  parameter integer SUBPIXEL_BITS = 4,  /// S: fraction bits of the command's x and y
  parameter integer Z_BITS = 24         /// N: the depth word
) (
  input  wire clk,
  input  wire rst,                      /// high for 4 cycles before the frame; cfg_* are steady from then on
  // The profile's run-time keys (encodings as rastersim's: docs/verification.md).
  input  wire [2:0]  cfg_depth_func,    /// 0 never, 1 less, 2 equal, 3 lequal, 4 greater, 5 notequal, 6 gequal, 7 always
  input  wire        cfg_depth_write,   /// 1: a passing fragment writes its depth
  input  wire [Z_BITS-1:0] cfg_depth_clear,  /// the depth buffer's value after reset
  input  wire [1:0]  cfg_cull,          /// 0 none, 1 back, 2 front
  input  wire        cfg_front_face,    /// 0 counter-clockwise, 1 clockwise (as seen on the screen, y down)
  input  wire        cfg_shading,       /// 0 flat (vertex 0's colour), 1 Gouraud
  // Commands: one triangle per handshake, in order; the k-th accepted is triangle k.
  input  wire        cmd_valid,
  output wire        cmd_ready,
  input  wire [31:0] cmd_x0, cmd_y0, cmd_x1, cmd_y1, cmd_x2, cmd_y2,  /// snapped, two's complement, S fraction bits
  input  wire [Z_BITS-1:0] cmd_z0, cmd_z1, cmd_z2,                    /// depth words, 0 near
  input  wire [23:0] cmd_rgb0, cmd_rgb1, cmd_rgb2,                    /// {r, g, b}
  // Decisions: one per triangle, in triangle order.
  output wire        dec_valid,
  output wire [31:0] dec_index,         /// the triangle
  output wire [2:0]  dec_status,        /// 0 drawn, 1 degenerate, 2 culled, 3 offscreen, 4 no pixel centre
  // Retired fragments: one per covered pixel, after its depth test.
  output wire        frag_valid,
  output wire [31:0] frag_index,        /// its triangle
  output wire [15:0] frag_x, frag_y,    /// its pixel
  output wire [Z_BITS-1:0] frag_z,      /// the depth word that entered the test
  output wire [23:0] frag_rgb,          /// its colour {r, g, b}
  output wire        frag_pass,         /// 1: the depth test passed
  // High when every accepted triangle is retired and the buffers hold every write.
  output wire        frame_done,
  // The memory port: the harness's memory, words y * WIDTH + x, cleared before the frame.
  input  wire        mem_clear_done,    /// high from the first cycle after reset
  output wire        mem_rd_valid,      /// a read, taken in a cycle with mem_rd_ready high
  input  wire        mem_rd_ready,      /// low in the cycles the profile's stall pattern names
  output wire [31:0] mem_rd_addr,
  input  wire [Z_BITS-1:0] mem_rd_depth,  /// in cycle c + L: the word of the read taken in c
  output wire        mem_wr_depth_en,   /// writes land at the end of their cycle, always taken
  output wire        mem_wr_color_en,
  output wire [31:0] mem_wr_addr,
  output wire [Z_BITS-1:0] mem_wr_depth,
  output wire [23:0] mem_wr_rgb
);
  assign cmd_ready = 1'b0;
  assign {dec_valid, dec_index, dec_status} = '0;
  assign {frag_valid, frag_index, frag_x, frag_y, frag_z, frag_rgb, frag_pass} = '0;
  assign frame_done = 1'b1;
  assign {mem_rd_valid, mem_rd_addr, mem_wr_depth_en, mem_wr_color_en, mem_wr_addr, mem_wr_depth, mem_wr_rgb} = '0;
endmodule
