// rastersim's own z-buffer (rtl/zbuffer.sv) with its memory (rtl/zbuffer_memory.sv) behind the
// z-buffer's interface (docs/verification.md "Checking one unit: cosim --unit"), joined as
// rastersim_top joins them: `rastersim cosim --unit zbuffer --dut
// testbench/dut/rastersim_zbuffer_unit.f --top rastersim_zbuffer_unit`. The frame starts when the
// memory has cleared itself; fragments wait until then.
`include "rastersim_pkg.sv"
module rastersim_zbuffer_unit #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer SUBPIXEL_BITS = 4,
  parameter integer Z_BITS = 24,
  parameter integer FRACTION_BITS = 9,
  // The micro-architecture (not part of the interface): the memory's read latency, 1..64.
  parameter integer MEMORY_LATENCY = 2
) (
  input  wire clk,
  input  wire rst,
  input  wire [2:0]  cfg_depth_func,
  input  wire        cfg_depth_write,
  input  wire [Z_BITS-1:0] cfg_depth_clear,
  input  wire        frag_valid,
  output wire        frag_ready,
  input  wire [15:0] frag_x, frag_y,
  input  wire [Z_BITS-1:0] frag_z,
  input  wire [23:0] frag_rgb,
  output wire        res_valid,
  output wire        res_pass,
  output wire        frame_done,
  input  wire [31:0] rb_addr,
  output wire [Z_BITS-1:0] rb_depth,
  output wire [23:0] rb_rgb
);
`include "rastersim_widths.vh"
  localparam integer X_BITS = rs_ubits32(WIDTH - 1);
  localparam integer Y_BITS = rs_ubits32(HEIGHT - 1);
  localparam integer ADDR_BITS = rs_ubits32(WIDTH * HEIGHT - 1);
  localparam integer LATENCY_BITS = rs_ubits32(MEMORY_LATENCY);

  wire frame_ready, mem_clear_done, mem_rd_valid, mem_rd_ready, mem_wr_depth_en, mem_wr_color_en, busy, ready;
  wire [ADDR_BITS-1:0] mem_rd_addr, mem_wr_addr;
  wire [Z_BITS-1:0] mem_rd_depth, mem_wr_depth;
  wire [23:0] mem_wr_rgb;
  /* verilator lint_off PINCONNECTEMPTY */
  zbuffer #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .Z_BITS(Z_BITS), .MAX_MEMORY_LATENCY(MEMORY_LATENCY)) zbuf (
    .clk(clk), .rst(rst), .cfg_depth_func(cfg_depth_func), .cfg_depth_write(cfg_depth_write),
    .cfg_memory_latency(LATENCY_BITS'(MEMORY_LATENCY)), .clear_done(frame_ready),
    .frag_valid(frag_valid && frame_ready), .frag_ready(ready), .frag_x(frag_x[X_BITS-1:0]),
    .frag_y(frag_y[Y_BITS-1:0]), .frag_z(frag_z), .frag_rgb(frag_rgb),
    .result_valid(res_valid), .result_pass(res_pass), .busy(busy), .stall(),
    .mem_clear_done(mem_clear_done), .mem_rd_valid(mem_rd_valid), .mem_rd_ready(mem_rd_ready),
    .mem_rd_addr(mem_rd_addr), .mem_rd_depth(mem_rd_depth), .mem_wr_depth_en(mem_wr_depth_en),
    .mem_wr_color_en(mem_wr_color_en), .mem_wr_addr(mem_wr_addr), .mem_wr_depth(mem_wr_depth),
    .mem_wr_rgb(mem_wr_rgb));
  /* verilator lint_on PINCONNECTEMPTY */
  zbuffer_memory #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .Z_BITS(Z_BITS), .MAX_MEMORY_LATENCY(MEMORY_LATENCY)) zmem (
    .clk(clk), .rst(rst), .cfg_depth_clear(cfg_depth_clear), .cfg_memory_latency(LATENCY_BITS'(MEMORY_LATENCY)),
    .clear_done(mem_clear_done), .rd_valid(mem_rd_valid), .rd_ready(mem_rd_ready), .rd_addr(mem_rd_addr),
    .rd_depth(mem_rd_depth), .wr_depth_en(mem_wr_depth_en), .wr_color_en(mem_wr_color_en),
    .wr_addr(mem_wr_addr), .wr_depth(mem_wr_depth), .wr_rgb(mem_wr_rgb),
    .readback_addr(rb_addr[ADDR_BITS-1:0]), .readback_depth(rb_depth), .readback_rgb(rb_rgb));
  assign frag_ready = ready && frame_ready;
  // Idle: the clear done and no fragment held or in flight (the last write lands with its result).
  assign frame_done = frame_ready && !busy;
endmodule
