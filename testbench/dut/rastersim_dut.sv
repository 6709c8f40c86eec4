// rastersim's own core behind the verification interface (docs/verification.md "The verification
// interface"): rastersim_dut_memory (the core with the interface's decision and retire ports) with
// the on-chip memory (rtl/zbuffer_memory.sv, as in rastersim_top) behind its memory port, whose
// read-back port is the interface's, so that `rastersim cosim --dut` checks it exactly as it
// checks a user's design that keeps its buffers inside.
`include "rastersim_pkg.sv"
module rastersim_dut #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer SUBPIXEL_BITS = 4,
  parameter integer Z_BITS = 24,
  // The micro-architecture (not part of the interface): the profile's values.
  parameter integer SETUP_INTERVAL = 4,
  parameter integer TRAVERSAL_SPAN = 1,   /// 1: span, 0: bbox
  parameter integer MEMORY_LATENCY = 2,   /// the on-chip memory's read latency L
  parameter integer SETUP_FIFO_DEPTH = 8,
  // The conventions (the profile's pixel_center, fill_rule, depth_rounding and color_rounding, as
  // rastersim_core's parameters).
  parameter integer PIXEL_CENTER = 0,
  parameter integer FILL_RULE = 0,
  parameter integer DEPTH_ROUNDING = 0,
  parameter integer COLOR_ROUNDING = 0
) (
  input  wire clk,
  input  wire rst,
  input  wire [2:0]  cfg_depth_func,
  input  wire        cfg_depth_write,
  input  wire [Z_BITS-1:0] cfg_depth_clear,
  input  wire [1:0]  cfg_cull,
  input  wire        cfg_front_face,
  input  wire        cfg_shading,
  input  wire        cmd_valid,
  output wire        cmd_ready,
  input  wire [31:0] cmd_x0, cmd_y0, cmd_x1, cmd_y1, cmd_x2, cmd_y2,
  input  wire [Z_BITS-1:0] cmd_z0, cmd_z1, cmd_z2,
  input  wire [23:0] cmd_rgb0, cmd_rgb1, cmd_rgb2,
  output wire        dec_valid,
  output wire [31:0] dec_index,
  output wire [2:0]  dec_status,
  output wire        frag_valid,
  output wire [31:0] frag_index,
  output wire [15:0] frag_x,
  output wire [15:0] frag_y,
  output wire [Z_BITS-1:0] frag_z,
  output wire [23:0] frag_rgb,
  output wire        frag_pass,
  output wire        frame_done,
  input  wire [31:0] rb_addr,
  output wire [Z_BITS-1:0] rb_depth,
  output wire [23:0] rb_rgb
);
`include "rastersim_widths.vh"
  localparam integer ADDR_BITS = rs_ubits32(WIDTH * HEIGHT - 1);
  localparam integer LATENCY_BITS = rs_ubits32(MEMORY_LATENCY);

  wire mem_clear_done, mem_rd_valid, mem_rd_ready, mem_wr_depth_en, mem_wr_color_en;
  wire [31:0] mem_rd_addr, mem_wr_addr;
  wire [Z_BITS-1:0] mem_rd_depth, mem_wr_depth;
  wire [23:0] mem_wr_rgb;
  rastersim_dut_memory #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS), .Z_BITS(Z_BITS),
                         .SETUP_INTERVAL(SETUP_INTERVAL), .TRAVERSAL_SPAN(TRAVERSAL_SPAN),
                         .MEMORY_LATENCY(MEMORY_LATENCY), .SETUP_FIFO_DEPTH(SETUP_FIFO_DEPTH),
                         .PIXEL_CENTER(PIXEL_CENTER), .FILL_RULE(FILL_RULE), .DEPTH_ROUNDING(DEPTH_ROUNDING),
                         .COLOR_ROUNDING(COLOR_ROUNDING)) dut (
    .clk(clk), .rst(rst), .cfg_depth_func(cfg_depth_func), .cfg_depth_write(cfg_depth_write),
    .cfg_depth_clear(cfg_depth_clear), .cfg_cull(cfg_cull), .cfg_front_face(cfg_front_face),
    .cfg_shading(cfg_shading), .cmd_valid(cmd_valid), .cmd_ready(cmd_ready),
    .cmd_x0(cmd_x0), .cmd_y0(cmd_y0), .cmd_x1(cmd_x1), .cmd_y1(cmd_y1), .cmd_x2(cmd_x2), .cmd_y2(cmd_y2),
    .cmd_z0(cmd_z0), .cmd_z1(cmd_z1), .cmd_z2(cmd_z2), .cmd_rgb0(cmd_rgb0), .cmd_rgb1(cmd_rgb1), .cmd_rgb2(cmd_rgb2),
    .dec_valid(dec_valid), .dec_index(dec_index), .dec_status(dec_status), .frag_valid(frag_valid),
    .frag_index(frag_index), .frag_x(frag_x), .frag_y(frag_y), .frag_z(frag_z), .frag_rgb(frag_rgb),
    .frag_pass(frag_pass), .frame_done(frame_done),
    .mem_clear_done(mem_clear_done), .mem_rd_valid(mem_rd_valid), .mem_rd_ready(mem_rd_ready),
    .mem_rd_addr(mem_rd_addr), .mem_rd_depth(mem_rd_depth), .mem_wr_depth_en(mem_wr_depth_en),
    .mem_wr_color_en(mem_wr_color_en), .mem_wr_addr(mem_wr_addr), .mem_wr_depth(mem_wr_depth),
    .mem_wr_rgb(mem_wr_rgb));

  zbuffer_memory #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .Z_BITS(Z_BITS), .MAX_MEMORY_LATENCY(MEMORY_LATENCY)) zmem (
    .clk(clk), .rst(rst), .cfg_depth_clear(cfg_depth_clear), .cfg_memory_latency(LATENCY_BITS'(MEMORY_LATENCY)),
    .clear_done(mem_clear_done), .rd_valid(mem_rd_valid), .rd_ready(mem_rd_ready),
    .rd_addr(mem_rd_addr[ADDR_BITS-1:0]), .rd_depth(mem_rd_depth), .wr_depth_en(mem_wr_depth_en),
    .wr_color_en(mem_wr_color_en), .wr_addr(mem_wr_addr[ADDR_BITS-1:0]), .wr_depth(mem_wr_depth),
    .wr_rgb(mem_wr_rgb), .readback_addr(rb_addr[ADDR_BITS-1:0]), .readback_depth(rb_depth), .readback_rgb(rb_rgb));
endmodule
