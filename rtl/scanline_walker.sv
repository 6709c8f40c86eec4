// Counter-driven scanline walker (model/scanline_walker.h): x and y counters step over the
// triangle's bounding box, edge functions are updated by additions only, one candidate per clock.
// cfg_traversal selects the traversal at run time (both emit the same fragments in the same order):
//  0 bbox: every bounding-box pixel, row-major; the counters wrap to the next row in the same cycle.
//    A pixel is covered when it lies in its row's span (below), the same DDA and bounds as span
//    traversal: no edge value is stepped per pixel.
//  1 span: one cycle per covered pixel, one for a row with none. A row's span bounds come from the
//    DDA registers (quotient and remainder of each edge by |step_x|, additions only) in the cycle
//    before the row: the first row's is the entry's (scanline_walker_entry formed it from the
//    record before the record FIFO), each next row's is computed in the previous row's last cycle,
//    when the DDA registers step on and the plane registers move to the span start (x0, or the
//    bounding left edge's, by its left-edge slot). So the DDA registers always hold the row after
//    the current one.
// A covered candidate is presented on frag_*; the walker holds it until frag_ready.
// Cycles (docs/cycle-model.md): the entry is taken in walker_load (in_valid & in_ready), which is
// the cycle of the previous triangle's last candidate when the entry is there by then; the first
// candidate follows in walker_load + 1; `last` marks walker_end.
`include "rastersim_pkg.sv"
module scanline_walker #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer SUBPIXEL_BITS = 4
) (
  input  wire clk,
  input  wire rst,
  input  wire cfg_traversal,  // rastersim_pkg::TRAVERSAL_*
  // The walker's entry (scanline_walker_entry, through the record FIFO).
  input  wire in_valid,
  output wire in_ready,
  input  wire [rs_entry_lsb(20, WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] in_entry,
  // Plane register control (z_adder), in lockstep with the counters.
  output wire adder_load,       // take the setup planes (LOAD cycle)
  output wire adder_step_x,     // next pixel of the row
  output wire adder_next_row,   // bbox: wrap to the next row
  output wire adder_row_enter,  // span, next row: row += step_y; value = row or the entered slot's
  output wire adder_enter_left, // load, row_enter: the span starts at a left edge (else at x0)
  output wire adder_enter_slot, // that edge's left-edge slot: the number of left edges before it
  output wire [rastersim_pkg::LEFT_EDGE_SLOTS-1:0] adder_left_carry,  // each slot's DDA carry into the row after the one entered
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
  localparam integer EDGE_STEP_Y_BITS = rs_edge_step_y_bits(WIDTH, S);
  localparam integer SPAN_REM_BITS = rs_span_rem_bits(HEIGHT, S);
  localparam integer REM_BITS = SPAN_REM_BITS + 1;
  localparam integer X_BITS = rs_ubits32(WIDTH - 1);
  localparam integer Y_BITS = rs_ubits32(HEIGHT - 1);
  localparam [EDGE_BITS-1:0] CARRY = {{(EDGE_BITS-1){1'b0}}, 1'b1};

  // The entry's fields at their places (rastersim_widths.vh; constants, so that the simulator does
  // not evaluate the sums at run time).
  localparam integer LSB_X0 = rs_entry_lsb(RS_ENTRY_X0, WIDTH, HEIGHT, S);
  localparam integer LSB_X1 = rs_entry_lsb(RS_ENTRY_X1, WIDTH, HEIGHT, S);
  localparam integer LSB_Y0 = rs_entry_lsb(RS_ENTRY_Y0, WIDTH, HEIGHT, S);
  localparam integer LSB_Y1 = rs_entry_lsb(RS_ENTRY_Y1, WIDTH, HEIGHT, S);
  localparam integer LSB_LAST_OFFSET = rs_entry_lsb(RS_ENTRY_LAST_OFFSET, WIDTH, HEIGHT, S);
  localparam integer LSB_LEFT = rs_entry_lsb(RS_ENTRY_LEFT, WIDTH, HEIGHT, S);
  localparam integer LSB_RIGHT = rs_entry_lsb(RS_ENTRY_RIGHT, WIDTH, HEIGHT, S);
  localparam integer LSB_STEP_Y = rs_entry_lsb(RS_ENTRY_STEP_Y, WIDTH, HEIGHT, S);
  localparam integer LSB_STEP_QUOT = rs_entry_lsb(RS_ENTRY_STEP_QUOT, WIDTH, HEIGHT, S);
  localparam integer LSB_STEP_REM = rs_entry_lsb(RS_ENTRY_STEP_REM, WIDTH, HEIGHT, S);
  localparam integer LSB_STEP_REM_LESS = rs_entry_lsb(RS_ENTRY_STEP_REM_LESS, WIDTH, HEIGHT, S);
  localparam integer LSB_EDGE_ROW = rs_entry_lsb(RS_ENTRY_EDGE_ROW, WIDTH, HEIGHT, S);
  localparam integer LSB_QUOT = rs_entry_lsb(RS_ENTRY_QUOT, WIDTH, HEIGHT, S);
  localparam integer LSB_REM_LESS = rs_entry_lsb(RS_ENTRY_REM_LESS, WIDTH, HEIGHT, S);
  localparam integer LSB_SPAN_START = rs_entry_lsb(RS_ENTRY_SPAN_START, WIDTH, HEIGHT, S);
  localparam integer LSB_SPAN_END = rs_entry_lsb(RS_ENTRY_SPAN_END, WIDTH, HEIGHT, S);
  localparam integer LSB_ROW_EMPTY = rs_entry_lsb(RS_ENTRY_ROW_EMPTY, WIDTH, HEIGHT, S);
  localparam integer LSB_ENTER_LEFT = rs_entry_lsb(RS_ENTRY_ENTER_LEFT, WIDTH, HEIGHT, S);
  localparam integer LSB_ENTER_SLOT = rs_entry_lsb(RS_ENTRY_ENTER_SLOT, WIDTH, HEIGHT, S);
  localparam integer LSB_LEFT_CARRY = rs_entry_lsb(RS_ENTRY_LEFT_CARRY, WIDTH, HEIGHT, S);
  wire [X_BITS-1:0] in_x0 = in_entry[LSB_X0 +: X_BITS];
  wire [Y_BITS-1:0] in_y0 = in_entry[LSB_Y0 +: Y_BITS];
  wire [Y_BITS-1:0] in_y1 = in_entry[LSB_Y1 +: Y_BITS];
  wire [X_BITS-1:0] in_span_start = in_entry[LSB_SPAN_START +: X_BITS];

  wire signed [EDGE_BITS-1:0] in_step_y_wide [0:2];     // sign-extended
  wire signed [EDGE_BITS-1:0] in_step_quot_wide [0:2];
  genvar g;
  generate
    for (g = 0; g < 3; g = g + 1) begin : widen
      wire [EDGE_STEP_Y_BITS-1:0] step_y = in_entry[LSB_STEP_Y + g*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS];
      wire [EDGE_STEP_Y_BITS-1:0] step_quot = in_entry[LSB_STEP_QUOT + g*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS];
      assign in_step_y_wide[g] = {{(EDGE_BITS-EDGE_STEP_Y_BITS){step_y[EDGE_STEP_Y_BITS-1]}}, step_y};
      assign in_step_quot_wide[g] = {{(EDGE_BITS-EDGE_STEP_Y_BITS){step_quot[EDGE_STEP_Y_BITS-1]}}, step_quot};
    end
  endgenerate

  wire span_traversal = cfg_traversal == rastersim_pkg::TRAVERSAL_SPAN;
  reg walking_q;  // a triangle is loaded and not finished

  reg [X_BITS-1:0] x0_q, x1_q, x_end_q, last_offset_q;
  reg [Y_BITS-1:0] y1_q;
  reg          row_empty_q;                // the current row has no covered pixel
  reg [X_BITS-1:0] span_start_q;           // bbox: the current row's first covered pixel
  reg [2:0] left_q, right_q;               // edge k's step_x > 0, < 0
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
  // bbox: the pixel lies in its row's span (the span's pixels are exactly those with every edge >= 0),
  // found a candidate ahead (covered_q), so that no compare sits before the z-buffer handshake.
  reg covered_q;
  assign frag_valid = walking_q && (span_traversal ? !row_empty_q : covered_q);
  wire advance = walking_q && (frag_ready || !frag_valid);
  wire row_done = span_traversal ? row_empty_q || frag_x == x_end_q : frag_x == x1_q;
  reg  last_row_q;  // frag_y == y1, kept as a register (set with frag_y)
  assign last = advance && row_done && last_row_q;
  assign in_ready = !walking_q || last;
  wire load = in_valid && in_ready;
  wire next_row = advance && row_done && !last_row_q;
  wire enter_row = load || next_row;
  // mid_walk_q = walking_q && !last_row_q: a next row can come (else only a load), kept as a
  // register of its own. It chooses between the entry and the registers' next row wherever both
  // feed a register or the plane registers' control, so that the choice does not wait for the
  // z-buffer's ready (`load` and `next_row` only enable). Reset (and all zeros) is idle.
  reg mid_walk_q;

  // ---- the next row, from the registers: its span, and the DDA stepped to the row after it ----
  wire [2:0] lo_fits_last, hi_le_last, dda_carry, edge_negative;
  wire [REM_BITS-1:0] next_rem_less [0:2];
  wire signed [EDGE_BITS-1:0] next_quot [0:2];
  wire [3*EDGE_BITS-1:0] quot_packed;
  generate
    for (g = 0; g < 3; g = g + 1) begin : dda
      assign quot_packed[g*EDGE_BITS +: EDGE_BITS] = quot_q[g];
      assign edge_negative[g] = edge_row_q[g][EDGE_BITS-1];
      // Each quotient against the box's last offset (span_bounds).
      wire [X_BITS+1:0] lo_sum = {quot_q[g][X_BITS], quot_q[g][X_BITS:0]} + {2'b00, last_offset_q};
      assign lo_fits_last[g] = !lo_sum[X_BITS+1];
      assign hi_le_last[g] = quot_q[g][X_BITS-1:0] <= last_offset_q;
      // The step: quot += step_quot (+ 1 on the remainder's carry); both quotient sums side by
      // side, the carry picks one. All EDGE_BITS bits: modular, sign-agnostic. A horizontal edge's
      // quotient is the record's 0 throughout (the span bounds rely on it); its remainder is
      // never used.
      wire [REM_BITS-1:0] rem_sum = rem_less_q[g] + step_rem_q[g];
      assign dda_carry[g] = !rem_sum[REM_BITS-1];
      assign next_rem_less[g] = dda_carry[g] ? rem_less_q[g] + step_rem_less_q[g] : rem_sum;
      wire signed [EDGE_BITS-1:0] quot_sum = quot_q[g] + step_quot_q[g];
      wire signed [EDGE_BITS-1:0] quot_carried = quot_q[g] + step_quot_q[g] + CARRY;
      assign next_quot[g] = !(left_q[g] || right_q[g]) ? quot_q[g] : dda_carry[g] ? quot_carried : quot_sum;
    end
  endgenerate
  wire [X_BITS-1:0] span_start, span_end;
  wire span_nonempty, lo_from_x0, enter_slot;
  span_bounds #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(S)) next_row_span (
    .quot(quot_packed), .left(left_q), .right(right_q), .edge_negative(edge_negative), .x0(x0_q), .x1(x1_q),
    .lo_fits_last(lo_fits_last), .hi_le_last(hi_le_last), .span_start(span_start), .span_end(span_end),
    .nonempty(span_nonempty), .lo_from_x0(lo_from_x0), .enter_slot(enter_slot));

  assign adder_load = load;
  assign adder_step_x = advance && !row_done;
  assign adder_next_row = next_row && !span_traversal;
  assign adder_row_enter = next_row && span_traversal;
  // The plane registers enter a span row at x0 or at the chosen left edge's span start (bbox: x0).
  // Slot j is the j-th left edge in edge order; a triangle has at most two.
  assign adder_enter_left = span_traversal && (mid_walk_q ? !lo_from_x0 : in_entry[LSB_ENTER_LEFT]);
  assign adder_enter_slot = mid_walk_q ? enter_slot : in_entry[LSB_ENTER_SLOT];
  assign adder_left_carry = mid_walk_q ? {left_q[0] && left_q[1] ? dda_carry[1] : dda_carry[2],
                                          left_q[0] ? dda_carry[0] : left_q[1] ? dda_carry[1] : dda_carry[2]}
                                       : in_entry[LSB_LEFT_CARRY +: 2];

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
      x1_q <= in_entry[LSB_X1 +: X_BITS];
      last_offset_q <= in_entry[LSB_LAST_OFFSET +: X_BITS];
      y1_q <= in_y1;
      frag_y <= in_y0;
      last_row_q <= in_y0 == in_y1;
      left_q <= in_entry[LSB_LEFT +: 3];
      right_q <= in_entry[LSB_RIGHT +: 3];
      for (i = 0; i < 3; i = i + 1) begin
        step_y_q[i] <= in_step_y_wide[i];
        step_quot_q[i] <= in_step_quot_wide[i];
        step_rem_q[i] <= {1'b0, in_entry[LSB_STEP_REM + i*SPAN_REM_BITS +: SPAN_REM_BITS]};
        step_rem_less_q[i] <= in_entry[LSB_STEP_REM_LESS + i*REM_BITS +: REM_BITS];
      end
    end else if (advance) begin
      if (!row_done) begin
        frag_x <= frag_x + 1'b1;
        covered_q <= !row_empty_q && frag_x + 1'b1 >= span_start_q && frag_x + 1'b1 <= x_end_q;
      end else if (!last_row_q) begin
        frag_y <= frag_y + 1'b1;
        last_row_q <= frag_y + 1'b1 == y1_q;
      end
    end
    if (enter_row) begin
      // The row about to start: its span (span traversal starts there, bbox at x0); the DDA steps
      // every edge to the row after it.
      // A row's first bbox candidate, x0, is covered when the span starts there: no left edge
      // bounds it (a small lower bound is at least 1).
      if (mid_walk_q) begin
        frag_x <= span_traversal ? span_start : x0_q;
        covered_q <= span_nonempty && lo_from_x0;
        span_start_q <= span_start;
        x_end_q <= span_end;
        row_empty_q <= !span_nonempty;
        for (i = 0; i < 3; i = i + 1) begin
          edge_row_q[i] <= edge_row_q[i] + step_y_q[i];
          rem_less_q[i] <= next_rem_less[i];
          quot_q[i] <= next_quot[i];
        end
      end else begin
        frag_x <= span_traversal ? in_span_start : in_x0;
        covered_q <= !in_entry[LSB_ROW_EMPTY] && !in_entry[LSB_ENTER_LEFT];
        span_start_q <= in_span_start;
        x_end_q <= in_entry[LSB_SPAN_END +: X_BITS];
        row_empty_q <= in_entry[LSB_ROW_EMPTY];
        for (i = 0; i < 3; i = i + 1) begin
          edge_row_q[i] <= in_entry[LSB_EDGE_ROW + i*EDGE_BITS +: EDGE_BITS];
          rem_less_q[i] <= in_entry[LSB_REM_LESS + i*REM_BITS +: REM_BITS];
          quot_q[i] <= in_entry[LSB_QUOT + i*EDGE_BITS +: EDGE_BITS];
        end
      end
    end
  end

`include "rastersim_assert.vh"
  // A fragment stays offered until the z-buffer (or texture unit) takes it; it lies inside the
  // bounding box of its triangle and on the screen.
  `RS_ASSERT_HELD(fragment_held, frag_valid, frag_ready, {frag_x, frag_y})
  `RS_ASSERT(fragment_in_box, !frag_valid || (x0_q <= frag_x && frag_x <= x1_q && frag_y <= y1_q))
  `RS_ASSERT(fragment_on_screen, !frag_valid || (32'(frag_x) < WIDTH && 32'(frag_y) < HEIGHT))
  // The plane registers enter a row at a left edge's slot only when that slot holds a left edge
  // (slot 1: the triangle has two); the edges' sides are the entry's at a load, else the registers'.
  `RS_ASSERT(left_slot_holds_a_left_edge,
      !(((adder_row_enter && span_nonempty) || (adder_load && cfg_traversal && !in_entry[LSB_ROW_EMPTY])) && adder_enter_left)
      || (adder_enter_slot ? {1'b0, mid_walk_q ? left_q[0] : in_entry[LSB_LEFT]} + {1'b0, mid_walk_q ? left_q[1] : in_entry[LSB_LEFT + 1]}
                             + {1'b0, mid_walk_q ? left_q[2] : in_entry[LSB_LEFT + 2]} >= 2'd2
                           : |(mid_walk_q ? left_q : in_entry[LSB_LEFT +: 3])))
endmodule
