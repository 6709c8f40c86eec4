// Included at the end of rtl/scanline_walker.sv by scripts/formal.sh, after
// scanline_walker_inputs.svh. Coverage equals the edge functions' sign test: at every bbox
// candidate (x, y), frag_valid is exactly E_k(x, y) >= 0 for all three edges, with the exact
// E_k(x, y) = start_k + (x - x0) step_x_k + (y - y0) step_y_k (the walker finds it from the span
// DDA and bounds, no edge value is stepped per pixel); in both traversals the edge row registers
// hold the edge values at x0 of the row after the current one (modulo 2^EDGE_BITS, as they wrap).
// Assumed of the record, as the setup unit guarantees it (model/triangle_setup.cpp): the span
// fields are the floor divisions of start and step_y by d = |step_x| (all zero when step_x = 0),
// and every edge value inside the box fits EDGE_BITS (the widths are derived for the screen).
  localparam integer F_WIDE = EDGE_BITS + EDGE_STEP_Y_BITS + 4;  // holds every product and sum below
  // n * a for an n of EDGE_STEP_X_BITS + 1 bits (a divisor d, or an offset inside the box: at the
  // proof's small boxes EDGE_STEP_X_BITS > X_BITS, Y_BITS), as shifts and adds: the
  // solver then handles a few adders instead of an F_WIDE x F_WIDE multiplier.
  function automatic signed [F_WIDE-1:0] times_small(input signed [EDGE_STEP_X_BITS:0] n, input signed [F_WIDE-1:0] a);
    integer b;
    begin
      times_small = n[EDGE_STEP_X_BITS] ? -(a <<< EDGE_STEP_X_BITS) : {F_WIDE{1'b0}};
      for (b = 0; b < EDGE_STEP_X_BITS; b = b + 1) if (n[b]) times_small = times_small + (a <<< b);
    end
  endfunction
  // An edge's exact value at (x, y): start at (x0, y0), stepped by step_x per pixel and step_y per row.
  function automatic signed [F_WIDE-1:0] edge_at(input signed [F_WIDE-1:0] start, input signed [F_WIDE-1:0] step_x,
                                                 input signed [F_WIDE-1:0] step_y, input [X_BITS-1:0] x0,
                                                 input [Y_BITS-1:0] y0, input [X_BITS-1:0] x, input [Y_BITS-1:0] y);
    reg signed [F_WIDE-1:0] dx, dy;
    begin
      dx = $signed({1'b0, x}) - $signed({1'b0, x0});
      dy = $signed({1'b0, y}) - $signed({1'b0, y0});
      edge_at = start + times_small(dx[EDGE_STEP_X_BITS:0], step_x) + times_small(dy[EDGE_STEP_X_BITS:0], step_y);
    end
  endfunction
  // Edge k of the triangle taken at the last load.
  function automatic signed [F_WIDE-1:0] exact(input integer k, input [X_BITS-1:0] x, input [Y_BITS-1:0] y);
    exact = edge_at(f_start[k], f_step_x[k], f_step_y[k], f_x0, f_y0, x, y);
  endfunction
  function automatic fits_edge_bits(input signed [F_WIDE-1:0] v);
    fits_edge_bits = v >= -(64'sd1 <<< (EDGE_BITS - 1)) && v < (64'sd1 <<< (EDGE_BITS - 1));
  endfunction

  // The record at its load: the DDA fields are floor divisions (multiplication by d < 2^EDGE_STEP_X_BITS).
  integer f_r;
  always @* begin
    if (load) begin
      for (f_r = 0; f_r < 3; f_r = f_r + 1) begin : record_dda
        reg signed [F_WIDE-1:0] sx, d, start, step_y, quot, rem, step_quot, step_rem;
        sx = $signed(f_rec_edge_step_x[f_r*EDGE_STEP_X_BITS +: EDGE_STEP_X_BITS]);
        d = sx < 0 ? -sx : sx;
        start = $signed(f_rec_edge_start[f_r*EDGE_BITS +: EDGE_BITS]);
        step_y = $signed(f_rec_edge_step_y[f_r*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS]);
        quot = $signed(f_rec_span_quot[f_r*EDGE_BITS +: EDGE_BITS]);
        rem = $signed({1'b0, f_rec_span_rem[f_r*SPAN_REM_BITS +: SPAN_REM_BITS]});
        step_quot = $signed(f_rec_span_step_quot[f_r*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS]);
        step_rem = $signed({1'b0, f_rec_span_step_rem[f_r*SPAN_REM_BITS +: SPAN_REM_BITS]});
        if (sx == 0) assume(quot == 0 && rem == 0 && step_quot == 0 && step_rem == 0);
        else assume(start == times_small(d[EDGE_STEP_X_BITS:0], quot) + rem && rem < d
                    && step_y == times_small(d[EDGE_STEP_X_BITS:0], step_quot) + step_rem && step_rem < d);
      end
    end
  end
  // Every edge value of the box fits (they are linear: the four corners suffice), assumed once, at
  // the load, of the record (f_* hold it from the next cycle on).
  function automatic signed [F_WIDE-1:0] record_at(input integer k, input [X_BITS-1:0] x, input [Y_BITS-1:0] y);
    record_at = edge_at($signed(f_rec_edge_start[k*EDGE_BITS +: EDGE_BITS]),
                        $signed(f_rec_edge_step_x[k*EDGE_STEP_X_BITS +: EDGE_STEP_X_BITS]),
                        $signed(f_rec_edge_step_y[k*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS]), f_rec_x0, f_rec_y0, x, y);
  endfunction
  genvar f_g;
  for (f_g = 0; f_g < 3; f_g = f_g + 1) begin : f_fit
    always @* if (load) assume(fits_edge_bits(record_at(f_g, f_rec_x0, f_rec_y0)) && fits_edge_bits(record_at(f_g, f_rec_x1, f_rec_y0))
                               && fits_edge_bits(record_at(f_g, f_rec_x0, f_rec_y1)) && fits_edge_bits(record_at(f_g, f_rec_x1, f_rec_y1)));
  end

  wire signed [F_WIDE-1:0] f_at_pixel [0:2];
  wire signed [F_WIDE-1:0] f_next_row [0:2];
  for (f_g = 0; f_g < 3; f_g = f_g + 1) begin : f_forms
    assign f_at_pixel[f_g] = exact(f_g, frag_x, frag_y);
    assign f_next_row[f_g] = exact(f_g, f_x0, frag_y) + f_step_y[f_g];
  end

  integer f_e;
  always @* begin
    if (f_loaded && walking_q && !cfg_traversal)
      assert(frag_valid == (f_at_pixel[0] >= 0 && f_at_pixel[1] >= 0 && f_at_pixel[2] >= 0));
    if (f_loaded && walking_q)
      for (f_e = 0; f_e < 3; f_e = f_e + 1) assert(edge_row_q[f_e] == f_next_row[f_e][EDGE_BITS-1:0]);
  end
