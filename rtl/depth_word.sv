// The depth word (model/z_adder.h DepthWord::encode; docs/arithmetic.md section 6): the plane's
// output X (0 <= X < 2^Np) as the z-buffer stores it. With DEPTH_EXPONENT_BITS Ne >= 2 the unsigned
// floating-point word {e, mantissa} of Z_BITS bits, Nm = Z_BITS - Ne mantissa bits: X < 2^Nm gives
// e = 0 and X; else e = floor(log2 X) - Nm + 1 and the bits below X's leading one, truncated. With
// Ne = 0 or 1 the word is X itself. Combinational: the z-buffer encodes a fragment between its input
// buffer and its read (docs/cycle-model.md, "Depth output stage"), the core's trace port likewise.
`include "rastersim_pkg.sv"
module depth_word #(
  parameter integer Z_BITS = 24,
  parameter integer DEPTH_EXPONENT_BITS = 0
) (
  // X, Np bits (rastersim_widths.vh rs_depth_plane_bits, written out: a file before
  // rastersim_core.sv in rtl/rastersim.f that includes the widths header upsets Verilator 5.006's
  // lint of the core).
  input  wire [(DEPTH_EXPONENT_BITS == 0 ? Z_BITS : Z_BITS - DEPTH_EXPONENT_BITS + (1 << DEPTH_EXPONENT_BITS) - 1)-1:0] value,
  output wire [Z_BITS-1:0] word
);
  generate
    if (DEPTH_EXPONENT_BITS >= 2) begin : float_word
      localparam integer NE = DEPTH_EXPONENT_BITS;
      localparam integer NM = Z_BITS - NE;
      reg [Z_BITS-1:0] encoded;
      integer e;
      always @* begin
        encoded = {{NE{1'b0}}, value[NM-1:0]};
        for (e = 1; e < (1 << NE); e = e + 1)  // the highest set bit at NM + e - 1 wins
          if (value[NM + e - 1]) encoded = {e[NE-1:0], value[e - 1 +: NM]};
      end
      assign word = encoded;
    end else begin : fixed_word
      assign word = value;  // Ne = 1: Np = Z_BITS, the same word
    end
  endgenerate
endmodule
