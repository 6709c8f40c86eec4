// One plane register of the Z adder (model/z_adder.h): a wrapping two's-complement value of
// REG_BITS with GUARD_BITS fraction bits, a row register keeping the row start, the per-pixel
// steps, and the plane along the triangle's two left-edge slots (docs/cycle-model.md). Additions
// only: the span walker enters a row at the row start (x0) or at a left edge's span start, whose
// plane value each slot steps from row to row.
`include "rastersim_pkg.sv"
module plane_register #(
  parameter integer REG_BITS = 37,    // s(OUT_BITS+1).GUARD_BITS
  parameter integer GUARD_BITS = 12,  // F
  parameter integer OUT_BITS = 24,    // output u(OUT_BITS), clamped to [0, 2^OUT_BITS - 1]
  parameter integer ROUNDING = 0,     // rastersim_pkg::ROUNDING_NEAREST: out adds 2^(F-1) before the shift; _TRUNCATE: not
  parameter integer ENTRY_AHEAD = 1   // 1: each slot's entry value ready in registers (wide planes); 0: formed on entry
) (
  input  wire clk,
  input  wire load,         // take the record; value = start, or the entered slot's left_start
  input  wire step_x,       // value += step_x
  input  wire next_row,     // row += step_y; value = row (bbox row wrap)
  input  wire row_enter,    // row += step_y; value = row, or the entered slot's value (span: the next row)
  input  wire enter_left,   // load, row_enter: the row starts at a left edge's span start (else at x0)
  input  wire enter_slot,   // which left-edge slot
  input  wire [rastersim_pkg::LEFT_EDGE_SLOTS-1:0] left_carry,  // load, row_enter: each slot's DDA carry into the row after this one
  input  wire [REG_BITS-1:0] start,
  input  wire [REG_BITS-1:0] step_x_in,
  input  wire [REG_BITS-1:0] step_y_in,
  input  wire [2*REG_BITS-1:0] left_start,  // slot j at [j*REG_BITS]: the plane at its span start, first row
  input  wire [2*REG_BITS-1:0] left_step,   // its change per row without the DDA's carry
  output wire [OUT_BITS-1:0] out,       // clamp((value + 2^(F-1) or 0) >>> F, 0, 2^OUT_BITS - 1)
  output wire [REG_BITS-1:0] value,     // the register itself (the texture planes' divide takes it)
  output wire [REG_BITS-1:0] next_value  // its value from the next cycle on
);
  // Parameter legality, as RS_REQUIRE of rastersim_widths.vh checks it (that header is not included
  // here: Verilator 5.006's lint then reports its functions as hiding themselves in rastersim_core).
`ifdef __ICARUS__
  initial if (!(GUARD_BITS >= 1 && OUT_BITS >= 1 && REG_BITS >= OUT_BITS + GUARD_BITS + 1 && REG_BITS <= 64)) $fatal(1, "plane_register: need GUARD_BITS, OUT_BITS >= 1 and OUT_BITS + GUARD_BITS + 1 <= REG_BITS <= 64");
`else
  if (!(GUARD_BITS >= 1 && OUT_BITS >= 1 && REG_BITS >= OUT_BITS + GUARD_BITS + 1 && REG_BITS <= 64)) begin : illegal_widths
    $error("plane_register: need GUARD_BITS, OUT_BITS >= 1 and OUT_BITS + GUARD_BITS + 1 <= REG_BITS <= 64");
  end
`endif
  reg [REG_BITS-1:0] value_q, row_q, step_x_q, step_y_q;
  // Per left-edge slot j, with the DDA's carry one row behind so that no sum waits for it:
  // along_q - carry_q * step_x = the plane at the slot edge's span start on the row after the
  // current one; along_step_q and along_step_carry_q (= along_step_q - step_x) step along_q.
  // With ENTRY_AHEAD, along_carry_q = along_q - step_x is kept beside along_q (stepped by the same
  // sums), so that entering a row selects registers and adds nothing; without it (a narrow plane,
  // whose subtraction is short) the entry subtracts.
  reg [REG_BITS-1:0] along_q [0:1];
  reg [REG_BITS-1:0] along_step_q [0:1];
  reg [REG_BITS-1:0] along_step_carry_q [0:1];
  reg [1:0] carry_q;

  // All sums are taken modulo 2^REG_BITS: the register wraps by design.
  wire [REG_BITS-1:0] next_row_value = row_q + step_y_q;
  wire [REG_BITS-1:0] record_left [0:1];
  wire [REG_BITS-1:0] record_step [0:1];
  wire [REG_BITS-1:0] entered [0:1];  // each slot's plane at its span start on the row being entered
  genvar j;
  generate
    for (j = 0; j < 2; j = j + 1) begin : slots
      assign record_left[j] = left_start[j*REG_BITS +: REG_BITS];
      assign record_step[j] = left_step[j*REG_BITS +: REG_BITS];
      if (ENTRY_AHEAD != 0) begin : ahead
        reg [REG_BITS-1:0] along_carry_q;
        // The record's left + step - step_x through one carry chain: a carry-save layer, then one
        // adder; -step_x is ~step_x + 1, the 1 in the shifted carries' empty low bit.
        wire [REG_BITS-1:0] a = record_left[j], b = record_step[j], c = ~step_x_in;
        wire [REG_BITS-1:0] save_sum = a ^ b ^ c;
        /* verilator lint_off UNUSEDSIGNAL */
        wire [REG_BITS-1:0] save_carry = (a & b) | (a & c) | (b & c);  // its top bit leaves the width
        /* verilator lint_on UNUSEDSIGNAL */
        always @(posedge clk)
          if (load) along_carry_q <= save_sum + {save_carry[REG_BITS-2:0], 1'b1};
          else if (row_enter) along_carry_q <= along_carry_q + (carry_q[j] ? along_step_carry_q[j] : along_step_q[j]);
        assign entered[j] = carry_q[j] ? along_carry_q : along_q[j];
      end else begin : on_entry
        assign entered[j] = carry_q[j] ? along_q[j] - step_x_q : along_q[j];
      end
    end
  endgenerate

  // The value the register takes at this cycle's end (the Z adder's bias works ahead on its low bits).
  assign next_value = load ? (enter_left ? record_left[enter_slot] : start)
                    : row_enter ? (enter_left ? entered[enter_slot] : next_row_value)
                    : next_row ? next_row_value
                    : step_x ? value_q + step_x_q
                    : value_q;

  integer k;
  always @(posedge clk) begin
    value_q <= next_value;
    if (load) begin
      row_q <= start;
      step_x_q <= step_x_in;
      step_y_q <= step_y_in;
      for (k = 0; k < 2; k = k + 1) begin
        along_q[k] <= record_left[k] + record_step[k];
        along_step_q[k] <= record_step[k];
        along_step_carry_q[k] <= record_step[k] - step_x_in;
      end
      carry_q <= left_carry;
    end else if (row_enter) begin
      row_q <= next_row_value;
      for (k = 0; k < 2; k = k + 1) along_q[k] <= along_q[k] + (carry_q[k] ? along_step_carry_q[k] : along_step_q[k]);
      carry_q <= left_carry;
    end else if (next_row) begin
      row_q <= next_row_value;
    end
  end

  assign value = value_q;
  localparam integer ROUNDED_BITS = REG_BITS - GUARD_BITS;
  // The fraction bits are dropped by the rounding shift.
  /* verilator lint_off UNUSEDSIGNAL */
  wire [REG_BITS-1:0] biased = value_q + {{(REG_BITS-GUARD_BITS){1'b0}}, 1'(ROUNDING == 0), {(GUARD_BITS-1){1'b0}}};
  /* verilator lint_on UNUSEDSIGNAL */
  wire signed [ROUNDED_BITS-1:0] rounded = biased[REG_BITS-1:GUARD_BITS];
  wire [ROUNDED_BITS-1:0] out_max = {{(ROUNDED_BITS-OUT_BITS){1'b0}}, {OUT_BITS{1'b1}}};
  assign out = rounded[ROUNDED_BITS-1] ? {OUT_BITS{1'b0}}
             : rounded > $signed(out_max) ? {OUT_BITS{1'b1}}
             : rounded[OUT_BITS-1:0];
endmodule
