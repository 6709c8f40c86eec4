// Counter-driven scanline walker (model/scanline_walker.h): x and y counters step over the
// triangle's bounding box, edge functions are updated by additions only, one candidate per clock.
// cfg_traversal selects the traversal at run time (both emit the same fragments in the same order):
//  0 bbox: every bounding-box pixel, row-major; the counters wrap to the next row in the same cycle.
//  1 span: one cycle per covered pixel, one for a row with none. A row's span bounds come from the
//    DDA registers (quotient and remainder of each edge by |step_x|, additions only) in the cycle
//    before the row: the first row's from the record in the load cycle, each next row's in the
//    previous row's last cycle, when the DDA registers step on and the plane registers move to
//    the span start. So the DDA registers always hold the row after the current one.
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
  output wire adder_row_enter,  // span, next row: row += step_y; value = row + offset * step_x
  output wire [rs_ubits32(WIDTH - 1)-1:0] adder_row_offset,
  output wire adder_from_record, // the offset product is the record's (a load can happen), not the registers'
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
  reg          row_empty_q;                // span: the current row has no covered pixel
  reg signed [EDGE_BITS-1:0]  edge_row_q [0:2];    // edge value at x0: bbox the current row, span the next
  reg signed [EDGE_BITS-1:0]  edge_value_q [0:2];  // bbox: edge value at (x, y)
  reg signed [EDGE_BITS-1:0]  step_x_q [0:2];     // sign-extended to EDGE_BITS at load
  reg signed [EDGE_BITS-1:0]  step_y_q [0:2];
  reg signed [EDGE_BITS-1:0]  quot_q [0:2];        // span DDA of the next row: floor(edge_row / d), d = |step_x|
  reg [SPAN_REM_BITS-1:0]         rem_q [0:2];         // edge_row - quot * d, in [0, d)
  reg signed [EDGE_BITS-1:0]  step_quot_q [0:2];
  reg [SPAN_REM_BITS-1:0]         step_rem_q [0:2];
  reg [SPAN_REM_BITS-1:0]         divisor_q [0:2];

  // ---- the current candidate ----
  wire covered = !edge_value_q[0][EDGE_BITS-1] && !edge_value_q[1][EDGE_BITS-1] && !edge_value_q[2][EDGE_BITS-1];
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
  wire use_record = !walking_q || last_row_q;
  wire signed [EDGE_BITS-1:0] src_edge_row [0:2];
  wire signed [EDGE_BITS-1:0] src_step_x [0:2];
  wire signed [EDGE_BITS-1:0] src_step_y [0:2];
  wire signed [EDGE_BITS-1:0] src_quot [0:2];
  wire [SPAN_REM_BITS-1:0]        src_rem [0:2];
  wire signed [EDGE_BITS-1:0] src_step_quot [0:2];
  wire [SPAN_REM_BITS-1:0]        src_step_rem [0:2];
  wire [SPAN_REM_BITS-1:0]        src_divisor [0:2];
  genvar g;
  generate
    for (g = 0; g < 3; g = g + 1) begin : source
      wire signed [EDGE_BITS-1:0] in_step_x_wide = $signed({{(EDGE_BITS-EDGE_STEP_X_BITS){in_edge_step_x[g*EDGE_STEP_X_BITS + EDGE_STEP_X_BITS - 1]}}, in_edge_step_x[g*EDGE_STEP_X_BITS +: EDGE_STEP_X_BITS]});
      wire signed [EDGE_BITS-1:0] in_step_y_wide = $signed({{(EDGE_BITS-EDGE_STEP_Y_BITS){in_edge_step_y[g*EDGE_STEP_Y_BITS + EDGE_STEP_Y_BITS - 1]}}, in_edge_step_y[g*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS]});
      wire signed [EDGE_BITS-1:0] in_step_quot_wide = $signed({{(EDGE_BITS-EDGE_STEP_Y_BITS){in_span_step_quot[g*EDGE_STEP_Y_BITS + EDGE_STEP_Y_BITS - 1]}}, in_span_step_quot[g*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS]});
      wire [SPAN_REM_BITS-1:0] in_divisor = in_edge_step_x[g*EDGE_STEP_X_BITS + EDGE_STEP_X_BITS - 1] ? -in_edge_step_x[g*EDGE_STEP_X_BITS +: SPAN_REM_BITS] : in_edge_step_x[g*EDGE_STEP_X_BITS +: SPAN_REM_BITS];
      assign src_edge_row[g] = use_record ? in_edge_start[g*EDGE_BITS +: EDGE_BITS] : edge_row_q[g];
      assign src_step_x[g] = use_record ? in_step_x_wide : step_x_q[g];
      assign src_step_y[g] = use_record ? in_step_y_wide : step_y_q[g];
      assign src_quot[g] = use_record ? in_span_quot[g*EDGE_BITS +: EDGE_BITS] : quot_q[g];
      assign src_rem[g] = use_record ? in_span_rem[g*SPAN_REM_BITS +: SPAN_REM_BITS] : rem_q[g];
      assign src_step_quot[g] = use_record ? in_step_quot_wide : step_quot_q[g];
      assign src_step_rem[g] = use_record ? in_span_step_rem[g*SPAN_REM_BITS +: SPAN_REM_BITS] : step_rem_q[g];
      assign src_divisor[g] = use_record ? in_divisor : divisor_q[g];
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

  // Span bounds: offsets t from x0 with every edge >= 0, on X_BITS + 1 bits: each edge's bound is
  // saturated first (a bound at or beyond 2^X_BITS only ever means "outside the box", as the box's last
  // offset is below 2^X_BITS), so the comparisons are X_BITS + 1 bits wide, not EDGE_BITS + 2.
  //  left edge (step_x > 0):  t >= -floor(E / d) = -quot, saturated to [0, 2^X_BITS]
  //  right edge (step_x < 0): t <= quot, saturated to [0, 2^X_BITS - 1]; quot < 0: no pixel
  //  horizontal edge: the whole row or, with E < 0, no pixel
  wire [X_BITS-1:0] last_offset = src_x1 - src_x0;
  wire [X_BITS:0] edge_lo [0:2];
  wire [X_BITS-1:0] edge_hi [0:2];
  wire [2:0] edge_empty;
  generate
    for (g = 0; g < 3; g = g + 1) begin : bounds
      wire negative = src_quot[g][EDGE_BITS-1];
      // quot in [-2^X_BITS, -1]: its bits above X_BITS-1 are all ones.
      wire small_negative = &src_quot[g][EDGE_BITS-1:X_BITS];
      wire [X_BITS:0] minus_quot = -src_quot[g][X_BITS:0];
      // quot in [0, 2^X_BITS - 1]: its bits above X_BITS-1 are all zeros.
      wire small_positive = ~|src_quot[g][EDGE_BITS-1:X_BITS];
      wire left = src_left[g];
      wire right = src_right[g];
      assign edge_lo[g] = !left || !negative ? {(X_BITS+1){1'b0}}
                        : small_negative ? minus_quot : {1'b1, {X_BITS{1'b0}}};
      assign edge_hi[g] = !right || !small_positive ? {X_BITS{1'b1}} : src_quot[g][X_BITS-1:0];
      assign edge_empty[g] = right ? negative : !left && src_edge_row[g][EDGE_BITS-1];
    end
  endgenerate
  // Minimum and maximum as trees: two compare levels each.
  wire [X_BITS:0] lo01 = edge_lo[0] > edge_lo[1] ? edge_lo[0] : edge_lo[1];
  wire [X_BITS:0] span_lo = lo01 > edge_lo[2] ? lo01 : edge_lo[2];
  wire [X_BITS-1:0] hi01 = edge_hi[0] < edge_hi[1] ? edge_hi[0] : edge_hi[1];
  wire [X_BITS-1:0] hi2 = edge_hi[2] < last_offset ? edge_hi[2] : last_offset;
  wire [X_BITS-1:0] span_hi = hi01 < hi2 ? hi01 : hi2;
  wire span_nonempty = !(|edge_empty) && span_lo <= {1'b0, span_hi};
  wire enter_span_row = span_traversal && (load || next_row);

  assign adder_load = load;
  assign adder_step_x = advance && !row_done;
  assign adder_next_row = next_row && !span_traversal;
  assign adder_row_enter = next_row && span_traversal;
  // The first row's offset at load (0 for bbox: the plane registers start at x0).
  assign adder_row_offset = span_traversal ? span_lo[X_BITS-1:0] : {X_BITS{1'b0}};
  assign adder_from_record = use_record;

  assign busy = load || advance;
  assign candidate = advance && (frag_valid || !span_traversal);

  always @(posedge clk) begin
    if (rst) walking_q <= 1'b0;
    else if (load) walking_q <= 1'b1;
    else if (last) walking_q <= 1'b0;
  end

  // Counters and edge registers (no reset: loaded in the load cycle before use).
  integer i;
  always @(posedge clk) begin
    if (load) begin
      x0_q <= in_x0;
      x1_q <= in_x1;
      y1_q <= in_y1;
      frag_x <= in_x0;
      frag_y <= in_y0;
      last_row_q <= in_y0 == in_y1;
      left_q <= in_left;
      right_q <= in_right;
      for (i = 0; i < 3; i = i + 1) begin
        edge_row_q[i] <= src_edge_row[i];
        edge_value_q[i] <= src_edge_row[i];
        step_x_q[i] <= src_step_x[i];
        step_y_q[i] <= src_step_y[i];
        step_quot_q[i] <= src_step_quot[i];
        step_rem_q[i] <= src_step_rem[i];
        divisor_q[i] <= src_divisor[i];
      end
    end else if (advance) begin
      if (!row_done) begin
        frag_x <= frag_x + 1'b1;
        for (i = 0; i < 3; i = i + 1) edge_value_q[i] <= edge_value_q[i] + step_x_q[i];
      end else if (!last_row_q) begin
        frag_y <= frag_y + 1'b1;
        last_row_q <= frag_y + 1'b1 == y1_q;
        if (!span_traversal) begin
          frag_x <= x0_q;
          for (i = 0; i < 3; i = i + 1) begin
            edge_row_q[i] <= edge_row_q[i] + step_y_q[i];
            edge_value_q[i] <= edge_row_q[i] + step_y_q[i];
          end
        end
      end
    end
    if (enter_span_row) begin
      // The row about to start: its span; the DDA steps every edge to the row after it.
      frag_x <= src_x0 + span_lo[X_BITS-1:0];
      x_end_q <= src_x0 + span_hi;
      row_empty_q <= !span_nonempty;
      for (i = 0; i < 3; i = i + 1) begin
        edge_row_q[i] <= src_edge_row[i] + src_step_y[i];
        if (src_left[i] || src_right[i]) begin
          if ({1'b0, src_rem[i]} + {1'b0, src_step_rem[i]} >= {1'b0, src_divisor[i]}) begin
            rem_q[i] <= src_rem[i] + src_step_rem[i] - src_divisor[i];
            quot_q[i] <= src_quot[i] + src_step_quot[i] + CARRY;  // all EDGE_BITS bits: modular, sign-agnostic
          end else begin
            rem_q[i] <= src_rem[i] + src_step_rem[i];
            quot_q[i] <= src_quot[i] + src_step_quot[i];
          end
        end else begin
          rem_q[i] <= src_rem[i];
          quot_q[i] <= src_quot[i];
        end
      end
    end
  end
endmodule
