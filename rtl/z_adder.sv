// Z register adder (model/z_adder.h): the depth plane register and, for Gouraud shading, the
// r, g, b plane registers, stepped in lockstep with the walker. No multiplication.
// Depth registers are s(N+1).F, colour registers s9.F (F = guard bits), all wrapping. With TEXTURE
// the S, T, Q plane registers too (s9.(P+Ft), docs/arithmetic.md section 5), for the texture unit.
module z_adder #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer Z_BITS = 24,
  parameter integer Z_GUARD_BITS = 0,
  parameter integer TEXTURE = 0     // 1: the texture planes (rs_texture_record_bits), else none
) (
  input  wire clk,
  input  wire cfg_shading,  // RS_SHADING_* (rastersim_widths.vh); flat: the provoking vertex colour
  input  wire load,
  input  wire step_x,
  input  wire next_row,
  input  wire row_enter,
  input  wire enter_left,         // load, row_enter: the span starts at a left edge (scanline_walker)
  input  wire enter_slot,         // its left-edge slot
  input  wire [1:0] left_carry,   // each slot's DDA carry into the row after the one entered
  input  wire [Z_BITS+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS):0]  depth_start,
  input  wire [Z_BITS+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS):0]  depth_step_x,
  input  wire [Z_BITS+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS):0]  depth_step_y,
  input  wire [3*(9+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS))-1:0] color_start,   // r, g, b at [c*B +: B]
  input  wire [3*(9+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS))-1:0] color_step_x,
  input  wire [3*(9+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS))-1:0] color_step_y,
  input  wire [23:0] flat_rgb,
  // The planes along the left edges: slot j at [j*(Z_REG_BITS + 3 COLOR_REG_BITS)], depth first,
  // then r, g, b (rastersim_widths.vh, record fields 18 and 19).
  input  wire [2*(Z_BITS+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS)+1+3*(9+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS)))-1:0] left_start,
  input  wire [2*(Z_BITS+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS)+1+3*(9+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS)))-1:0] left_step,
  // The texture record (rs_texture_record_bits of rastersim_widths.vh; unused without TEXTURE).
  input  wire [1+21*(50+$clog2(2*(WIDTH+HEIGHT-1)))-1:0] texture_record,
  output wire [Z_BITS-1:0] depth,  // uN
  output wire [23:0] rgb,          // {r, g, b}, u8 each
  output wire triangle_textured,   // the record's texture flag (0 without TEXTURE)
  output wire [3*(50+$clog2(2*(WIDTH+HEIGHT-1)))-1:0] stq  // the S, T, Q registers at [c*TR +: TR]
);
`include "rastersim_widths.vh"
  `RS_REQUIRE(illegal_z_bits, Z_BITS >= 16 && Z_BITS <= 32, "z_adder: Z_BITS must be 16..32")
  `RS_REQUIRE(illegal_z_guard_bits, Z_GUARD_BITS >= 0 && Z_GUARD_BITS <= 24, "z_adder: Z_GUARD_BITS must be 0 (derived) or 1..24")

  localparam integer F = rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS);
  localparam integer Z_REG_BITS = Z_BITS + F + 1;
  localparam integer COLOR_REG_BITS = 9 + F;
  localparam integer SLOT_BITS = Z_REG_BITS + 3 * COLOR_REG_BITS;

  reg [23:0] flat_q;
  always @(posedge clk) if (load) flat_q <= flat_rgb;

  /* verilator lint_off UNUSEDSIGNAL */
  wire [Z_REG_BITS-1:0] depth_value_unused;
  /* verilator lint_on UNUSEDSIGNAL */
  plane_register #(.REG_BITS(Z_REG_BITS), .GUARD_BITS(F), .OUT_BITS(Z_BITS)) depth_plane (
    .clk(clk), .load(load), .step_x(step_x), .next_row(next_row), .row_enter(row_enter),
    .enter_left(enter_left), .enter_slot(enter_slot), .left_carry(left_carry),
    .start(depth_start), .step_x_in(depth_step_x), .step_y_in(depth_step_y),
    .left_start({left_start[SLOT_BITS +: Z_REG_BITS], left_start[0 +: Z_REG_BITS]}),
    .left_step({left_step[SLOT_BITS +: Z_REG_BITS], left_step[0 +: Z_REG_BITS]}),
    .out(depth), .value(depth_value_unused));

  wire [23:0] gouraud_rgb;
  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : color_planes
      // Channel c is r, g, b for c = 0, 1, 2; rgb holds r in [23:16].
      localparam integer AT = Z_REG_BITS + c * COLOR_REG_BITS;  // the channel in a left-edge slot
      /* verilator lint_off UNUSEDSIGNAL */
      wire [COLOR_REG_BITS-1:0] value_unused;
      /* verilator lint_on UNUSEDSIGNAL */
      plane_register #(.REG_BITS(COLOR_REG_BITS), .GUARD_BITS(F), .OUT_BITS(8)) plane (
        .clk(clk), .load(load), .step_x(step_x), .next_row(next_row), .row_enter(row_enter),
        .enter_left(enter_left), .enter_slot(enter_slot), .left_carry(left_carry),
        .start(color_start[c*COLOR_REG_BITS +: COLOR_REG_BITS]), .step_x_in(color_step_x[c*COLOR_REG_BITS +: COLOR_REG_BITS]),
        .step_y_in(color_step_y[c*COLOR_REG_BITS +: COLOR_REG_BITS]),
        .left_start({left_start[SLOT_BITS + AT +: COLOR_REG_BITS], left_start[AT +: COLOR_REG_BITS]}),
        .left_step({left_step[SLOT_BITS + AT +: COLOR_REG_BITS], left_step[AT +: COLOR_REG_BITS]}),
        .out(gouraud_rgb[8*(2-c) +: 8]), .value(value_unused));
    end
  endgenerate

  assign rgb = cfg_shading == RS_SHADING_GOURAUD ? gouraud_rgb : flat_q;

  localparam integer TR = rs_texture_reg_bits(WIDTH, HEIGHT);
  `RS_REQUIRE(texture_reg_bits_match, TR == 50 + $clog2(2 * (WIDTH + HEIGHT - 1)), "z_adder: texture register width")
  generate
    if (TEXTURE != 0) begin : texture_planes
      reg textured_q;
      always @(posedge clk) if (load) textured_q <= texture_record[0];
      assign triangle_textured = textured_q;
      // Register 3 g + c of the record (g: 0 start, 1 step x, 2 step y, 3 + 2 j slot j's start, 4 + 2 j its step).
      for (c = 0; c < 3; c = c + 1) begin : planes
        /* verilator lint_off UNUSEDSIGNAL */
        wire [7:0] rounded_unused;
        /* verilator lint_on UNUSEDSIGNAL */
        plane_register #(.REG_BITS(TR), .GUARD_BITS(F), .OUT_BITS(8)) plane (
          .clk(clk), .load(load), .step_x(step_x), .next_row(next_row), .row_enter(row_enter),
          .enter_left(enter_left), .enter_slot(enter_slot), .left_carry(left_carry),
          .start(texture_record[1 + c*TR +: TR]), .step_x_in(texture_record[1 + (3 + c)*TR +: TR]),
          .step_y_in(texture_record[1 + (6 + c)*TR +: TR]),
          .left_start({texture_record[1 + (15 + c)*TR +: TR], texture_record[1 + (9 + c)*TR +: TR]}),
          .left_step({texture_record[1 + (18 + c)*TR +: TR], texture_record[1 + (12 + c)*TR +: TR]}),
          .out(rounded_unused), .value(stq[c*TR +: TR]));
      end
    end else begin : no_texture
      /* verilator lint_off UNUSEDSIGNAL */
      wire record_unused = ^texture_record;
      /* verilator lint_on UNUSEDSIGNAL */
      assign triangle_textured = 1'b0;
      assign stq = {3*TR{1'b0}};
    end
  endgenerate
endmodule
