// Included at the end of rtl/plane_register.sv by scripts/formal.sh (formal runs only). The Z
// adder's recurrence: whatever sequence of load, step_x, next_row and row_enter the walker drives,
// entering rows at x0 or at either left-edge slot with any DDA carries, the register holds the plane
// stepped the plain way. With s, dx, dy taken at the last load and each slot's SQ (the plane change
// of its edge's per-row quotient, left_step = dy - SQ) free here (all modulo 2^REG_BITS, as the
// register wraps):
//   row     = s + dy per row since the load
//   E_j     = slot j's plane at its edge's span start on the current row: left_start at the load,
//             then per entered row + dy - SQ_j - (the carry given one entry before) dx
//   value   = the row's start (row, or E of the entered slot) + dx per x step since
// and the output is clamp((value + 2^(F-1)) >>> F, 0, 2^OUT_BITS - 1), written here independently.
// The register instead keeps each slot one row ahead with the carry one row behind and its two
// steps precomputed, so that no sum waits for the walker (docs/cycle-model.md). A triangle's rows
// are either all wrapped (bbox) or all entered (span). Proven by induction (unbounded sequences).
  (* anyseq *) wire [REG_BITS-1:0] f_any_sq_0, f_any_sq_1;
  reg f_loaded = 1'b0;
  reg f_wrapped, f_entered;  // since the load: rows by next_row, rows by row_enter
  reg [REG_BITS-1:0] f_dx, f_dy, f_row, f_value;
  reg [REG_BITS-1:0] f_e0, f_e1, f_sq0, f_sq1;
  reg [1:0] f_c;  // the carries given at the last entry (or load)
  wire [REG_BITS-1:0] f_e0_next = f_e0 + f_dy - f_sq0 - (f_c[0] ? f_dx : {REG_BITS{1'b0}});
  wire [REG_BITS-1:0] f_e1_next = f_e1 + f_dy - f_sq1 - (f_c[1] ? f_dx : {REG_BITS{1'b0}});
  always @* begin
    if (load) begin
      assume(left_step[0 +: REG_BITS] == step_y_in - f_any_sq_0);
      assume(left_step[REG_BITS +: REG_BITS] == step_y_in - f_any_sq_1);
    end
    // The walker's contract: one traversal per triangle.
    if (f_loaded && !load && row_enter) assume(!f_wrapped);
    if (f_loaded && !load && next_row) assume(!f_entered);
  end
  always @(posedge clk) begin
    if (load) begin
      f_loaded <= 1'b1;
      f_wrapped <= 1'b0;
      f_entered <= 1'b0;
      f_dx <= step_x_in; f_dy <= step_y_in;
      f_row <= start;
      f_e0 <= left_start[0 +: REG_BITS]; f_e1 <= left_start[REG_BITS +: REG_BITS];
      f_sq0 <= f_any_sq_0; f_sq1 <= f_any_sq_1;
      f_c <= left_carry;
      f_value <= !enter_left ? start : enter_slot ? left_start[REG_BITS +: REG_BITS] : left_start[0 +: REG_BITS];
    end else if (row_enter) begin
      f_entered <= 1'b1;
      f_e0 <= f_e0_next; f_e1 <= f_e1_next;
      f_c <= left_carry;
      f_row <= f_row + f_dy;
      f_value <= !enter_left ? f_row + f_dy : enter_slot ? f_e1_next : f_e0_next;
    end else if (next_row) begin
      f_wrapped <= 1'b1;
      f_row <= f_row + f_dy;
      f_value <= f_row + f_dy;
    end else if (step_x) begin
      f_value <= f_value + f_dx;
    end
  end
  wire signed [REG_BITS-1:0] f_biased = f_value + (1 << (GUARD_BITS - 1));
  wire signed [REG_BITS-1:0] f_shifted = f_biased >>> GUARD_BITS;
  wire [OUT_BITS-1:0] f_out = f_shifted < 0 ? 0 : f_shifted > (1 << OUT_BITS) - 1 ? {OUT_BITS{1'b1}} : f_shifted[OUT_BITS-1:0];
  always @* begin
    if (f_loaded) begin
      assert(step_x_q == f_dx);
      assert(step_y_q == f_dy);
      assert(row_q == f_row);
      assert(value_q == f_value);
      assert(out == f_out);
      assert(carry_q == f_c);
      assert(along_step_q[0] == f_dy - f_sq0);
      assert(along_step_q[1] == f_dy - f_sq1);
      assert(along_step_carry_q[0] == f_dy - f_sq0 - f_dx);
      assert(along_step_carry_q[1] == f_dy - f_sq1 - f_dx);
      if (!f_wrapped) begin
        assert(along_q[0] == f_e0 + f_dy - f_sq0);
        assert(along_q[1] == f_e1 + f_dy - f_sq1);
      end
    end
  end
  // ENTRY_AHEAD: each slot's along_q - step_x, kept in a register of its own.
  generate
    if (ENTRY_AHEAD != 0) begin : f_ahead
      always @* if (f_loaded && !f_wrapped) begin
        assert(slots[0].ahead.along_carry_q == f_e0 + f_dy - f_sq0 - f_dx);
        assert(slots[1].ahead.along_carry_q == f_e1 + f_dy - f_sq1 - f_dx);
      end
    end
  endgenerate
