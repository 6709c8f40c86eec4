// One plane register of the Z adder (model/z_adder.h PlaneRegister): a wrapping two's-complement
// value of REG_BITS with GUARD_BITS fraction bits, a row register keeping the row start, and the
// per-pixel steps. Additions only, except the span walker's once-per-row offset multiply (at load
// for the first row, at row_enter for the others).
module plane_register #(
  parameter integer REG_BITS = 37,    // s(OUT_BITS+1).GUARD_BITS
  parameter integer GUARD_BITS = 12,  // F
  parameter integer OUT_BITS = 24,    // output u(OUT_BITS), clamped to [0, 2^OUT_BITS - 1]
  parameter integer OFFSET_BITS = 10  // span row offset t, u
) (
  input  wire clk,
  input  wire load,       // row = start; value = start + offset * step_x_in; take the steps
  input  wire step_x,     // value += step_x
  input  wire next_row,   // row += step_y; value = row (bbox row wrap)
  input  wire row_enter,  // row += step_y; value = row + offset * step_x (span: the next row)
  input  wire [OFFSET_BITS-1:0] offset,
  input  wire from_record,  // the product takes step_x_in (high whenever load may be), else step_x
  input  wire [REG_BITS-1:0] start,
  input  wire [REG_BITS-1:0] step_x_in,
  input  wire [REG_BITS-1:0] step_y_in,
  output wire [OUT_BITS-1:0] out        // clamp((value + 2^(F-1)) >>> F, 0, 2^OUT_BITS - 1)
);
  // Parameter legality, as RS_REQUIRE of rastersim_widths.vh checks it (that header is not included
  // here: Verilator 5.006's lint then reports its functions as hiding themselves in rastersim_core).
`ifdef __ICARUS__
  initial if (!(GUARD_BITS >= 1 && OUT_BITS >= 1 && REG_BITS >= OUT_BITS + GUARD_BITS + 1 && REG_BITS <= 64 && OFFSET_BITS >= 1)) $fatal(1, "plane_register: need GUARD_BITS, OUT_BITS, OFFSET_BITS >= 1 and OUT_BITS + GUARD_BITS + 1 <= REG_BITS <= 64");
`else
  if (!(GUARD_BITS >= 1 && OUT_BITS >= 1 && REG_BITS >= OUT_BITS + GUARD_BITS + 1 && REG_BITS <= 64 && OFFSET_BITS >= 1)) begin : illegal_widths
    $error("plane_register: need GUARD_BITS, OUT_BITS, OFFSET_BITS >= 1 and OUT_BITS + GUARD_BITS + 1 <= REG_BITS <= 64");
  end
`endif
  reg [REG_BITS-1:0] value_q, row_q, step_x_q, step_y_q;

  // Products and sums are taken modulo 2^REG_BITS: the register wraps by design.
  wire [REG_BITS-1:0] next_row_value = row_q + step_y_q;
  // Only the low REG_BITS of the product matter (modular register).
  /* verilator lint_off UNUSEDSIGNAL */
  // The operand follows from_record, not load, so that the product does not wait for the handshake.
  wire [REG_BITS-1:0] offset_step = from_record ? step_x_in : step_x_q;
  wire [REG_BITS+OFFSET_BITS-1:0] offset_product = {{OFFSET_BITS{1'b0}}, offset_step} * {{REG_BITS{1'b0}}, offset};
  /* verilator lint_on UNUSEDSIGNAL */

  always @(posedge clk) begin
    if (load) begin
      value_q <= start + offset_product[REG_BITS-1:0];
      row_q <= start;
      step_x_q <= step_x_in;
      step_y_q <= step_y_in;
    end else if (row_enter) begin
      value_q <= next_row_value + offset_product[REG_BITS-1:0];
      row_q <= next_row_value;
    end else if (next_row) begin
      value_q <= next_row_value;
      row_q <= next_row_value;
    end else if (step_x) begin
      value_q <= value_q + step_x_q;
    end
  end

  localparam integer ROUNDED_BITS = REG_BITS - GUARD_BITS;
  // The fraction bits are dropped by the rounding shift.
  /* verilator lint_off UNUSEDSIGNAL */
  wire [REG_BITS-1:0] biased = value_q + {{(REG_BITS-GUARD_BITS){1'b0}}, 1'b1, {(GUARD_BITS-1){1'b0}}};
  /* verilator lint_on UNUSEDSIGNAL */
  wire signed [ROUNDED_BITS-1:0] rounded = biased[REG_BITS-1:GUARD_BITS];
  wire [ROUNDED_BITS-1:0] out_max = {{(ROUNDED_BITS-OUT_BITS){1'b0}}, {OUT_BITS{1'b1}}};
  assign out = rounded[ROUNDED_BITS-1] ? {OUT_BITS{1'b0}}
             : rounded > $signed(out_max) ? {OUT_BITS{1'b1}}
             : rounded[OUT_BITS-1:0];
endmodule
