// Included at the end of rtl/scanline_walker.sv by scripts/formal.sh (formal runs only): what the
// walker may assume of its inputs, and a record of the triangle it took at its last load.
// The setup unit hands over a bounding box inside the screen (x0 <= x1 < WIDTH, y0 <= y1 < HEIGHT),
// and the traversal does not change mid-walk; edge values, steps and span quotients are free, but
// for a horizontal edge (step_x = 0) the setup leaves the span quotient 0.
// The proof starts in the reset state (all registers zero: not walking) and rst stays low.
  reg f_loaded = 1'b0;
  reg f_traversal;
  reg [X_BITS-1:0] f_x0, f_x1;
  reg [Y_BITS-1:0] f_y0, f_y1;
  reg signed [EDGE_BITS-1:0] f_start [0:2];
  reg signed [EDGE_BITS-1:0] f_step_x [0:2];
  reg signed [EDGE_BITS-1:0] f_step_y [0:2];
  integer f_k;
  always @(posedge clk) begin
    if (load) begin
      f_loaded <= 1'b1;
      f_traversal <= cfg_traversal;
      f_x0 <= in_x0;
      f_x1 <= in_x1;
      f_y0 <= in_y0;
      f_y1 <= in_y1;
      for (f_k = 0; f_k < 3; f_k = f_k + 1) begin
        f_start[f_k] <= in_edge_start[f_k*EDGE_BITS +: EDGE_BITS];
        f_step_x[f_k] <= $signed(in_edge_step_x[f_k*EDGE_STEP_X_BITS +: EDGE_STEP_X_BITS]);  // sign-extended by the assignment
        f_step_y[f_k] <= $signed(in_edge_step_y[f_k*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS]);
      end
    end
  end

  always @* begin
    assume(!rst);
    if (load) begin
      assume(in_x0 <= in_x1 && in_x1 <= WIDTH - 1 && in_y0 <= in_y1 && in_y1 <= HEIGHT - 1);
      for (f_k = 0; f_k < 3; f_k = f_k + 1)
        if (in_edge_step_x[f_k*EDGE_STEP_X_BITS +: EDGE_STEP_X_BITS] == 0) assume(in_span_quot[f_k*EDGE_BITS +: EDGE_BITS] == 0);
    end
    // Constant while a triangle is walked (a load in its last cycle keeps it for the next one).
    if (walking_q) assume(cfg_traversal == f_traversal);
  end
