// Texture unit (model/texture_unit.h; cycles: docs/cycle-model.md, "Texture unit"): between the
// walker and the z-buffer in a TEXTURE build. Every fragment passes in order; a textured one
// leaves with its texel colour modulated by its shade, an untextured one with its shade.
//   t          take (in_valid & in_ready): the input register, at most C = Lt + 40 held
//   t+1..t+29  texture_divide: u, v registered at the end of t + 29
//   t+30..t+32 texture_address (TEXTURE_ADDRESS_STAGES = 3): columns, rows, weights registered
//   s >= t+33  the pending queue's head issues its read (a textured one when the memory takes it)
//   s+Lt       the texels arrive; texture_filter (TEXTURE_FILTER_STAGES = 6) registers the modulated
//              colour at the end of s + Lt + 5
//   s+Lt+6     offered to the z-buffer from the output buffer (o = s + Lt + 6)
// The divider and the address stages never stall: the capacity leaves room in the pending queue and
// the output buffer, which bypass their storage when empty.
// Memory port contract (rtl/texture_memory.sv): a read taken in c (rd_valid & rd_ready) returns
// bank b's texel on rd_texels[24 b +: 24] in c + Lt; bank 2 (j mod 2) + (i mod 2) holds column i,
// row j at {j >> 1, i >> 1}.
`include "rastersim_pkg.sv"
module texture_unit `RS_IMPORT #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer Z_BITS = 24,
  parameter integer DEPTH_EXPONENT_BITS = 0,  // in_z, out_z: X, rs_depth_plane_bits(Z_BITS, Ne) bits
  parameter integer MAX_TEXTURE_LATENCY = 64
) (
  input  wire clk,
  input  wire rst,
  // Static configuration (registers of the core, held for the frame).
  input  wire [rastersim_pkg::TEXTURE_LATENCY_BITS-1:0] cfg_texture_latency,  // Lt, 1 .. MAX_TEXTURE_LATENCY
  input  wire [rastersim_pkg::TEXTURE_LOG2_BITS-1:0] cfg_log2_width,       // texture size, 0..10
  input  wire [rastersim_pkg::TEXTURE_LOG2_BITS-1:0] cfg_log2_height,
  input  wire cfg_bilinear,               // 0: nearest
  input  wire cfg_clamp,                  // 0: repeat
  // Fragments from the walker: pixel, depth (the plane's output X), shade {r, g, b}, and the S, T, Q registers
  // (s9.(P+Ft), rs_texture_reg_bits wide, written as in texture_divide).
  input  wire in_valid,
  output wire in_ready,
  input  wire [rs_ubits32(WIDTH - 1)-1:0]  in_x,
  input  wire [rs_ubits32(HEIGHT - 1)-1:0] in_y,
  input  wire [rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS)-1:0] in_z,
  input  `RS_TYPE(rgb_t) in_rgb,
  input  wire in_textured,
  input  wire [rs_texture_reg_bits(WIDTH, HEIGHT)-1:0] in_s,
  input  wire [rs_texture_reg_bits(WIDTH, HEIGHT)-1:0] in_t,
  input  wire [rs_texture_reg_bits(WIDTH, HEIGHT)-1:0] in_q,
  // Fragments to the z-buffer.
  output wire out_valid,
  input  wire out_ready,
  output wire [rs_ubits32(WIDTH - 1)-1:0]  out_x,
  output wire [rs_ubits32(HEIGHT - 1)-1:0] out_y,
  output wire [rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS)-1:0] out_z,
  output `RS_TYPE(rgb_t) out_rgb,
  // Texture memory read port.
  output wire tex_rd_valid,
  input  wire tex_rd_ready,
  output wire [rastersim_pkg::TEXTURE_BANKS*rastersim_pkg::TEXEL_WORD_BITS-1:0] tex_rd_addr,
  input  wire [rastersim_pkg::TEXTURE_BANKS*rastersim_pkg::TEXEL_BITS-1:0] tex_rd_texels,
  output wire busy,   // holds a fragment, or takes one
  output wire stall   // a textured read waits for the memory
);
`include "rastersim_widths.vh"
  `RS_REQUIRE(illegal_latency, MAX_TEXTURE_LATENCY >= 1 && MAX_TEXTURE_LATENCY <= 64, "texture_unit: MAX_TEXTURE_LATENCY must be 1..64")

  localparam integer X_BITS = rs_ubits32(WIDTH - 1);
  localparam integer Y_BITS = rs_ubits32(HEIGHT - 1);
  localparam integer TR = rs_texture_reg_bits(WIDTH, HEIGHT);
  // A fragment beside the arithmetic: {textured, shade, z, y, x}.
  localparam integer FRAG_BITS = 1 + 24 + rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS) + Y_BITS + X_BITS;
  // A looked-up fragment: the fragment, then {x0, x1, y0, y1, wx, wy} from the address stage.
  localparam integer LOOKUP_BITS = FRAG_BITS + 56;
  localparam integer ADDRESS_STAGES = rastersim_pkg::TEXTURE_ADDRESS_STAGES;
  localparam integer FILTER_STAGES = rastersim_pkg::TEXTURE_FILTER_STAGES;
  // The capacity beyond Lt: take to offer without waiting is 30 + ADDRESS_STAGES + Lt + FILTER_STAGES.
  localparam integer CAPACITY_BEYOND_LATENCY = 31 + ADDRESS_STAGES + FILTER_STAGES;
  localparam integer MAX_CAPACITY = MAX_TEXTURE_LATENCY + CAPACITY_BEYOND_LATENCY;
  localparam integer COUNT_BITS = $clog2(MAX_CAPACITY + 1);

  // ---- Take: while fewer than C = Lt + 40 fragments are held at the cycle's start ----
  wire [COUNT_BITS:0] capacity = (COUNT_BITS+1)'(cfg_texture_latency) + (COUNT_BITS+1)'(CAPACITY_BEYOND_LATENCY);
  reg [COUNT_BITS-1:0] held_q;
  assign in_ready = {1'b0, held_q} < capacity;
  wire take = in_valid && in_ready;
  wire leave = out_valid && out_ready;
  always @(posedge clk) begin
    if (rst) held_q <= {COUNT_BITS{1'b0}};
    else held_q <= held_q + COUNT_BITS'(take) - COUNT_BITS'(leave);
  end
  assign busy = take || held_q != {COUNT_BITS{1'b0}};

  // The input register (the end of t).
  reg taken_q;
  reg [FRAG_BITS-1:0] taken_frag_q;
  reg [TR-1:0] taken_s_q, taken_t_q, taken_q_q;
  always @(posedge clk) begin
    taken_q <= take && !rst;
    if (take) begin
      taken_frag_q <= {in_textured, in_rgb, in_z, in_y, in_x};
      taken_s_q <= in_s;
      taken_t_q <= in_t;
      taken_q_q <= in_q;
    end
  end

  // ---- Divide (t + 1 .. t + 29); the fragments wait beside it in order ----
  wire divided;
  wire [27:0] u, v;
  texture_divide #(.WIDTH(WIDTH), .HEIGHT(HEIGHT)) divide (
    .clk(clk), .rst(rst), .in_valid(taken_q), .in_s(taken_s_q), .in_t(taken_t_q), .in_q(taken_q_q),
    .out_valid(divided), .out_u(u), .out_v(v));
  wire beside_empty_unused;
  wire [FRAG_BITS-1:0] divided_frag;
  setup_fifo #(.RECORD_BITS(FRAG_BITS), .ENTRIES(32)) beside_divide (
    .clk(clk), .rst(rst), .push(taken_q), .push_data(taken_frag_q), .pop(divided),
    .empty(beside_empty_unused), .head(divided_frag));

  // ---- Address (the end of t + 32): the fragments beside it in a delay line ----
  wire [9:0] x0, x1, y0, y1;
  wire [7:0] wx, wy;
  texture_address address (
    .clk(clk), .u(u), .v(v), .cfg_log2_width(cfg_log2_width), .cfg_log2_height(cfg_log2_height),
    .cfg_bilinear(cfg_bilinear), .cfg_clamp(cfg_clamp),
    .x0_q(x0), .x1_q(x1), .y0_q(y0), .y1_q(y1), .wx_q(wx), .wy_q(wy));
  reg [ADDRESS_STAGES-1:0] addressing_q;  // stage k's valid at bit k
  reg [FRAG_BITS-1:0] addressing_frag_q [0:ADDRESS_STAGES-1];
  integer a;
  always @(posedge clk) begin
    addressing_q <= rst ? {ADDRESS_STAGES{1'b0}} : {addressing_q[ADDRESS_STAGES-2:0], divided};
    addressing_frag_q[0] <= divided_frag;
    for (a = 1; a < ADDRESS_STAGES; a = a + 1) addressing_frag_q[a] <= addressing_frag_q[a-1];
  end
  wire addressed_valid = addressing_q[ADDRESS_STAGES-1];
  wire [FRAG_BITS-1:0] addressed_frag = addressing_frag_q[ADDRESS_STAGES-1];

  // ---- Read: the pending queue's head, in order; untextured fragments issue without a read ----
  wire [LOOKUP_BITS-1:0] addressed = {addressed_frag, x0, x1, y0, y1, wx, wy};
  wire pending_empty;
  wire [LOOKUP_BITS-1:0] pending_head;
  wire head_valid = addressed_valid || !pending_empty;
  wire [LOOKUP_BITS-1:0] head = pending_empty ? addressed : pending_head;
  wire head_textured = head[LOOKUP_BITS-1];
  wire issue = head_valid && (!head_textured || tex_rd_ready);
  setup_fifo #(.RECORD_BITS(LOOKUP_BITS), .ENTRIES(MAX_CAPACITY)) pending (
    .clk(clk), .rst(rst), .push(addressed_valid && !(pending_empty && issue)), .push_data(addressed),
    .pop(!pending_empty && issue), .empty(pending_empty), .head(pending_head));
  assign tex_rd_valid = head_valid && head_textured;
  assign stall = tex_rd_valid && !tex_rd_ready;

  // Bank 2 py + px reads the column of parity px and the row of parity py among the lookup's two
  // (a nearest or clamped lookup's two are one texel: any bank not holding it reads what it likes).
  wire [9:0] head_x0 = head[55:46], head_x1 = head[45:36], head_y0 = head[35:26], head_y1 = head[25:16];
  genvar b;
  generate
    for (b = 0; b < 4; b = b + 1) begin : bank_address
      /* verilator lint_off UNUSEDSIGNAL */
      wire [9:0] column = head_x0[0] == (b % 2 == 1) ? head_x0 : head_x1;
      wire [9:0] row = head_y0[0] == (b / 2 == 1) ? head_y0 : head_y1;  // bit 0 is the bank
      /* verilator lint_on UNUSEDSIGNAL */
      assign tex_rd_addr[18*b +: 18] = {row[9:1], column[9:1]};
    end
  endgenerate

  // ---- In flight: what the texels meet in s + Lt, a ring of the last RING cycles' issues ----
  // {fragment, weights, the parities of x0, x1, y0, y1}.
  localparam integer FLIGHT_BITS = FRAG_BITS + 16 + 4;
  localparam integer RING_BITS = MAX_TEXTURE_LATENCY > 2 ? $clog2(MAX_TEXTURE_LATENCY) : 1;
  localparam integer RING = 1 << RING_BITS;
  reg [RING_BITS-1:0] now_slot_q;
  reg [FLIGHT_BITS-1:0] flight_q [0:RING-1];
  reg [RING-1:0] flight_valid_q;
  wire [RING_BITS-1:0] arriving_slot = now_slot_q - cfg_texture_latency[RING_BITS-1:0];  // modulo RING
  always @(posedge clk) begin
    if (rst) begin
      now_slot_q <= {RING_BITS{1'b0}};
      flight_valid_q <= {RING{1'b0}};
    end else begin
      now_slot_q <= now_slot_q + 1'b1;
      flight_valid_q[now_slot_q] <= issue;
    end
    flight_q[now_slot_q] <= {head[LOOKUP_BITS-1 -: FRAG_BITS], head[15:0], head_x0[0], head_x1[0], head_y0[0], head_y1[0]};
  end
  wire arriving = flight_valid_q[arriving_slot];
  wire [FLIGHT_BITS-1:0] arrival = flight_q[arriving_slot];
  wire [1:0] px = arrival[3:2], py = arrival[1:0];  // x0, x1 and y0, y1 parities
  wire [23:0] texel00 = tex_rd_texels[24*{py[1], px[1]} +: 24];
  wire [23:0] texel10 = tex_rd_texels[24*{py[1], px[0]} +: 24];
  wire [23:0] texel01 = tex_rd_texels[24*{py[0], px[1]} +: 24];
  wire [23:0] texel11 = tex_rd_texels[24*{py[0], px[0]} +: 24];
  wire [FRAG_BITS-1:0] arrival_frag = arrival[FLIGHT_BITS-1 -: FRAG_BITS];

  // ---- Filter (the end of s + Lt .. s + Lt + 5): the fragments beside it in a delay line ----
  wire [23:0] modulated;
  texture_filter filter (
    .clk(clk), .texel00(texel00), .texel10(texel10), .texel01(texel01), .texel11(texel11),
    .wx(arrival[19:12]), .wy(arrival[11:4]), .shade(arrival_frag[FRAG_BITS-2 -: 24]), .rgb_q(modulated));
  reg [FILTER_STAGES-1:0] filtering_q;
  reg [FRAG_BITS-1:0] filtering_frag_q [0:FILTER_STAGES-1];
  integer f;
  always @(posedge clk) begin
    filtering_q <= rst ? {FILTER_STAGES{1'b0}} : {filtering_q[FILTER_STAGES-2:0], arriving};
    filtering_frag_q[0] <= arrival_frag;
    for (f = 1; f < FILTER_STAGES; f = f + 1) filtering_frag_q[f] <= filtering_frag_q[f-1];
  end
  wire modulated_valid = filtering_q[FILTER_STAGES-1];
  wire [FRAG_BITS-1:0] modulated_frag = filtering_frag_q[FILTER_STAGES-1];
  // The fragment as it leaves: the modulated colour in place of a textured fragment's shade.
  wire [FRAG_BITS-2:0] finished = modulated_frag[FRAG_BITS-1]
      ? {modulated, modulated_frag[FRAG_BITS-26:0]} : modulated_frag[FRAG_BITS-2:0];

  // ---- Output buffer (offered from s + Lt + 6) ----
  wire output_empty;
  wire [FRAG_BITS-2:0] output_head;
  setup_fifo #(.RECORD_BITS(FRAG_BITS - 1), .ENTRIES(MAX_CAPACITY)) output_buffer (
    .clk(clk), .rst(rst), .push(modulated_valid && !(output_empty && out_ready)), .push_data(finished),
    .pop(!output_empty && out_ready), .empty(output_empty), .head(output_head));
  assign out_valid = modulated_valid || !output_empty;
  wire [FRAG_BITS-2:0] offered = output_empty ? finished : output_head;
  assign {out_rgb, out_z, out_y, out_x} = offered;

`include "rastersim_assert.vh"
  // Requests and fragments stay offered until taken; never more than C fragments are held.
  `RS_ASSERT_HELD(read_held, tex_rd_valid, tex_rd_ready, tex_rd_addr)
  `RS_ASSERT_HELD(fragment_held, out_valid, out_ready, {out_rgb, out_z, out_y, out_x})
  `RS_ASSERT(within_capacity, {1'b0, held_q} <= capacity)
  // A textured fragment's Q register lies in [2^D, 2^(P+Ft)] (D the bits the divide drops): the
  // shifted divisor is positive and as wide as texture_divide.sv's divider.
  `RS_ASSERT(divisor_in_range, !taken_q || !taken_frag_q[FRAG_BITS-1] ||
                               (taken_q_q >= (TR'(1) << rs_texture_divide_shift(WIDTH, HEIGHT)) &&
                                taken_q_q <= (TR'(1) << (TR - 9))))
endmodule
