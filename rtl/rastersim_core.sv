// The pipeline without its memory (model/pipeline.cpp): triangle_setup -> scanline_walker
// (+ z_adder) -> zbuffer, coupled by valid/ready handshakes so that each unit can stall
// (docs/cycle-model.md), with the z-buffer's memory port on the mem_* ports (contract in
// rtl/zbuffer.sv and docs/rtl.md). rastersim_top puts the on-chip memory (zbuffer_memory) behind
// it; the SystemC system (testbench/systemc/) puts a memory model with a stall pattern there.
// Widths come from the profile parameters; the runtime profile keys (depth test, cull, traversal,
// shading, memory latency) are cfg_* inputs, sampled during reset.
// Cycle 0 of a frame is the first cycle with frame_ready (= mem_clear_done) high.
// The trace_* outputs expose the unit handshakes and decisions for the co-simulation scoreboard.
// With TEXTURE = 1 the texture unit sits between the walker and the z-buffer (its memory on the
// tex_rd_* port, rtl/texture_unit.sv) and the setup computes the texture planes; with TEXTURE = 0
// the texture ports are unused and tied off, and the core is as it was without them.
// DEPTH_EXPONENT_BITS >= 2 makes the depth word floating point, the depth plane then wider than
// the word (DEPTH_PLANE_BITS); DEPTH_BIAS = 1 adds the depth bias of cfg_depth_bias_* (docs/
// arithmetic.md section 6). Both only change the Z adder's output stage and the plane's width.
`include "rastersim_pkg.sv"
`include "rastersim_core_parameters.vh"  // its build parameters
module rastersim_core `RS_IMPORT #(`RASTERSIM_CORE_PARAMETERS) (
  input  wire clk,
  input  wire rst,
  input  `RS_TYPE(depth_func_t) cfg_depth_func,  // rastersim_pkg::DEPTH_*
  input  wire       cfg_depth_write,
  input  `RS_TYPE(cull_t) cfg_cull,              // rastersim_pkg::CULL_*
  input  wire       cfg_front_face,        // rastersim_pkg::FRONT_*
  input  wire       cfg_traversal,         // rastersim_pkg::TRAVERSAL_*
  input  wire       cfg_shading,           // rastersim_pkg::SHADING_*
  input  wire [rs_ubits32(MAX_MEMORY_LATENCY)-1:0] cfg_memory_latency,  // 1 .. MAX_MEMORY_LATENCY
  input  wire [rs_ubits32(MAX_SETUP_FIFO_DEPTH)-1:0] cfg_setup_fifo_depth,  // record credits, 1 .. MAX
  input  wire [rastersim_pkg::TEXTURE_LATENCY_BITS-1:0] cfg_texture_latency,   // Lt, 1 .. MAX_TEXTURE_LATENCY (TEXTURE builds)
  input  wire [rastersim_pkg::TEXTURE_LOG2_BITS-1:0] cfg_texture_log2_width,  // the texture's size, 0..10
  input  wire [rastersim_pkg::TEXTURE_LOG2_BITS-1:0] cfg_texture_log2_height,
  input  wire       cfg_texture_bilinear,  // 0: nearest
  input  wire       cfg_texture_clamp,     // 0: repeat
  input  wire [rastersim_pkg::DEPTH_BIAS_CONSTANT_BITS-1:0] cfg_depth_bias_constant,  // c, plane LSBs, two's complement (DEPTH_BIAS builds)
  input  wire [rastersim_pkg::DEPTH_BIAS_SLOPE_BITS-1:0] cfg_depth_bias_slope,     // f, s4.4 (16 x the slope factor)
  output wire frame_ready,
  // Triangle command: snapped vertices, x and y s(COORD_BITS-S).S, z u(DEPTH_PLANE_BITS), rgb {r, g, b}.
  input  wire cmd_valid,
  output wire cmd_ready,
  input  wire [rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] cmd_x0, cmd_y0, cmd_x1, cmd_y1, cmd_x2, cmd_y2,
  input  wire [rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS)-1:0] cmd_z0, cmd_z1, cmd_z2,
  input  `RS_TYPE(rgb_t) cmd_rgb0, cmd_rgb1, cmd_rgb2,
  // Texture coordinates (TEXTURE builds): S at [0 +: 50], T at [50 +: 50], Q at [100 +: 50] (S, T
  // s8.41, Q u1.41: rastersim_pkg::TEXTURE_VERTEX_BITS), used when cmd_textured.
  input  wire cmd_textured,
  input  `RS_TYPE(texture_vertex_t) cmd_texture0, cmd_texture1, cmd_texture2,
  // Trace: setup decision (FRONT cycle) and activity.
  output wire trace_setup_decided,
  output `RS_TYPE(status_t) trace_setup_status,    // 0 drawn, 1 degenerate, 2 culled, 3 offscreen, 4 no centre
  output wire trace_setup_busy,
  output wire trace_setup_stall,           // a triangle offered, the unit free, not accepted (credits, slot)
  output wire trace_setup_done,            // a drawn triangle's record is in the setup output register
  output wire trace_walker_load,           // record -> walker handshake
  output wire trace_walker_busy,
  output wire trace_walker_candidate,
  output wire trace_walker_last,
  // Trace: the walker's fragment handshake (into the texture unit, else the z-buffer's), the texture
  // unit's activity (0 without one).
  output wire trace_walker_frag_valid,
  output wire trace_walker_frag_ready,
  output wire trace_texture_busy,
  output wire trace_texture_stall,         // a textured read waits for the texture memory
  // Trace: the z-buffer's fragment handshake and the depth test result L cycles later.
  output wire trace_frag_valid,
  output wire trace_frag_ready,
  output wire [rs_ubits32(WIDTH - 1)-1:0]  trace_frag_x,
  output wire [rs_ubits32(HEIGHT - 1)-1:0] trace_frag_y,
  output wire [Z_BITS-1:0] trace_frag_z,
  output `RS_TYPE(rgb_t)   trace_frag_rgb,
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
  output `RS_TYPE(rgb_t)   mem_wr_rgb,
  // Texture memory port of the texture unit (rtl/texture_unit.sv; tied off without TEXTURE).
  output wire tex_rd_valid,
  input  wire tex_rd_ready,
  output wire [rastersim_pkg::TEXTURE_BANKS*rastersim_pkg::TEXEL_WORD_BITS-1:0] tex_rd_addr,
  input  wire [rastersim_pkg::TEXTURE_BANKS*rastersim_pkg::TEXEL_BITS-1:0] tex_rd_texels
);
`include "rastersim_widths.vh"
  `RS_REQUIRE(illegal_setup_fifo_depth, MAX_SETUP_FIFO_DEPTH >= 1, "rastersim_core: MAX_SETUP_FIFO_DEPTH must be at least 1")
  `RS_REQUIRE(illegal_texture, TEXTURE == 0 || TEXTURE == 1, "rastersim_core: TEXTURE must be 0 or 1")
  `RS_REQUIRE(illegal_depth_bias, DEPTH_BIAS == 0 || DEPTH_BIAS == 1, "rastersim_core: DEPTH_BIAS must be 0 or 1")
  `RS_REQUIRE(illegal_depth_exponent_bits, DEPTH_EXPONENT_BITS >= 0 && DEPTH_EXPONENT_BITS <= 4 && rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS) <= 32,
              "rastersim_core: DEPTH_EXPONENT_BITS must be 0..4, with a depth plane of at most 32 bits")

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
  localparam integer DEPTH_PLANE_BITS /*verilator public*/ = rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS);
  localparam integer DIVIDER_BITS /*verilator public*/ =
      rs_divider_bits(WIDTH, HEIGHT, SUBPIXEL_BITS, DEPTH_PLANE_BITS, Z_GUARD_BITS);
  localparam integer Z_REG_BITS /*verilator public*/ = DEPTH_PLANE_BITS + GUARD_BITS + 1;
  localparam integer COLOR_REG_BITS /*verilator public*/ = 8 + GUARD_BITS + 1;
  localparam integer LEFT_BITS = 2 * (Z_REG_BITS + 3 * COLOR_REG_BITS);  // rec_left_start, rec_left_step: two slots
  localparam integer X_BITS /*verilator public*/ = rs_ubits32(WIDTH - 1);
  localparam integer Y_BITS /*verilator public*/ = rs_ubits32(HEIGHT - 1);
  localparam integer ADDR_BITS /*verilator public*/ = rs_ubits32(WIDTH * HEIGHT - 1);
  // Untextured and textured triangles (equal unless the serial unit is built with TEXTURE).
  localparam integer SETUP_DRAWN_LATENCY /*verilator public*/ =
      rs_setup_texture_drawn_latency(WIDTH, HEIGHT, SUBPIXEL_BITS, DEPTH_PLANE_BITS, Z_GUARD_BITS, SETUP_INTERVAL, TEXTURE, 0);
  localparam integer SETUP_TEXTURED_DRAWN_LATENCY /*verilator public*/ =
      rs_setup_texture_drawn_latency(WIDTH, HEIGHT, SUBPIXEL_BITS, DEPTH_PLANE_BITS, Z_GUARD_BITS, SETUP_INTERVAL, TEXTURE, 1);
  localparam integer SETUP_REJECTED_LATENCY /*verilator public*/ =
      rs_setup_rejected_latency(WIDTH, HEIGHT, SUBPIXEL_BITS, SETUP_INTERVAL);
  localparam integer WALKER_LOAD_CYCLES /*verilator public*/ = 1;
  // The encodings of rastersim_pkg in one word, from bit 0: DEPTH_NEVER .. DEPTH_ALWAYS (3 bits
  // each), CULL_NONE, _BACK, _FRONT (2), FRONT_CCW, _CW, TRAVERSAL_BBOX, _SPAN, SHADING_FLAT,
  // _GOURAUD (1), STATUS_DRAWN .. STATUS_NO_CENTRE (3), PIXEL_CENTER_HALF, _CORNER (1),
  // FILL_TOP_LEFT .. FILL_BOTTOM_RIGHT (2), ROUNDING_NEAREST, _TRUNCATE (1).
  localparam [62:0] ENCODINGS /*verilator public*/ = {
      1'(rastersim_pkg::ROUNDING_TRUNCATE), 1'(rastersim_pkg::ROUNDING_NEAREST),
      2'(rastersim_pkg::FILL_BOTTOM_RIGHT), 2'(rastersim_pkg::FILL_BOTTOM_LEFT), 2'(rastersim_pkg::FILL_TOP_RIGHT), 2'(rastersim_pkg::FILL_TOP_LEFT),
      1'(rastersim_pkg::PIXEL_CENTER_CORNER), 1'(rastersim_pkg::PIXEL_CENTER_HALF),
      rastersim_pkg::STATUS_NO_CENTRE, rastersim_pkg::STATUS_OFFSCREEN, rastersim_pkg::STATUS_CULLED, rastersim_pkg::STATUS_DEGENERATE, rastersim_pkg::STATUS_DRAWN,
      rastersim_pkg::SHADING_GOURAUD, rastersim_pkg::SHADING_FLAT, rastersim_pkg::TRAVERSAL_SPAN, rastersim_pkg::TRAVERSAL_BBOX, rastersim_pkg::FRONT_CW, rastersim_pkg::FRONT_CCW,
      rastersim_pkg::CULL_FRONT, rastersim_pkg::CULL_BACK, rastersim_pkg::CULL_NONE,
      rastersim_pkg::DEPTH_ALWAYS, rastersim_pkg::DEPTH_GEQUAL, rastersim_pkg::DEPTH_NOTEQUAL, rastersim_pkg::DEPTH_GREATER, rastersim_pkg::DEPTH_LEQUAL, rastersim_pkg::DEPTH_EQUAL,
      rastersim_pkg::DEPTH_LESS, rastersim_pkg::DEPTH_NEVER};
  // The profile parameters themselves, for the harness.
  localparam integer P_WIDTH /*verilator public*/ = WIDTH;
  localparam integer P_HEIGHT /*verilator public*/ = HEIGHT;
  localparam integer P_SUBPIXEL_BITS /*verilator public*/ = SUBPIXEL_BITS;
  localparam integer P_Z_BITS /*verilator public*/ = Z_BITS;
  localparam integer P_Z_GUARD_BITS /*verilator public*/ = Z_GUARD_BITS;
  localparam integer P_MAX_MEMORY_LATENCY /*verilator public*/ = MAX_MEMORY_LATENCY;
  localparam integer P_MAX_SETUP_FIFO_DEPTH /*verilator public*/ = MAX_SETUP_FIFO_DEPTH;
  localparam integer P_SETUP_INTERVAL /*verilator public*/ = SETUP_INTERVAL;
  localparam integer P_TEXTURE /*verilator public*/ = TEXTURE;
  localparam integer P_MAX_TEXTURE_LATENCY /*verilator public*/ = MAX_TEXTURE_LATENCY;
  localparam integer P_DEPTH_EXPONENT_BITS /*verilator public*/ = DEPTH_EXPONENT_BITS;
  localparam integer P_DEPTH_BIAS /*verilator public*/ = DEPTH_BIAS;
  localparam integer P_PIXEL_CENTER /*verilator public*/ = PIXEL_CENTER;
  localparam integer P_FILL_RULE /*verilator public*/ = FILL_RULE;
  localparam integer P_DEPTH_ROUNDING /*verilator public*/ = DEPTH_ROUNDING;
  localparam integer P_COLOR_ROUNDING /*verilator public*/ = COLOR_ROUNDING;
  localparam integer TEXTURE_REG_BITS /*verilator public*/ = rs_texture_reg_bits(WIDTH, HEIGHT);
  /* verilator lint_on UNUSEDPARAM */

  // The runtime profile keys are sampled while rst is high and held for the frame (static
  // configuration registers: the units see registers, not the ports).
  `RS_TYPE(depth_func_t) depth_func_q;
  reg depth_write_q, front_face_q, traversal_q, shading_q;
  `RS_TYPE(cull_t) cull_q;
  reg [rs_ubits32(MAX_MEMORY_LATENCY)-1:0] memory_latency_q;
  reg [rs_ubits32(MAX_SETUP_FIFO_DEPTH)-1:0] setup_fifo_depth_q;
  reg [rastersim_pkg::TEXTURE_LATENCY_BITS-1:0] texture_latency_q;
  reg [rastersim_pkg::TEXTURE_LOG2_BITS-1:0] texture_log2_width_q, texture_log2_height_q;
  reg texture_bilinear_q, texture_clamp_q;
  reg [rastersim_pkg::DEPTH_BIAS_CONSTANT_BITS-1:0] depth_bias_constant_q;
  reg [rastersim_pkg::DEPTH_BIAS_SLOPE_BITS-1:0] depth_bias_slope_q;
  always @(posedge clk) begin
    if (rst) begin
      depth_bias_constant_q <= cfg_depth_bias_constant;
      depth_bias_slope_q <= cfg_depth_bias_slope;
      texture_latency_q <= cfg_texture_latency;
      texture_log2_width_q <= cfg_texture_log2_width;
      texture_log2_height_q <= cfg_texture_log2_height;
      texture_bilinear_q <= cfg_texture_bilinear;
      texture_clamp_q <= cfg_texture_clamp;
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
  localparam integer RECORD_Z_BITS = DEPTH_PLANE_BITS;
  localparam integer RECORD_BITS = rs_rec_lsb(20, WIDTH, HEIGHT, SUBPIXEL_BITS, RECORD_Z_BITS, Z_GUARD_BITS);
  localparam integer WALKER_RECORD_BITS = rs_rec_walker_bits(WIDTH, HEIGHT, SUBPIXEL_BITS);
  `include "rastersim_record.vh"
  wire setup_valid;
  wire [RECORD_BITS-1:0] setup_record;
  wire setup_ready;
  localparam integer TEXTURE_RECORD_BITS = rs_texture_record_bits(WIDTH, HEIGHT);
  wire [TEXTURE_RECORD_BITS-1:0] setup_texture;
  wire decided_front_facing_unused;
  wire [AREA_BITS-1:0] decided_area2_unused;

  // Record credits (docs/cycle-model.md): a triangle holds one from its accept until it is rejected
  // or its record is loaded by the walker; the setup unit accepts only while one is free.
  localparam integer CREDIT_BITS = rs_ubits32(MAX_SETUP_FIFO_DEPTH);
  reg [CREDIT_BITS-1:0] credits_held_q;
  wire credit_free = credits_held_q < setup_fifo_depth_q;
  wire accept = cmd_valid && cmd_ready;
  wire rejected = trace_setup_decided && trace_setup_status != rastersim_pkg::STATUS_DRAWN;
  always @(posedge clk) begin
    if (rst) credits_held_q <= {CREDIT_BITS{1'b0}};
    else credits_held_q <= credits_held_q + {{(CREDIT_BITS-1){1'b0}}, accept}
                         - {{(CREDIT_BITS-1){1'b0}}, rejected} - {{(CREDIT_BITS-1){1'b0}}, trace_walker_load};
  end

  assign cmd_ready = setup_ready && frame_ready && credit_free;
`include "rastersim_assert.vh"
  `RS_ASSERT(credits_within_depth, credits_held_q <= setup_fifo_depth_q)
  wire setup_free;
  assign trace_setup_stall = cmd_valid && frame_ready && setup_free && !accept;
  assign trace_setup_done = setup_valid;

  triangle_setup #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS), .Z_BITS(DEPTH_PLANE_BITS),
                   .Z_GUARD_BITS(Z_GUARD_BITS), .SETUP_INTERVAL(SETUP_INTERVAL), .TEXTURE(TEXTURE),
                   .PIXEL_CENTER(PIXEL_CENTER), .FILL_RULE(FILL_RULE)) setup (
    .clk(clk), .rst(rst), .run(frame_ready), .free(setup_free), .cfg_cull(cull_q), .cfg_front_face(front_face_q),
    .in_valid(cmd_valid && frame_ready && credit_free), .in_ready(setup_ready),
    .in_x({cmd_x2, cmd_x1, cmd_x0}), .in_y({cmd_y2, cmd_y1, cmd_y0}), .in_z({cmd_z2, cmd_z1, cmd_z0}),
    .in_rgb({cmd_rgb2, cmd_rgb1, cmd_rgb0}),
    .in_textured(cmd_textured), .in_texture({cmd_texture2, cmd_texture1, cmd_texture0}),
    .decided(trace_setup_decided), .decided_status(trace_setup_status),
    .decided_front_facing(decided_front_facing_unused), .decided_area2(decided_area2_unused),
    .busy(trace_setup_busy),
    .out_valid(setup_valid),
    .out_record(setup_record), .out_texture(setup_texture));

  // Record FIFO: every record goes in, as the walker's entry (scanline_walker_entry: its state at
  // the load) and the Z adder's planes; it is at the head from the next cycle (the credits leave it
  // room).
  localparam integer ENTRY_BITS = rs_entry_lsb(20, WIDTH, HEIGHT, SUBPIXEL_BITS);
  localparam integer PLANE_BITS = RECORD_BITS - WALKER_RECORD_BITS;
  // The texture record rides above the planes in a TEXTURE build only.
  localparam integer FIFO_TEXTURE_BITS = TEXTURE != 0 ? TEXTURE_RECORD_BITS : 0;
  localparam integer FIFO_BITS = ENTRY_BITS + PLANE_BITS + FIFO_TEXTURE_BITS;
  wire [ENTRY_BITS-1:0] setup_entry;
  scanline_walker_entry #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS)) walker_entry (
    .record(setup_record[WALKER_RECORD_BITS-1:0]), .entry(setup_entry));
  wire fifo_empty;
  wire [FIFO_BITS-1:0] fifo_head;
  wire walker_ready, walker_load;
  wire [FIFO_BITS-1:0] fifo_push_data;
  wire [TEXTURE_RECORD_BITS-1:0] head_texture;
  generate
    if (TEXTURE != 0) begin : fifo_texture
      assign fifo_push_data = {setup_texture, setup_record[RECORD_BITS-1:WALKER_RECORD_BITS], setup_entry};
      assign head_texture = fifo_head[FIFO_BITS-1 -: TEXTURE_RECORD_BITS];
    end else begin : fifo_plain
      /* verilator lint_off UNUSEDSIGNAL */
      wire setup_texture_unused = ^setup_texture;
      /* verilator lint_on UNUSEDSIGNAL */
      assign fifo_push_data = {setup_record[RECORD_BITS-1:WALKER_RECORD_BITS], setup_entry};
      assign head_texture = {TEXTURE_RECORD_BITS{1'b0}};
    end
  endgenerate
  setup_fifo #(.RECORD_BITS(FIFO_BITS), .ENTRIES(MAX_SETUP_FIFO_DEPTH)) record_fifo (
    .clk(clk), .rst(rst), .push(setup_valid), .push_data(fifo_push_data),
    .pop(walker_load), .empty(fifo_empty), .head(fifo_head));

  // With DEPTH_BIAS a record is ready for the walker once the bias unit has its bias
  // (docs/cycle-model.md, "Depth bias"); else as it reaches the FIFO's head.
  wire record_ready;
  wire [Z_REG_BITS:0] head_bias;
  generate
    if (DEPTH_BIAS != 0) begin : biasing
      wire bias_ready;
      depth_bias #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .Z_BITS(Z_BITS), .Z_GUARD_BITS(Z_GUARD_BITS),
                   .DEPTH_EXPONENT_BITS(DEPTH_EXPONENT_BITS), .DEPTH_ROUNDING(DEPTH_ROUNDING),
                   .MAX_SETUP_FIFO_DEPTH(MAX_SETUP_FIFO_DEPTH)) bias_unit (
        .clk(clk), .rst(rst), .cfg_depth_bias_constant(depth_bias_constant_q), .cfg_depth_bias_slope(depth_bias_slope_q),
        .in_valid(setup_valid), .in_step_x(setup_record[LSB_DEPTH_STEP_X +: Z_REG_BITS]),
        .in_step_y(setup_record[LSB_DEPTH_STEP_Y +: Z_REG_BITS]), .pop(walker_load), .ready(bias_ready),
        .bias(head_bias));
      assign record_ready = !fifo_empty && bias_ready;
    end else begin : no_bias
      /* verilator lint_off UNUSEDSIGNAL */
      wire bias_config_unused = ^depth_bias_constant_q ^ ^depth_bias_slope_q;
      /* verilator lint_on UNUSEDSIGNAL */
      assign record_ready = !fifo_empty;
      assign head_bias = {(Z_REG_BITS+1){1'b0}};
    end
  endgenerate
  assign walker_load = record_ready && walker_ready;
  assign trace_walker_load = walker_load;
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
  wire [TEXTURE_RECORD_BITS-1:0] rec_texture /*verilator public_flat_rd*/;  // rs_texture_record_bits layout
  assign rec_texture = setup_texture;
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

  // Walker + Z adder -> (texture unit ->) z-buffer fragment.
  localparam integer TR = rs_texture_reg_bits(WIDTH, HEIGHT);
  wire walker_frag_valid, walker_frag_ready;
  wire [X_BITS-1:0] walker_frag_x;
  wire [Y_BITS-1:0] walker_frag_y;
  wire [DEPTH_PLANE_BITS-1:0] walker_frag_z;  // X (the z-buffer forms the word)
  wire [23:0] walker_frag_rgb;
  wire walker_frag_textured;
  wire [3*TR-1:0] walker_frag_texture;
  wire adder_load, adder_step_x, adder_next_row, adder_row_enter, adder_enter_left, adder_enter_slot;
  wire [1:0] adder_left_carry;
  wire frag_valid, frag_ready;
  wire [X_BITS-1:0] frag_x;
  wire [Y_BITS-1:0] frag_y;
  wire [DEPTH_PLANE_BITS-1:0] frag_z;
  wire [23:0] frag_rgb;

  scanline_walker #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS)) walker (
    .clk(clk), .rst(rst), .cfg_traversal(traversal_q),
    .in_valid(record_ready), .in_ready(walker_ready),
    .in_entry(fifo_head[ENTRY_BITS-1:0]),
    .adder_load(adder_load), .adder_step_x(adder_step_x), .adder_next_row(adder_next_row),
    .adder_row_enter(adder_row_enter), .adder_enter_left(adder_enter_left), .adder_enter_slot(adder_enter_slot),
    .adder_left_carry(adder_left_carry),
    .frag_valid(walker_frag_valid), .frag_ready(walker_frag_ready), .frag_x(walker_frag_x), .frag_y(walker_frag_y),
    .busy(trace_walker_busy), .candidate(trace_walker_candidate), .last(trace_walker_last));

  z_adder #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .Z_BITS(Z_BITS), .Z_GUARD_BITS(Z_GUARD_BITS), .TEXTURE(TEXTURE),
            .DEPTH_EXPONENT_BITS(DEPTH_EXPONENT_BITS), .DEPTH_BIAS(DEPTH_BIAS), .DEPTH_ROUNDING(DEPTH_ROUNDING),
            .COLOR_ROUNDING(COLOR_ROUNDING)) adders (
    .clk(clk), .cfg_shading(shading_q), .load(adder_load), .depth_bias(head_bias), .step_x(adder_step_x),
    .next_row(adder_next_row), .row_enter(adder_row_enter), .enter_left(adder_enter_left),
    .enter_slot(adder_enter_slot), .left_carry(adder_left_carry),
    .depth_start(fifo_head[PLANES_AT + LSB_DEPTH_START +: Z_REG_BITS]), .depth_step_x(fifo_head[PLANES_AT + LSB_DEPTH_STEP_X +: Z_REG_BITS]),
    .depth_step_y(fifo_head[PLANES_AT + LSB_DEPTH_STEP_Y +: Z_REG_BITS]), .color_start(fifo_head[PLANES_AT + LSB_COLOR_START +: 3*COLOR_REG_BITS]),
    .color_step_x(fifo_head[PLANES_AT + LSB_COLOR_STEP_X +: 3*COLOR_REG_BITS]), .color_step_y(fifo_head[PLANES_AT + LSB_COLOR_STEP_Y +: 3*COLOR_REG_BITS]),
    .flat_rgb(fifo_head[PLANES_AT + LSB_FLAT_RGB +: 24]), .left_start(fifo_head[PLANES_AT + LSB_LEFT_START +: LEFT_BITS]),
    .left_step(fifo_head[PLANES_AT + LSB_LEFT_STEP +: LEFT_BITS]), .texture_record(head_texture),
    .depth(walker_frag_z), .rgb(walker_frag_rgb), .triangle_textured(walker_frag_textured), .stq(walker_frag_texture));

  generate
    if (TEXTURE != 0) begin : texturing
      texture_unit #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .Z_BITS(Z_BITS), .DEPTH_EXPONENT_BITS(DEPTH_EXPONENT_BITS),
                     .MAX_TEXTURE_LATENCY(MAX_TEXTURE_LATENCY)) unit (
        .clk(clk), .rst(rst), .cfg_texture_latency(texture_latency_q), .cfg_log2_width(texture_log2_width_q),
        .cfg_log2_height(texture_log2_height_q), .cfg_bilinear(texture_bilinear_q), .cfg_clamp(texture_clamp_q),
        .in_valid(walker_frag_valid), .in_ready(walker_frag_ready), .in_x(walker_frag_x), .in_y(walker_frag_y),
        .in_z(walker_frag_z), .in_rgb(walker_frag_rgb), .in_textured(walker_frag_textured),
        .in_s(walker_frag_texture[0 +: TR]), .in_t(walker_frag_texture[TR +: TR]), .in_q(walker_frag_texture[2*TR +: TR]),
        .out_valid(frag_valid), .out_ready(frag_ready), .out_x(frag_x), .out_y(frag_y), .out_z(frag_z), .out_rgb(frag_rgb),
        .tex_rd_valid(tex_rd_valid), .tex_rd_ready(tex_rd_ready), .tex_rd_addr(tex_rd_addr), .tex_rd_texels(tex_rd_texels),
        .busy(trace_texture_busy), .stall(trace_texture_stall));
    end else begin : no_texture
      // The texture configuration and ports are unused: the walker feeds the z-buffer.
      /* verilator lint_off UNUSEDSIGNAL */
      wire unused = ^{walker_frag_textured, walker_frag_texture, tex_rd_ready, tex_rd_texels, texture_latency_q,
                      texture_log2_width_q, texture_log2_height_q, texture_bilinear_q, texture_clamp_q};
      /* verilator lint_on UNUSEDSIGNAL */
      assign frag_valid = walker_frag_valid;
      assign walker_frag_ready = frag_ready;
      assign frag_x = walker_frag_x;
      assign frag_y = walker_frag_y;
      assign frag_z = walker_frag_z;
      assign frag_rgb = walker_frag_rgb;
      assign tex_rd_valid = 1'b0;
      assign tex_rd_addr = {4*18{1'b0}};
      assign trace_texture_busy = 1'b0;
      assign trace_texture_stall = 1'b0;
    end
  endgenerate
  assign trace_walker_frag_valid = walker_frag_valid;
  assign trace_walker_frag_ready = walker_frag_ready;

  zbuffer #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .Z_BITS(Z_BITS), .DEPTH_EXPONENT_BITS(DEPTH_EXPONENT_BITS),
            .MAX_MEMORY_LATENCY(MAX_MEMORY_LATENCY)) zbuf (
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
  // The offered fragment's depth word, as the z-buffer forms it from X (observation only).
  depth_word #(.Z_BITS(Z_BITS), .DEPTH_EXPONENT_BITS(DEPTH_EXPONENT_BITS)) trace_encoder (
    .value(frag_z), .word(trace_frag_z));
  assign trace_frag_rgb = frag_rgb;
endmodule
