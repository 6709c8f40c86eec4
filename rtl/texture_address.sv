// The texture sampler's address stages (model/texture_sampler.h, axis_texels; docs/design/texturing.md,
// "The sampler"): from a fragment's u and v (s8.20) the texel columns and rows a lookup reads and
// the bilinear weights, in rastersim_pkg::TEXTURE_ADDRESS_STAGES = 3 registered stages (the texture
// unit's address stages, docs/cycle-model.md: inputs of a cycle are in the outputs after three
// rising edges; the configuration is static for the frame). Per axis, with T = 20 - log2 size:
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
  // Per axis from the configuration alone (static for the frame; registered so that no stage starts
  // at the configuration): T = 20 - log2 size, the fraction bits of a coordinate in texels; half a
  // texel (bilinear) or 0; the last index, size - 1.
  reg [4:0] fraction_x_q, fraction_y_q;
  reg signed [28:0] half_x_q, half_y_q;
  reg [9:0] last_x_q, last_y_q;
  always @(posedge clk) begin
    fraction_x_q <= 5'd20 - {1'b0, cfg_log2_width};
    fraction_y_q <= 5'd20 - {1'b0, cfg_log2_height};
    half_x_q <= cfg_bilinear ? $signed(29'd1 << (5'd19 - {1'b0, cfg_log2_width})) : 29'sd0;
    half_y_q <= cfg_bilinear ? $signed(29'd1 << (5'd19 - {1'b0, cfg_log2_height})) : 29'sd0;
    last_x_q <= 10'((11'd1 << cfg_log2_width) - 11'd1);
    last_y_q <= 10'((11'd1 << cfg_log2_height) - 11'd1);
  end

  // The second texel's weight: the top 8 of the T fraction bits (T >= 10); 0 for nearest.
  function automatic [7:0] weight(input signed [28:0] centred, input [4:0] fraction_bits, input bilinear);
    weight = bilinear ? 8'(29'(centred) >> (fraction_bits - 5'd8)) : 8'd0;
  endfunction

  // Repeat keeps the low log2-size bits (last = size - 1), clamp limits to [0, last].
  function automatic [9:0] place(input signed [28:0] index, input [9:0] last, input clamp);
    begin
      if (!clamp) place = index[9:0] & last;
      else if (index < 0) place = 10'd0;
      else if (index > $signed({19'd0, last})) place = last;
      else place = index[9:0];
    end
  endfunction

  // Three registered stages (the texture unit's address stages): the coordinate less half a texel,
  // then its integer part and the weight, then the wrapped or clamped indices.
  reg signed [28:0] centred_x_q, centred_y_q;
  reg signed [28:0] index_x_q, index_y_q;
  reg [7:0] weight_x_q, weight_y_q;
  always @(posedge clk) begin
    centred_x_q <= $signed({u[27], u}) - half_x_q;
    centred_y_q <= $signed({v[27], v}) - half_y_q;
    index_x_q <= centred_x_q >>> fraction_x_q;
    index_y_q <= centred_y_q >>> fraction_y_q;
    weight_x_q <= weight(centred_x_q, fraction_x_q, cfg_bilinear);
    weight_y_q <= weight(centred_y_q, fraction_y_q, cfg_bilinear);
    x0_q <= place(index_x_q, last_x_q, cfg_clamp);
    x1_q <= place(cfg_bilinear ? index_x_q + 29'sd1 : index_x_q, last_x_q, cfg_clamp);
    wx_q <= weight_x_q;
    y0_q <= place(index_y_q, last_y_q, cfg_clamp);
    y1_q <= place(cfg_bilinear ? index_y_q + 29'sd1 : index_y_q, last_y_q, cfg_clamp);
    wy_q <= weight_y_q;
  end
endmodule
