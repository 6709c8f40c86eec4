// The texture unit's perspective divide (model/texture_divide.h; docs/arithmetic.md section 5): a textured
// fragment's u = clamp(floor(floor(s / 2^D) 2^20 / floor(q / 2^D)), -2^27, 2^27 - 1) and v from t
// likewise, s8.20, from its S, T, Q plane registers (s9.(P+Ft), q > 0; D = Ft - min(Ft, 4)).
// Pipelined, one fragment per clock, no stall: inputs present in a cycle are in the output
// registers 29 rising edges later (docs/cycle-model.md, "Texture unit": taken in t, u and v
// registered at the end of t + 29). Stage 0 takes the operands (a negative one inverted) and the
// clamp tests, stages 1..27 one quotient bit each (restoring, on the shifted q's P + 1 + min(Ft, 4)
// bits; q's pipeline serves u and v), stage 28 the sign and the clamp.
`include "rastersim_pkg.sv"
module texture_divide #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480
) (
  input  wire clk,
  input  wire rst,       // clears the valid bits (the data registers need no reset)
  input  wire in_valid,
  // The registers' width, rs_texture_reg_bits (P + Ft + 9) written with $clog2: a port list that
  // calls the widths header's functions before its include upsets Verilator 5.006's lint of the
  // other modules (rtl/rastersim.f).
  input  wire [rs_texture_reg_bits(WIDTH, HEIGHT)-1:0] in_s,  // S register, two's complement
  input  wire [rs_texture_reg_bits(WIDTH, HEIGHT)-1:0] in_t,  // T register
  input  wire [rs_texture_reg_bits(WIDTH, HEIGHT)-1:0] in_q,  // Q register, > 0 at a covered pixel
  output wire out_valid,
  output wire [rastersim_pkg::UV_BITS-1:0] out_u,  // s8.20
  output wire [rastersim_pkg::UV_BITS-1:0] out_v
);
`include "rastersim_widths.vh"
  `RS_REQUIRE(illegal_width, WIDTH >= 1 && WIDTH <= 4096, "texture_divide: WIDTH must be 1..4096")
  `RS_REQUIRE(illegal_height, HEIGHT >= 1 && HEIGHT <= 4096, "texture_divide: HEIGHT must be 1..4096")

  localparam integer REG_BITS = 50 + $clog2(2 * (WIDTH + HEIGHT - 1));
  `RS_REQUIRE(reg_bits_match, REG_BITS == rs_texture_reg_bits(WIDTH, HEIGHT), "texture_divide: register width")
  // The registers' low DIVIDE_SHIFT bits are dropped (the model's Widths::texture_divide_shift):
  // the divide keeps min(Ft, 4) of their Ft guard bits.
  localparam integer DIVIDE_SHIFT = rs_texture_divide_shift(WIDTH, HEIGHT);
  localparam integer OPERAND_BITS = REG_BITS - DIVIDE_SHIFT;
  // At a textured fragment's pixel 0 < q <= 2^(P+Ft) (docs/arithmetic.md section 5: the Q plane
  // lies below 2^Ft times its vertex values, all at most 2^P; texture_unit asserts it), so the
  // shifted q has DIVISOR_BITS = P + min(Ft, 4) + 1 bits, 8 fewer than its operand, and a partial
  // remainder (< q) one bit less. An untextured fragment's quotients are not used.
  localparam integer DIVISOR_BITS = OPERAND_BITS - 8;
  localparam integer REMAINDER_BITS = DIVISOR_BITS - 1;
  localparam integer QUOTIENT_BITS = rastersim_pkg::UV_BITS - 1;           // 27: |u| < 2^27 unless clamped
  localparam integer SHIFT = QUOTIENT_BITS - rastersim_pkg::UV_FRAC_BITS;  // 7 dividend bits below the first remainder
  localparam integer STAGES = QUOTIENT_BITS + 2;               // 29
  `RS_REQUIRE(stages_match_model, STAGES == RS_TEXTURE_DIVIDE_STAGES, "texture_divide: stage count")

  // Per coordinate (0: u, 1: v) and stage: the partial remainder, the dividend bits still to shift
  // in (the operand's low 7 bits, then 20 fill bits), the quotient so far, the sign and the clamp
  // test.
  reg [REMAINDER_BITS-1:0] remainder_q [0:1][0:QUOTIENT_BITS];
  reg [QUOTIENT_BITS-1:0] pending_q [0:1][0:QUOTIENT_BITS];
  reg [QUOTIENT_BITS-1:0] quotient_q [0:1][0:QUOTIENT_BITS];
  reg negative_q [0:1][0:QUOTIENT_BITS];
  reg clamp_q [0:1][0:QUOTIENT_BITS];
  // -q modulo 2^(DIVISOR_BITS+1), its top bit (always 1) not kept: a step then adds, and no
  // inverter stands between the pipeline's register and the step's carry chain.
  reg [DIVISOR_BITS-1:0] negated_divisor_q [0:QUOTIENT_BITS];
  reg valid_q [0:QUOTIENT_BITS];
  reg [27:0] result_q [0:1];
  reg result_valid_q;

  // The operands, floor(V / 2^DIVIDE_SHIFT) (an arithmetic shift).
  /* verilator lint_off UNUSEDSIGNAL */
  wire [REG_BITS-1:0] s_register = in_s, t_register = in_t;
  wire [REG_BITS-1:0] q_register = in_q;  // its top 8 bits are 0 at a covered pixel
  /* verilator lint_on UNUSEDSIGNAL */
  wire [OPERAND_BITS-1:0] dividend [0:1];
  assign dividend[0] = s_register[REG_BITS-1:DIVIDE_SHIFT];
  assign dividend[1] = t_register[REG_BITS-1:DIVIDE_SHIFT];
  wire [DIVISOR_BITS-1:0] q = q_register[DIVIDE_SHIFT +: DIVISOR_BITS];

  // Stage 0. A negative dividend d is divided as ~d = -d - 1 (its 20 fraction bits ones), the
  // quotient inverted at the end: floor(d 2^20 / q) = ~floor(~(d 2^20) / q). No negation, and the
  // clamp test is the same for both signs.
  genvar c;
  generate
    for (c = 0; c < 2; c = c + 1) begin : coordinate
      wire negative = dividend[c][OPERAND_BITS-1];
      /* verilator lint_off UNUSEDSIGNAL */
      wire [OPERAND_BITS-1:0] operand = negative ? ~dividend[c] : dividend[c];  // >= 0: the top bit is 0
      /* verilator lint_on UNUSEDSIGNAL */
      // The quotient reaches 2^27 (u clamps: to 2^27 - 1, or to -2^27 below it) when
      // operand 2^20 (+ 2^20 - 1) >= q 2^27, that is when operand >> 7 >= q.
      wire clamp = operand[OPERAND_BITS-2:SHIFT] >= q;
      always @(posedge clk) begin
        // Unless the quotient clamps, operand >> 7 < q fits the remainder.
        remainder_q[c][0] <= operand[SHIFT +: REMAINDER_BITS];
        // The fill is don't-care when the quotient clamps: clearing it there keeps the fill bits
        // from being a plain delay of the sign, which synthesis would share across the stages.
        pending_q[c][0] <= {operand[SHIFT-1:0], {rastersim_pkg::UV_FRAC_BITS{negative && !clamp}}};
        quotient_q[c][0] <= {QUOTIENT_BITS{1'b0}};
        negative_q[c][0] <= negative;
        clamp_q[c][0] <= clamp;
      end
    end
  endgenerate
  always @(posedge clk) begin
    negated_divisor_q[0] <= -q;
    valid_q[0] <= in_valid && !rst;
  end

  // Stages 1..27: one restoring step each, most significant quotient bit first.
  genvar k;
  generate
    for (k = 1; k <= QUOTIENT_BITS; k = k + 1) begin : step
      for (c = 0; c < 2; c = c + 1) begin : coordinate
        wire [DIVISOR_BITS-1:0] doubled = {remainder_q[c][k-1], pending_q[c][k-1][QUOTIENT_BITS-1]};
        wire [DIVISOR_BITS:0] difference = {1'b0, doubled} + {1'b1, negated_divisor_q[k-1]};  // doubled - q
        wire fits = !difference[DIVISOR_BITS];  // doubled >= q
        always @(posedge clk) begin
          remainder_q[c][k] <= fits ? difference[REMAINDER_BITS-1:0] : doubled[REMAINDER_BITS-1:0];
          pending_q[c][k] <= {pending_q[c][k-1][QUOTIENT_BITS-2:0], 1'b0};
          quotient_q[c][k] <= {quotient_q[c][k-1][QUOTIENT_BITS-2:0], fits};
          negative_q[c][k] <= negative_q[c][k-1];
          clamp_q[c][k] <= clamp_q[c][k-1];
        end
      end
      always @(posedge clk) begin
        negated_divisor_q[k] <= negated_divisor_q[k-1];
        valid_q[k] <= valid_q[k-1] && !rst;
      end
    end
  endgenerate

  // Stage 28: the quotient, inverted for a negative dividend; the clamp.
  generate
    for (c = 0; c < 2; c = c + 1) begin : finish
      wire [27:0] magnitude = {1'b0, quotient_q[c][QUOTIENT_BITS]};
      wire [27:0] limit = negative_q[c][QUOTIENT_BITS] ? 28'h8000000 : 28'h7FFFFFF;
      always @(posedge clk)
        result_q[c] <= clamp_q[c][QUOTIENT_BITS] ? limit : negative_q[c][QUOTIENT_BITS] ? ~magnitude : magnitude;
      /* verilator lint_off UNUSEDSIGNAL */
      wire remainder_unused = ^remainder_q[c][QUOTIENT_BITS];
      /* verilator lint_on UNUSEDSIGNAL */
    end
  endgenerate
  always @(posedge clk) result_valid_q <= valid_q[QUOTIENT_BITS] && !rst;

  assign out_valid = result_valid_q;
  assign out_u = result_q[0];
  assign out_v = result_q[1];
endmodule
