// Included at the end of rtl/scanline_walker.sv by scripts/formal.sh (formal runs only): what the
// walker may assume of its inputs, and a record of the triangle it took at its last load.
// The setup unit hands over a bounding box inside the screen (x0 <= x1 < WIDTH, y0 <= y1 < HEIGHT),
// and the traversal does not change mid-walk; edge values, steps and span quotients are free, but
// for a horizontal edge (step_x = 0) the setup leaves the span quotient 0.
// The proof starts in the reset state (all registers zero: not walking) and rst stays low.
// The walker takes entries: the entry is scanline_walker_entry's of a free record (f_record), so
// that the proofs cover the entry stage too.
  (* anyseq *) wire [rs_rec_walker_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] f_record;
  wire [rs_entry_lsb(20, WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] f_entry;
  scanline_walker_entry #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS)) f_entry_stage (
    .record(f_record), .entry(f_entry));
  localparam integer EDGE_STEP_X_BITS = rs_edge_step_x_bits(HEIGHT, SUBPIXEL_BITS);
  wire [X_BITS-1:0] f_rec_x0 = f_record[rs_rec_lsb(RS_REC_X0, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0) +: X_BITS];
  wire [X_BITS-1:0] f_rec_x1 = f_record[rs_rec_lsb(RS_REC_X1, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0) +: X_BITS];
  wire [Y_BITS-1:0] f_rec_y0 = f_record[rs_rec_lsb(RS_REC_Y0, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0) +: Y_BITS];
  wire [Y_BITS-1:0] f_rec_y1 = f_record[rs_rec_lsb(RS_REC_Y1, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0) +: Y_BITS];
  wire [3*EDGE_BITS-1:0] f_rec_edge_start = f_record[rs_rec_lsb(RS_REC_EDGE_START, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0) +: 3*EDGE_BITS];
  wire [3*EDGE_STEP_X_BITS-1:0] f_rec_edge_step_x = f_record[rs_rec_lsb(RS_REC_EDGE_STEP_X, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0) +: 3*EDGE_STEP_X_BITS];
  wire [3*EDGE_STEP_Y_BITS-1:0] f_rec_edge_step_y = f_record[rs_rec_lsb(RS_REC_EDGE_STEP_Y, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0) +: 3*EDGE_STEP_Y_BITS];
  wire [3*EDGE_BITS-1:0] f_rec_span_quot = f_record[rs_rec_lsb(RS_REC_SPAN_QUOT, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0) +: 3*EDGE_BITS];
  wire [3*SPAN_REM_BITS-1:0] f_rec_span_rem = f_record[rs_rec_lsb(RS_REC_SPAN_REM, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0) +: 3*SPAN_REM_BITS];
  wire [3*EDGE_STEP_Y_BITS-1:0] f_rec_span_step_quot = f_record[rs_rec_lsb(RS_REC_SPAN_STEP_QUOT, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0) +: 3*EDGE_STEP_Y_BITS];
  wire [3*SPAN_REM_BITS-1:0] f_rec_span_step_rem = f_record[rs_rec_lsb(RS_REC_SPAN_STEP_REM, WIDTH, HEIGHT, SUBPIXEL_BITS, 0, 0) +: 3*SPAN_REM_BITS];
  always @* assume(in_entry == f_entry);
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
      f_x0 <= f_rec_x0;
      f_x1 <= f_rec_x1;
      f_y0 <= f_rec_y0;
      f_y1 <= f_rec_y1;
      for (f_k = 0; f_k < 3; f_k = f_k + 1) begin
        f_start[f_k] <= f_rec_edge_start[f_k*EDGE_BITS +: EDGE_BITS];
        f_step_x[f_k] <= $signed(f_rec_edge_step_x[f_k*EDGE_STEP_X_BITS +: EDGE_STEP_X_BITS]);  // sign-extended by the assignment
        f_step_y[f_k] <= $signed(f_rec_edge_step_y[f_k*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS]);
      end
    end
  end

  always @* begin
    assume(!rst);
    if (load) begin
      assume(f_rec_x0 <= f_rec_x1 && f_rec_x1 <= WIDTH - 1 && f_rec_y0 <= f_rec_y1 && f_rec_y1 <= HEIGHT - 1);
      for (f_k = 0; f_k < 3; f_k = f_k + 1)
        if (f_rec_edge_step_x[f_k*EDGE_STEP_X_BITS +: EDGE_STEP_X_BITS] == 0) assume(f_rec_span_quot[f_k*EDGE_BITS +: EDGE_BITS] == 0);
    end
    // Constant while a triangle is walked (a load in its last cycle keeps it for the next one).
    if (walking_q) assume(cfg_traversal == f_traversal);
  end
