// Z register adder (model/z_adder.h): the depth plane register and, for Gouraud shading, the
// r, g, b plane registers, stepped in lockstep with the walker. No multiplication in the steps.
// Depth registers are s(Np+1).F, colour registers s9.F (F = guard bits), all wrapping. With TEXTURE
// the S, T, Q plane registers too (s9.(P+Ft), docs/arithmetic.md section 5), for the texture unit.
// The depth output stage (model/z_adder.h DepthOutput, docs/arithmetic.md section 6): with
// DEPTH_BIAS the triangle's bias, taken at the load from the bias unit (depth_bias.sv, which forms
// it from the record's depth steps), added before the rounding and the clamp: the plane output X,
// Np bits. Logic between the register and the fragment: no cycles. The depth word (floating point
// with DEPTH_EXPONENT_BITS >= 2) is formed from X by the z-buffer (depth_word.sv).
`include "rastersim_pkg.sv"
module z_adder `RS_IMPORT #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer Z_BITS = 24,     // N, the depth word's bits
  parameter integer Z_GUARD_BITS = 0,
  parameter integer TEXTURE = 0,    // 1: the texture planes (rs_texture_record_bits), else none
  parameter integer DEPTH_EXPONENT_BITS = 0,  // Ne: the depth plane has rs_depth_plane_bits(N, Ne) bits
  parameter integer DEPTH_BIAS = 0,           // 1: the depth bias
  parameter integer DEPTH_ROUNDING = 0,       // rastersim_pkg::ROUNDING_*: the depth output (profile depth_rounding)
  parameter integer COLOR_ROUNDING = 0        // rastersim_pkg::ROUNDING_*: the colour outputs (profile color_rounding)
) (
  input  wire clk,
  input  wire cfg_shading,  // rastersim_pkg::SHADING_*; flat: the provoking vertex colour
  input  wire load,
  // The loaded triangle's bias and the rounding's half, B + R in [-2^(Np+F), 2^(Np+F) + 2^(F-1)]
  // (depth_bias.sv; DEPTH_BIAS only).
  input  wire [rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS)+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS)+1:0] depth_bias,
  input  wire step_x,
  input  wire next_row,
  input  wire row_enter,
  input  wire enter_left,         // load, row_enter: the span starts at a left edge (scanline_walker)
  input  wire enter_slot,         // its left-edge slot
  input  wire [rastersim_pkg::LEFT_EDGE_SLOTS-1:0] left_carry,   // each slot's DDA carry into the row after the one entered
  input  wire [rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS)+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS):0]  depth_start,
  input  wire [rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS)+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS):0]  depth_step_x,
  input  wire [rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS)+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS):0]  depth_step_y,
  input  wire [3*(9+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS))-1:0] color_start,   // r, g, b at [c*B +: B]
  input  wire [3*(9+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS))-1:0] color_step_x,
  input  wire [3*(9+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS))-1:0] color_step_y,
  input  `RS_TYPE(rgb_t) flat_rgb,
  // The planes along the left edges: slot j at [j*(Z_REG_BITS + 3 COLOR_REG_BITS)], depth first,
  // then r, g, b (rastersim_widths.vh, record fields 18 and 19).
  input  wire [2*(rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS)+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS)+1+3*(9+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS)))-1:0] left_start,
  input  wire [2*(rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS)+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS)+1+3*(9+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS)))-1:0] left_step,
  // The texture record (rs_texture_record_bits of rastersim_widths.vh; unused without TEXTURE).
  input  wire [rs_texture_record_bits(WIDTH, HEIGHT)-1:0] texture_record,
  output wire [rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS)-1:0] depth,  // X, the plane's output (Np bits)
  output `RS_TYPE(rgb_t) rgb,          // {r, g, b}, u8 each
  output wire triangle_textured,   // the record's texture flag (0 without TEXTURE)
  output wire [3*rs_texture_reg_bits(WIDTH, HEIGHT)-1:0] stq  // the S, T, Q registers at [c*TR +: TR]
);
`include "rastersim_widths.vh"
  `RS_REQUIRE(illegal_z_bits, Z_BITS >= 16 && Z_BITS <= 32, "z_adder: Z_BITS must be 16..32")
  `RS_REQUIRE(illegal_z_guard_bits, Z_GUARD_BITS >= 0 && Z_GUARD_BITS <= 24, "z_adder: Z_GUARD_BITS must be 0 (derived) or 1..24")

  `RS_REQUIRE(illegal_depth_exponent_bits, DEPTH_EXPONENT_BITS >= 0 && DEPTH_EXPONENT_BITS <= 4, "z_adder: DEPTH_EXPONENT_BITS must be 0..4")

  localparam integer F = rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS);
  localparam integer NP = rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS);  // the depth plane's bits
  localparam integer Z_REG_BITS = NP + F + 1;
  localparam integer COLOR_REG_BITS = 9 + F;
  localparam integer SLOT_BITS = Z_REG_BITS + 3 * COLOR_REG_BITS;

  reg [23:0] flat_q;
  always @(posedge clk) if (load) flat_q <= flat_rgb;

  wire [NP-1:0] depth_rounded;  // clamp((V + R) >> F, 0, 2^Np - 1), R = 2^(F-1) (nearest) or 0 (truncate)
  wire [Z_REG_BITS-1:0] depth_value, depth_next;
  plane_register #(.REG_BITS(Z_REG_BITS), .GUARD_BITS(F), .OUT_BITS(NP), .ROUNDING(DEPTH_ROUNDING)) depth_plane (
    .clk(clk), .load(load), .step_x(step_x), .next_row(next_row), .row_enter(row_enter),
    .enter_left(enter_left), .enter_slot(enter_slot), .left_carry(left_carry),
    .start(depth_start), .step_x_in(depth_step_x), .step_y_in(depth_step_y),
    .left_start({left_start[SLOT_BITS +: Z_REG_BITS], left_start[0 +: Z_REG_BITS]}),
    .left_step({left_step[SLOT_BITS +: Z_REG_BITS], left_step[0 +: Z_REG_BITS]}),
    .out(depth_rounded), .value(depth_value), .next_value(depth_next));

  // The plane output X with the triangle's bias B: clamp((V + B + R) >> F, 0, 2^Np - 1).
  wire [NP-1:0] depth_x;
  generate
    if (DEPTH_BIAS != 0) begin : bias
      reg signed [Z_REG_BITS:0] bias_q;  // B + R
      always @(posedge clk) if (load) bias_q <= depth_bias;
      // (V + (B + R)) >> F in Np + 3 bits: the high parts' sum and the carry out of the low F
      // bits' sum, which is registered from the register's next value (its low bits come early
      // in the plane's carry chains), so the output's chain is Np + 3 bits, not Np + F + 3.
      wire [F-1:0] bias_next = load ? depth_bias[F-1:0] : bias_q[F-1:0];
      wire [F:0] low_sum = {1'b0, depth_next[F-1:0]} + {1'b0, bias_next};
      reg low_carry_q;
      always @(posedge clk) low_carry_q <= low_sum[F];
      wire [Z_REG_BITS+1-F:0] rounded = {{2{depth_value[Z_REG_BITS-1]}}, depth_value[Z_REG_BITS-1:F]} +
                                        {bias_q[Z_REG_BITS], bias_q[Z_REG_BITS:F]} +
                                        {{(Z_REG_BITS+1-F){1'b0}}, low_carry_q};  // Np + 3 bits, the top one the sign
      // The clamp by bit tests: below 0 when the sign is set, above 2^Np - 1 when a bit above
      // Np - 1 is.
      wire negative = rounded[NP+2];
      wire above = |rounded[NP+1:NP];
      assign depth_x = negative ? {NP{1'b0}} : above ? {NP{1'b1}} : rounded[NP-1:0];
      /* verilator lint_off UNUSEDSIGNAL */
      wire rounded_unused = ^depth_rounded ^ ^depth_value[F-1:0] ^ ^depth_next[Z_REG_BITS-1:F] ^ ^low_sum[F-1:0];
      /* verilator lint_on UNUSEDSIGNAL */
    end else begin : no_bias
      assign depth_x = depth_rounded;
      /* verilator lint_off UNUSEDSIGNAL */
      wire bias_unused = ^depth_bias ^ ^depth_value ^ ^depth_next;
      /* verilator lint_on UNUSEDSIGNAL */
    end
  endgenerate

  assign depth = depth_x;

  wire [23:0] gouraud_rgb;
  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : color_planes
      // Channel c is r, g, b for c = 0, 1, 2; rgb holds r in [23:16].
      localparam integer AT = Z_REG_BITS + c * COLOR_REG_BITS;  // the channel in a left-edge slot
      /* verilator lint_off UNUSEDSIGNAL */
      wire [COLOR_REG_BITS-1:0] value_unused, next_unused;
      /* verilator lint_on UNUSEDSIGNAL */
      // A colour register is short: its row entry subtracts (ENTRY_AHEAD 0), saving registers.
      plane_register #(.REG_BITS(COLOR_REG_BITS), .GUARD_BITS(F), .OUT_BITS(8), .ROUNDING(COLOR_ROUNDING), .ENTRY_AHEAD(0)) plane (
        .clk(clk), .load(load), .step_x(step_x), .next_row(next_row), .row_enter(row_enter),
        .enter_left(enter_left), .enter_slot(enter_slot), .left_carry(left_carry),
        .start(color_start[c*COLOR_REG_BITS +: COLOR_REG_BITS]), .step_x_in(color_step_x[c*COLOR_REG_BITS +: COLOR_REG_BITS]),
        .step_y_in(color_step_y[c*COLOR_REG_BITS +: COLOR_REG_BITS]),
        .left_start({left_start[SLOT_BITS + AT +: COLOR_REG_BITS], left_start[AT +: COLOR_REG_BITS]}),
        .left_step({left_step[SLOT_BITS + AT +: COLOR_REG_BITS], left_step[AT +: COLOR_REG_BITS]}),
        .out(gouraud_rgb[8*(2-c) +: 8]), .value(value_unused), .next_value(next_unused));
    end
  endgenerate

  assign rgb = cfg_shading == rastersim_pkg::SHADING_GOURAUD ? gouraud_rgb : flat_q;

  localparam integer TR = rs_texture_reg_bits(WIDTH, HEIGHT);
  `RS_REQUIRE(texture_reg_bits_match, TR == 50 + $clog2(2 * (WIDTH + HEIGHT - 1)), "z_adder: texture register width")
  generate
    if (TEXTURE != 0) begin : texture_planes
      reg textured_q;
      always @(posedge clk) if (load) textured_q <= texture_record[0];
      assign triangle_textured = textured_q;
      // Register 3 g + c of the record (g: 0 start, 1 step x, 2 step y, 3 + 2 j slot j's start, 4 + 2 j its step).
      for (c = 0; c < 3; c = c + 1) begin : planes
        /* verilator lint_off UNUSEDSIGNAL */
        wire [7:0] rounded_unused;
        wire [TR-1:0] next_unused;
        /* verilator lint_on UNUSEDSIGNAL */
        plane_register #(.REG_BITS(TR), .GUARD_BITS(F), .OUT_BITS(8)) plane (
          .clk(clk), .load(load), .step_x(step_x), .next_row(next_row), .row_enter(row_enter),
          .enter_left(enter_left), .enter_slot(enter_slot), .left_carry(left_carry),
          .start(texture_record[1 + c*TR +: TR]), .step_x_in(texture_record[1 + (3 + c)*TR +: TR]),
          .step_y_in(texture_record[1 + (6 + c)*TR +: TR]),
          .left_start({texture_record[1 + (15 + c)*TR +: TR], texture_record[1 + (9 + c)*TR +: TR]}),
          .left_step({texture_record[1 + (18 + c)*TR +: TR], texture_record[1 + (12 + c)*TR +: TR]}),
          .out(rounded_unused), .value(stq[c*TR +: TR]), .next_value(next_unused));
      end
    end else begin : no_texture
      /* verilator lint_off UNUSEDSIGNAL */
      wire record_unused = ^texture_record;
      /* verilator lint_on UNUSEDSIGNAL */
      assign triangle_textured = 1'b0;
      assign stq = {3*TR{1'b0}};
    end
  endgenerate
endmodule
