// Iterative restoring divider: one quotient bit per cycle, MSB first, DIVIDEND_BITS cycles.
// Floor division of a signed dividend (given as sign and magnitude) by a positive divisor, as
// model/fixed.h floor_div: unsigned q0, r0 = |n| / d; for n < 0: q = -q0 - (r0 != 0),
// r = r0 ? d - r0 : 0. The quotient is kept modulo 2^QUOTIENT_BITS (the plane registers wrap).
//
// Timing: `start` in cycle s loads the operands; iterations run in cycles s+1 .. s+DIVIDEND_BITS;
// `quotient` / `remainder` are valid from cycle s+DIVIDEND_BITS+1 and held until the next start.
module divider #(
  parameter integer DIVIDEND_BITS = 8,   // magnitude width of the dividend, u
  parameter integer DIVISOR_BITS = 8,    // divisor width, u (divisor > 0)
  parameter integer QUOTIENT_BITS = 8    // kept quotient bits (two's complement, wraps)
) (
  input  wire                            clk,
  input  wire                            start,
  input  wire                            dividend_negative,
  input  wire [DIVIDEND_BITS-1:0]        dividend_magnitude,
  input  wire [DIVISOR_BITS-1:0]         divisor,
  output wire                            busy,
  output wire signed [QUOTIENT_BITS-1:0] quotient,   // floor(n / d) mod 2^QUOTIENT_BITS
  output wire [DIVISOR_BITS-1:0]         remainder   // n - d * floor(n / d), in [0, d)
);
  localparam integer COUNT_BITS = $clog2(DIVIDEND_BITS + 1);
  localparam [COUNT_BITS-1:0] ITERATIONS = DIVIDEND_BITS[COUNT_BITS-1:0];

  reg [DIVIDEND_BITS-1:0] dividend_bits;  // not yet consumed dividend bits, MSB first
  reg [DIVISOR_BITS-1:0]  divisor_q;
  reg [DIVISOR_BITS-1:0]  partial;        // partial remainder, always < divisor
  reg [QUOTIENT_BITS-1:0] quotient_mag;   // q0 mod 2^QUOTIENT_BITS
  reg                     negative;
  reg [COUNT_BITS-1:0]    remaining;      // iterations still to do

  // One restoring step: shift in the next dividend bit, subtract when it fits. The shifted value
  // is < 2 * divisor, so one extra bit suffices.
  wire [DIVISOR_BITS:0] shifted = {partial, dividend_bits[DIVIDEND_BITS-1]};
  wire [DIVISOR_BITS:0] difference = shifted - {1'b0, divisor_q};
  wire                  fits = !difference[DIVISOR_BITS];

  always @(posedge clk) begin
    if (start) begin
      dividend_bits <= dividend_magnitude;
      divisor_q <= divisor;
      partial <= {DIVISOR_BITS{1'b0}};
      quotient_mag <= {QUOTIENT_BITS{1'b0}};
      negative <= dividend_negative;
      remaining <= ITERATIONS;
    end else if (remaining != {COUNT_BITS{1'b0}}) begin
      dividend_bits <= dividend_bits << 1;
      partial <= fits ? difference[DIVISOR_BITS-1:0] : shifted[DIVISOR_BITS-1:0];
      quotient_mag <= {quotient_mag[QUOTIENT_BITS-2:0], fits};
      remaining <= remaining - 1'b1;
    end
  end

  assign busy = remaining != {COUNT_BITS{1'b0}};

  // Floor correction for a negative dividend: -q0 - 1 = ~q0 when a remainder is left.
  wire remainder_nonzero = partial != {DIVISOR_BITS{1'b0}};
  assign quotient = !negative ? quotient_mag
                  : remainder_nonzero ? ~quotient_mag
                  : -quotient_mag;
  assign remainder = (negative && remainder_nonzero) ? divisor_q - partial : partial;
endmodule
