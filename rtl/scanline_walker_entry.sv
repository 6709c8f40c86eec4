// The scanline walker's entry stage (docs/cycle-model.md, "Record FIFO"): from the walker part of a
// setup record, the walker's state at its load (the entry, rs_entry_lsb in rastersim_widths.vh):
// the first row's span and the span DDA stepped to the second row, the left-edge slot the first
// row enters and the slots' carries. Combinational: rastersim_core forms the entry as the record
// is pushed into the record FIFO, whose entry register holds it, so that the walker's load takes
// registers only and the walker computes every later row from its own registers.
`include "rastersim_pkg.sv"
module scanline_walker_entry #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer SUBPIXEL_BITS = 4
) (
  // Fields 0..10 of the record (rs_rec_lsb), edge k at [k*B +: B]: the walker part.
  input  wire [rs_rec_walker_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] record,
  output wire [rs_entry_lsb(20, WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] entry
);
`include "rastersim_widths.vh"
  `RS_REQUIRE(illegal_width, WIDTH >= 1 && WIDTH <= 4096, "scanline_walker_entry: WIDTH must be 1..4096")
  `RS_REQUIRE(illegal_height, HEIGHT >= 1 && HEIGHT <= 4096, "scanline_walker_entry: HEIGHT must be 1..4096")
  `RS_REQUIRE(illegal_subpixel_bits, SUBPIXEL_BITS >= 1 && SUBPIXEL_BITS <= 8, "scanline_walker_entry: SUBPIXEL_BITS must be 1..8")

  localparam integer S = SUBPIXEL_BITS;
  localparam integer EDGE_BITS = rs_edge_bits(WIDTH, HEIGHT, S);
  localparam integer EDGE_STEP_X_BITS = rs_edge_step_x_bits(HEIGHT, S);
  localparam integer EDGE_STEP_Y_BITS = rs_edge_step_y_bits(WIDTH, S);
  localparam integer SPAN_REM_BITS = rs_span_rem_bits(HEIGHT, S);
  localparam integer REM_BITS = SPAN_REM_BITS + 1;
  localparam integer X_BITS = rs_ubits32(WIDTH - 1);
  localparam integer Y_BITS = rs_ubits32(HEIGHT - 1);
  localparam [EDGE_BITS-1:0] CARRY = {{(EDGE_BITS-1){1'b0}}, 1'b1};

  // The record's fields at their places (constants, so that the simulator does not evaluate the
  // sums at run time).
  localparam integer LSB_X0 = rs_rec_lsb(RS_REC_X0, WIDTH, HEIGHT, S, 0, 0);
  localparam integer LSB_X1 = rs_rec_lsb(RS_REC_X1, WIDTH, HEIGHT, S, 0, 0);
  localparam integer LSB_Y0 = rs_rec_lsb(RS_REC_Y0, WIDTH, HEIGHT, S, 0, 0);
  localparam integer LSB_Y1 = rs_rec_lsb(RS_REC_Y1, WIDTH, HEIGHT, S, 0, 0);
  localparam integer LSB_EDGE_START = rs_rec_lsb(RS_REC_EDGE_START, WIDTH, HEIGHT, S, 0, 0);
  localparam integer LSB_EDGE_STEP_X = rs_rec_lsb(RS_REC_EDGE_STEP_X, WIDTH, HEIGHT, S, 0, 0);
  localparam integer LSB_EDGE_STEP_Y = rs_rec_lsb(RS_REC_EDGE_STEP_Y, WIDTH, HEIGHT, S, 0, 0);
  localparam integer LSB_SPAN_QUOT = rs_rec_lsb(RS_REC_SPAN_QUOT, WIDTH, HEIGHT, S, 0, 0);
  localparam integer LSB_SPAN_REM = rs_rec_lsb(RS_REC_SPAN_REM, WIDTH, HEIGHT, S, 0, 0);
  localparam integer LSB_SPAN_STEP_QUOT = rs_rec_lsb(RS_REC_SPAN_STEP_QUOT, WIDTH, HEIGHT, S, 0, 0);
  localparam integer LSB_SPAN_STEP_REM = rs_rec_lsb(RS_REC_SPAN_STEP_REM, WIDTH, HEIGHT, S, 0, 0);
  wire [X_BITS-1:0] x0 = record[LSB_X0 +: X_BITS];
  wire [X_BITS-1:0] x1 = record[LSB_X1 +: X_BITS];
  wire [3*EDGE_BITS-1:0] edge_start = record[LSB_EDGE_START +: 3*EDGE_BITS];  // s.2S
  wire [3*EDGE_STEP_X_BITS-1:0] edge_step_x = record[LSB_EDGE_STEP_X +: 3*EDGE_STEP_X_BITS];  // s.2S
  wire [3*EDGE_STEP_Y_BITS-1:0] edge_step_y = record[LSB_EDGE_STEP_Y +: 3*EDGE_STEP_Y_BITS];  // s.2S
  wire [3*EDGE_BITS-1:0] span_quot = record[LSB_SPAN_QUOT +: 3*EDGE_BITS];
  wire [3*SPAN_REM_BITS-1:0] span_rem = record[LSB_SPAN_REM +: 3*SPAN_REM_BITS];
  wire [3*EDGE_STEP_Y_BITS-1:0] span_step_quot = record[LSB_SPAN_STEP_QUOT +: 3*EDGE_STEP_Y_BITS];
  wire [3*SPAN_REM_BITS-1:0] span_step_rem = record[LSB_SPAN_STEP_REM +: 3*SPAN_REM_BITS];

  // a + b + c + plus[1] + plus[0] modulo 2^n (each plus bit adds one), as one carry-save level and
  // one adder; `sum3_rem` on REM_BITS, `sum3_offset` on X_BITS + 2.
  function automatic [REM_BITS-1:0] sum3_rem(input [REM_BITS-1:0] a, input [REM_BITS-1:0] b,
                                             input [REM_BITS-1:0] c, input [1:0] plus);
    reg [REM_BITS-1:0] save_carry;
    begin
      save_carry = ((a & b) | (a & c) | (b & c)) << 1;
      sum3_rem = (a ^ b ^ c) + (save_carry | {{(REM_BITS-1){1'b0}}, plus[1]}) + {{(REM_BITS-1){1'b0}}, plus[0]};
    end
  endfunction
  localparam integer OFFSET_SUM_BITS = X_BITS + 2;
  function automatic [OFFSET_SUM_BITS-1:0] sum3_offset(input [OFFSET_SUM_BITS-1:0] a, input [OFFSET_SUM_BITS-1:0] b,
                                                      input [OFFSET_SUM_BITS-1:0] c, input [1:0] plus);
    reg [OFFSET_SUM_BITS-1:0] save_carry;
    begin
      save_carry = ((a & b) | (a & c) | (b & c)) << 1;
      sum3_offset = (a ^ b ^ c) + (save_carry | {{(OFFSET_SUM_BITS-1){1'b0}}, plus[1]}) + {{(OFFSET_SUM_BITS-1){1'b0}}, plus[0]};
    end
  endfunction

  // Per edge: its side, the first DDA step (the record's remainders are in [0, d), the DDA keeps
  // them less d), the second row's values, and the compares with the box's last offset formed from
  // x1, x0 and the quotient (x1 - x0 + low and x1 - x0 - low, neither waiting for the other).
  wire [2:0] left, right, dda_carry, lo_fits_last, hi_le_last, edge_negative;
  wire [3*REM_BITS-1:0] step_rem_less, rem_less;
  wire [3*EDGE_BITS-1:0] edge_row, quot;
  wire [3*EDGE_STEP_Y_BITS-1:0] step_y = edge_step_y;
  wire [OFFSET_SUM_BITS-1:0] x1_wide = {2'b00, x1};
  wire [OFFSET_SUM_BITS-1:0] minus_x0_less_1 = ~{2'b00, x0};  // -x0 - 1
  genvar g;
  generate
    for (g = 0; g < 3; g = g + 1) begin : edges
      wire [EDGE_BITS-1:0] start_k = edge_start[g*EDGE_BITS +: EDGE_BITS];
      wire [EDGE_BITS-1:0] quot_k = span_quot[g*EDGE_BITS +: EDGE_BITS];
      wire [EDGE_BITS-1:0] step_y_k = {{(EDGE_BITS-EDGE_STEP_Y_BITS){edge_step_y[g*EDGE_STEP_Y_BITS + EDGE_STEP_Y_BITS - 1]}}, edge_step_y[g*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS]};
      wire [EDGE_BITS-1:0] step_quot_k = {{(EDGE_BITS-EDGE_STEP_Y_BITS){span_step_quot[g*EDGE_STEP_Y_BITS + EDGE_STEP_Y_BITS - 1]}}, span_step_quot[g*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS]};
      wire step_x_negative = edge_step_x[g*EDGE_STEP_X_BITS + EDGE_STEP_X_BITS - 1];
      // Left edges have step_x > 0, right ones < 0.
      assign right[g] = step_x_negative;
      assign left[g] = !step_x_negative && |edge_step_x[g*EDGE_STEP_X_BITS +: EDGE_STEP_X_BITS];
      assign edge_negative[g] = start_k[EDGE_BITS-1];
      // The first step's carry is rem + step_rem - d >= 0 (the sum lies in [-d, d)), and the next
      // remainder less d is that sum, or the sum less d again on a carry: -d is step_x when
      // step_x < 0, else ~step_x + 1, -2d twice that (modulo 2^REM_BITS).
      wire [REM_BITS-1:0] rem = {1'b0, span_rem[g*SPAN_REM_BITS +: SPAN_REM_BITS]};
      wire [REM_BITS-1:0] step_rem = {1'b0, span_step_rem[g*SPAN_REM_BITS +: SPAN_REM_BITS]};
      wire [REM_BITS-1:0] step_x_low = edge_step_x[g*EDGE_STEP_X_BITS +: REM_BITS];
      wire [REM_BITS-1:0] minus_d_less = step_x_negative ? step_x_low : ~step_x_low;  // -d, less 1 when step_x > 0
      wire [REM_BITS-1:0] sum_less_d = sum3_rem(rem, step_rem, minus_d_less, {1'b0, !step_x_negative});
      wire [REM_BITS-1:0] sum_less_2d = sum3_rem(rem, step_rem, minus_d_less << 1, {2{!step_x_negative}});
      assign dda_carry[g] = !sum_less_d[REM_BITS-1];
      assign rem_less[g*REM_BITS +: REM_BITS] = dda_carry[g] ? sum_less_2d : sum_less_d;
      assign step_rem_less[g*REM_BITS +: REM_BITS] = step_x_negative ? step_rem + step_x_low : step_rem - step_x_low;
      // A horizontal edge's quotient is the record's 0 throughout (span_bounds relies on it).
      // Both sums side by side, the carry picks one (no carry chain after the remainder's).
      wire [EDGE_BITS-1:0] quot_sum = quot_k + step_quot_k;
      wire [EDGE_BITS-1:0] quot_carried = quot_k + step_quot_k + CARRY;
      assign quot[g*EDGE_BITS +: EDGE_BITS] = !(left[g] || right[g]) ? quot_k : dda_carry[g] ? quot_carried : quot_sum;
      assign edge_row[g*EDGE_BITS +: EDGE_BITS] = start_k + step_y_k;
      // The quotient against the last offset: its lower bound fits under it (x1 - x0 + low >= 0),
      // its upper bound is at most it (x1 - x0 - low >= 0, with low's top bit 0 for a small upper
      // bound).
      wire [X_BITS:0] low = quot_k[X_BITS:0];
      wire [OFFSET_SUM_BITS-1:0] lo_sum = sum3_offset(x1_wide, minus_x0_less_1, {low[X_BITS], low}, 2'b01);
      wire [OFFSET_SUM_BITS-1:0] hi_sum = sum3_offset(x1_wide, minus_x0_less_1, ~{2'b00, low[X_BITS-1:0]}, 2'b11);
      assign lo_fits_last[g] = !lo_sum[OFFSET_SUM_BITS-1];
      assign hi_le_last[g] = !hi_sum[OFFSET_SUM_BITS-1];
    end
  endgenerate

  wire [X_BITS-1:0] span_start, span_end;
  wire nonempty, lo_from_x0, enter_slot;
  span_bounds #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(S)) first_row (
    .quot(span_quot), .left(left), .right(right), .edge_negative(edge_negative), .x0(x0), .x1(x1),
    .lo_fits_last(lo_fits_last), .hi_le_last(hi_le_last), .span_start(span_start), .span_end(span_end),
    .nonempty(nonempty), .lo_from_x0(lo_from_x0), .enter_slot(enter_slot));

  // Each left-edge slot's carry (slot j: the j-th left edge in edge order).
  wire [1:0] left_carry = {left[0] && left[1] ? dda_carry[1] : dda_carry[2],
                           left[0] ? dda_carry[0] : left[1] ? dda_carry[1] : dda_carry[2]};

  assign entry = {left_carry, enter_slot, !lo_from_x0, !nonempty, span_end, span_start, rem_less, quot,
                  edge_row, step_rem_less, span_step_rem, span_step_quot, step_y, right, left, x1 - x0,
                  record[LSB_Y1 +: Y_BITS], record[LSB_Y0 +: Y_BITS], x1, x0};
endmodule
