// Triangle setup unit (model/triangle_setup.cpp): snapped vertices in; edge functions with the
// top-left bias, the screen-clipped bounding box, the cull / degenerate / offscreen decision, the
// span-walker quotients, and the depth and colour planes from exact floor divisions.
//
// This module holds what both schedules share: the vertex registers, the bounding box, the
// cull / degenerate / offscreen / no-centre decision and its status, and the record's packing. The
// arithmetic runs in one of two schedules (docs/cycle-model.md), chosen by SETUP_INTERVAL:
// - 0: triangle_setup_serial, one shared shift-add / restoring datapath running a program of
//   operations, one triangle at a time;
// - I = 2..64: triangle_setup_pipelined, slots of I cycles, one triangle accepted per slot.
// TEXTURE = 1 adds the S, T, Q planes (docs/cycle-model.md, "The setup units with the texture
// unit"): the texture coordinates are registered here beside the vertices.
`include "rastersim_pkg.sv"
module triangle_setup `RS_IMPORT #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer SUBPIXEL_BITS = 4,
  parameter integer Z_BITS = 24,         // the depth plane's bits (docs/arithmetic.md section 6)
  parameter integer Z_GUARD_BITS = 0,
  parameter integer SETUP_INTERVAL = 0,  // 0: serial (one shared datapath); 2..64: pipelined, initiation interval
  parameter integer TEXTURE = 0,         // 1: the S, T, Q planes (profile texture_unit)
  parameter integer PIXEL_CENTER = 0,    // rastersim_pkg::PIXEL_CENTER_*: the sample point, half or corner (profile pixel_center)
  parameter integer FILL_RULE = 0        // rastersim_pkg::FILL_*: the edges that own samples on them (profile fill_rule)
) (
  input  wire clk,
  input  wire rst,
  input  wire run,                   // the frame runs (cycle 0 is its first cycle): slots count
  output wire free,                  // no triangle accepted in this slot yet (0: parallel, busy)
  input  `RS_TYPE(cull_t) cfg_cull,  // rastersim_pkg::CULL_*
  input  wire       cfg_front_face,  // rastersim_pkg::FRONT_*
  // Command input: vertex k at [k*B +: B]; x, y s(COORD_BITS-S).S subpixels; z uN; rgb {r,g,b} u8.
  input  wire in_valid,
  output wire in_ready,
  input  wire [3*rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] in_x,
  input  wire [3*rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] in_y,
  input  wire [3*Z_BITS-1:0] in_z,
  input  wire [3*rastersim_pkg::RGB_BITS-1:0] in_rgb,
  // Texture coordinates (TEXTURE = 1; unused otherwise): the triangle is textured, and vertex k's
  // c (0 S, 1 T, 2 Q) at [(3k + c) 50 +: 50], S and T s8.41, Q u1.41 (50 = rastersim_pkg::TEXTURE_VERTEX_BITS).
  /* verilator lint_off UNUSEDSIGNAL */
  input  wire in_textured,
  input  wire [3*rastersim_pkg::TEXTURE_COMMAND_BITS-1:0] in_texture,
  /* verilator lint_on UNUSEDSIGNAL */
  // Decision, valid in the FRONT cycle: status 0 drawn, 1 degenerate, 2 culled, 3 offscreen,
  // 4 no centre (rastersim_pkg::STATUS_*).
  output wire        decided,
  output `RS_TYPE(status_t) decided_status,
  output wire        decided_front_facing,
  output wire signed [rs_area_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] decided_area2,  // s.2S
  output wire busy,   // accept, FRONT, DIVIDE, or OUT cycles
  // Setup record of a drawn triangle (the model's SetupResult), valid for the one cycle setup_done.
  output wire out_valid,
  // Its fields by rs_rec_lsb / rs_rec_field_bits (rastersim_widths.vh).
  output wire [rs_rec_lsb(20, WIDTH, HEIGHT, SUBPIXEL_BITS, Z_BITS, Z_GUARD_BITS)-1:0] out_record,
  // The texture record beside it (rs_texture_record_bits): 0 with TEXTURE = 0 or untextured.
  output wire [rs_texture_record_bits(WIDTH, HEIGHT)-1:0] out_texture
);
`include "rastersim_widths.vh"
  `RS_REQUIRE(illegal_width, WIDTH >= 1 && WIDTH <= 4096, "triangle_setup: WIDTH must be 1..4096")
  `RS_REQUIRE(illegal_height, HEIGHT >= 1 && HEIGHT <= 4096, "triangle_setup: HEIGHT must be 1..4096")
  `RS_REQUIRE(illegal_subpixel_bits, SUBPIXEL_BITS >= 1 && SUBPIXEL_BITS <= 8, "triangle_setup: SUBPIXEL_BITS must be 1..8")
  `RS_REQUIRE(illegal_z_bits, Z_BITS >= 16 && Z_BITS <= 32, "triangle_setup: Z_BITS must be 16..32")
  `RS_REQUIRE(illegal_z_guard_bits, Z_GUARD_BITS >= 0 && Z_GUARD_BITS <= 24, "triangle_setup: Z_GUARD_BITS must be 0 (derived) or 1..24")
  `RS_REQUIRE(illegal_setup_interval, SETUP_INTERVAL == 0 || (SETUP_INTERVAL >= 2 && SETUP_INTERVAL <= 64), "triangle_setup: SETUP_INTERVAL must be 0 (serial) or 2..64")
  `RS_REQUIRE(illegal_texture, TEXTURE == 0 || TEXTURE == 1, "triangle_setup: TEXTURE must be 0 or 1")
  `RS_REQUIRE(illegal_pixel_center, PIXEL_CENTER == 0 || PIXEL_CENTER == 1, "triangle_setup: PIXEL_CENTER must be 0 (half) or 1 (corner)")
  `RS_REQUIRE(illegal_fill_rule, FILL_RULE >= 0 && FILL_RULE <= 3, "triangle_setup: FILL_RULE must be 0..3")

  localparam integer S = SUBPIXEL_BITS;
  localparam integer COORD_BITS = rs_coord_bits(WIDTH, HEIGHT, S);
  localparam integer AREA_BITS = rs_area_bits(WIDTH, HEIGHT, S);
  localparam integer BB = COORD_BITS + 2;           // bounding-box arithmetic, signed pixels
  // The sample point within a pixel, subpixels: half a pixel, or 0 at the corner (arithmetic.md 7).
  localparam integer SAMPLE = PIXEL_CENTER == rastersim_pkg::PIXEL_CENTER_CORNER ? 0 : 1 << (S - 1);
  localparam integer ONE_LESS = (1 << S) - 1;  // one pixel less one subpixel
  localparam integer X_LAST = WIDTH - 1;
  localparam integer Y_LAST = HEIGHT - 1;

  localparam signed [BB-1:0] SAMPLE_B = SAMPLE[BB-1:0];
  localparam signed [BB-1:0] ONE_LESS_B = ONE_LESS[BB-1:0];
  localparam signed [BB-1:0] X_LAST_B = X_LAST[BB-1:0];
  localparam signed [BB-1:0] Y_LAST_B = Y_LAST[BB-1:0];

  // The texture coordinates (TEXTURE = 1): vertex values m_t = 50 bits (S, T s8.41, Q u1.41).
  localparam integer TEX = TEXTURE != 0 ? 1 : 0;
  localparam integer MT = rastersim_pkg::TEXTURE_VERTEX_BITS;
  `RS_REQUIRE(texture_port_width, MT == 50, "triangle_setup: in_texture is written for 50-bit values")

  // The record (rastersim_widths.vh): both schedules give fields 0..17 packed in out_base and the
  // 16 PRODUCT results in out_along (n = 4p + 2j + t: plane p, left-edge slot j, t start / step,
  // at [n Z_REG_BITS]), packed below.
  localparam integer RECORD_Z_BITS = Z_BITS;  // the depth plane's (the core passes them as Z_BITS)
  `include "rastersim_record.vh"
  localparam integer BASE_BITS = LSB_LEFT_START;
  localparam integer Z_REG_BITS = Z_BITS + rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS) + 1;
  localparam integer COLOR_REG_BITS = 9 + rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS);
  localparam integer LEFT_SLOT_BITS = Z_REG_BITS + 3 * COLOR_REG_BITS;
  wire [BASE_BITS-1:0] out_base;
  // The colour planes in the low bits (their top bits unused).
  /* verilator lint_off UNUSEDSIGNAL */
  wire [16*Z_REG_BITS-1:0] out_along;
  /* verilator lint_on UNUSEDSIGNAL */
  assign out_record[BASE_BITS-1:0] = out_base;
  genvar lj, lc;
  generate
    for (lj = 0; lj < 2; lj = lj + 1) begin : left_record
      // Slot j of the left-edge fields holds depth, then r, g, b.
      assign out_record[LSB_LEFT_START + lj*LEFT_SLOT_BITS +: Z_REG_BITS] = out_along[(2*lj)*Z_REG_BITS +: Z_REG_BITS];
      assign out_record[LSB_LEFT_STEP + lj*LEFT_SLOT_BITS +: Z_REG_BITS] = out_along[(2*lj + 1)*Z_REG_BITS +: Z_REG_BITS];
      for (lc = 0; lc < 3; lc = lc + 1) begin : colors
        assign out_record[LSB_LEFT_START + lj*LEFT_SLOT_BITS + Z_REG_BITS + lc*COLOR_REG_BITS +: COLOR_REG_BITS] =
            out_along[(4*(lc + 1) + 2*lj)*Z_REG_BITS +: COLOR_REG_BITS];
        assign out_record[LSB_LEFT_STEP + lj*LEFT_SLOT_BITS + Z_REG_BITS + lc*COLOR_REG_BITS +: COLOR_REG_BITS] =
            out_along[(4*(lc + 1) + 2*lj + 1)*Z_REG_BITS +: COLOR_REG_BITS];
      end
    end
  endgenerate

  wire load_vertices;  // the accept cycle
  wire swap_vertices;  // order the vertices so that area2 > 0 (v1 and v2 trade places)

  // Vertices as accepted (v1 and v2 swapped by swap_vertices), vertex k at [k*B +: B] as in_*.
  reg signed [COORD_BITS-1:0] vx_q [0:2];
  reg signed [COORD_BITS-1:0] vy_q [0:2];
  reg [Z_BITS-1:0]    vz_q [0:2];
  reg [23:0]          vrgb_q [0:2];
  wire [3*COORD_BITS-1:0] vertex_x = {vx_q[2], vx_q[1], vx_q[0]};
  wire [3*COORD_BITS-1:0] vertex_y = {vy_q[2], vy_q[1], vy_q[0]};
  wire [3*Z_BITS-1:0] vertex_z = {vz_q[2], vz_q[1], vz_q[0]};
  wire [3*24-1:0] vertex_rgb = {vrgb_q[2], vrgb_q[1], vrgb_q[0]};
  // The texture coordinates as accepted (vertex k's c at [(3k + c) 50], as in_texture) and the
  // textured flag; zero without TEXTURE.
  wire [9*50-1:0] vertex_texture;
  wire vertex_textured;

  // ---- FRONT: area, facing, cull, bounding box (from the registered vertices) ----
  // Twice the signed area of the vertices as accepted, s.2S: combinational in the pipelined unit's
  // FRONT cycle, the AREA operation's result in the serial unit's DECIDE cycle.
  wire signed [AREA_BITS-1:0] area2;
  // y points down: area2 > 0 is clockwise as the viewer sees the screen.
  wire front_facing = cfg_front_face == rastersim_pkg::FRONT_CCW ? area2[AREA_BITS-1] : (area2 != 0 && !area2[AREA_BITS-1]);
  wire culled = (cfg_cull == rastersim_pkg::CULL_BACK && !front_facing) || (cfg_cull == rastersim_pkg::CULL_FRONT && front_facing);

  // The least of three from its three pairwise compares side by side (none waits for another);
  // the greatest is the least of the negated order (`greatest` set).
  function automatic signed [COORD_BITS-1:0] extreme3(input signed [COORD_BITS-1:0] a, input signed [COORD_BITS-1:0] b,
                                                       input signed [COORD_BITS-1:0] c, input greatest);
    reg a_b, a_c, b_c;  // the first is at least as extreme as the second
    begin
      a_b = greatest ? a >= b : a <= b;
      a_c = greatest ? a >= c : a <= c;
      b_c = greatest ? b >= c : b <= c;
      extreme3 = a_b && a_c ? a : !a_b && b_c ? b : c;
    end
  endfunction
  wire signed [COORD_BITS-1:0] x_min_c = extreme3(vx_q[0], vx_q[1], vx_q[2], 1'b0);
  wire signed [COORD_BITS-1:0] x_max_c = extreme3(vx_q[0], vx_q[1], vx_q[2], 1'b1);
  wire signed [COORD_BITS-1:0] y_min_c = extreme3(vy_q[0], vy_q[1], vy_q[2], 1'b0);
  wire signed [COORD_BITS-1:0] y_max_c = extreme3(vy_q[0], vy_q[1], vy_q[2], 1'b1);
  wire signed [BB-1:0] x_min = $signed({{(BB-COORD_BITS){x_min_c[COORD_BITS-1]}}, x_min_c});
  wire signed [BB-1:0] x_max = $signed({{(BB-COORD_BITS){x_max_c[COORD_BITS-1]}}, x_max_c});
  wire signed [BB-1:0] y_min = $signed({{(BB-COORD_BITS){y_min_c[COORD_BITS-1]}}, y_min_c});
  wire signed [BB-1:0] y_max = $signed({{(BB-COORD_BITS){y_max_c[COORD_BITS-1]}}, y_max_c});
  // The extremes the box is cut from: x_min .. y_max themselves for the pipelined unit, registered
  // copies for the serial unit (below).
  wire signed [BB-1:0] box_x_min, box_x_max, box_y_min, box_y_max;
  // Pixel i is a candidate when its sample point i 2^S + SAMPLE lies in [min, max].
  wire signed [BB-1:0] bx0_num = box_x_min - SAMPLE_B + ONE_LESS_B;
  wire signed [BB-1:0] by0_num = box_y_min - SAMPLE_B + ONE_LESS_B;
  wire signed [BB-1:0] bx1_num = box_x_max - SAMPLE_B;
  wire signed [BB-1:0] by1_num = box_y_max - SAMPLE_B;
  wire signed [BB-1:0] bx0_raw = bx0_num >>> S;
  wire signed [BB-1:0] by0_raw = by0_num >>> S;
  wire signed [BB-1:0] bx1_raw = bx1_num >>> S;
  wire signed [BB-1:0] by1_raw = by1_num >>> S;
  wire signed [BB-1:0] bx0 = bx0_raw < 0 ? 0 : bx0_raw;
  wire signed [BB-1:0] by0 = by0_raw < 0 ? 0 : by0_raw;
  wire signed [BB-1:0] bx1 = bx1_raw > X_LAST_B ? X_LAST_B : bx1_raw;
  wire signed [BB-1:0] by1 = by1_raw > Y_LAST_B ? Y_LAST_B : by1_raw;
  // Offscreen: the box's centre columns or rows all lie beyond the screen. Otherwise the clipped
  // box is empty only when the whole-grid one is: no pixel centre in the box.
  wire offscreen = bx1_raw < 0 || by1_raw < 0 || bx0_raw > X_LAST_B || by0_raw > Y_LAST_B;
  // The box as the status and the schedules take it: the pipelined unit's FRONT cycle uses the
  // combinational box; for the serial unit the box is computed in three registered steps (the
  // extremes, the clipped box and offscreen, then no_centre from the clipped box), which takes that
  // chain off its critical path and moves no cycle: its vertices are loaded 2 DELTA_BITS + 2 cycles
  // before DECIDE, and the box does not change when DECIDE swaps two vertices.
  wire box_offscreen, box_no_centre;
  // The first candidate column and row (its centre feeds the edge values) and the last ones, the
  // record's x0, x1, y0, y1 in their low bits; signed pixels, in 0 .. WIDTH-1 (HEIGHT-1) when drawn.
  wire signed [BB-1:0] box_x0, box_x1, box_y0, box_y1;

  `RS_TYPE(status_t) status;
  assign status = area2 == 0 ? rastersim_pkg::STATUS_DEGENERATE : culled ? rastersim_pkg::STATUS_CULLED
                 : box_offscreen ? rastersim_pkg::STATUS_OFFSCREEN : box_no_centre ? rastersim_pkg::STATUS_NO_CENTRE : rastersim_pkg::STATUS_DRAWN;
  assign decided_status = status;
  assign decided_front_facing = area2 != 0 && front_facing;
  assign decided_area2 = area2;

  generate
  if (SETUP_INTERVAL == 0) begin : serial
    // ---- The box, in three registered steps (the vertices change only at accept and swap): the
    // extremes, the clipped box and offscreen, then no_centre from the clipped box ----
    reg signed [BB-1:0] x_min_q, x_max_q, y_min_q, y_max_q;
    always @(posedge clk) begin
      x_min_q <= x_min;
      x_max_q <= x_max;
      y_min_q <= y_min;
      y_max_q <= y_max;
    end
    assign box_x_min = x_min_q;
    assign box_x_max = x_max_q;
    assign box_y_min = y_min_q;
    assign box_y_max = y_max_q;
    reg signed [BB-1:0] box_x0_q, box_y0_q;  // the first candidate
    reg signed [BB-1:0] box_x1_q, box_y1_q;  // the last candidate column and row
    reg box_offscreen_q, box_no_centre_q;
    always @(posedge clk) begin
      box_x0_q <= bx0;
      box_x1_q <= bx1;
      box_y0_q <= by0;
      box_y1_q <= by1;
      box_offscreen_q <= offscreen;
      box_no_centre_q <= box_x0_q > box_x1_q || box_y0_q > box_y1_q;
    end
    assign box_x0 = box_x0_q;
    assign box_x1 = box_x1_q;
    assign box_y0 = box_y0_q;
    assign box_y1 = box_y1_q;
    assign box_offscreen = box_offscreen_q;
    assign box_no_centre = box_no_centre_q;
    wire unused_run = run;  // one triangle at a time: no slots

    triangle_setup_serial #(
      .WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS), .Z_BITS(Z_BITS), .Z_GUARD_BITS(Z_GUARD_BITS),
      .TEXTURE(TEXTURE), .PIXEL_CENTER(PIXEL_CENTER), .FILL_RULE(FILL_RULE)
    ) schedule (
      .clk(clk), .rst(rst), .free(free), .in_valid(in_valid), .in_ready(in_ready), .in_x(in_x), .in_y(in_y),
      .load_vertices(load_vertices), .swap_vertices(swap_vertices),
      .vertex_x(vertex_x), .vertex_y(vertex_y), .vertex_z(vertex_z), .vertex_rgb(vertex_rgb),
      .vertex_texture(vertex_texture), .vertex_textured(vertex_textured),
      .box_x0(box_x0), .box_x1(box_x1), .box_y0(box_y0), .box_y1(box_y1),
      .area2(area2), .status(status), .decided(decided), .busy(busy),
      .out_valid(out_valid), .out_base(out_base), .out_along(out_along), .out_texture(out_texture)
    );
  end else begin : pipelined
    assign box_x_min = x_min;
    assign box_x_max = x_max;
    assign box_y_min = y_min;
    assign box_y_max = y_max;
    assign box_x0 = bx0;
    assign box_x1 = bx1;
    assign box_y0 = by0;
    assign box_y1 = by1;
    assign box_offscreen = offscreen;
    assign box_no_centre = bx0 > bx1 || by0 > by1;

    triangle_setup_pipelined #(
      .WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS), .Z_BITS(Z_BITS), .Z_GUARD_BITS(Z_GUARD_BITS),
      .SETUP_INTERVAL(SETUP_INTERVAL), .TEXTURE(TEXTURE), .PIXEL_CENTER(PIXEL_CENTER), .FILL_RULE(FILL_RULE)
    ) schedule (
      .clk(clk), .rst(rst), .run(run), .free(free), .in_valid(in_valid), .in_ready(in_ready),
      .load_vertices(load_vertices), .swap_vertices(swap_vertices),
      .vertex_x(vertex_x), .vertex_y(vertex_y), .vertex_z(vertex_z), .vertex_rgb(vertex_rgb),
      .vertex_texture(vertex_texture), .vertex_textured(vertex_textured),
      .box_x0(box_x0), .box_x1(box_x1), .box_y0(box_y0), .box_y1(box_y1),
      .area2(area2), .status(status), .decided(decided), .busy(busy),
      .out_valid(out_valid), .out_base(out_base), .out_along(out_along), .out_texture(out_texture)
    );
  end
  endgenerate

  // Vertices (no reset: loaded before use).
  integer v;
  always @(posedge clk) begin
    if (load_vertices) begin
      for (v = 0; v < 3; v = v + 1) begin
        vx_q[v] <= in_x[v*COORD_BITS +: COORD_BITS];
        vy_q[v] <= in_y[v*COORD_BITS +: COORD_BITS];
        vz_q[v] <= in_z[v*Z_BITS +: Z_BITS];
        vrgb_q[v] <= in_rgb[v*24 +: 24];
      end
    end else if (swap_vertices) begin
      vx_q[1] <= vx_q[2];
      vx_q[2] <= vx_q[1];
      vy_q[1] <= vy_q[2];
      vy_q[2] <= vy_q[1];
      vz_q[1] <= vz_q[2];
      vz_q[2] <= vz_q[1];
      vrgb_q[1] <= vrgb_q[2];
      vrgb_q[2] <= vrgb_q[1];
    end
  end

  // Texture coordinates and flag (TEXTURE = 1; no reset: loaded before use), swapped with the
  // vertices.
  genvar tv;
  generate
  if (TEX != 0) begin : texture_vertices
    reg [MT-1:0] vtex_q [0:8];
    reg textured_q;
    integer tk;
    always @(posedge clk) begin
      if (load_vertices) begin
        textured_q <= in_textured;
        for (tk = 0; tk < 9; tk = tk + 1) vtex_q[tk] <= in_texture[tk*MT +: MT];
      end else if (swap_vertices) begin
        for (tk = 0; tk < 3; tk = tk + 1) begin
          vtex_q[3 + tk] <= vtex_q[6 + tk];
          vtex_q[6 + tk] <= vtex_q[3 + tk];
        end
      end
    end
    for (tv = 0; tv < 9; tv = tv + 1) begin : values
      assign vertex_texture[tv*MT +: MT] = vtex_q[tv];
    end
    assign vertex_textured = textured_q;
  end else begin : no_texture_vertices
    assign vertex_texture = {(9*50){1'b0}};
    assign vertex_textured = 1'b0;
  end
  endgenerate
endmodule
