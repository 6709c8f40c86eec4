// A row's span from its span DDA (model/scanline_walker.h, walk_span): the first and last pixel
// with every edge >= 0, combinational. scanline_walker_entry forms the first row's from a setup
// record, scanline_walker every later row's from its DDA registers.
// Span bounds are offsets t from x0 with every edge >= 0. Each edge's bound is of a class, and only
// a small bound carries a value (its quotient's low bits):
//  left edge (step_x > 0):  t >= -floor(E / d) = -quot: no bound (quot >= 0, or not a left edge),
//                           a small one (quot in [-2^X_BITS, -1]), or beyond the box (empty row)
//  right edge (step_x < 0): t <= quot: a small one (quot in [0, 2^X_BITS - 1]), no bound
//                           (larger, or not a right edge); quot < 0: empty row
//  horizontal edge: the whole row or, with E < 0, no pixel
// The box's last offset x1 - x0 is one more upper bound; the caller compares each quotient with it
// (lo_fits_last, hi_le_last), as its operands allow. The compares below work on the quotients' low
// bits and the classes join them after, so that no compare waits for a class (the reductions over
// the quotients' high bits), and all compares are side by side (none waits for another): the span
// start and end are one-hot selects, and the row is empty when some lower bound exceeds some upper
// one.
`include "rastersim_pkg.sv"
module span_bounds #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer SUBPIXEL_BITS = 4
) (
  input  wire [3*rs_edge_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] quot,  // edge k at [k*EDGE_BITS]: floor(E / d)
  input  wire [rastersim_pkg::TRIANGLE_EDGES-1:0] left,          // step_x > 0
  input  wire [rastersim_pkg::TRIANGLE_EDGES-1:0] right,         // step_x < 0
  input  wire [rastersim_pkg::TRIANGLE_EDGES-1:0] edge_negative, // E < 0 (used for horizontal edges only)
  input  wire [rs_ubits32(WIDTH - 1)-1:0] x0,
  input  wire [rs_ubits32(WIDTH - 1)-1:0] x1,
  input  wire [rastersim_pkg::TRIANGLE_EDGES-1:0] lo_fits_last,  // x1 - x0 + quot_k >= 0 (quot_k's low X_BITS + 1 bits, signed)
  input  wire [rastersim_pkg::TRIANGLE_EDGES-1:0] hi_le_last,    // quot_k's low X_BITS bits <= x1 - x0
  output wire [rs_ubits32(WIDTH - 1)-1:0] span_start,  // both used only when nonempty
  output wire [rs_ubits32(WIDTH - 1)-1:0] span_end,
  output wire nonempty,
  output wire lo_from_x0,                // no edge bounds the start: it is x0
  output wire enter_slot                 // else the left-edge slot of the edge whose bound it is
);
`include "rastersim_widths.vh"
  localparam integer EDGE_BITS = rs_edge_bits(WIDTH, HEIGHT, SUBPIXEL_BITS);
  localparam integer X_BITS = rs_ubits32(WIDTH - 1);

  wire [X_BITS:0] low [0:2];  // each quotient's low X_BITS + 1 bits
  wire [X_BITS-1:0] edge_hi [0:2];
  wire [2:0] lo_none, lo_small, hi_none, edge_empty;
  genvar g, h;
  generate
    for (g = 0; g < 3; g = g + 1) begin : bounds
      wire [EDGE_BITS-1:0] q = quot[g*EDGE_BITS +: EDGE_BITS];
      wire negative = q[EDGE_BITS-1];
      wire small_negative = &q[EDGE_BITS-1:X_BITS];  // in [-2^X_BITS, -1]
      wire small_positive = ~|q[EDGE_BITS-1:X_BITS];  // in [0, 2^X_BITS - 1]
      assign low[g] = q[X_BITS:0];
      assign edge_hi[g] = q[X_BITS-1:0];
      // A horizontal edge's quotient is 0 (the record's, and the DDA holds it), so "not a right
      // edge" is enough here: no zero test of step_x on this path.
      assign lo_none[g] = right[g] || !negative;
      assign lo_small[g] = !right[g] && small_negative;
      assign hi_none[g] = !right[g] || !small_positive;
      assign edge_empty[g] = right[g] ? negative : !left[g] && edge_negative[g];
    end
  endgenerate
  // Lower bounds ordered "none" below every small one, small ones by value (-quot: a lower quotient
  // is a larger bound); a bound beyond the box fits under no upper bound, so the row is empty and
  // the choice does not matter. Upper bounds by value, "none" above every value. Ties go to the
  // lower index.
  wire lo_ge_01 = lo_none[1] || (lo_small[0] && lo_small[1] && low[0] <= low[1]);
  wire lo_ge_02 = lo_none[2] || (lo_small[0] && lo_small[2] && low[0] <= low[2]);
  wire lo_ge_12 = lo_none[2] || (lo_small[1] && lo_small[2] && low[1] <= low[2]);
  wire hi_le_01 = hi_none[1] || (!hi_none[0] && edge_hi[0] <= edge_hi[1]);
  wire hi_le_02 = hi_none[2] || (!hi_none[0] && edge_hi[0] <= edge_hi[2]);
  wire hi_le_12 = hi_none[2] || (!hi_none[1] && edge_hi[1] <= edge_hi[2]);
  wire hi_le_03 = !hi_none[0] && hi_le_last[0];
  wire hi_le_13 = !hi_none[1] && hi_le_last[1];
  wire hi_le_23 = !hi_none[2] && hi_le_last[2];
  // fits[i][j]: lower bound i <= upper bound j (j = 3: the last offset). A small lower bound -quot_i
  // is at most an upper value u when quot_i + u >= 0; every lower bound fits under "none" (the
  // last offset bounds it too).
  wire [3:0] fits [0:2];
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
  // A left edge's slot is the number of left edges before it; a triangle has at most two.
  assign enter_slot = (lo_pick_1 && left[0]) || (lo_pick_2 && (left[0] || left[1]));
  wire hi_pick_0 = hi_le_01 && hi_le_02 && hi_le_03;
  wire hi_pick_1 = !hi_pick_0 && hi_le_12 && hi_le_13;
  wire hi_pick_2 = !hi_pick_0 && !hi_pick_1 && hi_le_23;
  wire hi_pick_3 = !hi_pick_0 && !hi_pick_1 && !hi_le_23;
  assign nonempty = !(|edge_empty) && &fits[0] && &fits[1] && &fits[2];
  // The span start and end, the candidates added before the select: the start is x0 when no edge
  // bounds it (then every lower bound is "none"), else x0 - quot of the chosen edge; the end is
  // x0 + quot of the chosen edge or x1.
  assign lo_from_x0 = &lo_none;
  wire [X_BITS-1:0] start_at [0:2];
  wire [X_BITS-1:0] end_at [0:2];
  generate
    for (g = 0; g < 3; g = g + 1) begin : ends
      assign start_at[g] = x0 - low[g][X_BITS-1:0];
      assign end_at[g] = x0 + edge_hi[g];
    end
  endgenerate
  assign span_start = lo_from_x0 ? x0
      : ({X_BITS{lo_pick_0}} & start_at[0]) | ({X_BITS{lo_pick_1}} & start_at[1]) | ({X_BITS{lo_pick_2}} & start_at[2]);
  assign span_end = ({X_BITS{hi_pick_0}} & end_at[0]) | ({X_BITS{hi_pick_1}} & end_at[1])
                  | ({X_BITS{hi_pick_2}} & end_at[2]) | ({X_BITS{hi_pick_3}} & x1);
endmodule
