// rastersim's own setup unit (rtl/triangle_setup.sv) behind the setup unit's interface
// (docs/verification.md "Checking one unit: cosim --unit"): `rastersim cosim --unit setup --dut
// testbench/dut/rastersim_setup_unit.f --top rastersim_setup_unit`. Its packed record's fields
// (rastersim_record.vh) are sign-extended into setup_record_t; it carries no owns_samples flag, so
// each edge's is formed from its steps by the fill rule the unit is built with (docs/arithmetic.md
// section 7: a left edge has step_x = -dy 2^S > 0, a top edge step_x = 0 and step_y = dx 2^S > 0).
`include "rastersim_pkg.sv"
module rastersim_setup_unit #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer SUBPIXEL_BITS = 4,
  parameter integer Z_BITS = 24,
  parameter integer FRACTION_BITS = 9,
  // The micro-architecture (not part of the interface): 0 serial, 2..64 pipelined.
  parameter integer SETUP_INTERVAL = 4,
  // The conventions (the profile's pixel_center and fill_rule, as rastersim_core's parameters).
  parameter integer PIXEL_CENTER = 0,
  parameter integer FILL_RULE = 0
) (
  input  wire clk,
  input  wire rst,
  input  wire [1:0]  cfg_cull,
  input  wire        cfg_front_face,
  input  wire        cmd_valid,
  output wire        cmd_ready,
  input  wire [31:0] cmd_x0, cmd_y0, cmd_x1, cmd_y1, cmd_x2, cmd_y2,
  input  wire [Z_BITS-1:0] cmd_z0, cmd_z1, cmd_z2,
  input  wire [23:0] cmd_rgb0, cmd_rgb1, cmd_rgb2,
  output wire        dec_valid,
  output wire [2:0]  dec_status,
  output wire        rec_valid,
  output rastersim_unit_pkg::setup_record_t rec,
  output wire        frame_done
);
`include "rastersim_widths.vh"
  localparam integer Z_GUARD_BITS = FRACTION_BITS;  // F itself (rs_guard_bits takes a non-zero value as is)
  localparam integer RECORD_Z_BITS = Z_BITS;
  `include "rastersim_record.vh"
  localparam integer COORD_BITS = rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS);
  localparam integer X_BITS = rs_ubits32(WIDTH - 1);
  localparam integer Y_BITS = rs_ubits32(HEIGHT - 1);
  localparam integer EB = rs_edge_bits(WIDTH, HEIGHT, SUBPIXEL_BITS);
  localparam integer SXB = rs_edge_step_x_bits(HEIGHT, SUBPIXEL_BITS);
  localparam integer SYB = rs_edge_step_y_bits(WIDTH, SUBPIXEL_BITS);
  localparam integer ZR = Z_BITS + FRACTION_BITS + 1;  // s(N+1).F
  localparam integer CR = 9 + FRACTION_BITS;           // s9.F

  wire [2:0] status;
  wire decided, out_valid;
  wire [rs_rec_lsb(20, WIDTH, HEIGHT, SUBPIXEL_BITS, Z_BITS, Z_GUARD_BITS)-1:0] r;
  /* verilator lint_off PINCONNECTEMPTY */
  triangle_setup #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS), .Z_BITS(Z_BITS),
                   .Z_GUARD_BITS(Z_GUARD_BITS), .SETUP_INTERVAL(SETUP_INTERVAL), .TEXTURE(0),
                   .PIXEL_CENTER(PIXEL_CENTER), .FILL_RULE(FILL_RULE)) setup (
    .clk(clk), .rst(rst), .run(!rst), .free(), .cfg_cull(cfg_cull), .cfg_front_face(cfg_front_face),
    .in_valid(cmd_valid), .in_ready(cmd_ready),
    .in_x({cmd_x2[COORD_BITS-1:0], cmd_x1[COORD_BITS-1:0], cmd_x0[COORD_BITS-1:0]}),
    .in_y({cmd_y2[COORD_BITS-1:0], cmd_y1[COORD_BITS-1:0], cmd_y0[COORD_BITS-1:0]}),
    .in_z({cmd_z2, cmd_z1, cmd_z0}), .in_rgb({cmd_rgb2, cmd_rgb1, cmd_rgb0}),
    .in_textured(1'b0), .in_texture(450'd0),
    .decided(decided), .decided_status(status), .decided_front_facing(), .decided_area2(), .busy(),
    .out_valid(out_valid), .out_record(r), .out_texture());
  /* verilator lint_on PINCONNECTEMPTY */
  assign dec_valid = decided;
  assign dec_status = status;
  assign rec_valid = out_valid;

  wire [EB-1:0]  start [0:2];
  wire [SXB-1:0] step_x [0:2];
  wire [SYB-1:0] step_y [0:2];
  localparam [0:0] OWN_LEFT = FILL_RULE == rastersim_pkg::FILL_TOP_LEFT || FILL_RULE == rastersim_pkg::FILL_BOTTOM_LEFT;
  localparam [0:0] OWN_TOP = FILL_RULE == rastersim_pkg::FILL_TOP_LEFT || FILL_RULE == rastersim_pkg::FILL_TOP_RIGHT;
  wire [2:0] owns_samples;
  genvar k;
  generate
    for (k = 0; k < 3; k = k + 1) begin : edges
      assign start[k] = r[LSB_EDGE_START + k*EB +: EB];
      assign step_x[k] = r[LSB_EDGE_STEP_X + k*SXB +: SXB];
      assign step_y[k] = r[LSB_EDGE_STEP_Y + k*SYB +: SYB];
      wire left_edge = $signed(step_x[k]) > 0, right_edge = $signed(step_x[k]) < 0;
      wire top_edge = $signed(step_y[k]) > 0, bottom_edge = $signed(step_y[k]) < 0;
      assign owns_samples[k] = left_edge || right_edge ? (OWN_LEFT ? left_edge : right_edge)
                                                       : (OWN_TOP ? top_edge : bottom_edge);
    end
  endgenerate
  wire [ZR-1:0] depth_start = r[LSB_DEPTH_START +: ZR];
  wire [ZR-1:0] depth_step_x = r[LSB_DEPTH_STEP_X +: ZR];
  wire [ZR-1:0] depth_step_y = r[LSB_DEPTH_STEP_Y +: ZR];
  // The colour planes: channel c at [c * CR] of each colour field.
  wire [CR-1:0] color_start [0:2];
  wire [CR-1:0] color_step_x [0:2];
  wire [CR-1:0] color_step_y [0:2];
  generate
    for (k = 0; k < 3; k = k + 1) begin : channels
      assign color_start[k] = r[LSB_COLOR_START + k*CR +: CR];
      assign color_step_x[k] = r[LSB_COLOR_STEP_X + k*CR +: CR];
      assign color_step_y[k] = r[LSB_COLOR_STEP_Y + k*CR +: CR];
    end
  endgenerate

  // The record, field by field: one process drives the whole struct.
  always_comb begin
    rec.x0 = 16'(r[LSB_X0 +: X_BITS]);
    rec.x1 = 16'(r[LSB_X1 +: X_BITS]);
    rec.y0 = 16'(r[LSB_Y0 +: Y_BITS]);
    rec.y1 = 16'(r[LSB_Y1 +: Y_BITS]);
    rec.edge0_start = {{(64-EB){start[0][EB-1]}}, start[0]};
    rec.edge1_start = {{(64-EB){start[1][EB-1]}}, start[1]};
    rec.edge2_start = {{(64-EB){start[2][EB-1]}}, start[2]};
    rec.edge0_step_x = {{(64-SXB){step_x[0][SXB-1]}}, step_x[0]};
    rec.edge1_step_x = {{(64-SXB){step_x[1][SXB-1]}}, step_x[1]};
    rec.edge2_step_x = {{(64-SXB){step_x[2][SXB-1]}}, step_x[2]};
    rec.edge0_step_y = {{(64-SYB){step_y[0][SYB-1]}}, step_y[0]};
    rec.edge1_step_y = {{(64-SYB){step_y[1][SYB-1]}}, step_y[1]};
    rec.edge2_step_y = {{(64-SYB){step_y[2][SYB-1]}}, step_y[2]};
    rec.edge0_owns_samples = owns_samples[0];
    rec.edge1_owns_samples = owns_samples[1];
    rec.edge2_owns_samples = owns_samples[2];
    rec.depth_start = {{(64-ZR){depth_start[ZR-1]}}, depth_start};
    rec.depth_step_x = {{(64-ZR){depth_step_x[ZR-1]}}, depth_step_x};
    rec.depth_step_y = {{(64-ZR){depth_step_y[ZR-1]}}, depth_step_y};
    rec.red_start = {{(64-CR){color_start[0][CR-1]}}, color_start[0]};
    rec.red_step_x = {{(64-CR){color_step_x[0][CR-1]}}, color_step_x[0]};
    rec.red_step_y = {{(64-CR){color_step_y[0][CR-1]}}, color_step_y[0]};
    rec.green_start = {{(64-CR){color_start[1][CR-1]}}, color_start[1]};
    rec.green_step_x = {{(64-CR){color_step_x[1][CR-1]}}, color_step_x[1]};
    rec.green_step_y = {{(64-CR){color_step_y[1][CR-1]}}, color_step_y[1]};
    rec.blue_start = {{(64-CR){color_start[2][CR-1]}}, color_start[2]};
    rec.blue_step_x = {{(64-CR){color_step_x[2][CR-1]}}, color_step_x[2]};
    rec.blue_step_y = {{(64-CR){color_step_y[2][CR-1]}}, color_step_y[2]};
    rec.flat_rgb = r[LSB_FLAT_RGB +: 24];
  end

  // Done when every accepted triangle has its decision and every drawn one its record.
  reg [31:0] accepted_q, decided_q, drawn_q, records_q;
  always @(posedge clk) begin
    if (rst) begin
      accepted_q <= 32'd0;
      decided_q <= 32'd0;
      drawn_q <= 32'd0;
      records_q <= 32'd0;
    end else begin
      if (cmd_valid && cmd_ready) accepted_q <= accepted_q + 32'd1;
      if (decided) decided_q <= decided_q + 32'd1;
      if (decided && status == 3'd0) drawn_q <= drawn_q + 32'd1;
      if (out_valid) records_q <= records_q + 32'd1;
    end
  end
  assign frame_done = accepted_q == decided_q && drawn_q == records_q;
endmodule
