// Z register adder (model/z_adder.h): the depth plane register and, for Gouraud shading, the
// r, g, b plane registers, stepped in lockstep with the walker. No multiplication per pixel.
// Depth registers are s(N+1).F, colour registers s9.F (F = guard bits), all wrapping.
module z_adder #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer Z_BITS = 24,
  parameter integer Z_GUARD_BITS = 0
) (
  input  wire clk,
  input  wire cfg_shading,  // RS_SHADING_* (rastersim_widths.vh); flat: the provoking vertex colour
  input  wire load,
  input  wire step_x,
  input  wire next_row,
  input  wire row_enter,
  input  wire [rs_ubits32(WIDTH - 1)-1:0] row_offset,
  input  wire from_record,  // row_offset belongs to the record (load), not to the next row
  input  wire [Z_BITS+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS):0]  depth_start,
  input  wire [Z_BITS+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS):0]  depth_step_x,
  input  wire [Z_BITS+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS):0]  depth_step_y,
  input  wire [3*(9+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS))-1:0] color_start,   // r, g, b at [c*B +: B]
  input  wire [3*(9+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS))-1:0] color_step_x,
  input  wire [3*(9+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS))-1:0] color_step_y,
  input  wire [23:0] flat_rgb,
  output wire [Z_BITS-1:0] depth,  // uN
  output wire [23:0] rgb           // {r, g, b}, u8 each
);
`include "rastersim_widths.vh"
  `RS_REQUIRE(illegal_z_bits, Z_BITS >= 16 && Z_BITS <= 32, "z_adder: Z_BITS must be 16..32")
  `RS_REQUIRE(illegal_z_guard_bits, Z_GUARD_BITS >= 0 && Z_GUARD_BITS <= 24, "z_adder: Z_GUARD_BITS must be 0 (derived) or 1..24")

  localparam integer F = rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS);
  localparam integer Z_REG_BITS = Z_BITS + F + 1;
  localparam integer COLOR_REG_BITS = 9 + F;
  localparam integer X_BITS = rs_ubits32(WIDTH - 1);

  reg [23:0] flat_q;
  always @(posedge clk) if (load) flat_q <= flat_rgb;

  plane_register #(.REG_BITS(Z_REG_BITS), .GUARD_BITS(F), .OUT_BITS(Z_BITS), .OFFSET_BITS(X_BITS)) depth_plane (
    .clk(clk), .load(load), .step_x(step_x), .next_row(next_row), .row_enter(row_enter),
    .offset(row_offset), .from_record(from_record), .start(depth_start), .step_x_in(depth_step_x), .step_y_in(depth_step_y),
    .out(depth));

  wire [23:0] gouraud_rgb;
  genvar c;
  generate
    for (c = 0; c < 3; c = c + 1) begin : color_planes
      // Channel c is r, g, b for c = 0, 1, 2; rgb holds r in [23:16].
      plane_register #(.REG_BITS(COLOR_REG_BITS), .GUARD_BITS(F), .OUT_BITS(8), .OFFSET_BITS(X_BITS)) plane (
        .clk(clk), .load(load), .step_x(step_x), .next_row(next_row), .row_enter(row_enter),
        .offset(row_offset), .from_record(from_record), .start(color_start[c*COLOR_REG_BITS +: COLOR_REG_BITS]), .step_x_in(color_step_x[c*COLOR_REG_BITS +: COLOR_REG_BITS]),
        .step_y_in(color_step_y[c*COLOR_REG_BITS +: COLOR_REG_BITS]), .out(gouraud_rgb[8*(2-c) +: 8]));
    end
  endgenerate

  assign rgb = cfg_shading == RS_SHADING_GOURAUD ? gouraud_rgb : flat_q;
endmodule
