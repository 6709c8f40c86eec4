// The texture sampler's filter stages (model/texture_sampler.h, blend_channel and modulate_channel):
// the four texels a lookup read, blended per 8-bit channel with the bilinear weights, the exact
// weighted mean rounded half up; then modulated by the fragment's Gouraud colour, round(t g / 255)
// half up as (x + (x >> 8)) >> 8 with x = t g + 128. rastersim_pkg::TEXTURE_FILTER_STAGES = 6
// registered stages (the texture unit's filter stages, docs/cycle-model.md: inputs of a cycle are in
// `rgb_q` after six rising edges); the shade travels beside them. Nearest lookups come with weights
// 0: the blend is the first texel.
`include "rastersim_pkg.sv"
module texture_filter `RS_IMPORT (
  input  wire clk,
  input  `RS_TYPE(rgb_t) texel00,  // {r, g, b}: the lower row's first and second column, the upper row's
  input  `RS_TYPE(rgb_t) texel10,
  input  `RS_TYPE(rgb_t) texel01,
  input  `RS_TYPE(rgb_t) texel11,
  input  wire [rastersim_pkg::TEXTURE_WEIGHT_BITS-1:0] wx,        // weight of the second column, 1/256
  input  wire [rastersim_pkg::TEXTURE_WEIGHT_BITS-1:0] wy,        // weight of the second row
  input  `RS_TYPE(rgb_t) shade,    // the fragment's Gouraud colour
  output reg  [rastersim_pkg::RGB_BITS-1:0] rgb_q
);
  // The blend in two steps, each one product of a difference, a (256 - f) + b f = 256 a + (b - a) f,
  // formed as two products by the halves of f, (b - a) f = ((b - a) f[7:4]) 16 + (b - a) f[3:0], and
  // their sum: along x in each row (a row below 2^17: an 8-bit channel times 256 at most), then
  // along y with the rounding, + 32768 (below 2^24: the mean is at most 255, its low 16 bits
  // rounded off).
  function automatic [43:0] halves(input signed [21:0] difference, input [7:0] f);  // {high, low}
    halves = {22'(difference * $signed({18'd0, f[7:4]})), 22'(difference * $signed({18'd0, f[3:0]}))};
  endfunction

  function automatic [26:0] summed(input [16:0] base, input [43:0] two_halves, input [26:0] rounding);
    summed = 27'($signed({2'd0, base, 8'd0}) + $signed({{5{two_halves[43]}}, two_halves[43:22]}) * 27'sd16 +
                 $signed({{5{two_halves[21]}}, two_halves[21:0]}) + $signed(rounding));
  endfunction

  function automatic [7:0] modulate(input [7:0] texel, input [7:0] g);
    reg [16:0] x;
    /* verilator lint_off UNUSEDSIGNAL */
    reg [16:0] y;  // below 2^16; its low byte is rounded off
    /* verilator lint_on UNUSEDSIGNAL */
    begin
      x = {9'd0, texel} * {9'd0, g} + 17'd128;
      y = x + (x >> 8);
      modulate = y[15:8];
    end
  endfunction

  // Six registered stages: the halves of the products along x; the rows (lower, upper); their
  // difference; the halves of the product along y; the blend; the modulation. What a stage needs
  // later travels beside it.
  reg [3*44-1:0] lower_halves_q, upper_halves_q, y_halves_q;
  reg [3*8-1:0] a_lower_q, a_upper_q;  // the first texel of each row
  reg [3*17-1:0] lower_q, upper_q, lower_2q, lower_3q;
  reg [3*18-1:0] difference_q;  // upper - lower, |.| < 2^16
  reg [7:0] wy_q, wy_2q, wy_3q;
  reg [23:0] blended_q;
  reg [23:0] shade_q, shade_2q, shade_3q, shade_4q, shade_5q;
  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : channel
      wire [7:0] t00 = texel00[8*c +: 8], t10 = texel10[8*c +: 8], t01 = texel01[8*c +: 8], t11 = texel11[8*c +: 8];
      /* verilator lint_off UNUSEDSIGNAL */
      wire [26:0] lower = summed({9'd0, a_lower_q[8*c +: 8]}, lower_halves_q[44*c +: 44], 27'd0);
      wire [26:0] upper = summed({9'd0, a_upper_q[8*c +: 8]}, upper_halves_q[44*c +: 44], 27'd0);
      wire [26:0] blend = summed(lower_3q[17*c +: 17], y_halves_q[44*c +: 44], 27'd32768);
      /* verilator lint_on UNUSEDSIGNAL */
      always @(posedge clk) begin
        lower_halves_q[44*c +: 44] <= halves($signed({14'd0, t10}) - $signed({14'd0, t00}), wx);
        upper_halves_q[44*c +: 44] <= halves($signed({14'd0, t11}) - $signed({14'd0, t01}), wx);
        a_lower_q[8*c +: 8] <= t00;
        a_upper_q[8*c +: 8] <= t01;
        lower_q[17*c +: 17] <= lower[16:0];
        upper_q[17*c +: 17] <= upper[16:0];
        difference_q[18*c +: 18] <= 18'($signed({1'b0, upper_q[17*c +: 17]}) - $signed({1'b0, lower_q[17*c +: 17]}));
        lower_2q[17*c +: 17] <= lower_q[17*c +: 17];
        y_halves_q[44*c +: 44] <= halves(22'($signed(difference_q[18*c +: 18])), wy_3q);
        lower_3q[17*c +: 17] <= lower_2q[17*c +: 17];
        blended_q[8*c +: 8] <= blend[23:16];
        rgb_q[8*c +: 8] <= modulate(blended_q[8*c +: 8], shade_5q[8*c +: 8]);
      end
    end
  endgenerate
  always @(posedge clk) begin
    wy_q <= wy;
    wy_2q <= wy_q;
    wy_3q <= wy_2q;
    shade_q <= shade;
    shade_2q <= shade_q;
    shade_3q <= shade_2q;
    shade_4q <= shade_3q;
    shade_5q <= shade_4q;
  end
endmodule
