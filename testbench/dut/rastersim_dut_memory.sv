// rastersim's own core behind the verification interface with the memory port (docs/verification.md
// "The memory port"): rastersim_core, whose z-buffer reads and writes the frame buffers through the
// harness's memory, with the profile's micro-architecture settings as parameters and its trace
// ports turned into the interface's decision and fragment retire ports, so that `rastersim cosim
// --dut` checks it exactly as it checks a user's design. rastersim_dut.sv is this module with the
// on-chip memory behind the port and the read-back port instead.
//
// Triangle attribution, as the co-simulation harness does it (testbench/core_ports.h): the k-th
// decision is triangle k's; a drawn triangle's index waits in `drawn` until the walker loads its
// record; a fragment belongs to the walker's triangle when the walker hands it on, and travels in
// `passing` to the z-buffer's handshake; there its pixel, depth and colour enter `in_flight`,
// which the depth-test result pops, L cycles later, as one retired fragment.
`include "rastersim_pkg.sv"
module rastersim_dut_memory #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer SUBPIXEL_BITS = 4,
  parameter integer Z_BITS = 24,
  // The micro-architecture (not part of the interface): the profile's values.
  parameter integer SETUP_INTERVAL = 4,
  parameter integer TRAVERSAL_SPAN = 1,   /// 1: span, 0: bbox
  parameter integer MEMORY_LATENCY = 2,   /// the memory's read latency L (the profile's memory_latency)
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
  input  wire        mem_clear_done,
  output wire        mem_rd_valid,
  input  wire        mem_rd_ready,
  output wire [31:0] mem_rd_addr,
  input  wire [Z_BITS-1:0] mem_rd_depth,
  output wire        mem_wr_depth_en,
  output wire        mem_wr_color_en,
  output wire [31:0] mem_wr_addr,
  output wire [Z_BITS-1:0] mem_wr_depth,
  output wire [23:0] mem_wr_rgb
);
`include "rastersim_widths.vh"
  localparam integer COORD_BITS = rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS);
  localparam integer X_BITS = rs_ubits32(WIDTH - 1);
  localparam integer Y_BITS = rs_ubits32(HEIGHT - 1);
  localparam integer ADDR_BITS = rs_ubits32(WIDTH * HEIGHT - 1);
  localparam integer LATENCY_BITS = rs_ubits32(MEMORY_LATENCY);
  localparam integer FIFO_DEPTH_BITS = rs_ubits32(16);
  localparam integer QUEUE_BITS = 7;  // 128 entries: more than the triangles or fragments in flight
  localparam integer QUEUE = 1 << QUEUE_BITS;

  wire frame_ready, setup_decided, setup_busy, walker_load, walker_busy, walker_frag_valid, walker_frag_ready;
  wire texture_busy, zb_frag_valid, zb_frag_ready, result_valid, result_pass, zbuffer_busy;
  wire [2:0] setup_status;
  wire [X_BITS-1:0] zb_x;
  wire [Y_BITS-1:0] zb_y;
  wire [Z_BITS-1:0] zb_z;
  wire [23:0] zb_rgb;
  wire cmd_ready_core;
  wire [ADDR_BITS-1:0] rd_addr, wr_addr;
  /* verilator lint_off PINCONNECTEMPTY */
  rastersim_core #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS), .Z_BITS(Z_BITS),
                  .MAX_MEMORY_LATENCY(MEMORY_LATENCY), .MAX_SETUP_FIFO_DEPTH(SETUP_FIFO_DEPTH),
                  .SETUP_INTERVAL(SETUP_INTERVAL), .PIXEL_CENTER(PIXEL_CENTER), .FILL_RULE(FILL_RULE),
                  .DEPTH_ROUNDING(DEPTH_ROUNDING), .COLOR_ROUNDING(COLOR_ROUNDING)) core (
    .clk(clk), .rst(rst), .cfg_depth_func(cfg_depth_func), .cfg_depth_write(cfg_depth_write),
    .cfg_cull(cfg_cull), .cfg_front_face(cfg_front_face),
    .cfg_traversal(TRAVERSAL_SPAN[0]), .cfg_shading(cfg_shading),
    .cfg_memory_latency(LATENCY_BITS'(MEMORY_LATENCY)), .cfg_setup_fifo_depth(FIFO_DEPTH_BITS'(SETUP_FIFO_DEPTH)),
    .cfg_texture_latency(7'd1), .cfg_texture_log2_width(4'd0), .cfg_texture_log2_height(4'd0),
    .cfg_texture_bilinear(1'b0), .cfg_texture_clamp(1'b0), .cfg_depth_bias_constant(33'd0),
    .cfg_depth_bias_slope(8'd0), .frame_ready(frame_ready),
    .cmd_valid(cmd_valid && frame_ready), .cmd_ready(cmd_ready_core),
    .cmd_x0(cmd_x0[COORD_BITS-1:0]), .cmd_y0(cmd_y0[COORD_BITS-1:0]), .cmd_x1(cmd_x1[COORD_BITS-1:0]),
    .cmd_y1(cmd_y1[COORD_BITS-1:0]), .cmd_x2(cmd_x2[COORD_BITS-1:0]), .cmd_y2(cmd_y2[COORD_BITS-1:0]),
    .cmd_z0(cmd_z0), .cmd_z1(cmd_z1), .cmd_z2(cmd_z2), .cmd_rgb0(cmd_rgb0), .cmd_rgb1(cmd_rgb1), .cmd_rgb2(cmd_rgb2),
    .cmd_textured(1'b0), .cmd_texture0(150'd0), .cmd_texture1(150'd0), .cmd_texture2(150'd0),
    .trace_setup_decided(setup_decided), .trace_setup_status(setup_status), .trace_setup_busy(setup_busy),
    .trace_setup_stall(), .trace_setup_done(), .trace_walker_load(walker_load), .trace_walker_busy(walker_busy),
    .trace_walker_candidate(), .trace_walker_last(), .trace_walker_frag_valid(walker_frag_valid),
    .trace_walker_frag_ready(walker_frag_ready), .trace_texture_busy(texture_busy), .trace_texture_stall(),
    .trace_frag_valid(zb_frag_valid), .trace_frag_ready(zb_frag_ready), .trace_frag_x(zb_x), .trace_frag_y(zb_y),
    .trace_frag_z(zb_z), .trace_frag_rgb(zb_rgb), .trace_result_valid(result_valid),
    .trace_result_pass(result_pass), .trace_zbuffer_busy(zbuffer_busy), .trace_zbuffer_stall(),
    .mem_clear_done(mem_clear_done), .mem_rd_valid(mem_rd_valid), .mem_rd_ready(mem_rd_ready),
    .mem_rd_addr(rd_addr), .mem_rd_depth(mem_rd_depth), .mem_wr_depth_en(mem_wr_depth_en),
    .mem_wr_color_en(mem_wr_color_en), .mem_wr_addr(wr_addr), .mem_wr_depth(mem_wr_depth), .mem_wr_rgb(mem_wr_rgb),
    .tex_rd_valid(), .tex_rd_ready(1'b0), .tex_rd_addr(), .tex_rd_texels({4*24{1'b0}}));
  /* verilator lint_on PINCONNECTEMPTY */
  assign mem_rd_addr = 32'(rd_addr);
  assign mem_wr_addr = 32'(wr_addr);
  /* verilator lint_off UNUSEDSIGNAL */
  wire unused = ^cfg_depth_clear;  // the harness's memory clears itself
  /* verilator lint_on UNUSEDSIGNAL */

  assign cmd_ready = cmd_ready_core && frame_ready;

  // Decisions: the k-th is triangle k's.
  reg [31:0] decided_q;
  assign dec_valid = setup_decided;
  assign dec_index = decided_q;
  assign dec_status = setup_status;

  // Drawn triangles waiting for the walker, then the walker's triangle.
  reg [31:0] drawn_q [0:QUEUE-1];
  reg [QUEUE_BITS:0] drawn_head_q, drawn_tail_q;
  reg [31:0] walker_index_q;
  // Each handed-on fragment's triangle until the z-buffer takes the fragment.
  reg [31:0] passing_q [0:QUEUE-1];
  reg [QUEUE_BITS:0] passing_head_q, passing_tail_q;
  // Fragments taken by the z-buffer, awaiting their depth-test result.
  localparam integer FLIGHT_BITS = 32 + 16 + 16 + Z_BITS + 24;
  reg [FLIGHT_BITS-1:0] flight_q [0:QUEUE-1];
  reg [QUEUE_BITS:0] flight_head_q, flight_tail_q;

  wire drawn = setup_decided && setup_status == 3'd0;
  wire handed_on = walker_frag_valid && walker_frag_ready;
  wire taken = zb_frag_valid && zb_frag_ready;
  // A queue that is empty passes this cycle's entry straight through: without a texture unit the
  // walker's hand-on is the z-buffer's take, and a record may be loaded in its decision's cycle.
  wire passing_empty = passing_head_q == passing_tail_q;
  wire drawn_empty = drawn_head_q == drawn_tail_q;
  wire [31:0] passing_index = passing_empty ? walker_index_q : passing_q[passing_head_q[QUEUE_BITS-1:0]];
  wire [31:0] drawn_index = drawn_empty ? decided_q : drawn_q[drawn_head_q[QUEUE_BITS-1:0]];
  wire passing_through = passing_empty && handed_on && taken;
  wire drawn_through = drawn_empty && drawn && walker_load;
  wire [FLIGHT_BITS-1:0] oldest = flight_q[flight_head_q[QUEUE_BITS-1:0]];

  always @(posedge clk) begin
    if (rst) begin
      decided_q <= 32'd0;
      drawn_head_q <= '0;
      drawn_tail_q <= '0;
      walker_index_q <= 32'hffffffff;
      passing_head_q <= '0;
      passing_tail_q <= '0;
      flight_head_q <= '0;
      flight_tail_q <= '0;
    end else begin
      if (setup_decided) decided_q <= decided_q + 32'd1;
      if (drawn && !drawn_through) begin
        drawn_q[drawn_tail_q[QUEUE_BITS-1:0]] <= decided_q;
        drawn_tail_q <= drawn_tail_q + 1'b1;
      end
      // A load may share the cycle of the previous triangle's last fragment, which is still that
      // triangle's (the register's old value below).
      if (handed_on && !passing_through) begin
        passing_q[passing_tail_q[QUEUE_BITS-1:0]] <= walker_index_q;
        passing_tail_q <= passing_tail_q + 1'b1;
      end
      if (walker_load && (!drawn_empty || drawn)) begin
        walker_index_q <= drawn_index;
        if (!drawn_through) drawn_head_q <= drawn_head_q + 1'b1;
      end
      if (taken) begin
        flight_q[flight_tail_q[QUEUE_BITS-1:0]] <= {passing_index, 16'(zb_x), 16'(zb_y), zb_z, zb_rgb};
        flight_tail_q <= flight_tail_q + 1'b1;
        if (!passing_through) passing_head_q <= passing_head_q + 1'b1;
      end
      if (result_valid) flight_head_q <= flight_head_q + 1'b1;
    end
  end

  assign frag_valid = result_valid;
  assign {frag_index, frag_x, frag_y, frag_z, frag_rgb} = oldest;
  assign frag_pass = result_pass;
  // Idle: the clear done, no unit busy, no fragment waiting or in flight.
  assign frame_done = frame_ready && !setup_busy && !walker_busy && !texture_busy && !zbuffer_busy &&
                      !zb_frag_valid && !walker_frag_valid && flight_head_q == flight_tail_q;
endmodule
