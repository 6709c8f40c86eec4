// The bias unit (model/z_adder.h DepthOutput::bias; docs/arithmetic.md section 6): each drawn
// triangle's depth bias B = clamp(c 2^F + floor(f max(|step_x|, |step_y|) / 16), -2^(Np+F),
// 2^(Np+F)) from its record's depth steps (s(Np+1).F as the plane register holds them), formed
// beside the record FIFO so that the Z adder's load takes a register. It gives B + R, R the
// rounding's half (2^(F-1) with DEPTH_ROUNDING nearest, else 0), so that the Z adder's sum
// V + B + R has two operands. Seven stages, one a cycle, the record's setup_done the first
// (docs/cycle-model.md, "Depth bias"): the steps' magnitudes, the larger one, three adder levels
// of the product with the 8-bit factor f, the constant, the clamp, which writes B + R into a FIFO
// of its own in record order. With c = 0 and f = 0 (a build with the bias running an unbiased
// profile) B = 0, and R goes into the FIFO with the record, in setup_done. A record takes one
// entry, from then to the walker's load, as in the record FIFO: the core's record credits leave
// it room.
`include "rastersim_pkg.sv"
module depth_bias #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer Z_BITS = 24,
  parameter integer Z_GUARD_BITS = 0,
  parameter integer DEPTH_EXPONENT_BITS = 0,
  parameter integer DEPTH_ROUNDING = 0,  // rastersim_pkg::ROUNDING_*: R = 2^(F-1) (nearest) or 0
  parameter integer MAX_SETUP_FIFO_DEPTH = 8
) (
  input  wire clk,
  input  wire rst,  // clears the stages' valid bits and the FIFO
  input  wire [rastersim_pkg::DEPTH_BIAS_CONSTANT_BITS-1:0] cfg_depth_bias_constant,  // c, two's complement, |c| < 2^Np
  input  wire [rastersim_pkg::DEPTH_BIAS_SLOPE_BITS-1:0] cfg_depth_bias_slope,      // f, s4.4
  // The depth steps and B are Np + F + 1 and Np + F + 2 bits wide, Np and F written out as
  // rastersim_widths.vh's rs_depth_plane_bits and rs_guard_bits give them: a file before
  // rastersim_core.sv in rtl/rastersim.f that includes the widths header upsets Verilator 5.006's
  // lint of the core.
  input  wire in_valid,  // a drawn triangle's record, in its setup_done
  input  wire [(DEPTH_EXPONENT_BITS == 0 ? Z_BITS : Z_BITS - DEPTH_EXPONENT_BITS + (1 << DEPTH_EXPONENT_BITS) - 1) +
               (Z_GUARD_BITS > 0 ? Z_GUARD_BITS : $clog2(2 * (WIDTH + HEIGHT - 1))):0] in_step_x,
  input  wire [(DEPTH_EXPONENT_BITS == 0 ? Z_BITS : Z_BITS - DEPTH_EXPONENT_BITS + (1 << DEPTH_EXPONENT_BITS) - 1) +
               (Z_GUARD_BITS > 0 ? Z_GUARD_BITS : $clog2(2 * (WIDTH + HEIGHT - 1))):0] in_step_y,
  input  wire pop,      // the walker loads the record at the record FIFO's head
  output wire ready,    // the head record's B is in the FIFO
  // B + R, in [-2^(Np+F), 2^(Np+F) + 2^(F-1)]: the plane register's width and one bit more.
  output wire [(DEPTH_EXPONENT_BITS == 0 ? Z_BITS : Z_BITS - DEPTH_EXPONENT_BITS + (1 << DEPTH_EXPONENT_BITS) - 1) +
               (Z_GUARD_BITS > 0 ? Z_GUARD_BITS : $clog2(2 * (WIDTH + HEIGHT - 1))) + 1:0] bias
);
  localparam integer F = Z_GUARD_BITS > 0 ? Z_GUARD_BITS : $clog2(2 * (WIDTH + HEIGHT - 1));
  localparam integer NP = DEPTH_EXPONENT_BITS == 0 ? Z_BITS : Z_BITS - DEPTH_EXPONENT_BITS + (1 << DEPTH_EXPONENT_BITS) - 1;
  localparam integer Z_REG_BITS = NP + F + 1;
  localparam integer BIAS_BITS = Z_REG_BITS + 1;
  localparam integer STAGES = 7;  // the stages below
`ifdef __ICARUS__
  initial if (STAGES != rastersim_pkg::DEPTH_BIAS_STAGES || MAX_SETUP_FIFO_DEPTH < 1) $fatal(1, "depth_bias: stage count or FIFO depth");
`else
  if (STAGES != rastersim_pkg::DEPTH_BIAS_STAGES || MAX_SETUP_FIFO_DEPTH < 1) begin : illegal_parameters
    $error("depth_bias: stage count or FIFO depth");
  end
`endif
  // The sums' width: |f slope| <= 2^(Np+F+7), and the 33-bit c shifted by F.
  localparam integer PB = Z_REG_BITS + 10 > 34 + F ? Z_REG_BITS + 10 : 34 + F;

  wire biased = |cfg_depth_bias_constant || |cfg_depth_bias_slope;

  // Stage 1 (setup_done): the steps' magnitudes (|-2^(Np+F)| fits the unsigned register).
  reg [Z_REG_BITS-1:0] magnitude_x_q, magnitude_y_q;
  reg [STAGES-2:0] valid_q;  // valid_q[k]: stage k + 2 has a record
  always @(posedge clk) begin
    magnitude_x_q <= in_step_x[Z_REG_BITS-1] ? -in_step_x : in_step_x;
    magnitude_y_q <= in_step_y[Z_REG_BITS-1] ? -in_step_y : in_step_y;
  end

  // Stage 2: the slope, the larger magnitude.
  reg [Z_REG_BITS-1:0] slope_q;
  always @(posedge clk) slope_q <= magnitude_x_q > magnitude_y_q ? magnitude_x_q : magnitude_y_q;

  // Stage 3: f slope as four sums of two of its eight partial products (bit 7 of the
  // two's-complement f weighs -2^7).
  wire signed [PB-1:0] slope_wide = $signed({{(PB-Z_REG_BITS){1'b0}}, slope_q});
  wire signed [PB-1:0] partial [0:7];
  genvar i;
  generate
    for (i = 0; i < 8; i = i + 1) begin : partials
      if (i < 7) begin : positive
        assign partial[i] = cfg_depth_bias_slope[i] ? slope_wide <<< i : {PB{1'b0}};
      end else begin : negative
        assign partial[i] = cfg_depth_bias_slope[i] ? -(slope_wide <<< i) : {PB{1'b0}};
      end
    end
  endgenerate
  reg signed [PB-1:0] pair_q [0:3];
  integer k;
  always @(posedge clk)
    for (k = 0; k < 4; k = k + 1) pair_q[k] <= partial[2*k] + partial[2*k+1];

  // Stage 4 and 5: the sums of the pairs, then the product.
  reg signed [PB-1:0] half_q [0:1];
  reg signed [PB-1:0] product_q;
  always @(posedge clk) begin
    half_q[0] <= pair_q[0] + pair_q[1];
    half_q[1] <= pair_q[2] + pair_q[3];
    product_q <= half_q[0] + half_q[1];
  end

  // Stage 6: u = c 2^F + floor(f slope / 16), and beside it u + R from c 2^F + R (a register of the
  // static configuration, settled long before the frame's first record).
  wire signed [PB-1:0] constant_part = $signed({{(PB-33-F){cfg_depth_bias_constant[32]}}, cfg_depth_bias_constant, {F{1'b0}}});
  wire [BIAS_BITS-1:0] rounding = {{(BIAS_BITS-F){1'b0}}, 1'(DEPTH_ROUNDING == rastersim_pkg::ROUNDING_NEAREST), {(F-1){1'b0}}};
  // (u + R is used only where it is not clamped, so its low BIAS_BITS bits, modulo 2^BIAS_BITS.)
  wire signed [PB-1:0] product_floor = product_q >>> 4;
  reg [BIAS_BITS-1:0] constant_rounded_q;
  always @(posedge clk) constant_rounded_q <= constant_part[BIAS_BITS-1:0] + rounding;
  reg signed [PB-1:0] unclamped_q;
  reg [BIAS_BITS-1:0] unclamped_rounded_q;
  always @(posedge clk) unclamped_q <= constant_part + product_floor;
  always @(posedge clk) unclamped_rounded_q <= constant_rounded_q + product_floor[BIAS_BITS-1:0];

  // Stage 7: the clamp to [-2^(Np+F), 2^(Np+F)], plus R, into the FIFO. With u = h 2^(Np+F) + l,
  // h the bits from Np + F up (signed) and 0 <= l < 2^(Np+F): u > 2^(Np+F) when h >= 2, or h = 1
  // and l > 0; u < -2^(Np+F) when h <= -2. Bit tests, no comparator; u + R unclamped is there.
  localparam integer LOW_BITS = Z_REG_BITS - 1;  // Np + F
  wire [PB-LOW_BITS-1:0] high = unclamped_q[PB-1:LOW_BITS];
  wire high_negative = high[PB-LOW_BITS-1];
  wire high_over_one = !high_negative && |high[PB-LOW_BITS-2:1];                    // h >= 2
  wire high_one = high == {{(PB-LOW_BITS-1){1'b0}}, 1'b1};                          // h = 1
  wire high_under_minus_one = high_negative && !(&high[PB-LOW_BITS-2:0]);          // h <= -2 (h != -1)
  wire over = high_over_one || (high_one && |unclamped_q[LOW_BITS-1:0]);
  wire [BIAS_BITS-1:0] limit = {2'b01, {LOW_BITS{1'b0}}};  // 2^(Np+F)
  wire [BIAS_BITS-1:0] clamped = over ? limit + rounding : high_under_minus_one ? rounding - limit
                                                         : unclamped_rounded_q;

  always @(posedge clk) begin
    if (rst) valid_q <= {(STAGES-1){1'b0}};
    else valid_q <= {valid_q[STAGES-3:0], in_valid && biased};
  end

  // Unbiased, R goes in with the record; biased, B + R leaves stage 7 six cycles after the record.
  wire push = biased ? valid_q[STAGES-2] : in_valid;
  wire [BIAS_BITS-1:0] push_bias = biased ? clamped : rounding;
  wire empty;
  setup_fifo #(.RECORD_BITS(BIAS_BITS), .ENTRIES(MAX_SETUP_FIFO_DEPTH)) bias_fifo (
    .clk(clk), .rst(rst), .push(push), .push_data(push_bias), .pop(pop), .empty(empty), .head(bias));
  assign ready = !empty;
`include "rastersim_assert.vh"
  `RS_ASSERT(pop_only_when_ready, !pop || !empty)

endmodule
