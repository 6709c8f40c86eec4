// The pipeline without its memory (model/pipeline.cpp): triangle_setup -> scanline_walker
// (+ z_adder) -> zbuffer, coupled by valid/ready handshakes so that each unit can stall
// (docs/cycle-model.md), with the z-buffer's memory port on the mem_* ports (contract in
// rtl/zbuffer.sv and docs/rtl.md). rastersim_top puts the on-chip memory (zbuffer_memory) behind
// it; the SystemC system (testbench/systemc/) puts a memory model with a stall pattern there.
// Widths come from the profile parameters; the runtime profile keys (depth test, cull, traversal,
// shading, memory latency) are cfg_* inputs, sampled during reset.
// Cycle 0 of a frame is the first cycle with frame_ready (= mem_clear_done) high.
// The trace_* outputs expose the unit handshakes and decisions for the co-simulation scoreboard.
module rastersim_core #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer SUBPIXEL_BITS = 4,
  parameter integer Z_BITS = 24,
  parameter integer Z_GUARD_BITS = 0,      // 0: derived (proven minimum)
  parameter integer MAX_MEMORY_LATENCY = 64,
  parameter integer MAX_SETUP_FIFO_DEPTH = 16,  // record FIFO entries; cfg_setup_fifo_depth <= this
  parameter integer SETUP_INTERVAL = 0         // 0: serial setup; 2..64: pipelined (profile setup_interval)
) (
  input  wire clk,
  input  wire rst,
  input  wire [2:0] cfg_depth_func,        // RS_DEPTH_* (rastersim_widths.vh)
  input  wire       cfg_depth_write,
  input  wire [1:0] cfg_cull,              // RS_CULL_*
  input  wire       cfg_front_face,        // RS_FRONT_*
  input  wire       cfg_traversal,         // RS_TRAVERSAL_*
  input  wire       cfg_shading,           // RS_SHADING_*
  input  wire [rs_ubits32(MAX_MEMORY_LATENCY)-1:0] cfg_memory_latency,  // 1 .. MAX_MEMORY_LATENCY
  input  wire [rs_ubits32(MAX_SETUP_FIFO_DEPTH)-1:0] cfg_setup_fifo_depth,  // record credits, 1 .. MAX
  output wire frame_ready,
  // Triangle command: snapped vertices, x and y s(COORD_BITS-S).S, z uN, rgb {r, g, b}.
  input  wire cmd_valid,
  output wire cmd_ready,
  input  wire [rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] cmd_x0, cmd_y0, cmd_x1, cmd_y1, cmd_x2, cmd_y2,
  input  wire [Z_BITS-1:0] cmd_z0, cmd_z1, cmd_z2,
  input  wire [23:0] cmd_rgb0, cmd_rgb1, cmd_rgb2,
  // Trace: setup decision (FRONT cycle) and activity.
  output wire trace_setup_decided,
  output wire [2:0] trace_setup_status,    // 0 drawn, 1 degenerate, 2 culled, 3 offscreen, 4 no centre
  output wire trace_setup_busy,
  output wire trace_setup_stall,           // a triangle offered, the unit free, not accepted (credits, slot)
  output wire trace_setup_done,            // a drawn triangle's record is in the setup output register
  output wire trace_walker_load,           // record -> walker handshake
  output wire trace_walker_busy,
  output wire trace_walker_candidate,
  output wire trace_walker_last,
  // Trace: walker -> z-buffer fragment handshake and the depth test result L cycles later.
  output wire trace_frag_valid,
  output wire trace_frag_ready,
  output wire [rs_ubits32(WIDTH - 1)-1:0]  trace_frag_x,
  output wire [rs_ubits32(HEIGHT - 1)-1:0] trace_frag_y,
  output wire [Z_BITS-1:0] trace_frag_z,
  output wire [23:0]       trace_frag_rgb,
  output wire trace_result_valid,
  output wire trace_result_pass,
  output wire trace_zbuffer_busy,
  output wire trace_zbuffer_stall,         // the z-buffer's oldest held fragment waits to be read
  // Memory port of the z-buffer (word address y * WIDTH + x).
  input  wire mem_clear_done,
  output wire mem_rd_valid,
  input  wire mem_rd_ready,
  output wire [rs_ubits32(WIDTH * HEIGHT - 1)-1:0] mem_rd_addr,
  input  wire [Z_BITS-1:0] mem_rd_depth,
  output wire mem_wr_depth_en,
  output wire mem_wr_color_en,
  output wire [rs_ubits32(WIDTH * HEIGHT - 1)-1:0] mem_wr_addr,
  output wire [Z_BITS-1:0] mem_wr_depth,
  output wire [23:0]       mem_wr_rgb
);
`include "rastersim_widths.vh"
  `RS_REQUIRE(illegal_setup_fifo_depth, MAX_SETUP_FIFO_DEPTH >= 1, "rastersim_core: MAX_SETUP_FIFO_DEPTH must be at least 1")

  // Derived widths, the same formulas as model/widths.h; the C++ build static_asserts these
  // (public, so Verilator emits them as static constexpr) against rastersim::derive_widths.
  // Some are published for that check only, hence unused here.
  /* verilator lint_off UNUSEDPARAM */
  localparam integer GUARD_BITS /*verilator public*/ = rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS);
  localparam integer COORD_BITS /*verilator public*/ = rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS);
  localparam integer DELTA_BITS /*verilator public*/ = rs_delta_bits(WIDTH, HEIGHT, SUBPIXEL_BITS);
  localparam integer AREA_BITS /*verilator public*/ = rs_area_bits(WIDTH, HEIGHT, SUBPIXEL_BITS);
  localparam integer EDGE_BITS /*verilator public*/ = rs_edge_bits(WIDTH, HEIGHT, SUBPIXEL_BITS);
  localparam integer EDGE_STEP_X_BITS /*verilator public*/ = rs_edge_step_x_bits(HEIGHT, SUBPIXEL_BITS);
  localparam integer EDGE_STEP_Y_BITS /*verilator public*/ = rs_edge_step_y_bits(WIDTH, SUBPIXEL_BITS);
  localparam integer SPAN_REM_BITS /*verilator public*/ = rs_span_rem_bits(HEIGHT, SUBPIXEL_BITS);
  localparam integer DIVIDER_BITS /*verilator public*/ =
      rs_divider_bits(WIDTH, HEIGHT, SUBPIXEL_BITS, Z_BITS, Z_GUARD_BITS);
  localparam integer Z_REG_BITS /*verilator public*/ = Z_BITS + GUARD_BITS + 1;
  localparam integer COLOR_REG_BITS /*verilator public*/ = 8 + GUARD_BITS + 1;
  localparam integer LEFT_BITS = 2 * (Z_REG_BITS + 3 * COLOR_REG_BITS);  // rec_left_start, rec_left_step: two slots
  localparam integer X_BITS /*verilator public*/ = rs_ubits32(WIDTH - 1);
  localparam integer Y_BITS /*verilator public*/ = rs_ubits32(HEIGHT - 1);
  localparam integer ADDR_BITS /*verilator public*/ = rs_ubits32(WIDTH * HEIGHT - 1);
  localparam integer SETUP_DRAWN_LATENCY /*verilator public*/ =
      rs_setup_drawn_latency(WIDTH, HEIGHT, SUBPIXEL_BITS, Z_BITS, Z_GUARD_BITS, SETUP_INTERVAL);
  localparam integer SETUP_REJECTED_LATENCY /*verilator public*/ =
      rs_setup_rejected_latency(WIDTH, HEIGHT, SUBPIXEL_BITS, SETUP_INTERVAL);
  localparam integer WALKER_LOAD_CYCLES /*verilator public*/ = 1;
  // The encodings of rastersim_widths.vh in one word, from bit 0: RS_DEPTH_NEVER .. RS_DEPTH_ALWAYS
  // (3 bits each), RS_CULL_NONE, _BACK, _FRONT (2), RS_FRONT_CCW, _CW, RS_TRAVERSAL_BBOX, _SPAN,
  // RS_SHADING_FLAT, _GOURAUD (1), RS_STATUS_DRAWN .. RS_STATUS_NO_CENTRE (3).
  localparam [50:0] ENCODINGS /*verilator public*/ = {
      RS_STATUS_NO_CENTRE, RS_STATUS_OFFSCREEN, RS_STATUS_CULLED, RS_STATUS_DEGENERATE, RS_STATUS_DRAWN,
      RS_SHADING_GOURAUD, RS_SHADING_FLAT, RS_TRAVERSAL_SPAN, RS_TRAVERSAL_BBOX, RS_FRONT_CW, RS_FRONT_CCW,
      RS_CULL_FRONT, RS_CULL_BACK, RS_CULL_NONE,
      RS_DEPTH_ALWAYS, RS_DEPTH_GEQUAL, RS_DEPTH_NOTEQUAL, RS_DEPTH_GREATER, RS_DEPTH_LEQUAL, RS_DEPTH_EQUAL,
      RS_DEPTH_LESS, RS_DEPTH_NEVER};
  // The profile parameters themselves, for the harness.
  localparam integer P_WIDTH /*verilator public*/ = WIDTH;
  localparam integer P_HEIGHT /*verilator public*/ = HEIGHT;
  localparam integer P_SUBPIXEL_BITS /*verilator public*/ = SUBPIXEL_BITS;
  localparam integer P_Z_BITS /*verilator public*/ = Z_BITS;
  localparam integer P_Z_GUARD_BITS /*verilator public*/ = Z_GUARD_BITS;
  localparam integer P_MAX_MEMORY_LATENCY /*verilator public*/ = MAX_MEMORY_LATENCY;
  localparam integer P_MAX_SETUP_FIFO_DEPTH /*verilator public*/ = MAX_SETUP_FIFO_DEPTH;
  localparam integer P_SETUP_INTERVAL /*verilator public*/ = SETUP_INTERVAL;
  /* verilator lint_on UNUSEDPARAM */

  // The runtime profile keys are sampled while rst is high and held for the frame (static
  // configuration registers: the units see registers, not the ports).
  reg [2:0] depth_func_q;
  reg depth_write_q, front_face_q, traversal_q, shading_q;
  reg [1:0] cull_q;
  reg [rs_ubits32(MAX_MEMORY_LATENCY)-1:0] memory_latency_q;
  reg [rs_ubits32(MAX_SETUP_FIFO_DEPTH)-1:0] setup_fifo_depth_q;
  always @(posedge clk) begin
    if (rst) begin
      depth_func_q <= cfg_depth_func;
      depth_write_q <= cfg_depth_write;
      cull_q <= cfg_cull;
      front_face_q <= cfg_front_face;
      traversal_q <= cfg_traversal;
      shading_q <= cfg_shading;
      memory_latency_q <= cfg_memory_latency;
      setup_fifo_depth_q <= cfg_setup_fifo_depth;
    end
  end

  // The setup record, packed (rs_rec_lsb in rastersim_widths.vh).
  localparam integer RECORD_BITS = rs_rec_lsb(20, WIDTH, HEIGHT, SUBPIXEL_BITS, Z_BITS, Z_GUARD_BITS);
  localparam integer WALKER_RECORD_BITS = rs_rec_walker_bits(WIDTH, HEIGHT, SUBPIXEL_BITS);
  `include "rastersim_record.vh"
  wire setup_valid;
  wire [RECORD_BITS-1:0] setup_record;
  wire setup_ready;
  wire decided_front_facing_unused;
  wire [AREA_BITS-1:0] decided_area2_unused;

  // Record credits (docs/cycle-model.md): a triangle holds one from its accept until it is rejected
  // or its record is loaded by the walker; the setup unit accepts only while one is free.
  localparam integer CREDIT_BITS = rs_ubits32(MAX_SETUP_FIFO_DEPTH);
  reg [CREDIT_BITS-1:0] credits_held_q;
  wire credit_free = credits_held_q < setup_fifo_depth_q;
  wire accept = cmd_valid && cmd_ready;
  wire rejected = trace_setup_decided && trace_setup_status != RS_STATUS_DRAWN;
  always @(posedge clk) begin
    if (rst) credits_held_q <= {CREDIT_BITS{1'b0}};
    else credits_held_q <= credits_held_q + {{(CREDIT_BITS-1){1'b0}}, accept}
                         - {{(CREDIT_BITS-1){1'b0}}, rejected} - {{(CREDIT_BITS-1){1'b0}}, trace_walker_load};
  end

  assign cmd_ready = setup_ready && frame_ready && credit_free;
  wire setup_free;
  assign trace_setup_stall = cmd_valid && frame_ready && setup_free && !accept;
  assign trace_setup_done = setup_valid;

  triangle_setup #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS), .Z_BITS(Z_BITS),
                   .Z_GUARD_BITS(Z_GUARD_BITS), .SETUP_INTERVAL(SETUP_INTERVAL)) setup (
    .clk(clk), .rst(rst), .run(frame_ready), .free(setup_free), .cfg_cull(cull_q), .cfg_front_face(front_face_q),
    .in_valid(cmd_valid && frame_ready && credit_free), .in_ready(setup_ready),
    .in_x({cmd_x2, cmd_x1, cmd_x0}), .in_y({cmd_y2, cmd_y1, cmd_y0}), .in_z({cmd_z2, cmd_z1, cmd_z0}),
    .in_rgb({cmd_rgb2, cmd_rgb1, cmd_rgb0}),
    .decided(trace_setup_decided), .decided_status(trace_setup_status),
    .decided_front_facing(decided_front_facing_unused), .decided_area2(decided_area2_unused),
    .busy(trace_setup_busy),
    .out_valid(setup_valid),
    .out_record(setup_record));

  // Record FIFO: every record goes in, as the walker's entry (scanline_walker_entry: its state at
  // the load) and the Z adder's planes; it is at the head from the next cycle (the credits leave it
  // room).
  localparam integer ENTRY_BITS = rs_entry_lsb(20, WIDTH, HEIGHT, SUBPIXEL_BITS);
  localparam integer PLANE_BITS = RECORD_BITS - WALKER_RECORD_BITS;
  wire [ENTRY_BITS-1:0] setup_entry;
  scanline_walker_entry #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS)) walker_entry (
    .record(setup_record[WALKER_RECORD_BITS-1:0]), .entry(setup_entry));
  wire fifo_empty;
  wire [ENTRY_BITS+PLANE_BITS-1:0] fifo_head;
  wire walker_ready;
  setup_fifo #(.RECORD_BITS(ENTRY_BITS + PLANE_BITS), .ENTRIES(MAX_SETUP_FIFO_DEPTH)) record_fifo (
    .clk(clk), .rst(rst), .push(setup_valid), .push_data({setup_record[RECORD_BITS-1:WALKER_RECORD_BITS], setup_entry}),
    .pop(!fifo_empty && walker_ready), .empty(fifo_empty), .head(fifo_head));
  assign trace_walker_load = !fifo_empty && walker_ready;
  // A plane field of the record at LSB is at PLANES_AT + LSB of the head (the walker part's place
  // holds the entry).
  localparam integer PLANES_AT = ENTRY_BITS - WALKER_RECORD_BITS;

  // The setup unit's record. Readable from C++ (public_flat_rd) so that the co-simulation
  // compares the setup unit's outputs field by field in setup_done.
  wire [X_BITS-1:0] rec_x0 /*verilator public_flat_rd*/;
  wire [X_BITS-1:0] rec_x1 /*verilator public_flat_rd*/;
  wire [Y_BITS-1:0] rec_y0 /*verilator public_flat_rd*/;
  wire [Y_BITS-1:0] rec_y1 /*verilator public_flat_rd*/;
  wire [3*EDGE_BITS-1:0]  rec_edge_start /*verilator public_flat_rd*/;
  wire [3*EDGE_STEP_X_BITS-1:0] rec_edge_step_x /*verilator public_flat_rd*/;
  wire [3*EDGE_STEP_Y_BITS-1:0] rec_edge_step_y /*verilator public_flat_rd*/;
  wire [3*EDGE_BITS-1:0]  rec_span_quot /*verilator public_flat_rd*/;
  wire [3*SPAN_REM_BITS-1:0]  rec_span_rem /*verilator public_flat_rd*/;
  wire [3*EDGE_STEP_Y_BITS-1:0] rec_span_step_quot /*verilator public_flat_rd*/;
  wire [3*SPAN_REM_BITS-1:0]  rec_span_step_rem /*verilator public_flat_rd*/;
  wire [Z_REG_BITS-1:0]   rec_depth_start /*verilator public_flat_rd*/;
  wire [Z_REG_BITS-1:0]   rec_depth_step_x /*verilator public_flat_rd*/;
  wire [Z_REG_BITS-1:0]   rec_depth_step_y /*verilator public_flat_rd*/;
  wire [3*COLOR_REG_BITS-1:0] rec_color_start /*verilator public_flat_rd*/;
  wire [3*COLOR_REG_BITS-1:0] rec_color_step_x /*verilator public_flat_rd*/;
  wire [3*COLOR_REG_BITS-1:0] rec_color_step_y /*verilator public_flat_rd*/;
  wire [23:0]      rec_flat_rgb /*verilator public_flat_rd*/;
  wire [LEFT_BITS-1:0] rec_left_start /*verilator public_flat_rd*/;
  wire [LEFT_BITS-1:0] rec_left_step /*verilator public_flat_rd*/;
  wire [RECORD_BITS-1:0] rec = setup_record;
  assign rec_x0 = rec[LSB_X0 +: X_BITS];
  assign rec_x1 = rec[LSB_X1 +: X_BITS];
  assign rec_y0 = rec[LSB_Y0 +: Y_BITS];
  assign rec_y1 = rec[LSB_Y1 +: Y_BITS];
  assign rec_edge_start = rec[LSB_EDGE_START +: 3*EDGE_BITS];
  assign rec_edge_step_x = rec[LSB_EDGE_STEP_X +: 3*EDGE_STEP_X_BITS];
  assign rec_edge_step_y = rec[LSB_EDGE_STEP_Y +: 3*EDGE_STEP_Y_BITS];
  assign rec_span_quot = rec[LSB_SPAN_QUOT +: 3*EDGE_BITS];
  assign rec_span_rem = rec[LSB_SPAN_REM +: 3*SPAN_REM_BITS];
  assign rec_span_step_quot = rec[LSB_SPAN_STEP_QUOT +: 3*EDGE_STEP_Y_BITS];
  assign rec_span_step_rem = rec[LSB_SPAN_STEP_REM +: 3*SPAN_REM_BITS];
  assign rec_depth_start = rec[LSB_DEPTH_START +: Z_REG_BITS];
  assign rec_depth_step_x = rec[LSB_DEPTH_STEP_X +: Z_REG_BITS];
  assign rec_depth_step_y = rec[LSB_DEPTH_STEP_Y +: Z_REG_BITS];
  assign rec_color_start = rec[LSB_COLOR_START +: 3*COLOR_REG_BITS];
  assign rec_color_step_x = rec[LSB_COLOR_STEP_X +: 3*COLOR_REG_BITS];
  assign rec_color_step_y = rec[LSB_COLOR_STEP_Y +: 3*COLOR_REG_BITS];
  assign rec_flat_rgb = rec[LSB_FLAT_RGB +: 24];
  assign rec_left_start = rec[LSB_LEFT_START +: LEFT_BITS];
  assign rec_left_step = rec[LSB_LEFT_STEP +: LEFT_BITS];

  // Walker + Z adder -> z-buffer fragment.
  wire adder_load, adder_step_x, adder_next_row, adder_row_enter, adder_enter_left, adder_enter_slot;
  wire [1:0] adder_left_carry;
  wire frag_valid, frag_ready;
  wire [X_BITS-1:0] frag_x;
  wire [Y_BITS-1:0] frag_y;
  wire [Z_BITS-1:0] frag_z;
  wire [23:0] frag_rgb;

  scanline_walker #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS)) walker (
    .clk(clk), .rst(rst), .cfg_traversal(traversal_q),
    .in_valid(!fifo_empty), .in_ready(walker_ready),
    .in_entry(fifo_head[ENTRY_BITS-1:0]),
    .adder_load(adder_load), .adder_step_x(adder_step_x), .adder_next_row(adder_next_row),
    .adder_row_enter(adder_row_enter), .adder_enter_left(adder_enter_left), .adder_enter_slot(adder_enter_slot),
    .adder_left_carry(adder_left_carry),
    .frag_valid(frag_valid), .frag_ready(frag_ready), .frag_x(frag_x), .frag_y(frag_y),
    .busy(trace_walker_busy), .candidate(trace_walker_candidate), .last(trace_walker_last));

  z_adder #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .Z_BITS(Z_BITS), .Z_GUARD_BITS(Z_GUARD_BITS)) adders (
    .clk(clk), .cfg_shading(shading_q), .load(adder_load), .step_x(adder_step_x),
    .next_row(adder_next_row), .row_enter(adder_row_enter), .enter_left(adder_enter_left),
    .enter_slot(adder_enter_slot), .left_carry(adder_left_carry),
    .depth_start(fifo_head[PLANES_AT + LSB_DEPTH_START +: Z_REG_BITS]), .depth_step_x(fifo_head[PLANES_AT + LSB_DEPTH_STEP_X +: Z_REG_BITS]),
    .depth_step_y(fifo_head[PLANES_AT + LSB_DEPTH_STEP_Y +: Z_REG_BITS]), .color_start(fifo_head[PLANES_AT + LSB_COLOR_START +: 3*COLOR_REG_BITS]),
    .color_step_x(fifo_head[PLANES_AT + LSB_COLOR_STEP_X +: 3*COLOR_REG_BITS]), .color_step_y(fifo_head[PLANES_AT + LSB_COLOR_STEP_Y +: 3*COLOR_REG_BITS]),
    .flat_rgb(fifo_head[PLANES_AT + LSB_FLAT_RGB +: 24]), .left_start(fifo_head[PLANES_AT + LSB_LEFT_START +: LEFT_BITS]),
    .left_step(fifo_head[PLANES_AT + LSB_LEFT_STEP +: LEFT_BITS]), .depth(frag_z), .rgb(frag_rgb));

  zbuffer #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .Z_BITS(Z_BITS), .MAX_MEMORY_LATENCY(MAX_MEMORY_LATENCY)) zbuf (
    .clk(clk), .rst(rst), .cfg_depth_func(depth_func_q), .cfg_depth_write(depth_write_q),
    .cfg_memory_latency(memory_latency_q), .clear_done(frame_ready),
    .frag_valid(frag_valid), .frag_ready(frag_ready), .frag_x(frag_x), .frag_y(frag_y),
    .frag_z(frag_z), .frag_rgb(frag_rgb),
    .result_valid(trace_result_valid), .result_pass(trace_result_pass), .busy(trace_zbuffer_busy),
    .stall(trace_zbuffer_stall),
    .mem_clear_done(mem_clear_done), .mem_rd_valid(mem_rd_valid), .mem_rd_ready(mem_rd_ready),
    .mem_rd_addr(mem_rd_addr), .mem_rd_depth(mem_rd_depth), .mem_wr_depth_en(mem_wr_depth_en),
    .mem_wr_color_en(mem_wr_color_en), .mem_wr_addr(mem_wr_addr), .mem_wr_depth(mem_wr_depth),
    .mem_wr_rgb(mem_wr_rgb));

  assign trace_frag_valid = frag_valid;
  assign trace_frag_ready = frag_ready;
  assign trace_frag_x = frag_x;
  assign trace_frag_y = frag_y;
  assign trace_frag_z = frag_z;
  assign trace_frag_rgb = frag_rgb;
endmodule
