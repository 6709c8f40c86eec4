// Included at the end of rtl/plane_register.sv by scripts/formal.sh (formal runs only). The Z
// adder's recurrence: whatever sequence of load, step_x, next_row and row_enter (any offset) the
// walker drives, the register equals the absolute form of its plane. With s, dx, dy taken at the
// last load and i, j counted here (all modulo 2^REG_BITS, as the register wraps):
//   value = s + j_value dy + i dx   (i: the offset the row was entered at plus the x steps since,
//                                    j_value: its row)
//   row   = s + j_row dy            (the row the value was last entered or wrapped to)
// and the output is clamp((value + 2^(F-1)) >>> F, 0, 2^OUT_BITS - 1), written here independently.
// Proven by induction (unbounded sequences); the unit's registers are the induction invariant.
  reg f_loaded = 1'b0;
  reg [REG_BITS-1:0] f_s, f_dx, f_dy, f_i, f_j_value, f_j_row;
  always @(posedge clk) begin
    if (load) begin
      f_loaded <= 1'b1;
      f_s <= start; f_dx <= step_x_in; f_dy <= step_y_in;
      f_i <= {{(REG_BITS-OFFSET_BITS){1'b0}}, offset};  // the span's first row entered at its offset
      f_j_value <= 0; f_j_row <= 0;
    end else if (row_enter) begin
      f_i <= {{(REG_BITS-OFFSET_BITS){1'b0}}, offset};
      f_j_value <= f_j_row + 1'b1;
      f_j_row <= f_j_row + 1'b1;
    end else if (next_row) begin
      f_i <= 0;
      f_j_value <= f_j_row + 1'b1;
      f_j_row <= f_j_row + 1'b1;
    end else if (step_x) begin
      f_i <= f_i + 1'b1;
    end
  end
  wire [REG_BITS-1:0] f_value = f_s + f_j_value * f_dy + f_i * f_dx;
  wire [REG_BITS-1:0] f_row = f_s + f_j_row * f_dy;
  wire signed [REG_BITS-1:0] f_biased = f_value + (1 << (GUARD_BITS - 1));
  wire signed [REG_BITS-1:0] f_shifted = f_biased >>> GUARD_BITS;
  wire [OUT_BITS-1:0] f_out = f_shifted < 0 ? 0 : f_shifted > (1 << OUT_BITS) - 1 ? {OUT_BITS{1'b1}} : f_shifted[OUT_BITS-1:0];
  // The walker's contract: the product takes the record's step in a load, the register's in a
  // row_enter.
  always @* begin
    if (load) assume(from_record);
    if (row_enter) assume(!from_record);
  end
  always @* begin
    if (f_loaded) begin
      assert(step_x_q == f_dx);
      assert(step_y_q == f_dy);
      assert(row_q == f_row);
      assert(value_q == f_value);
      assert(out == f_out);
    end
  end
