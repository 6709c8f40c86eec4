// The walker (with its entry stage) and the Z adder as rastersim_core joins them, alone: the record
// comes from the test (packed as rs_rec_lsb lays it out), frag_ready is the test's script. Verilated for the unit test
// of the walk against the model's (tests/units/test_walker_unit.cpp).
`include "rastersim_pkg.sv"
module walker_unit #(
  parameter integer WIDTH = 64,
  parameter integer HEIGHT = 48,
  parameter integer SUBPIXEL_BITS = 4,
  parameter integer Z_BITS = 24,
  parameter integer Z_GUARD_BITS = 0
) (
  input  wire clk,
  input  wire rst,
  input  wire cfg_traversal,  // 0 bbox, 1 span
  input  wire cfg_shading,    // 0 flat, 1 gouraud
  input  wire in_valid,
  output wire in_ready,
  input  wire [rs_rec_lsb(20, WIDTH, HEIGHT, SUBPIXEL_BITS, Z_BITS, Z_GUARD_BITS)-1:0] in_record,
  output wire load,           // the walker takes the record (walker_load)
  output wire frag_valid,
  input  wire frag_ready,
  output wire [rs_ubits32(WIDTH - 1)-1:0]  frag_x,
  output wire [rs_ubits32(HEIGHT - 1)-1:0] frag_y,
  output wire [Z_BITS-1:0] frag_z,
  output wire [23:0] frag_rgb,
  output wire busy,
  output wire candidate,
  output wire last
);
`include "rastersim_widths.vh"
  localparam integer RECORD_Z_BITS = Z_BITS;  // the fixed-point depth word: the plane's bits
  `include "rastersim_record.vh"
  localparam integer F = rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS);
  localparam integer Z_REG_BITS = Z_BITS + F + 1;
  localparam integer COLOR_REG_BITS = 9 + F;
  localparam integer X_BITS = rs_ubits32(WIDTH - 1);
  // The packed record's width, for the test's check of its own packing (setup_record.h).
  localparam integer RECORD_BITS /*verilator public*/ =
      rs_rec_lsb(20, WIDTH, HEIGHT, SUBPIXEL_BITS, Z_BITS, Z_GUARD_BITS);

  wire adder_step_x, adder_next_row, adder_row_enter, adder_enter_left, adder_enter_slot;
  wire [1:0] adder_left_carry;

  // The walker's entry formed from the record in the cycle the walker takes it (rastersim_core
  // forms it as the record enters the record FIFO, a cycle or more before).
  wire [rs_entry_lsb(20, WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] entry;
  scanline_walker_entry #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS)) walker_entry (
    .record(in_record[rs_rec_walker_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0]), .entry(entry));
  scanline_walker #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS)) walker (
    .clk(clk), .rst(rst), .cfg_traversal(cfg_traversal),
    .in_valid(in_valid), .in_ready(in_ready), .in_entry(entry),
    .adder_load(load), .adder_step_x(adder_step_x), .adder_next_row(adder_next_row),
    .adder_row_enter(adder_row_enter), .adder_enter_left(adder_enter_left), .adder_enter_slot(adder_enter_slot),
    .adder_left_carry(adder_left_carry),
    .frag_valid(frag_valid), .frag_ready(frag_ready), .frag_x(frag_x), .frag_y(frag_y),
    .busy(busy), .candidate(candidate), .last(last));

  /* verilator lint_off UNUSEDSIGNAL */
  wire textured_unused;
  wire [3*rs_texture_reg_bits(WIDTH, HEIGHT)-1:0] stq_unused;
  /* verilator lint_on UNUSEDSIGNAL */
  z_adder #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .Z_BITS(Z_BITS), .Z_GUARD_BITS(Z_GUARD_BITS)) adders (
    .clk(clk), .cfg_shading(cfg_shading), .depth_bias('0),  // no bias (DEPTH_BIAS 0)
    .load(load), .step_x(adder_step_x), .next_row(adder_next_row), .row_enter(adder_row_enter), .enter_left(adder_enter_left),
    .enter_slot(adder_enter_slot), .left_carry(adder_left_carry),
    .depth_start(in_record[LSB_DEPTH_START +: Z_REG_BITS]),
    .depth_step_x(in_record[LSB_DEPTH_STEP_X +: Z_REG_BITS]),
    .depth_step_y(in_record[LSB_DEPTH_STEP_Y +: Z_REG_BITS]),
    .color_start(in_record[LSB_COLOR_START +: 3*COLOR_REG_BITS]),
    .color_step_x(in_record[LSB_COLOR_STEP_X +: 3*COLOR_REG_BITS]),
    .color_step_y(in_record[LSB_COLOR_STEP_Y +: 3*COLOR_REG_BITS]),
    .flat_rgb(in_record[LSB_FLAT_RGB +: 24]), .left_start(in_record[LSB_LEFT_START +: 2*(Z_REG_BITS + 3*COLOR_REG_BITS)]),
    .left_step(in_record[LSB_LEFT_STEP +: 2*(Z_REG_BITS + 3*COLOR_REG_BITS)]), .depth(frag_z), .rgb(frag_rgb),
    // Built without the texture planes (TEXTURE 0): no texture record, outputs unused.
    .texture_record({rs_texture_record_bits(WIDTH, HEIGHT){1'b0}}), .triangle_textured(textured_unused),
    .stq(stq_unused));
endmodule
