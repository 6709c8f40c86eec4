// rastersim's own walker (rtl/scanline_walker.sv with its entry stage) and Z adder (rtl/z_adder.sv)
// behind the walker's interface (docs/verification.md "Checking one unit: cosim --unit"), joined
// as rastersim_core joins them: `rastersim cosim --unit walker --dut
// testbench/dut/rastersim_walker_unit.f --top rastersim_walker_unit`. Its packed record is rec_aux
// with every field that setup_record_t carries taken from rec instead (truncated to the record's
// widths), so that both inputs reach the walk.
`include "rastersim_pkg.sv"
module rastersim_walker_unit #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer SUBPIXEL_BITS = 4,
  parameter integer Z_BITS = 24,
  parameter integer FRACTION_BITS = 9,
  parameter integer AUX_BITS = 1,
  // The micro-architecture (not part of the interface): 1 span, 0 bounding-box traversal.
  parameter integer TRAVERSAL_SPAN = 1,
  // The conventions (the profile's depth_rounding and color_rounding, as rastersim_core's parameters).
  parameter integer DEPTH_ROUNDING = 0,
  parameter integer COLOR_ROUNDING = 0
) (
  input  wire clk,
  input  wire rst,
  input  wire        cfg_shading,
  input  wire        rec_valid,
  output wire        rec_ready,
  input  wire [31:0] rec_index,
  input  rastersim_unit_pkg::setup_record_t rec,
  input  wire [AUX_BITS-1:0] rec_aux,
  output wire        frag_valid,
  input  wire        frag_ready,
  output wire [31:0] frag_index,
  output wire [15:0] frag_x, frag_y,
  output wire [Z_BITS-1:0] frag_z,
  output wire [23:0] frag_rgb,
  output wire        frame_done
);
`include "rastersim_widths.vh"
  localparam integer Z_GUARD_BITS = FRACTION_BITS;  // F itself (rs_guard_bits takes a non-zero value as is)
  localparam integer RECORD_Z_BITS = Z_BITS;
  `include "rastersim_record.vh"
  localparam integer RECORD_BITS = rs_rec_lsb(20, WIDTH, HEIGHT, SUBPIXEL_BITS, Z_BITS, Z_GUARD_BITS);
  `RS_REQUIRE(aux_bits, AUX_BITS == RECORD_BITS, "rastersim_walker_unit: AUX_BITS is not the width of rastersim's record")
  localparam integer X_BITS = rs_ubits32(WIDTH - 1);
  localparam integer Y_BITS = rs_ubits32(HEIGHT - 1);
  localparam integer EB = rs_edge_bits(WIDTH, HEIGHT, SUBPIXEL_BITS);
  localparam integer SXB = rs_edge_step_x_bits(HEIGHT, SUBPIXEL_BITS);
  localparam integer SYB = rs_edge_step_y_bits(WIDTH, SUBPIXEL_BITS);
  localparam integer Z_REG_BITS = Z_BITS + FRACTION_BITS + 1;  // s(N+1).F
  localparam integer COLOR_REG_BITS = 9 + FRACTION_BITS;       // s9.F

  // rec's fields as arrays, per edge and per colour channel.
  wire [63:0] edge_start [0:2];
  wire [63:0] edge_step_x [0:2];
  wire [63:0] edge_step_y [0:2];
  wire [63:0] color_start [0:2];
  wire [63:0] color_step_x [0:2];
  wire [63:0] color_step_y [0:2];
  assign edge_start[0] = rec.edge0_start, edge_start[1] = rec.edge1_start, edge_start[2] = rec.edge2_start;
  assign edge_step_x[0] = rec.edge0_step_x, edge_step_x[1] = rec.edge1_step_x, edge_step_x[2] = rec.edge2_step_x;
  assign edge_step_y[0] = rec.edge0_step_y, edge_step_y[1] = rec.edge1_step_y, edge_step_y[2] = rec.edge2_step_y;
  assign color_start[0] = rec.red_start, color_start[1] = rec.green_start, color_start[2] = rec.blue_start;
  assign color_step_x[0] = rec.red_step_x, color_step_x[1] = rec.green_step_x, color_step_x[2] = rec.blue_step_x;
  assign color_step_y[0] = rec.red_step_y, color_step_y[1] = rec.green_step_y, color_step_y[2] = rec.blue_step_y;

  reg [RECORD_BITS-1:0] record;
  integer k;
  always_comb begin
    record = rec_aux;
    record[LSB_X0 +: X_BITS] = rec.x0[X_BITS-1:0];
    record[LSB_X1 +: X_BITS] = rec.x1[X_BITS-1:0];
    record[LSB_Y0 +: Y_BITS] = rec.y0[Y_BITS-1:0];
    record[LSB_Y1 +: Y_BITS] = rec.y1[Y_BITS-1:0];
    for (k = 0; k < 3; k = k + 1) begin
      record[LSB_EDGE_START + k*EB +: EB] = edge_start[k][EB-1:0];
      record[LSB_EDGE_STEP_X + k*SXB +: SXB] = edge_step_x[k][SXB-1:0];
      record[LSB_EDGE_STEP_Y + k*SYB +: SYB] = edge_step_y[k][SYB-1:0];
      record[LSB_COLOR_START + k*COLOR_REG_BITS +: COLOR_REG_BITS] = color_start[k][COLOR_REG_BITS-1:0];
      record[LSB_COLOR_STEP_X + k*COLOR_REG_BITS +: COLOR_REG_BITS] = color_step_x[k][COLOR_REG_BITS-1:0];
      record[LSB_COLOR_STEP_Y + k*COLOR_REG_BITS +: COLOR_REG_BITS] = color_step_y[k][COLOR_REG_BITS-1:0];
    end
    record[LSB_DEPTH_START +: Z_REG_BITS] = rec.depth_start[Z_REG_BITS-1:0];
    record[LSB_DEPTH_STEP_X +: Z_REG_BITS] = rec.depth_step_x[Z_REG_BITS-1:0];
    record[LSB_DEPTH_STEP_Y +: Z_REG_BITS] = rec.depth_step_y[Z_REG_BITS-1:0];
    record[LSB_FLAT_RGB +: 24] = rec.flat_rgb;
  end

  wire load, busy;
  wire adder_step_x, adder_next_row, adder_row_enter, adder_enter_left, adder_enter_slot;
  wire [1:0] adder_left_carry;
  wire [X_BITS-1:0] x;
  wire [Y_BITS-1:0] y;
  wire [rs_entry_lsb(20, WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] entry;
  scanline_walker_entry #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS)) walker_entry (
    .record(record[rs_rec_walker_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0]), .entry(entry));
  /* verilator lint_off PINCONNECTEMPTY */
  scanline_walker #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS)) walker (
    .clk(clk), .rst(rst), .cfg_traversal(TRAVERSAL_SPAN[0]),
    .in_valid(rec_valid), .in_ready(rec_ready), .in_entry(entry),
    .adder_load(load), .adder_step_x(adder_step_x), .adder_next_row(adder_next_row),
    .adder_row_enter(adder_row_enter), .adder_enter_left(adder_enter_left), .adder_enter_slot(adder_enter_slot),
    .adder_left_carry(adder_left_carry),
    .frag_valid(frag_valid), .frag_ready(frag_ready), .frag_x(x), .frag_y(y),
    .busy(busy), .candidate(), .last());
  /* verilator lint_on PINCONNECTEMPTY */
  /* verilator lint_off UNUSEDSIGNAL */
  wire textured_unused;
  wire [3*rs_texture_reg_bits(WIDTH, HEIGHT)-1:0] stq_unused;
  /* verilator lint_on UNUSEDSIGNAL */
  z_adder #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .Z_BITS(Z_BITS), .Z_GUARD_BITS(Z_GUARD_BITS),
            .DEPTH_ROUNDING(DEPTH_ROUNDING), .COLOR_ROUNDING(COLOR_ROUNDING)) adders (
    .clk(clk), .cfg_shading(cfg_shading), .depth_bias('0),  // DEPTH_BIAS 0
    .load(load), .step_x(adder_step_x), .next_row(adder_next_row), .row_enter(adder_row_enter),
    .enter_left(adder_enter_left), .enter_slot(adder_enter_slot), .left_carry(adder_left_carry),
    .depth_start(record[LSB_DEPTH_START +: Z_REG_BITS]),
    .depth_step_x(record[LSB_DEPTH_STEP_X +: Z_REG_BITS]),
    .depth_step_y(record[LSB_DEPTH_STEP_Y +: Z_REG_BITS]),
    .color_start(record[LSB_COLOR_START +: 3*COLOR_REG_BITS]),
    .color_step_x(record[LSB_COLOR_STEP_X +: 3*COLOR_REG_BITS]),
    .color_step_y(record[LSB_COLOR_STEP_Y +: 3*COLOR_REG_BITS]),
    .flat_rgb(record[LSB_FLAT_RGB +: 24]),
    .left_start(record[LSB_LEFT_START +: 2*(Z_REG_BITS + 3*COLOR_REG_BITS)]),
    .left_step(record[LSB_LEFT_STEP +: 2*(Z_REG_BITS + 3*COLOR_REG_BITS)]), .depth(frag_z), .rgb(frag_rgb),
    .texture_record({rs_texture_record_bits(WIDTH, HEIGHT){1'b0}}), .triangle_textured(textured_unused),
    .stq(stq_unused));

  // The walker's triangle: its index from the load on. A load may share the cycle of the previous
  // triangle's last fragment, which is still that triangle's (the register's old value).
  reg [31:0] index_q;
  always @(posedge clk) begin
    if (rst) index_q <= 32'd0;
    else if (load) index_q <= rec_index;
  end
  assign frag_index = index_q;
  assign frag_x = 16'(x);
  assign frag_y = 16'(y);
  assign frame_done = !busy && !frag_valid;
endmodule
