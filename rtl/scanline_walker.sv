// Counter-driven scanline walker (model/scanline_walker.h): x and y counters step over the
// triangle's bounding box, edge functions are updated by additions only, one candidate per clock.
// cfg_traversal selects the traversal at run time (both emit the same fragments in the same order):
//  0 bbox: every bounding-box pixel, row-major; the counters wrap to the next row in the same cycle.
//    A pixel is covered when it lies in its row's span (below), the same DDA and bounds as span
//    traversal: no edge value is stepped per pixel.
//  1 span: one cycle per covered pixel, one for a row with none. A row's span bounds come from the
//    DDA registers (quotient and remainder of each edge by |step_x|, additions only) in the cycle
//    before the row: the first row's from the record in the load cycle, each next row's in the
//    previous row's last cycle, when the DDA registers step on and the plane registers move to
//    the span start (x0, or the bounding left edge's, by its left-edge slot). So the DDA registers
//    always hold the row after the current one.
// A covered candidate is presented on frag_*; the walker holds it until frag_ready.
// Cycles (docs/cycle-model.md): the record is taken in walker_load (in_valid & in_ready), which is
// the cycle of the previous triangle's last candidate when the record is there by then; the first
// candidate follows in walker_load + 1; `last` marks walker_end.
module scanline_walker #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer SUBPIXEL_BITS = 4
) (
  input  wire clk,
  input  wire rst,
  input  wire cfg_traversal,  // RS_TRAVERSAL_* (rastersim_widths.vh)
  // Setup record (triangle_setup out_record).
  input  wire in_valid,
  output wire in_ready,
  // Fields 0..10 of the record (rs_rec_lsb), edge k at [k*B +: B]: the walker part.
  input  wire [rs_rec_walker_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] in_record,
  // Plane register control (z_adder), in lockstep with the counters.
  output wire adder_load,       // take the setup planes (LOAD cycle)
  output wire adder_step_x,     // next pixel of the row
  output wire adder_next_row,   // bbox: wrap to the next row
  output wire adder_row_enter,  // span, next row: row += step_y; value = row or the entered slot's
  output wire adder_enter_left, // load, row_enter: the span starts at a left edge (else at x0)
  output wire adder_enter_slot, // that edge's left-edge slot: the number of left edges before it
  output wire [1:0] adder_left_carry,  // each slot's DDA carry into the row after the one entered
  // Fragment to the z-buffer.
  output wire frag_valid,
  input  wire frag_ready,
  output reg  [rs_ubits32(WIDTH - 1)-1:0]  frag_x,
  output reg  [rs_ubits32(HEIGHT - 1)-1:0] frag_y,
  // Activity, for the cycle counters: busy = a candidate or empty row that moves on, or a load;
  // candidate = a bbox candidate or span pixel that moves on (not a stall); last = walker_end.
  output wire busy,
  output wire candidate,
  output wire last
);
`include "rastersim_widths.vh"
  `RS_REQUIRE(illegal_width, WIDTH >= 1 && WIDTH <= 4096, "scanline_walker: WIDTH must be 1..4096")
  `RS_REQUIRE(illegal_height, HEIGHT >= 1 && HEIGHT <= 4096, "scanline_walker: HEIGHT must be 1..4096")
  `RS_REQUIRE(illegal_subpixel_bits, SUBPIXEL_BITS >= 1 && SUBPIXEL_BITS <= 8, "scanline_walker: SUBPIXEL_BITS must be 1..8")

  localparam integer S = SUBPIXEL_BITS;
  localparam integer EDGE_BITS = rs_edge_bits(WIDTH, HEIGHT, S);
  localparam integer EDGE_STEP_X_BITS = rs_edge_step_x_bits(HEIGHT, S);
  localparam integer EDGE_STEP_Y_BITS = rs_edge_step_y_bits(WIDTH, S);
  localparam integer SPAN_REM_BITS = rs_span_rem_bits(HEIGHT, S);
  localparam integer REM_BITS = SPAN_REM_BITS + 1;
  localparam integer X_BITS = rs_ubits32(WIDTH - 1);
  localparam integer Y_BITS = rs_ubits32(HEIGHT - 1);
  localparam [EDGE_BITS-1:0] CARRY = {{(EDGE_BITS-1){1'b0}}, 1'b1};

  // The record's fields at their places (rastersim_widths.vh).
  // Constants, so that the simulator does not evaluate the sums at run time.
  localparam integer LSB_X0 = rs_rec_lsb(RS_REC_X0, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0);
  localparam integer LSB_X1 = rs_rec_lsb(RS_REC_X1, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0);
  localparam integer LSB_Y0 = rs_rec_lsb(RS_REC_Y0, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0);
  localparam integer LSB_Y1 = rs_rec_lsb(RS_REC_Y1, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0);
  localparam integer LSB_EDGE_START = rs_rec_lsb(RS_REC_EDGE_START, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0);
  localparam integer LSB_EDGE_STEP_X = rs_rec_lsb(RS_REC_EDGE_STEP_X, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0);
  localparam integer LSB_EDGE_STEP_Y = rs_rec_lsb(RS_REC_EDGE_STEP_Y, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0);
  localparam integer LSB_SPAN_QUOT = rs_rec_lsb(RS_REC_SPAN_QUOT, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0);
  localparam integer LSB_SPAN_REM = rs_rec_lsb(RS_REC_SPAN_REM, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0);
  localparam integer LSB_SPAN_STEP_QUOT = rs_rec_lsb(RS_REC_SPAN_STEP_QUOT, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0);
  localparam integer LSB_SPAN_STEP_REM = rs_rec_lsb(RS_REC_SPAN_STEP_REM, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0);
  wire [X_BITS-1:0] in_x0 = in_record[LSB_X0 +: X_BITS];
  wire [X_BITS-1:0] in_x1 = in_record[LSB_X1 +: X_BITS];
  wire [Y_BITS-1:0] in_y0 = in_record[LSB_Y0 +: Y_BITS];
  wire [Y_BITS-1:0] in_y1 = in_record[LSB_Y1 +: Y_BITS];
  wire [3*EDGE_BITS-1:0] in_edge_start = in_record[LSB_EDGE_START +: 3*EDGE_BITS];  // s.2S
  wire [3*EDGE_STEP_X_BITS-1:0] in_edge_step_x = in_record[LSB_EDGE_STEP_X +: 3*EDGE_STEP_X_BITS];  // s.2S
  wire [3*EDGE_STEP_Y_BITS-1:0] in_edge_step_y = in_record[LSB_EDGE_STEP_Y +: 3*EDGE_STEP_Y_BITS];  // s.2S
  wire [3*EDGE_BITS-1:0] in_span_quot = in_record[LSB_SPAN_QUOT +: 3*EDGE_BITS];
  wire [3*SPAN_REM_BITS-1:0] in_span_rem = in_record[LSB_SPAN_REM +: 3*SPAN_REM_BITS];
  wire [3*EDGE_STEP_Y_BITS-1:0] in_span_step_quot = in_record[LSB_SPAN_STEP_QUOT +: 3*EDGE_STEP_Y_BITS];
  wire [3*SPAN_REM_BITS-1:0] in_span_step_rem = in_record[LSB_SPAN_STEP_REM +: 3*SPAN_REM_BITS];

  wire span_traversal = cfg_traversal == RS_TRAVERSAL_SPAN;
  reg walking_q;  // a triangle is loaded and not finished

  reg [X_BITS-1:0] x0_q, x1_q, x_end_q;
  reg [Y_BITS-1:0] y1_q;
  reg          row_empty_q;                // the current row has no covered pixel
  reg [X_BITS-1:0] span_start_q;           // bbox: the current row's first covered pixel
  reg signed [EDGE_BITS-1:0]  edge_row_q [0:2];    // edge value at x0 of the row after the current one
  reg signed [EDGE_BITS-1:0]  step_y_q [0:2];
  reg signed [EDGE_BITS-1:0]  quot_q [0:2];        // span DDA of the next row: floor(edge_row / d), d = |step_x|
  // The DDA's remainders are kept less d (rem - d in [-d, -1]), so that the carry is the sign of one
  // sum: rem + step_rem >= d exactly when (rem - d) + step_rem >= 0. REM_BITS = SPAN_REM_BITS + 1,
  // signed, holds every sum formed (d < 2^SPAN_REM_BITS).
  reg [REM_BITS-1:0]              rem_less_q [0:2];    // edge_row - quot * d - d, in [-d, -1]
  reg signed [EDGE_BITS-1:0]  step_quot_q [0:2];
  reg [REM_BITS-1:0]              step_rem_q [0:2];       // in [0, d)
  reg [REM_BITS-1:0]              step_rem_less_q [0:2];  // step_rem - d, in [-d, -1]

  // ---- the current candidate ----
  // bbox: the pixel lies in its row's span (the span's pixels are exactly those with every edge >= 0).
  wire covered = !row_empty_q && frag_x >= span_start_q && frag_x <= x_end_q;
  assign frag_valid = walking_q && (span_traversal ? !row_empty_q : covered);
  wire advance = walking_q && (frag_ready || !frag_valid);
  wire row_done = span_traversal ? row_empty_q || frag_x == x_end_q : frag_x == x1_q;
  reg  last_row_q;  // frag_y == y1, kept as a register (set with frag_y)
  assign last = advance && row_done && last_row_q;
  assign in_ready = !walking_q || last;
  wire load = in_valid && in_ready;
  wire next_row = advance && row_done && !last_row_q;

  // ---- the DDA and span of the row about to start: the record's first row while the walker is
  // idle or on its last row (a load can only happen then), else the registers' next row. The choice
  // does not wait for the z-buffer's ready: `load` and `next_row` only enable the registers. ----
  // mid_walk_q = walking_q && !last_row_q, kept as a register of its own: it selects every DDA
  // field, and a gate there would sit at the head of the walker's longest path. Reset (and all
  // zeros) is idle.
  reg mid_walk_q;
  wire use_record = !mid_walk_q;
  wire signed [EDGE_BITS-1:0] src_edge_row [0:2];
  wire signed [EDGE_BITS-1:0] src_step_y [0:2];
  wire signed [EDGE_BITS-1:0] src_quot [0:2];
  wire signed [EDGE_BITS-1:0] src_step_quot [0:2];
  // The record's first DDA step, formed from the record alone (beside the multiplexer): its carries
  // and the remainders (less d) of the row after the first.
  wire [2:0] in_dda_carry;
  wire [REM_BITS-1:0] in_next_rem_less [0:2];
  wire [REM_BITS-1:0] in_step_rem [0:2];
  wire [REM_BITS-1:0] in_step_rem_less [0:2];
  // a + b + c + plus[1] + plus[0] modulo 2^REM_BITS (each plus bit adds one), as one carry-save
  // level and one adder.
  function automatic [REM_BITS-1:0] rem_sum3(input [REM_BITS-1:0] a, input [REM_BITS-1:0] b,
                                             input [REM_BITS-1:0] c, input [1:0] plus);
    reg [REM_BITS-1:0] save_carry;
    begin
      save_carry = ((a & b) | (a & c) | (b & c)) << 1;
      rem_sum3 = (a ^ b ^ c) + (save_carry | {{(REM_BITS-1){1'b0}}, plus[1]}) + {{(REM_BITS-1){1'b0}}, plus[0]};
    end
  endfunction
  genvar g;
  generate
    for (g = 0; g < 3; g = g + 1) begin : source
      wire signed [EDGE_BITS-1:0] in_step_y_wide = $signed({{(EDGE_BITS-EDGE_STEP_Y_BITS){in_edge_step_y[g*EDGE_STEP_Y_BITS + EDGE_STEP_Y_BITS - 1]}}, in_edge_step_y[g*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS]});
      wire signed [EDGE_BITS-1:0] in_step_quot_wide = $signed({{(EDGE_BITS-EDGE_STEP_Y_BITS){in_span_step_quot[g*EDGE_STEP_Y_BITS + EDGE_STEP_Y_BITS - 1]}}, in_span_step_quot[g*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS]});
      assign src_edge_row[g] = use_record ? in_edge_start[g*EDGE_BITS +: EDGE_BITS] : edge_row_q[g];
      assign src_step_y[g] = use_record ? in_step_y_wide : step_y_q[g];
      assign src_quot[g] = use_record ? in_span_quot[g*EDGE_BITS +: EDGE_BITS] : quot_q[g];
      // The record's remainders are in [0, d), d = |step_x|; the DDA keeps them less d. The first
      // step's carry is rem + step_rem - d >= 0 (the sum lies in [-d, d)), and the next remainder
      // less d is that sum, or the sum less d again on a carry: -d is step_x when step_x < 0, else
      // ~step_x + 1, -2d twice that (modulo 2^REM_BITS).
      wire [REM_BITS-1:0] in_rem = {1'b0, in_span_rem[g*SPAN_REM_BITS +: SPAN_REM_BITS]};
      assign in_step_rem[g] = {1'b0, in_span_step_rem[g*SPAN_REM_BITS +: SPAN_REM_BITS]};
      wire in_step_x_negative = in_edge_step_x[g*EDGE_STEP_X_BITS + EDGE_STEP_X_BITS - 1];
      wire [REM_BITS-1:0] in_step_x_low = in_edge_step_x[g*EDGE_STEP_X_BITS +: REM_BITS];
      wire [REM_BITS-1:0] in_minus_d_less = in_step_x_negative ? in_step_x_low : ~in_step_x_low;  // -d, less 1 when step_x > 0
      wire [REM_BITS-1:0] in_sum_less_d = rem_sum3(in_rem, in_step_rem[g], in_minus_d_less, {1'b0, !in_step_x_negative});
      wire [REM_BITS-1:0] in_sum_less_2d = rem_sum3(in_rem, in_step_rem[g], in_minus_d_less << 1, {2{!in_step_x_negative}});
      assign in_dda_carry[g] = !in_sum_less_d[REM_BITS-1];
      assign in_next_rem_less[g] = in_dda_carry[g] ? in_sum_less_2d : in_sum_less_d;
      assign in_step_rem_less[g] = in_step_x_negative ? in_step_rem[g] + in_step_x_low : in_step_rem[g] - in_step_x_low;
      assign src_step_quot[g] = use_record ? in_step_quot_wide : step_quot_q[g];
    end
  endgenerate
  // Left edges have step_x > 0, right ones < 0: the step's sign and a zero test, registered at load
  // so that the registers' side needs no logic at all.
  wire [2:0] in_right, in_left, src_left, src_right;
  reg  [2:0] left_q, right_q;
  generate
    for (g = 0; g < 3; g = g + 1) begin : side
      assign in_right[g] = in_edge_step_x[g*EDGE_STEP_X_BITS + EDGE_STEP_X_BITS - 1];
      assign in_left[g] = !in_right[g] && |in_edge_step_x[g*EDGE_STEP_X_BITS +: EDGE_STEP_X_BITS];
    end
  endgenerate
  assign src_left = use_record ? in_left : left_q;
  assign src_right = use_record ? in_right : right_q;
  wire [X_BITS-1:0] src_x0 = use_record ? in_x0 : x0_q;
  wire [X_BITS-1:0] src_x1 = use_record ? in_x1 : x1_q;

  // Span bounds: offsets t from x0 with every edge >= 0. Each edge's bound is of a class, and only
  // a small bound carries a value (its quotient's low bits):
  //  left edge (step_x > 0):  t >= -floor(E / d) = -quot: no bound (quot >= 0, or not a left edge),
  //                           a small one (quot in [-2^X_BITS, -1]), or beyond the box (empty row)
  //  right edge (step_x < 0): t <= quot: a small one (quot in [0, 2^X_BITS - 1]), no bound
  //                           (larger, or not a right edge); quot < 0: empty row
  //  horizontal edge: the whole row or, with E < 0, no pixel
  // The box's last offset is one more upper bound. The compares below work on the quotients' low
  // bits straight from the source and the classes join them after, so that no compare waits for a
  // class (the reductions over the quotients' high bits), and all compares are side by side (none
  // waits for another): the span start and end are one-hot selects, and the row is empty when some
  // lower bound exceeds some upper one.
  // The box's last offset: the record's is formed from the record alone, beside the multiplexer.
  reg [X_BITS-1:0] last_offset_q;
  wire [X_BITS-1:0] in_last_offset = in_x1 - in_x0;
  // Compares with the last offset are formed on each side of the multiplexer and the results chosen
  // after it: the record's as one carry-save level and one adder from x1, x0 and the quotient
  // (x1 - x0 + low and x1 - x0 - low on X_BITS + 2 bits, neither subtraction waiting for the other).
  localparam integer OFFSET_SUM_BITS = X_BITS + 2;
  function automatic nonnegative_sum3(input [OFFSET_SUM_BITS-1:0] a, input [OFFSET_SUM_BITS-1:0] b,
                                      input [OFFSET_SUM_BITS-1:0] c, input [1:0] plus);  // each plus bit adds one
    reg [OFFSET_SUM_BITS-1:0] save_sum, save_carry, total;
    begin
      save_sum = a ^ b ^ c;
      save_carry = ((a & b) | (a & c) | (b & c)) << 1;
      total = save_sum + (save_carry | {{(OFFSET_SUM_BITS-1){1'b0}}, plus[1]}) + {{(OFFSET_SUM_BITS-1){1'b0}}, plus[0]};
      nonnegative_sum3 = !total[OFFSET_SUM_BITS-1];
    end
  endfunction
  wire [OFFSET_SUM_BITS-1:0] in_x1_wide = {2'b00, in_x1};
  wire [OFFSET_SUM_BITS-1:0] in_minus_x0_less_1 = ~{2'b00, in_x0};  // -x0 - 1
  wire [X_BITS:0] low [0:2];  // each quotient's low X_BITS + 1 bits
  wire [2:0] lo_none, lo_small, hi_none, edge_empty;
  generate
    for (g = 0; g < 3; g = g + 1) begin : bounds
      wire negative = src_quot[g][EDGE_BITS-1];
      wire small_negative = &src_quot[g][EDGE_BITS-1:X_BITS];  // in [-2^X_BITS, -1]
      wire small_positive = ~|src_quot[g][EDGE_BITS-1:X_BITS];  // in [0, 2^X_BITS - 1]
      assign low[g] = src_quot[g][X_BITS:0];
      // A horizontal edge's quotient is 0 (the record's, and the DDA holds it), so "not a right
      // edge" is enough here: no zero test of step_x on this path.
      assign lo_none[g] = src_right[g] || !negative;
      assign lo_small[g] = !src_right[g] && small_negative;
      assign hi_none[g] = !src_right[g] || !small_positive;
      assign edge_empty[g] = src_right[g] ? negative : !src_left[g] && src_edge_row[g][EDGE_BITS-1];
    end
  endgenerate
  // Lower bounds ordered "none" below every small one, small ones by value (-quot: a lower quotient
  // is a larger bound); a bound beyond the box fits under no upper bound, so the row is empty and
  // the choice does not matter. Upper bounds by value, "none" above every value. Ties go to the
  // lower index.
  wire lo_ge_01 = lo_none[1] || (lo_small[0] && lo_small[1] && low[0] <= low[1]);
  wire lo_ge_02 = lo_none[2] || (lo_small[0] && lo_small[2] && low[0] <= low[2]);
  wire lo_ge_12 = lo_none[2] || (lo_small[1] && lo_small[2] && low[1] <= low[2]);
  wire [X_BITS-1:0] edge_hi [0:2];
  generate
    for (g = 0; g < 3; g = g + 1) begin : uppers
      assign edge_hi[g] = low[g][X_BITS-1:0];
    end
  endgenerate
  wire hi_le_01 = hi_none[1] || (!hi_none[0] && edge_hi[0] <= edge_hi[1]);
  wire hi_le_02 = hi_none[2] || (!hi_none[0] && edge_hi[0] <= edge_hi[2]);
  wire hi_le_12 = hi_none[2] || (!hi_none[1] && edge_hi[1] <= edge_hi[2]);
  // Each edge against the last offset: its lower bound fits under it (x1 - x0 + low >= 0), its upper
  // bound is at most it (x1 - x0 - low >= 0, with low's top bit 0 for a small upper bound).
  wire [2:0] lo_fits_last, hi_le_last;
  generate
    for (g = 0; g < 3; g = g + 1) begin : last_offset_compares
      wire [X_BITS:0] in_low = in_span_quot[g*EDGE_BITS +: X_BITS + 1];
      wire [OFFSET_SUM_BITS-1:0] in_low_wide = {in_low[X_BITS], in_low};
      wire [OFFSET_SUM_BITS-1:0] in_minus_hi_less_1 = ~{2'b00, in_low[X_BITS-1:0]};  // -hi - 1
      wire in_lo_fits = nonnegative_sum3(in_x1_wide, in_minus_x0_less_1, in_low_wide, 2'b01);
      wire in_hi_le = nonnegative_sum3(in_x1_wide, in_minus_x0_less_1, in_minus_hi_less_1, 2'b11);
      wire [OFFSET_SUM_BITS-1:0] registers_lo_sum = {quot_q[g][X_BITS], quot_q[g][X_BITS:0]} + {2'b00, last_offset_q};
      wire registers_hi_le = quot_q[g][X_BITS-1:0] <= last_offset_q;
      assign lo_fits_last[g] = use_record ? in_lo_fits : !registers_lo_sum[OFFSET_SUM_BITS-1];
      assign hi_le_last[g] = use_record ? in_hi_le : registers_hi_le;
    end
  endgenerate
  wire hi_le_03 = !hi_none[0] && hi_le_last[0];
  wire hi_le_13 = !hi_none[1] && hi_le_last[1];
  wire hi_le_23 = !hi_none[2] && hi_le_last[2];
  // fits[i][j]: lower bound i <= upper bound j (j = 3: the last offset). A small lower bound -quot_i
  // is at most an upper value u when quot_i + u >= 0; every lower bound fits under "none" (the
  // last offset bounds it too).
  wire [3:0] fits [0:2];
  genvar h;
  generate
    for (g = 0; g < 3; g = g + 1) begin : lo_fits
      for (h = 0; h < 4; h = h + 1) begin : fit
        if (h == g) begin : same_edge
          // An edge is not both left and right: its own upper bound is "none".
          assign fits[g][h] = 1'b1;
        end else if (h == 3) begin : last_offset
          assign fits[g][h] = lo_none[g] || (lo_small[g] && lo_fits_last[g]);
        end else begin : other_edge
          wire [X_BITS+1:0] sum = {low[g][X_BITS], low[g]} + {2'b00, edge_hi[h]};
          assign fits[g][h] = lo_none[g] || (lo_small[g] && (hi_none[h] || !sum[X_BITS+1]));
        end
      end
    end
  endgenerate
  wire lo_pick_0 = lo_ge_01 && lo_ge_02;
  wire lo_pick_1 = !lo_pick_0 && lo_ge_12;
  wire lo_pick_2 = !lo_pick_0 && !lo_ge_12;
  wire hi_pick_0 = hi_le_01 && hi_le_02 && hi_le_03;
  wire hi_pick_1 = !hi_pick_0 && hi_le_12 && hi_le_13;
  wire hi_pick_2 = !hi_pick_0 && !hi_pick_1 && hi_le_23;
  wire hi_pick_3 = !hi_pick_0 && !hi_pick_1 && !hi_le_23;
  wire span_nonempty = !(|edge_empty) && &fits[0] && &fits[1] && &fits[2];
  // The span start and end, the candidates added before the select: the start is x0 when no edge
  // bounds it (then every lower bound is "none"), else x0 - quot of the chosen edge; the end is
  // x0 + quot of the chosen edge or x1. Both are used only when the row is not empty.
  wire lo_from_x0 = &lo_none;
  wire [X_BITS-1:0] start_at [0:2];
  wire [X_BITS-1:0] end_at [0:2];
  wire [X_BITS-1:0] minus_low [0:2];
  generate
    for (g = 0; g < 3; g = g + 1) begin : ends
      assign minus_low[g] = -low[g][X_BITS-1:0];
      assign start_at[g] = src_x0 + minus_low[g];
      assign end_at[g] = src_x0 + edge_hi[g];
    end
  endgenerate
  wire [X_BITS-1:0] span_start = lo_from_x0 ? src_x0
      : ({X_BITS{lo_pick_0}} & start_at[0]) | ({X_BITS{lo_pick_1}} & start_at[1]) | ({X_BITS{lo_pick_2}} & start_at[2]);
  wire [X_BITS-1:0] span_end = ({X_BITS{hi_pick_0}} & end_at[0]) | ({X_BITS{hi_pick_1}} & end_at[1])
                             | ({X_BITS{hi_pick_2}} & end_at[2]) | ({X_BITS{hi_pick_3}} & src_x1);
  wire enter_row = load || next_row;

  // The DDA step to the row after the one about to start: quot += step_quot (+ 1 on the carry).
  wire [2:0] dda_carry;
  wire [REM_BITS-1:0] next_rem_less [0:2];
  wire signed [EDGE_BITS-1:0] quot_sum [0:2];
  wire signed [EDGE_BITS-1:0] quot_carried [0:2];
  generate
    for (g = 0; g < 3; g = g + 1) begin : dda
      // The registers' step beside the record's (in_dda_carry, in_next_rem_less), the results
      // chosen after: no carry chain follows the multiplexer.
      wire [REM_BITS-1:0] registers_rem_sum = rem_less_q[g] + step_rem_q[g];
      wire registers_carry = !registers_rem_sum[REM_BITS-1];
      wire [REM_BITS-1:0] registers_rem_carried = rem_less_q[g] + step_rem_less_q[g];
      assign dda_carry[g] = use_record ? in_dda_carry[g] : registers_carry;
      assign next_rem_less[g] = use_record ? in_next_rem_less[g] : registers_carry ? registers_rem_carried : registers_rem_sum;
      // All EDGE_BITS bits: modular, sign-agnostic.
      assign quot_sum[g] = src_quot[g] + src_step_quot[g];
      assign quot_carried[g] = src_quot[g] + src_step_quot[g] + CARRY;
    end
  endgenerate

  assign adder_load = load;
  assign adder_step_x = advance && !row_done;
  assign adder_next_row = next_row && !span_traversal;
  assign adder_row_enter = next_row && span_traversal;
  // The plane registers enter a span row at x0 or at the chosen left edge's span start (bbox: x0).
  // A left edge's slot is the number of left edges before it; a triangle has at most two.
  assign adder_enter_left = span_traversal && !lo_from_x0;
  assign adder_enter_slot = (lo_pick_1 && src_left[0]) || (lo_pick_2 && (src_left[0] || src_left[1]));
  assign adder_left_carry[0] = src_left[0] ? dda_carry[0] : src_left[1] ? dda_carry[1] : dda_carry[2];
  assign adder_left_carry[1] = src_left[0] && src_left[1] ? dda_carry[1] : dda_carry[2];

  assign busy = load || advance;
  assign candidate = advance && (frag_valid || !span_traversal);

  always @(posedge clk) begin
    if (rst) walking_q <= 1'b0;
    else if (load) walking_q <= 1'b1;
    else if (last) walking_q <= 1'b0;
  end
  always @(posedge clk) begin
    if (rst) mid_walk_q <= 1'b0;
    else if (load) mid_walk_q <= in_y0 != in_y1;
    else if (last) mid_walk_q <= 1'b0;
    else if (next_row) mid_walk_q <= frag_y + 1'b1 != y1_q;
  end

  // Counters and edge registers (no reset: loaded in the load cycle before use).
  integer i;
  always @(posedge clk) begin
    if (load) begin
      x0_q <= in_x0;
      x1_q <= in_x1;
      last_offset_q <= in_last_offset;
      y1_q <= in_y1;
      frag_x <= in_x0;
      frag_y <= in_y0;
      last_row_q <= in_y0 == in_y1;
      left_q <= in_left;
      right_q <= in_right;
      for (i = 0; i < 3; i = i + 1) begin
        step_y_q[i] <= src_step_y[i];
        step_quot_q[i] <= src_step_quot[i];
        step_rem_q[i] <= in_step_rem[i];
        step_rem_less_q[i] <= in_step_rem_less[i];
      end
    end else if (advance) begin
      if (!row_done) begin
        frag_x <= frag_x + 1'b1;
      end else if (!last_row_q) begin
        frag_y <= frag_y + 1'b1;
        last_row_q <= frag_y + 1'b1 == y1_q;
      end
    end
    if (enter_row) begin
      // The row about to start: its span (span traversal starts there, bbox at x0); the DDA steps
      // every edge to the row after it.
      frag_x <= span_traversal ? span_start : src_x0;
      span_start_q <= span_start;
      x_end_q <= span_end;
      row_empty_q <= !span_nonempty;
      for (i = 0; i < 3; i = i + 1) begin
        edge_row_q[i] <= src_edge_row[i] + src_step_y[i];
        // Both quotient sums side by side; the remainder's carry picks one. A horizontal edge's
        // quotient is the record's 0 throughout (the span bounds rely on it); its remainder is
        // never used.
        rem_less_q[i] <= next_rem_less[i];
        quot_q[i] <= !(src_left[i] || src_right[i]) ? src_quot[i] : dda_carry[i] ? quot_carried[i] : quot_sum[i];
      end
    end
  end
endmodule
