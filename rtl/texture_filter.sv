// The texture sampler's filter stages (model/texture_sampler.h, blend_channel and modulate_channel):
// the four texels a lookup read, blended per 8-bit channel with the bilinear weights, the exact
// weighted mean rounded half up, registered; then modulated by the fragment's Gouraud colour,
// round(t g / 255) half up as (x + (x >> 8)) >> 8 with x = t g + 128, registered (the texture
// unit's blend and modulate cycles, docs/cycle-model.md: inputs of a cycle are in `rgb_q` after
// two rising edges). The shade travels beside the blend. Nearest lookups come with weights 0: the
// blend is the first texel.
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
  // Operands widened to the result's width: no product is cut.
  function automatic [7:0] blend(input [7:0] a, input [7:0] b, input [7:0] c, input [7:0] d, input [7:0] fx,
                                 input [7:0] fy);
    reg [16:0] lower, upper;  // an 8-bit channel times 256 at most
    /* verilator lint_off UNUSEDSIGNAL */
    reg [33:0] sum;           // below 2^24: the mean is at most 255; its low 16 bits are rounded off
    /* verilator lint_on UNUSEDSIGNAL */
    begin
      lower = {9'd0, a} * (17'd256 - {9'd0, fx}) + {9'd0, b} * {9'd0, fx};
      upper = {9'd0, c} * (17'd256 - {9'd0, fx}) + {9'd0, d} * {9'd0, fx};
      sum = {17'd0, lower} * (34'd256 - {26'd0, fy}) + {17'd0, upper} * {26'd0, fy} + 34'd32768;
      blend = sum[23:16];
    end
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

  reg [23:0] blended_q;
  reg [23:0] shade_q;
  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : channel
      always @(posedge clk) begin
        blended_q[8*c +: 8] <= blend(texel00[8*c +: 8], texel10[8*c +: 8], texel01[8*c +: 8], texel11[8*c +: 8], wx, wy);
        rgb_q[8*c +: 8] <= modulate(blended_q[8*c +: 8], shade_q[8*c +: 8]);
      end
    end
  endgenerate
  always @(posedge clk) shade_q <= shade;
endmodule
