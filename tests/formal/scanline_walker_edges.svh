// Included at the end of rtl/scanline_walker.sv by scripts/formal.sh, after
// scanline_walker_inputs.svh. Edge stepping equals the absolute form: at every candidate (x, y)
// the incrementally stepped edge values are E_k(x, y) = start_k + (x - x0) step_x_k +
// (y - y0) step_y_k (modulo 2^EDGE_BITS, as the registers wrap), the covered decision is the sign test of
// those values; in span traversal the edge row registers equal the absolute form of the row after
// the current one (the DDA registers run one row ahead).
  // n a modulo 2^EDGE_BITS for a small signed n (an offset inside the box), as shifts and adds: the
  // solver then handles a few adders instead of an EDGE_BITS x EDGE_BITS multiplier.
  function automatic [EDGE_BITS-1:0] times_x(input [X_BITS:0] n, input [EDGE_BITS-1:0] a);
    integer b;
    begin
      times_x = n[X_BITS] ? -(a << X_BITS) : {EDGE_BITS{1'b0}};
      for (b = 0; b < X_BITS; b = b + 1) if (n[b]) times_x = times_x + (a << b);
    end
  endfunction
  function automatic [EDGE_BITS-1:0] times_y(input [Y_BITS:0] n, input [EDGE_BITS-1:0] a);
    integer b;
    begin
      times_y = n[Y_BITS] ? -(a << Y_BITS) : {EDGE_BITS{1'b0}};
      for (b = 0; b < Y_BITS; b = b + 1) if (n[b]) times_y = times_y + (a << b);
    end
  endfunction

  function automatic signed [EDGE_BITS-1:0] absolute(input integer k, input [X_BITS-1:0] x, input [Y_BITS-1:0] y);
    reg [X_BITS:0] dx;
    reg [Y_BITS:0] dy;
    begin
      dx = {1'b0, x} - {1'b0, f_x0};
      dy = {1'b0, y} - {1'b0, f_y0};
      absolute = f_start[k] + times_x(dx, f_step_x[k]) + times_y(dy, f_step_y[k]);
    end
  endfunction
  wire signed [EDGE_BITS-1:0] f_at_pixel [0:2];
  wire signed [EDGE_BITS-1:0] f_at_row [0:2];
  genvar f_g;
  for (f_g = 0; f_g < 3; f_g = f_g + 1) begin : f_forms
    assign f_at_pixel[f_g] = absolute(f_g, frag_x, frag_y);
    assign f_at_row[f_g] = absolute(f_g, f_x0, frag_y);
  end

  integer f_e;
  always @* begin
    if (f_loaded && walking_q && !cfg_traversal) begin
      for (f_e = 0; f_e < 3; f_e = f_e + 1) assert(edge_value_q[f_e] == f_at_pixel[f_e]);
      assert(frag_valid == (f_at_pixel[0] >= 0 && f_at_pixel[1] >= 0 && f_at_pixel[2] >= 0));
    end
    if (f_loaded && walking_q && cfg_traversal)
      for (f_e = 0; f_e < 3; f_e = f_e + 1) assert(edge_row_q[f_e] == f_at_row[f_e] + f_step_y[f_e]);
  end
