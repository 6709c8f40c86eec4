// The texture sampler's address stage (model/texture_sampler.h, axis_texels; docs/design/texturing.md,
// "The sampler"): from a fragment's u and v (s8.20) the texel columns and rows a lookup reads and
// the bilinear weights, registered (the texture unit's address register, docs/cycle-model.md:
// inputs of a cycle are in the outputs after one rising edge). Per axis, with T = 20 - log2 size:
// nearest reads floor(c 2^-T); bilinear the two texels around c - 2^(T-1), the second's weight the
// top 8 of its T fraction bits; repeat keeps an index's low log2-size bits, clamp limits it to
// [0, size - 1]. Nearest reads one texel: second == first, weight 0.
`include "rastersim_pkg.sv"
module texture_address (
  input  wire clk,
  input  wire [rastersim_pkg::UV_BITS-1:0] u,              // s8.20
  input  wire [rastersim_pkg::UV_BITS-1:0] v,
  input  wire [rastersim_pkg::TEXTURE_LOG2_BITS-1:0] cfg_log2_width,  // 0..10
  input  wire [rastersim_pkg::TEXTURE_LOG2_BITS-1:0] cfg_log2_height,
  input  wire cfg_bilinear,          // 0: nearest
  input  wire cfg_clamp,             // 0: repeat
  output reg  [rastersim_pkg::TEXTURE_COORD_BITS-1:0] x0_q, x1_q,      // the columns (first, second)
  output reg  [rastersim_pkg::TEXTURE_COORD_BITS-1:0] y0_q, y1_q,      // the rows
  output reg  [rastersim_pkg::TEXTURE_WEIGHT_BITS-1:0] wx_q, wy_q       // the weights of x1 and y1, in 1/256
);
  // One axis: {first, second, weight}; before wrapping an index lies within +-(2^17 + 1) texels.
  function automatic [27:0] axis(input [27:0] coord, input [3:0] log2_size, input bilinear, input clamp);
    reg [4:0] fraction_bits;
    reg signed [28:0] centred;  // one bit more than u: c - 1/2 reaches below -128
    reg signed [28:0] index;
    reg [28:0] fraction;
    reg [7:0] weight;
    reg [9:0] first, second;
    begin
      fraction_bits = 5'd20 - {1'b0, log2_size};
      centred = $signed({coord[27], coord}) - (bilinear ? $signed(29'd1 << (fraction_bits - 5'd1)) : 29'sd0);
      index = centred >>> fraction_bits;
      fraction = centred & ((29'd1 << fraction_bits) - 29'd1);
      weight = bilinear ? fraction[fraction_bits - 5'd1 -: 8] : 8'd0;  // the top 8 of the T fraction bits (T >= 10)
      first = place(index, log2_size, clamp);
      second = bilinear ? place(index + 29'sd1, log2_size, clamp) : first;
      axis = {first, second, weight};
    end
  endfunction

  function automatic [9:0] place(input signed [28:0] index, input [3:0] log2_size, input clamp);
    reg [28:0] last;
    begin
      last = (29'd1 << log2_size) - 29'd1;
      if (!clamp) place = index[9:0] & last[9:0];
      else if (index < 0) place = 10'd0;
      else if (index > $signed(last)) place = last[9:0];
      else place = index[9:0];
    end
  endfunction

  wire [27:0] across = axis(u, cfg_log2_width, cfg_bilinear, cfg_clamp);
  wire [27:0] up = axis(v, cfg_log2_height, cfg_bilinear, cfg_clamp);
  always @(posedge clk) begin
    x0_q <= across[27:18];
    x1_q <= across[17:8];
    wx_q <= across[7:0];
    y0_q <= up[27:18];
    y1_q <= up[17:8];
    wy_q <= up[7:0];
  end
endmodule
