// Triangle setup unit (model/triangle_setup.cpp): snapped vertices in; edge functions with the
// top-left bias, the screen-clipped bounding box, the cull / degenerate / offscreen decision, the
// span-walker quotients, and the depth and colour planes from exact floor divisions.
//
// Two schedules of the same arithmetic (docs/cycle-model.md), chosen by SETUP_INTERVAL:
// - 0, serial: accept in cycle a (in_valid & in_ready while idle); one shared shift-add / restoring
//   datapath runs the program of operations from a+1; DECIDE in a+2+2 DELTA_BITS decides (a rejected
//   triangle ends there); the output is valid one cycle after FINAL (setup_done, a +
//   rs_setup_serial_latency) for that one cycle, in which the core passes it to the walker or into
//   the record FIFO (rastersim_core.sv); the unit is free after it.
// - I = 2..64, pipelined: slots of I cycles counted from the first cycle of `run`; accept only in
//   a slot's first cycle; FRONT slot (decision in a+1), EDGE_STAGES edge slots, NUMER_STAGES
//   numerator slots, DIVIDE_STAGES divide slots, PRODUCT_STAGES product slots, then the output
//   register, valid in a + I (1 + EDGE_STAGES + NUMER_STAGES + DIVIDE_STAGES + PRODUCT_STAGES).
// TEXTURE = 1 adds the S, T, Q planes (docs/cycle-model.md, "The setup units with the texture
// unit"): the serial program inserts their operations for a textured triangle only; the pipelined
// slots are sized for them for every triangle.
module triangle_setup #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer SUBPIXEL_BITS = 4,
  parameter integer Z_BITS = 24,         // the depth plane's bits (docs/arithmetic.md section 6)
  parameter integer Z_GUARD_BITS = 0,
  parameter integer SETUP_INTERVAL = 0,  // 0: serial (one shared datapath); 2..64: pipelined, initiation interval
  parameter integer TEXTURE = 0,         // 1: the S, T, Q planes (profile texture_unit)
  parameter integer PIXEL_CENTER = 0,    // RS_PIXEL_CENTER_*: the sample point, half or corner (profile pixel_center)
  parameter integer FILL_RULE = 0        // RS_FILL_*: the edges that own samples on them (profile fill_rule)
) (
  input  wire clk,
  input  wire rst,
  input  wire run,                   // the frame runs (cycle 0 is its first cycle): slots count
  output wire free,                  // no triangle accepted in this slot yet (0: parallel, busy)
  input  wire [1:0] cfg_cull,        // RS_CULL_* (rastersim_widths.vh)
  input  wire       cfg_front_face,  // RS_FRONT_*
  // Command input: vertex k at [k*B +: B]; x, y s(COORD_BITS-S).S subpixels; z uN; rgb {r,g,b} u8.
  input  wire in_valid,
  output wire in_ready,
  input  wire [3*rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] in_x,
  input  wire [3*rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] in_y,
  input  wire [3*Z_BITS-1:0] in_z,
  input  wire [3*24-1:0]     in_rgb,
  // Texture coordinates (TEXTURE = 1; unused otherwise): the triangle is textured, and vertex k's
  // c (0 S, 1 T, 2 Q) at [(3k + c) 50 +: 50], S and T s8.41, Q u1.41 (50 = RS_TEXTURE_VERTEX_BITS).
  /* verilator lint_off UNUSEDSIGNAL */
  input  wire in_textured,
  input  wire [9*50-1:0] in_texture,
  /* verilator lint_on UNUSEDSIGNAL */
  // Decision, valid in the FRONT cycle: status 0 drawn, 1 degenerate, 2 culled, 3 offscreen,
  // 4 no centre (RS_STATUS_*).
  output wire        decided,
  output wire [2:0]  decided_status,
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
  localparam integer F = rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS);
  localparam integer COORD_BITS = rs_coord_bits(WIDTH, HEIGHT, S);
  localparam integer DELTA_BITS = rs_delta_bits(WIDTH, HEIGHT, S);
  localparam integer AREA_BITS = rs_area_bits(WIDTH, HEIGHT, S);
  localparam integer EDGE_BITS = rs_edge_bits(WIDTH, HEIGHT, S);
  localparam integer EDGE_STEP_X_BITS = rs_edge_step_x_bits(HEIGHT, S);
  localparam integer EDGE_STEP_Y_BITS = rs_edge_step_y_bits(WIDTH, S);
  localparam integer SPAN_REM_BITS = rs_span_rem_bits(HEIGHT, S);
  localparam integer DIVIDER_BITS = rs_divider_bits(WIDTH, HEIGHT, S, Z_BITS, Z_GUARD_BITS);
  localparam integer X_BITS = rs_ubits32(WIDTH - 1);
  localparam integer Y_BITS = rs_ubits32(HEIGHT - 1);
  localparam integer BB = COORD_BITS + 2;           // bounding-box arithmetic, signed pixels
  // Plane numerators sum_k v_k e_k, signed (pipelined unit): v of N bits, or m_t with TEXTURE.
  localparam integer NB = (TEXTURE != 0 ? RS_TEXTURE_VERTEX_BITS : Z_BITS) + EDGE_BITS + 4;
  // The sample point within a pixel, subpixels: half a pixel, or 0 at the corner (arithmetic.md 7).
  localparam integer SAMPLE = PIXEL_CENTER == RS_PIXEL_CENTER_CORNER ? 0 : 1 << (S - 1);
  // Which edges own the samples on them (FILL_RULE): left (else right) ones, top (else bottom) ones.
  localparam [0:0] OWN_LEFT = FILL_RULE == RS_FILL_TOP_LEFT || FILL_RULE == RS_FILL_BOTTOM_LEFT;
  localparam [0:0] OWN_TOP = FILL_RULE == RS_FILL_TOP_LEFT || FILL_RULE == RS_FILL_TOP_RIGHT;
  // Whether an edge owns the samples on it, from the signs of its -dy and dx (the ordered triangle
  // has its interior to the right as y points down: -dy > 0 is a left edge, a horizontal edge with
  // dx > 0 a top one); model/triangle_setup.cpp owns_samples_on_edge.
  function automatic owns_samples(input ndy_positive, input ndy_negative, input dx_positive, input dx_negative);
    owns_samples = ndy_positive || ndy_negative ? (OWN_LEFT ? ndy_positive : ndy_negative)
                                                : (OWN_TOP ? dx_positive : dx_negative);
  endfunction
  localparam integer ONE_LESS = (1 << S) - 1;  // one pixel less one subpixel
  localparam integer X_LAST = WIDTH - 1;
  localparam integer Y_LAST = HEIGHT - 1;

  localparam signed [BB-1:0] SAMPLE_B = SAMPLE[BB-1:0];
  localparam signed [BB-1:0] ONE_LESS_B = ONE_LESS[BB-1:0];
  localparam signed [BB-1:0] X_LAST_B = X_LAST[BB-1:0];
  localparam signed [BB-1:0] Y_LAST_B = Y_LAST[BB-1:0];

  // The texture planes (TEXTURE = 1; docs/arithmetic.md section 5): vertex values m_t = 50 bits (S,
  // T s8.41, Q u1.41), registers s9.(P+Ft) of TR = P + Ft + 9 bits, Ft the derived guard bits.
  localparam integer TEX = TEXTURE != 0 ? 1 : 0;
  localparam integer MT = RS_TEXTURE_VERTEX_BITS;
  localparam integer TR = rs_texture_reg_bits(WIDTH, HEIGHT);
  localparam integer FT = rs_guard_bits(WIDTH, HEIGHT, 0);
  localparam integer TVB = TEX != 0 ? MT : 1;  // a texture vertex value (1: none, tied to 0)
  `RS_REQUIRE(texture_port_width, MT == 50, "triangle_setup: in_texture is written for 50-bit values")


  // The record (rastersim_widths.vh): both schedules give fields 0..17 packed in out_base and the
  // 16 PRODUCT results in out_along (n = 4p + 2j + t: plane p, left-edge slot j, t start / step),
  // packed below.
  localparam integer RECORD_Z_BITS = Z_BITS;  // the depth plane's (the core passes them as Z_BITS)
  `include "rastersim_record.vh"
  localparam integer BASE_BITS = LSB_LEFT_START;
  localparam integer Z_REG_BITS = Z_BITS + rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS) + 1;
  localparam integer COLOR_REG_BITS = 9 + rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS);
  localparam integer LEFT_SLOT_BITS = Z_REG_BITS + 3 * COLOR_REG_BITS;
  wire [BASE_BITS-1:0] out_base;
  wire [Z_REG_BITS-1:0] out_along [0:15];  // colour planes in the low bits
  assign out_record[BASE_BITS-1:0] = out_base;
  genvar lj, lc;
  generate
    for (lj = 0; lj < 2; lj = lj + 1) begin : left_record
      // Slot j of the left-edge fields holds depth, then r, g, b.
      assign out_record[LSB_LEFT_START + lj*LEFT_SLOT_BITS +: Z_REG_BITS] = out_along[2*lj];
      assign out_record[LSB_LEFT_STEP + lj*LEFT_SLOT_BITS +: Z_REG_BITS] = out_along[2*lj + 1];
      for (lc = 0; lc < 3; lc = lc + 1) begin : colors
        assign out_record[LSB_LEFT_START + lj*LEFT_SLOT_BITS + Z_REG_BITS + lc*COLOR_REG_BITS +: COLOR_REG_BITS] =
            out_along[4*(lc + 1) + 2*lj][COLOR_REG_BITS-1:0];
        assign out_record[LSB_LEFT_STEP + lj*LEFT_SLOT_BITS + Z_REG_BITS + lc*COLOR_REG_BITS +: COLOR_REG_BITS] =
            out_along[4*(lc + 1) + 2*lj + 1][COLOR_REG_BITS-1:0];
      end
    end
  endgenerate

  wire load_vertices;  // the accept cycle
  wire swap_vertices;  // order the vertices so that area2 > 0 (v1 and v2 trade places)
  // The texture coordinates as accepted (vertex k's c at [3k + c]) and the textured flag; zero
  // without TEXTURE (and then unused by the pipelined unit).
  /* verilator lint_off UNUSEDSIGNAL */
  wire [TVB-1:0] vtex [0:8];
  wire vtextured;
  /* verilator lint_on UNUSEDSIGNAL */

  // Vertices as accepted.
  reg signed [COORD_BITS-1:0] vx_q [0:2];
  reg signed [COORD_BITS-1:0] vy_q [0:2];
  reg [Z_BITS-1:0]    vz_q [0:2];
  reg [23:0]          vrgb_q [0:2];

  // ---- FRONT: area, facing, cull, bounding box (from the registered vertices) ----
  // Twice the signed area of the vertices as accepted, s.2S: combinational in the pipelined unit's
  // FRONT cycle, the AREA operation's result in the serial unit's DECIDE cycle.
  wire signed [AREA_BITS-1:0] area2;
  // y points down: area2 > 0 is clockwise as the viewer sees the screen.
  wire front_facing = cfg_front_face == RS_FRONT_CCW ? area2[AREA_BITS-1] : (area2 != 0 && !area2[AREA_BITS-1]);
  wire culled = (cfg_cull == RS_CULL_BACK && !front_facing) || (cfg_cull == RS_CULL_FRONT && front_facing);
  wire swap = area2[AREA_BITS-1];  // order the vertices so that area2 > 0

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
  // The extremes the box is cut from: x_min .. y_max themselves in the pipelined unit, registered
  // copies in the serial unit (below).
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
  // The box's decision as the status takes it: the pipelined unit's FRONT cycle uses the
  // combinational box; the serial unit computes the box in three registered steps (the extremes,
  // the clipped box and offscreen, then no_centre from the clipped box), which takes that chain
  // off its critical path and moves no cycle: its vertices are loaded 2 DELTA_BITS + 2 cycles
  // before DECIDE, and the box does not change when DECIDE swaps two vertices.
  wire box_offscreen, box_no_centre;

  wire [2:0] status = area2 == 0 ? RS_STATUS_DEGENERATE : culled ? RS_STATUS_CULLED
                    : box_offscreen ? RS_STATUS_OFFSCREEN : box_no_centre ? RS_STATUS_NO_CENTRE : RS_STATUS_DRAWN;
  assign decided_status = status;
  assign decided_front_facing = area2 != 0 && front_facing;
  assign decided_area2 = area2;

  generate
  if (SETUP_INTERVAL == 0) begin : serial
    // The record fields, packed into out_base.
    wire [X_BITS-1:0] out_x0, out_x1;
    wire [Y_BITS-1:0] out_y0, out_y1;
    wire [3*EDGE_BITS-1:0] out_edge_start;  // s.2S, biased
    wire [3*EDGE_STEP_X_BITS-1:0] out_edge_step_x;  // s.2S
    wire [3*EDGE_STEP_Y_BITS-1:0] out_edge_step_y;  // s.2S
    wire [3*EDGE_BITS-1:0] out_span_quot;
    wire [3*SPAN_REM_BITS-1:0] out_span_rem;
    wire [3*EDGE_STEP_Y_BITS-1:0] out_span_step_quot;
    wire [3*SPAN_REM_BITS-1:0] out_span_step_rem;
    wire [Z_REG_BITS-1:0] out_depth_start, out_depth_step_x, out_depth_step_y;
    wire [3*COLOR_REG_BITS-1:0] out_color_start, out_color_step_x, out_color_step_y;
    wire [23:0] out_flat_rgb;  // provoking (first) vertex colour
    assign out_base = {out_flat_rgb, out_color_step_y, out_color_step_x, out_color_start, out_depth_step_y,
                       out_depth_step_x, out_depth_start, out_span_step_rem, out_span_step_quot, out_span_rem,
                       out_span_quot, out_edge_step_y, out_edge_step_x, out_edge_start, out_y1, out_y0, out_x1, out_x0};
    // ---- Serial schedule (docs/cycle-model.md): one shared datapath runs a program of operations ----
    // An operation is a load cycle (operands in, the previous operation's result into the record)
    // and its steps. Multiplies shift and add least significant bit first into ACC = {HI, LO}: HI is
    // H bits, LO holds the product's low bits; the terms of a sum of products take turns on one
    // adder, one bit of each per step. Divisions are restoring, dividend bits leaving ACC at the top
    // and quotient bits entering at the bottom; a negative dividend n is divided as ~n = -n - 1 and
    // its quotient inverted, floor(n / d) = ~floor(~n / d).
    localparam integer H = rs_setup_serial_bits(WIDTH, HEIGHT, S);
    localparam integer MB0 = (DELTA_BITS > COORD_BITS + 1 ? (DELTA_BITS > Z_BITS ? DELTA_BITS : Z_BITS) : (COORD_BITS + 1 > Z_BITS ? COORD_BITS + 1 : Z_BITS));
    localparam integer MB = TEX != 0 && MT > MB0 ? MT : MB0;  // multiplier bits: m_t with TEXTURE
    localparam integer ACC_BITS = H + MB;
    // Step counters: at most H + N + F + S + 1 < 128 steps; 3 m_t = 150 with TEXTURE.
    localparam integer SB = TEX != 0 ? 8 : 7;
    // Operations: AREA, DECIDE, EDGE k, SPAN START k / SPAN STEP k, plane n = 3p + c (p: depth, r,
    // g, b, with TEXTURE S, T, Q; c: start, step x, step y) numerator and division, PRODUCT n = 4p +
    // 2j + t (plane p along left-edge slot j, t: start, step), FINAL. An untextured triangle skips
    // the S, T, Q operations. Plane numbers p have PPB bits, the top one marking S, T, Q.
    localparam integer OPB = TEX != 0 ? 7 : 6;
    localparam integer PPB = TEX != 0 ? 3 : 2;
    localparam integer PNB = PPB + 2;             // product numbers
    localparam integer PNW = TEX != 0 ? 5 : 4;    // plane numbers n = 3p + c
    localparam integer PLANE_OPS = TEX != 0 ? 42 : 24;
    localparam integer PRODUCT_OPS = TEX != 0 ? 28 : 16;
    localparam [OPB-1:0] OP_AREA = OPB'(0), OP_DECIDE = OPB'(1), OP_EDGE = OPB'(2), OP_SPAN = OPB'(5),
                         OP_PLANE = OPB'(11), OP_PRODUCT = OPB'(11 + PLANE_OPS),
                         OP_FINAL = OPB'(11 + PLANE_OPS + PRODUCT_OPS);
    localparam integer PB = rs_setup_product_bits(WIDTH, HEIGHT, S, Z_BITS, Z_GUARD_BITS);
    localparam integer PBT = rs_setup_texture_product_bits(WIDTH, HEIGHT, S);  // PBt
    localparam integer PBM = TEX != 0 && PBT > PB ? PBT : PB;  // the multiplier register
    localparam integer PRB = TEX != 0 && TR > Z_REG_BITS ? TR : Z_REG_BITS;  // the product accumulator
    localparam integer PB_SHIFT = PBM - PB;  // a PB-bit multiplier at the register's top
    localparam integer PBT_SHIFT = PBM > PBT ? PBM - PBT : 0;

    reg active_q;                   // a triangle is in the unit, from the cycle after its accept
    reg out_q;                      // the record is in the output register (setup_done)
    reg load_q;                     // the current operation's load cycle
    reg [OPB-1:0] op_q;
    reg [SB-1:0] left_q;            // steps left in the operation
    reg [SB-1:0] data_left_q;       // dividend bits left before the appended zeros
    reg data_left_nonzero_q;        // data_left_q != 0, kept beside it (off the trial's path)
    reg [1:0] term_q;               // which product of the sum takes this step
    reg sign_q;                     // the dividend is negative: divide ~n, invert the quotient
    reg signed [ACC_BITS-1:0] acc_q;
    reg [AREA_BITS-1:0] rem_q;             // restoring remainder, < |divisor| <= 2^(AREA_BITS-1)
    reg [MB-1:0] mq_q [0:2];        // multipliers, consumed from bit 0, the current term's in mq_q[0]
    reg signed [AREA_BITS-1:0] area_q;     // twice the signed area (the plane divisor)
    // The record's computed fields (the others come from the vertex registers).
    reg signed [EDGE_BITS-1:0] start_q [0:2];
    reg [EDGE_BITS-1:0]  span_quot_q [0:2];
    reg [SPAN_REM_BITS-1:0]  span_rem_q [0:2];
    reg [EDGE_STEP_Y_BITS-1:0] span_step_quot_q [0:2];
    reg [SPAN_REM_BITS-1:0]  span_step_rem_q [0:2];
    reg [Z_REG_BITS-1:0] depth_q [0:2];
    reg [COLOR_REG_BITS-1:0] color_q [0:8];
    reg [Z_REG_BITS-1:0] along_q [0:15];  // PRODUCT n's result (colour planes in the low bits)

    // Ordered edge deltas (the vertices are swapped in DECIDE when area2 < 0): dx = b.x - a.x and
    // ndy = a.y - b.y, so edge_step_x = ndy 2^S and edge_step_y = dx 2^S. Registered: computed
    // from the command at the accept, and when DECIDE swaps v1 and v2 the edges trade places and
    // turn round (dx'0 = -dx2, dx'1 = -dx1, dx'2 = -dx0, ndy alike), so that no step waits for
    // a subtraction of vertex registers.
    reg signed [DELTA_BITS-1:0] dx_q [0:2];
    reg signed [DELTA_BITS-1:0] ndy_q [0:2];
    integer d;
    always @(posedge clk) begin
      if (load_vertices) begin
        for (d = 0; d < 3; d = d + 1) begin
          dx_q[d] <= DELTA_BITS'($signed(in_x[((d + 1) % 3)*COORD_BITS +: COORD_BITS]))
                     - DELTA_BITS'($signed(in_x[d*COORD_BITS +: COORD_BITS]));
          ndy_q[d] <= DELTA_BITS'($signed(in_y[d*COORD_BITS +: COORD_BITS]))
                      - DELTA_BITS'($signed(in_y[((d + 1) % 3)*COORD_BITS +: COORD_BITS]));
        end
      end else if (swap_vertices) begin
        for (d = 0; d < 3; d = d + 1) begin
          dx_q[d] <= -dx_q[2 - d];
          ndy_q[d] <= -ndy_q[2 - d];
        end
      end
    end
    // The fill rule's bias per edge, registered beside the deltas so that no step waits for
    // their compares: the cycle after the vertices are loaded from the deltas (nothing reads it
    // before DECIDE), and in the swap from the deltas as they turn round (each sign inverted).
    reg [2:0] bias_q;
    integer e;
    always @(posedge clk) begin
      for (e = 0; e < 3; e = e + 1)
        bias_q[e] <= swap_vertices ? !owns_samples(ndy_q[2 - e] < 0, ndy_q[2 - e] > 0, dx_q[2 - e] < 0, dx_q[2 - e] > 0)
                                   : !owns_samples(ndy_q[e] > 0, ndy_q[e] < 0, dx_q[e] > 0, dx_q[e] < 0);
    end
    wire signed [DELTA_BITS-1:0] dx [0:2];
    wire signed [DELTA_BITS-1:0] ndy [0:2];
    wire [2:0] bias;                // 1 unless the edge is top or left
    genvar k;
    for (k = 0; k < 3; k = k + 1) begin : deltas
      assign dx[k] = dx_q[k];
      assign ndy[k] = ndy_q[k];
      assign bias[k] = bias_q[k];
      assign out_edge_step_x[k*EDGE_STEP_X_BITS +: EDGE_STEP_X_BITS] = EDGE_STEP_X_BITS'({ndy[k], {S{1'b0}}});
      assign out_edge_step_y[k*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS] = EDGE_STEP_Y_BITS'({dx[k], {S{1'b0}}});
    end

    // The operation's shape, decoded into op_shape_q whenever op_q is set (from the operation it
    // is set to), so that no step waits for the decode of op_q: {is_product, product_n[PNB-1:0],
    // is_area, is_edge, is_span, is_plane, edge_k[1:0], span_k[1:0], span_step, plane_div,
    // plane_p[PPB-1:0], plane_c[1:0]}.
    localparam integer SHAPE_BITS = PNB + PPB + 13;  // 19 without TEXTURE
    /* verilator lint_off UNUSEDSIGNAL */
    function automatic [SHAPE_BITS-1:0] op_shape(input [OPB-1:0] op);
      reg [OPB-1:0] edge_op, span_op, plane_op, product_op;
      reg [PNW-1:0] plane_n, plane_c_wide;
      reg [PPB-1:0] plane_p;
      begin
        edge_op = op - OP_EDGE;
        span_op = op - OP_SPAN;
        plane_op = op - OP_PLANE;
        product_op = op - OP_PRODUCT;
        plane_n = plane_op[PNW:1];  // plane n = 3p + c: p depth, r, g, b (S, T, Q); c start, step x, step y
        plane_p = PPB'(plane_n < 3 ? 0 : plane_n < 6 ? 1 : plane_n < 9 ? 2 : 3);
        if (TEX != 0 && plane_n >= 12) plane_p = PPB'({1'b0, plane_n} < 15 ? 4 : {1'b0, plane_n} < 18 ? 5 : 6);
        plane_c_wide = plane_n - PNW'(3 * plane_p);
        op_shape = {op >= OP_PRODUCT && op < OP_FINAL, product_op[PNB-1:0],
                    op == OP_AREA, op >= OP_EDGE && op < OP_SPAN, op >= OP_SPAN && op < OP_PLANE,
                    op >= OP_PLANE && op < OP_PRODUCT, edge_op[1:0], span_op[2:1], span_op[0], plane_op[0], plane_p,
                    plane_c_wide[1:0]};
      end
    endfunction
    /* verilator lint_on UNUSEDSIGNAL */
    reg [SHAPE_BITS-1:0] op_shape_q;
    wire is_product = op_shape_q[SHAPE_BITS-1];
    wire [PNB-1:0] product_n = op_shape_q[PPB + 12 +: PNB];  // 4p + 2j + t
    wire is_area = op_shape_q[PPB + 11];
    wire is_edge = op_shape_q[PPB + 10];
    wire is_span = op_shape_q[PPB + 9];
    wire is_plane = op_shape_q[PPB + 8];
    wire [1:0] edge_k = op_shape_q[PPB + 6 +: 2];
    wire [1:0] span_k = op_shape_q[PPB + 4 +: 2];
    wire span_step = op_shape_q[PPB + 3];          // SPAN STEP (else SPAN START)
    wire plane_div = op_shape_q[PPB + 2];          // the division (else the numerator)
    wire [PPB-1:0] plane_p = op_shape_q[2 +: PPB];
    wire [1:0] plane_c = op_shape_q[1:0];
    wire plane_texture = TEX != 0 && is_plane && plane_p[PPB-1];  // S, T, Q: m_t-bit signed values, Ft guard bits
    wire product_texture = TEX != 0 && product_n[PNB-1];
    wire is_mul = is_area || is_edge || (is_plane && !plane_div);
    wire is_div = is_span || (is_plane && plane_div);
    // m: the vertex values' bits
    wire [SB-1:0] plane_bits = plane_texture ? SB'(MT) : plane_p == {PPB{1'b0}} ? SB'(Z_BITS) : SB'(8);
    wire [SB-1:0] steps = is_area ? SB'(2 * DELTA_BITS)
                        : is_edge ? SB'(2 * (COORD_BITS + 1))
                        : is_span ? (span_step ? SB'(H + S + 1) : SB'(H + 1))
                        : is_plane ? (!plane_div ? SB'(3) * plane_bits
                                                 : (plane_texture ? SB'(H + FT) : SB'(H + F)) + plane_bits
                                                   + (plane_c != 0 ? SB'(S) : SB'(0)))
                        : is_product ? (product_texture ? SB'(PBT + 1) : SB'(PB + 1))
                        : {SB{1'b0}};
    wire [1:0] last_term = is_plane ? 2'd2 : 2'd1;
    wire signed_multiplier = is_area || is_edge;

    // ---- Multiply step: HI += +-(bit ? B : 0) (+ the edge's bias as carry for start numerators) ----
    // The multiplicand B (and the start numerators' bias) of the next step's term, registered
    // (multiplicand_q, start_bias_q), so that the sum does not wait for the term's selection: the
    // next term is 0 after an operation's load cycle and after its last term, else the one after.
    wire [1:0] term_next = (active_q && load_q) || term_q == last_term ? 2'd0 : term_q + 1'b1;
    wire [1:0] weight_next = is_area ? (term_next == 2'd0 ? 2'd0 : 2'd2)
                           : is_edge ? edge_k
                           : (term_next == 2'd2 ? 2'd0 : term_next + 1'b1);  // numerators: v_t e_(t+1)
    wire use_start = is_plane && plane_c == 2'd0;
    wire use_ndy_next = (is_edge && term_next == 2'd1) || (is_plane && plane_c == 2'd1);
    // Whether the next step subtracts B when its bit is set (negate_q): the area's second term, and
    // the signed multipliers' (area, edge: two terms per bit) sign bit, their last two steps.
    wire [SB-1:0] left_next = active_q && load_q ? steps : left_q - 1'b1;
    reg signed [H-1:0] multiplicand_q;
    reg start_bias_q, negate_q;
    always @(posedge clk) begin
      multiplicand_q <= use_start ? H'(start_q[weight_next]) : use_ndy_next ? H'(ndy[weight_next]) : H'(dx[weight_next]);
      start_bias_q <= use_start && bias[weight_next];
      // The S, T, Q values are signed too: their last bit's three steps subtract.
      negate_q <= (is_area && term_next == 2'd1) ^ (signed_multiplier && left_next <= SB'(2))
                  ^ (plane_texture && !plane_div && left_next <= SB'(3));
    end
    wire bit_now = mq_q[0][0];
    wire subtract = bit_now && negate_q;
    wire signed [H-1:0] addend = bit_now ? multiplicand_q : {H{1'b0}};
    wire signed [H-1:0] hi = acc_q[ACC_BITS-1 -: H];
    // The carry in: 1 to subtract (~B + 1), the edge's bias to add a start weight (start_q is E -
    // bias); with TEXTURE both may meet on a signed value's last bit: -(start_q + bias) = ~start_q +
    // 1 - bias.
    wire carry = TEX != 0 ? bit_now && (negate_q ^ start_bias_q) : subtract || (bit_now && start_bias_q);
    wire signed [H-1:0] sum = hi + (subtract ? ~addend : addend) + H'(carry);

    // ---- Divide step: {rem, next bit} - |divisor|, or the remainder correction rem - |divisor| ----
    // -|divisor| (as ~|d| + 1: minus_divisor_q and its carry) and whether the next step is the
    // span's remainder correction, registered a cycle ahead (the divisor is constant through an
    // operation; the steps follow its load cycle), so that the trial's operands are registers.
    wire signed [AREA_BITS:0] divisor = is_span ? (AREA_BITS+1)'($signed({ndy[span_k], {S{1'b0}}})) : (AREA_BITS+1)'(area_q);
    wire divisor_nonzero = !is_span || ndy[span_k] != 0;
    reg [AREA_BITS:0] minus_divisor_q;
    reg minus_divisor_carry_q, correction_q;
    always @(posedge clk) begin
      minus_divisor_q <= divisor[AREA_BITS] ? divisor : ~divisor;
      minus_divisor_carry_q <= !divisor[AREA_BITS];
      correction_q <= is_span && left_next == SB'(1);
    end
    wire correction = correction_q;
    wire next_bit = (data_left_nonzero_q && acc_q[ACC_BITS-1]) ^ sign_q;
    wire [AREA_BITS-1:0] shifted = {rem_q[AREA_BITS-2:0], next_bit};
    wire [AREA_BITS:0] trial = {1'b0, correction ? rem_q : shifted} + minus_divisor_q
                             + (AREA_BITS+1)'(minus_divisor_carry_q);
    wire fits = !trial[AREA_BITS];
    wire quotient_bit = (fits && divisor_nonzero) ^ sign_q;

    // ---- Product step: a plane along a left edge, base - quot * step_x modulo 2^Z_REG_BITS ----
    // PB steps acc = 2 acc +- (bit ? step_x : 0), the quotient's bits most significant first (the
    // first, its sign bit, subtracts), then acc = base - acc (the colour planes in the low bits).
    // With TEXTURE the S, T, Q planes take PBt steps modulo 2^TR: the accumulator has PRB bits, and
    // the multiplier register PBM with either multiplier at its top.
    // Left edges have edge_step_x = ndy 2^S > 0; slot 0 is the first in edge order, slot 1 the second.
    // Registered beside the deltas as the bias is (the PRODUCT operations come long after DECIDE).
    reg [2:0] left_edge_q;
    integer edge_index;
    always @(posedge clk) begin
      for (edge_index = 0; edge_index < 3; edge_index = edge_index + 1)
        left_edge_q[edge_index] <= swap_vertices ? ndy_q[2 - edge_index] < 0 : ndy_q[edge_index] > 0;
    end
    wire [2:0] left_edge = left_edge_q;
    wire product_slot = product_n[1];
    // [1:0]: depth, r, g, b, or S, T, Q with product_texture (its top bit).
    /* verilator lint_off UNUSEDSIGNAL */
    wire [PPB-1:0] product_p = product_n[PNB-1:2];
    /* verilator lint_on UNUSEDSIGNAL */
    wire product_step_field = product_n[0];  // the step (else the start)
    wire [1:0] slot_edge = !product_slot ? (left_edge[0] ? 2'd0 : left_edge[1] ? 2'd1 : 2'd2)
                                         : (left_edge[0] && left_edge[1] ? 2'd1 : 2'd2);
    wire slot_used = !product_slot ? |left_edge
                                   : (left_edge[0] && left_edge[1]) || (left_edge[0] && left_edge[2]) || (left_edge[1] && left_edge[2]);
    wire [PB-1:0] plane_multiplier = !slot_used ? {PB{1'b0}}
        : product_step_field ? PB'($signed(span_step_quot_q[slot_edge])) : PB'($signed(span_quot_q[slot_edge]));
    wire [PBT-1:0] texture_multiplier = !slot_used ? {PBT{1'b0}}
        : product_step_field ? PBT'($signed(span_step_quot_q[slot_edge])) : PBT'($signed(span_quot_q[slot_edge]));
    wire [PBM-1:0] product_multiplier = product_texture ? PBM'(texture_multiplier) << PBT_SHIFT
                                                        : PBM'(plane_multiplier) << PB_SHIFT;
    // Plane p's step x and its start (or step y): depth_q[0..2], colour c = p - 1 at color_q[3c ..
    // 3c + 2], sign-extended; constant indices, so that each is one 4-way choice.
    wire [PRB-1:0] plane_field [0:11];  // 3p + (0 start, 1 step x, 2 step y)
    for (k = 0; k < 12; k = k + 1) begin : plane_fields
      if (k < 3) begin : depth
        assign plane_field[k] = PRB'(depth_q[k]);
      end else begin : colour
        assign plane_field[k] = PRB'($signed(color_q[k - 3]));
      end
    end
    wire [1:0] product_q = product_p[1:0];
    wire [PRB-1:0] plane_step_x = product_q == 2'd0 ? plane_field[1] : product_q == 2'd1 ? plane_field[4]
                                : product_q == 2'd2 ? plane_field[7] : plane_field[10];
    wire [PRB-1:0] plane_base = product_step_field
        ? (product_q == 2'd0 ? plane_field[2] : product_q == 2'd1 ? plane_field[5] : product_q == 2'd2 ? plane_field[8] : plane_field[11])
        : (product_q == 2'd0 ? plane_field[0] : product_q == 2'd1 ? plane_field[3] : product_q == 2'd2 ? plane_field[6] : plane_field[9]);
    wire [PRB-1:0] texture_step_x, texture_base;  // the S, T, Q plane's (the texture block below)
    wire [PRB-1:0] product_step_x = product_texture ? texture_step_x : plane_step_x;
    wire [PRB-1:0] product_base = product_texture ? texture_base : plane_base;
    reg [PRB-1:0] product_acc_q;
    reg [PBM-1:0] product_bits_q;  // the multiplier, consumed from the top
    // The operation's multiplicand and base, taken in its load cycle: the plane selection is then
    // off the accumulator's path.
    reg [PRB-1:0] product_step_x_q, product_base_q;
    // The first (sign) and the last (base - acc) steps, registered a cycle ahead from left_next.
    wire product_next_first = left_next == (product_texture ? SB'(PBT + 1) : SB'(PB + 1));
    reg product_first_q, product_last_q;
    always @(posedge clk) begin
      product_first_q <= product_next_first;
      product_last_q <= left_next == SB'(1);
    end
    wire product_first = product_first_q;
    wire product_last = product_last_q;
    // The next step's addend (bit ? step_x : 0) as it is added, registered a cycle ahead: inverted
    // on the first (sign) step, which subtracts (with a carry in).
    wire product_next_bit = active_q && load_q ? product_multiplier[PBM-1] : product_bits_q[PBM-2];
    wire [PRB-1:0] product_next_step_x = active_q && load_q ? product_step_x : product_step_x_q;
    wire [PRB-1:0] product_next_addend = product_next_bit ? product_next_step_x : {PRB{1'b0}};
    reg [PRB-1:0] product_addend_q;
    always @(posedge clk) product_addend_q <= product_next_first ? ~product_next_addend : product_next_addend;
    wire [PRB-1:0] product_doubled = {product_acc_q[PRB-2:0], 1'b0};

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
    reg signed [BB-1:0] box_x0_q, box_y0_q;  // the first candidate (its centre feeds the edge operations)
    reg signed [BB-1:0] box_x1_q, box_y1_q;  // the last candidate column and row (the record's low bits)
    reg box_offscreen_q, box_no_centre_q;
    always @(posedge clk) begin
      box_x0_q <= bx0;
      box_x1_q <= bx1;
      box_y0_q <= by0;
      box_y1_q <= by1;
      box_offscreen_q <= offscreen;
      box_no_centre_q <= box_x0_q > box_x1_q || box_y0_q > box_y1_q;
    end
    wire signed [BB-1:0] box_x0 = box_x0_q;
    wire signed [BB-1:0] box_y0 = box_y0_q;
    assign box_offscreen = box_offscreen_q;
    assign box_no_centre = box_no_centre_q;

    // ---- Operands of the load cycle ----
    wire signed [BB-1:0] centre_x = (box_x0 <<< S) + SAMPLE_B;  // the first candidate's sample point
    wire signed [BB-1:0] centre_y = (box_y0 <<< S) + SAMPLE_B;
    wire signed [BB-1:0] rel_x = centre_x - BB'(vx_q[edge_k]);
    wire signed [BB-1:0] rel_y = centre_y - BB'(vy_q[edge_k]);
    // Plane p's vertex values: depth and colour unsigned, S, T, Q m_t bits signed (Z_BITS < m_t).
    localparam integer VW = TEX != 0 ? MT : Z_BITS;
    wire [VW-1:0] value [0:2];
    genvar v;
    for (v = 0; v < 3; v = v + 1) begin : values
      wire [1:0] channel = plane_p[1:0];  // r, g, b from 1; S, T, Q from 0
      wire [7:0] color = channel == 2'd1 ? vrgb_q[v][23:16] : channel == 2'd2 ? vrgb_q[v][15:8] : vrgb_q[v][7:0];
      wire [TVB-1:0] coordinate = channel == 2'd0 ? vtex[3*v] : channel == 2'd1 ? vtex[3*v + 1] : vtex[3*v + 2];
      assign value[v] = plane_texture ? VW'(coordinate) : plane_p == {PPB{1'b0}} ? VW'(vz_q[v]) : VW'(color);
    end
    wire signed [DELTA_BITS-1:0] span_dividend_small = dx[span_k];
    wire signed [H-1:0] span_dividend = span_step ? H'(span_dividend_small) : H'(start_q[span_k]);

    // ---- Decision (DECIDE, the AREA result in ACC) ----
    assign area2 = acc_q[MB-DELTA_BITS +: AREA_BITS];
    wire deciding = active_q && load_q && op_q == OP_DECIDE;
    assign decided = deciding;
    assign swap_vertices = deciding && status == RS_STATUS_DRAWN && swap;

    assign load_vertices = !active_q && !out_q && in_valid;
    assign in_ready = !active_q && !out_q;
    assign free = in_ready;
    assign busy = load_vertices || active_q || out_q;
    assign out_valid = out_q;
    wire unused_run = run;  // one triangle at a time: no slots

    // The next operation: an untextured triangle skips the S, T, Q operations (TEXTURE = 1).
    wire [OPB-1:0] op_next = TEX != 0 && !vtextured && op_q == OP_PLANE + OPB'(23) ? OP_PRODUCT
                           : TEX != 0 && !vtextured && op_q == OP_PRODUCT + OPB'(15) ? OP_FINAL : op_q + 1'b1;
    integer t;
    always @(posedge clk) begin
      if (rst) begin
        active_q <= 1'b0;
        out_q <= 1'b0;
        load_q <= 1'b0;
        op_q <= OP_AREA;
        op_shape_q <= op_shape(OP_AREA);
      end else begin
        out_q <= 1'b0;
        if (load_vertices) begin
          active_q <= 1'b1;
          load_q <= 1'b1;
          op_q <= OP_AREA;
          op_shape_q <= op_shape(OP_AREA);
        end else if (active_q && load_q) begin
          if (op_q == OP_FINAL) begin
            active_q <= 1'b0;
            out_q <= 1'b1;
          end else if (deciding && status != RS_STATUS_DRAWN) begin
            active_q <= 1'b0;
          end else if (steps == 0) begin
            op_q <= op_next;
            op_shape_q <= op_shape(op_next);
          end else begin
            load_q <= 1'b0;
          end
        end else if (active_q && left_q == SB'(1)) begin
          load_q <= 1'b1;
          op_q <= op_next;
          op_shape_q <= op_shape(op_next);
        end
      end
    end

    // Datapath (no reset: every operation loads what it uses).
    always @(posedge clk) begin
      if (active_q && load_q) begin
        left_q <= steps;
        term_q <= 2'd0;
        rem_q <= {AREA_BITS{1'b0}};
        if (is_area) begin
          acc_q <= {ACC_BITS{1'b0}};
          mq_q[0] <= MB'(ndy[2]);
          mq_q[1] <= MB'(ndy[0]);
        end else if (is_edge) begin
          acc_q <= {{H{bias[edge_k]}}, {MB{1'b0}}};  // HI = -bias: the product comes out biased
          mq_q[0] <= MB'(rel_y);
          mq_q[1] <= MB'(rel_x);
        end else if (is_span) begin
          acc_q <= divisor_nonzero ? {span_dividend, {MB{1'b0}}} : {ACC_BITS{1'b0}};
          sign_q <= divisor_nonzero && span_dividend[H-1];
          data_left_q <= SB'(H);
          data_left_nonzero_q <= 1'b1;
        end else if (is_plane && !plane_div) begin
          acc_q <= {ACC_BITS{1'b0}};
          for (t = 0; t < 3; t = t + 1) mq_q[t] <= MB'(value[t]);
        end else if (is_plane) begin
          sign_q <= acc_q[ACC_BITS-1];
          data_left_q <= SB'(H) + plane_bits;
          data_left_nonzero_q <= 1'b1;
        end
      end else if (active_q && is_mul) begin
        left_q <= left_q - 1'b1;
        // The terms' multipliers rotate, so that the next term's is in mq_q[0] (no selection before
        // the sum); the one just used goes to the back a bit further on.
        mq_q[0] <= mq_q[1];
        if (last_term == 2'd2) begin
          mq_q[1] <= mq_q[2];
          mq_q[2] <= mq_q[0] >> 1;
        end else begin
          mq_q[1] <= mq_q[0] >> 1;
        end
        if (term_q == last_term) begin
          term_q <= 2'd0;
          acc_q <= {sum[H-1], sum, acc_q[MB-1:1]};
        end else begin
          term_q <= term_q + 1'b1;
          acc_q[ACC_BITS-1 -: H] <= sum;
        end
      end else if (active_q && is_product) begin
        left_q <= left_q - 1'b1;
      end else if (active_q && is_div) begin
        left_q <= left_q - 1'b1;
        if (correction) begin
          if (sign_q) rem_q <= ~trial[AREA_BITS-1:0];  // |d| - 1 - r: the remainder of n from that of ~n
        end else begin
          if (data_left_nonzero_q) begin
            data_left_q <= data_left_q - 1'b1;
            data_left_nonzero_q <= data_left_q != SB'(1);
          end
          rem_q <= fits ? trial[AREA_BITS-1:0] : shifted;
          acc_q <= {acc_q[ACC_BITS-2:0], quotient_bit};
        end
      end
    end

    // Product registers (no reset: each PRODUCT operation loads them).
    always @(posedge clk) begin
      if (active_q && load_q && is_product) begin
        product_acc_q <= {PRB{1'b0}};
        product_bits_q <= product_multiplier;
        product_step_x_q <= product_step_x;
        product_base_q <= product_base;
      end else if (active_q && is_product) begin
        if (product_last) product_acc_q <= product_base_q - product_acc_q;
        else product_acc_q <= product_doubled + product_addend_q + PRB'(product_first);
        product_bits_q <= {product_bits_q[PBM-2:0], 1'b0};
      end
    end

    // ---- Record: each result stored in the next operation's load cycle ----
    integer r;
    always @(posedge clk) begin
      if (active_q && load_q) begin
        if (op_q == OP_DECIDE) area_q <= area2;
        for (r = 0; r < 3; r = r + 1) begin
          if (op_q == OP_EDGE + OPB'(r) + OPB'(1)) start_q[r] <= acc_q[MB-(COORD_BITS+1) +: EDGE_BITS];
          if (op_q == OP_SPAN + OPB'(2 * r) + OPB'(1)) begin
            span_quot_q[r] <= acc_q[EDGE_BITS-1:0];
            span_rem_q[r] <= rem_q[SPAN_REM_BITS-1:0];
          end
          if (op_q == OP_SPAN + OPB'(2 * r) + OPB'(2)) begin
            span_step_quot_q[r] <= acc_q[EDGE_STEP_Y_BITS-1:0];
            span_step_rem_q[r] <= rem_q[SPAN_REM_BITS-1:0];
          end
          if (op_q == OP_PLANE + OPB'(2 * r) + OPB'(2)) depth_q[r] <= acc_q[Z_REG_BITS-1:0];
        end
        for (r = 0; r < 9; r = r + 1)
          // An untextured triangle's blue step y is stored in the first PRODUCT's load with TEXTURE.
          if (op_q == OP_PLANE + OPB'(2 * r) + OPB'(8) || (TEX != 0 && r == 8 && !vtextured && op_q == OP_PRODUCT))
            color_q[r] <= acc_q[COLOR_REG_BITS-1:0];
        for (r = 0; r < 16; r = r + 1)
          if (op_q == OP_PRODUCT + OPB'(r) + OPB'(1) || (TEX != 0 && r == 15 && !vtextured && op_q == OP_FINAL))
            along_q[r] <= product_acc_q[Z_REG_BITS-1:0];
      end
    end
    for (k = 0; k < 3; k = k + 1) begin : record
      assign out_edge_start[k*EDGE_BITS +: EDGE_BITS] = start_q[k];
      assign out_span_quot[k*EDGE_BITS +: EDGE_BITS] = span_quot_q[k];
      assign out_span_rem[k*SPAN_REM_BITS +: SPAN_REM_BITS] = span_rem_q[k];
      assign out_span_step_quot[k*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS] = span_step_quot_q[k];
      assign out_span_step_rem[k*SPAN_REM_BITS +: SPAN_REM_BITS] = span_step_rem_q[k];
      assign out_color_start[k*COLOR_REG_BITS +: COLOR_REG_BITS] = color_q[3*k];
      assign out_color_step_x[k*COLOR_REG_BITS +: COLOR_REG_BITS] = color_q[3*k + 1];
      assign out_color_step_y[k*COLOR_REG_BITS +: COLOR_REG_BITS] = color_q[3*k + 2];
    end
    for (k = 0; k < 16; k = k + 1) begin : along
      assign out_along[k] = along_q[k];
    end
    assign out_depth_start = depth_q[0];
    assign out_depth_step_x = depth_q[1];
    assign out_depth_step_y = depth_q[2];
    assign out_x0 = box_x0[X_BITS-1:0];
    assign out_x1 = box_x1_q[X_BITS-1:0];
    assign out_y0 = box_y0[Y_BITS-1:0];
    assign out_y1 = box_y1_q[Y_BITS-1:0];
    assign out_flat_rgb = vrgb_q[0];

    // ---- The S, T, Q planes (TEXTURE = 1): stored as the others, from their operations ----
    if (TEX != 0) begin : texture
      reg [TR-1:0] tex_plane_q [0:8];   // plane 3c + (0 start, 1 step x, 2 step y), c = S, T, Q; s9.(P+Ft)
      reg [TR-1:0] tex_along_q [0:11];  // PRODUCT 16 + 4c + 2j + t
      integer tr;
      always @(posedge clk) begin
        if (active_q && load_q) begin
          for (tr = 0; tr < 9; tr = tr + 1)
            if (op_q == OP_PLANE + OPB'(2 * (12 + tr)) + OPB'(2)) tex_plane_q[tr] <= acc_q[TR-1:0];
          for (tr = 0; tr < 12; tr = tr + 1)
            if (op_q == OP_PRODUCT + OPB'(16 + tr) + OPB'(1)) tex_along_q[tr] <= product_acc_q[TR-1:0];
        end
      end
      wire [1:0] c = product_q;  // the product's coordinate
      wire [TR-1:0] step_x = c == 2'd0 ? tex_plane_q[1] : c == 2'd1 ? tex_plane_q[4] : tex_plane_q[7];
      wire [TR-1:0] base = product_step_field ? (c == 2'd0 ? tex_plane_q[2] : c == 2'd1 ? tex_plane_q[5] : tex_plane_q[8])
                                              : (c == 2'd0 ? tex_plane_q[0] : c == 2'd1 ? tex_plane_q[3] : tex_plane_q[6]);
      assign texture_step_x = PRB'(step_x);
      assign texture_base = PRB'(base);
      // The record: register 3g + c, groups 0..2 the plane, 3..6 along the left edges; all zero
      // for an untextured triangle.
      genvar tg, tc;
      assign out_texture[0] = vtextured;
      for (tc = 0; tc < 3; tc = tc + 1) begin : coordinate
        for (tg = 0; tg < 7; tg = tg + 1) begin : group
          wire [TR-1:0] field;
          if (tg < 3) begin : plane
            assign field = tex_plane_q[3*tc + tg];
          end else begin : along
            assign field = tex_along_q[4*tc + tg - 3];
          end
          assign out_texture[1 + (3*tg + tc)*TR +: TR] = vtextured ? field : {TR{1'b0}};
        end
      end
    end else begin : no_texture
      assign texture_step_x = {PRB{1'b0}};
      assign texture_base = {PRB{1'b0}};
      assign out_texture = {rs_texture_record_bits(WIDTH, HEIGHT){1'b0}};
    end
  end else begin : pipelined
    // ---- FRONT: the area's two products (delta_bits x delta_bits), the only ones in one cycle ----
    wire signed [DELTA_BITS-1:0] d10x = vx_q[1] - vx_q[0];
    wire signed [DELTA_BITS-1:0] d10y = vy_q[1] - vy_q[0];
    wire signed [DELTA_BITS-1:0] d20x = vx_q[2] - vx_q[0];
    wire signed [DELTA_BITS-1:0] d20y = vy_q[2] - vy_q[0];
    wire signed [2*DELTA_BITS-1:0] cross_a = d10x * d20y;
    wire signed [2*DELTA_BITS-1:0] cross_b = d20x * d10y;
    // |area2| <= 9 W H M^2 fits AREA_BITS bits (docs/widths.md): the top bits are sign copies.
    /* verilator lint_off UNUSEDSIGNAL */
    wire signed [2*DELTA_BITS-1:0] area2_wide = cross_a - cross_b;
    /* verilator lint_on UNUSEDSIGNAL */
    assign area2 = area2_wide[AREA_BITS-1:0];
    wire [AREA_BITS-1:0] area = area2[AREA_BITS-1] ? -area2 : area2;
    assign swap_vertices = 1'b0;  // the FRONT slot orders them through muxes instead

    // ---- Ordered vertices, edge steps and the edge values' operands ----
    wire signed [COORD_BITS-1:0] ox [0:2];
    wire signed [COORD_BITS-1:0] oy [0:2];
    wire [Z_BITS-1:0]    oz [0:2];
    wire [23:0]          orgb [0:2];
    assign ox[0] = vx_q[0];
    assign oy[0] = vy_q[0];
    assign oz[0] = vz_q[0];
    assign orgb[0] = vrgb_q[0];
    assign ox[1] = swap ? vx_q[2] : vx_q[1];
    assign oy[1] = swap ? vy_q[2] : vy_q[1];
    assign oz[1] = swap ? vz_q[2] : vz_q[1];
    assign orgb[1] = swap ? vrgb_q[2] : vrgb_q[1];
    assign ox[2] = swap ? vx_q[1] : vx_q[2];
    assign oy[2] = swap ? vy_q[1] : vy_q[2];
    assign oz[2] = swap ? vz_q[1] : vz_q[2];
    assign orgb[2] = swap ? vrgb_q[1] : vrgb_q[2];

    // The first candidate's centre, >= 0 and < 2^(COORD_BITS-1) (on screen): the top bit is a sign copy.
    /* verilator lint_off UNUSEDSIGNAL */
    assign box_x_min = x_min;
    assign box_x_max = x_max;
    assign box_y_min = y_min;
    assign box_y_max = y_max;
    assign box_offscreen = offscreen;
    assign box_no_centre = bx0 > bx1 || by0 > by1;
    wire signed [BB-1:0] centre_x = (bx0 <<< S) + SAMPLE_B;  // the first candidate's sample point
    wire signed [BB-1:0] centre_y = (by0 <<< S) + SAMPLE_B;
    /* verilator lint_on UNUSEDSIGNAL */

    // An edge slot's operands for edge k at [k*EOP]: {bias, dx, ndy, rel_x, rel_y, E (accumulator)}.
    localparam integer RLB = COORD_BITS + 1;  // rel_x, rel_y: the first candidate's centre less the edge's first vertex
    localparam integer E_ACC = 0;
    localparam integer E_RY = E_ACC + EDGE_BITS;
    localparam integer E_RX = E_RY + RLB;
    localparam integer E_NDY = E_RX + RLB;
    localparam integer E_DX = E_NDY + DELTA_BITS;
    localparam integer E_BIAS = E_DX + DELTA_BITS;
    localparam integer EOP = E_BIAS + 1;
    wire [3*EOP-1:0] front_edges;
    wire signed [EDGE_STEP_X_BITS-1:0] edge_step_x [0:2];
    wire signed [EDGE_STEP_Y_BITS-1:0] edge_step_y [0:2];
    genvar k;
      for (k = 0; k < 3; k = k + 1) begin : edges
        wire signed [DELTA_BITS-1:0] dx = DELTA_BITS'(ox[(k + 1) % 3]) - DELTA_BITS'(ox[k]);
        wire signed [DELTA_BITS-1:0] ndy = DELTA_BITS'(oy[k]) - DELTA_BITS'(oy[(k + 1) % 3]);
        wire signed [RLB-1:0] rel_x = RLB'(centre_x) - RLB'(ox[k]);
        wire signed [RLB-1:0] rel_y = RLB'(centre_y) - RLB'(oy[k]);
        wire bias = !owns_samples(ndy > 0, ndy < 0, dx > 0, dx < 0);
        assign edge_step_x[k] = EDGE_STEP_X_BITS'({ndy, {S{1'b0}}});
        assign edge_step_y[k] = EDGE_STEP_Y_BITS'({dx, {S{1'b0}}});
        assign front_edges[k*EOP +: EOP] = {bias, dx, ndy, rel_x, rel_y, {EDGE_BITS{1'b0}}};
      end

    // ---- Pipelined schedule (docs/cycle-model.md): slots of I cycles, one triangle per slot ----
    localparam integer I = SETUP_INTERVAL;
    localparam integer EDGE_STAGES = rs_setup_edge_stages(COORD_BITS, I);
    localparam integer EDGE_STEPS = (RLB + I * EDGE_STAGES - 1) / (I * EDGE_STAGES);
    localparam integer EDGE_SKIP = I * EDGE_STAGES * EDGE_STEPS - RLB;  // leading no-op steps
    // With TEXTURE every slot is sized for the S, T, Q planes, whatever the triangle: m_t-bit values
    // (VW, two's complement: depth and colour zero-extended), PDB-bit dividends, quotients as
    // PB = max(PB, PBt)-bit multipliers, products in PRB bits (each plane in the low bits); NPL planes.
    localparam integer VW = TEX != 0 ? MT : Z_BITS;
    localparam integer TDB = rs_texture_divider_bits(WIDTH, HEIGHT, S);
    localparam integer PDB = TEX != 0 && TDB > DIVIDER_BITS ? TDB : DIVIDER_BITS;
    localparam integer PB0 = rs_setup_product_bits(WIDTH, HEIGHT, S, Z_BITS, Z_GUARD_BITS);
    localparam integer PBT = rs_setup_texture_product_bits(WIDTH, HEIGHT, S);
    localparam integer PB = TEX != 0 && PBT > PB0 ? PBT : PB0;
    localparam integer PRB = TEX != 0 && TR > Z_REG_BITS ? TR : Z_REG_BITS;
    localparam integer NPL = TEX != 0 ? 7 : 4;  // depth, r, g, b (S, T, Q)
    localparam integer NNUM = 3 * NPL;          // numerators and plane divisions
    localparam integer NPROD = 4 * NPL;         // products along the left edges
    localparam integer NUMER_STAGES = rs_setup_numer_stages(VW, I);
    localparam integer NUMER_STEPS = (VW + I * NUMER_STAGES - 1) / (I * NUMER_STAGES);
    localparam integer NUMER_SKIP = I * NUMER_STAGES * NUMER_STEPS - VW;
    localparam integer DIVIDE_STAGES = rs_setup_divide_stages(PDB, I);
    localparam integer DIVIDE_STEPS = (PDB + I * DIVIDE_STAGES - 1) / (I * DIVIDE_STAGES);
    localparam integer PLANE_SKIP = I * DIVIDE_STAGES * DIVIDE_STEPS - PDB;
    localparam integer SPAN_SKIP = I * DIVIDE_STAGES * DIVIDE_STEPS - EDGE_BITS;
    localparam integer PRODUCT_STAGES = rs_setup_product_stages(PB, I);
    localparam integer PRODUCT_STEPS = (PB + I * PRODUCT_STAGES - 1) / (I * PRODUCT_STAGES);
    localparam integer PRODUCT_SKIP = I * PRODUCT_STAGES * PRODUCT_STEPS - PB;
    `RS_REQUIRE(latency_matches, I * (1 + EDGE_STAGES + NUMER_STAGES + DIVIDE_STAGES + PRODUCT_STAGES)
                == rs_setup_texture_drawn_latency(WIDTH, HEIGHT, S, Z_BITS, Z_GUARD_BITS, I, TEX, 1),
                "triangle_setup: the slots disagree with rs_setup_texture_drawn_latency")
    localparam integer PHASE_BITS = rs_ubits32(I - 1);
    localparam integer LAST_PHASE = I - 1;
    localparam integer EDGES = 3 * EOP;
    // Numerator slot state: vertex values (plane p, vertex k at [(3p+k)*VW]), accumulators
    // (numerator n = 3p + t at [n*NB], t: 0 start, 1 step x, 2 step y), weights (term t, edge k at
    // [(3t+k)*EDGE_BITS]: E at the first candidate, edge_step_x, edge_step_y, widened).
    localparam integer VALS = NNUM * VW;
    localparam integer ACCS = NNUM * NB;
    localparam integer WTS = 9 * EDGE_BITS;
    // The record fields decided in FRONT, carried along: {x0, x1, y0, y1, edge_start[2:0] (from the
    // last edge slot), edge_step_x[2:0], edge_step_y[2:0], flat rgb, |area2|}, with TEXTURE the
    // textured flag above.
    localparam integer P_AREA = 0;
    localparam integer P_RGB = P_AREA + AREA_BITS;
    localparam integer P_SY = P_RGB + 24;
    localparam integer P_SX = P_SY + 3 * EDGE_STEP_Y_BITS;
    localparam integer P_ES = P_SX + 3 * EDGE_STEP_X_BITS;
    localparam integer P_Y1 = P_ES + 3 * EDGE_BITS;
    localparam integer P_Y0 = P_Y1 + Y_BITS;
    localparam integer P_X1 = P_Y0 + Y_BITS;
    localparam integer P_X0 = P_X1 + X_BITS;
    localparam integer P_TEX = P_X0 + X_BITS;
    localparam integer PAY = P_TEX + TEX;
    // Divide slot state: plane division n {negative, partial remainder, dividend/quotient bits};
    // span division m = 2k (edge start) or 2k+1 (edge step y) the same with |edge_step_x| widths.
    localparam integer PLANE_W = 1 + AREA_BITS + PDB;
    localparam integer SPAN_W = 1 + EDGE_STEP_X_BITS + EDGE_BITS;
    localparam integer PLANES = NNUM * PLANE_W;
    localparam integer SPANS = 6 * SPAN_W;

    integer j, s, n;
    reg [PHASE_BITS-1:0] phase_q;
    wire slot_first = phase_q == {PHASE_BITS{1'b0}};
    wire advance = run && phase_q == LAST_PHASE[PHASE_BITS-1:0];
    reg front_q;  // a triangle is in its FRONT slot (after its accept cycle)
    reg [EDGE_STAGES-1:0] edge_valid_q;
    reg [NUMER_STAGES-1:0] numer_valid_q;
    reg [DIVIDE_STAGES-1:0] divide_valid_q;
    reg [PRODUCT_STAGES-1:0] product_valid_q;
    reg out_valid_q;
    always @(posedge clk) begin
      if (rst) begin
        phase_q <= {PHASE_BITS{1'b0}};
        front_q <= 1'b0;
        edge_valid_q <= {EDGE_STAGES{1'b0}};
        numer_valid_q <= {NUMER_STAGES{1'b0}};
        divide_valid_q <= {DIVIDE_STAGES{1'b0}};
        product_valid_q <= {PRODUCT_STAGES{1'b0}};
        out_valid_q <= 1'b0;
      end else begin
        if (run) phase_q <= advance ? {PHASE_BITS{1'b0}} : phase_q + 1'b1;
        if (load_vertices) front_q <= 1'b1;
        else if (advance) front_q <= 1'b0;
        if (advance) begin
          for (j = EDGE_STAGES - 1; j > 0; j = j - 1) edge_valid_q[j] <= edge_valid_q[j-1];
          edge_valid_q[0] <= front_q && status == RS_STATUS_DRAWN;
          for (j = NUMER_STAGES - 1; j > 0; j = j - 1) numer_valid_q[j] <= numer_valid_q[j-1];
          numer_valid_q[0] <= edge_valid_q[EDGE_STAGES-1];
          for (j = DIVIDE_STAGES - 1; j > 0; j = j - 1) divide_valid_q[j] <= divide_valid_q[j-1];
          divide_valid_q[0] <= numer_valid_q[NUMER_STAGES-1];
          for (j = PRODUCT_STAGES - 1; j > 0; j = j - 1) product_valid_q[j] <= product_valid_q[j-1];
          product_valid_q[0] <= divide_valid_q[DIVIDE_STAGES-1];
          out_valid_q <= product_valid_q[PRODUCT_STAGES-1];
        end
      end
    end
    assign in_ready = slot_first;
    assign load_vertices = in_valid && slot_first;
    assign free = !front_q;
    assign decided = front_q && phase_q == {{(PHASE_BITS-1){1'b0}}, 1'b1};
    assign out_valid = out_valid_q && slot_first;
    assign busy = load_vertices || (front_q && (decided || status == RS_STATUS_DRAWN)) || edge_valid_q != 0
                  || numer_valid_q != 0 || divide_valid_q != 0 || product_valid_q != 0 || out_valid;

    // FRONT's results: the vertex values of the planes, the payload (edge starts still zero).
    wire [VALS-1:0] front_vals;
    genvar fp, fk;
    for (fp = 0; fp < NPL; fp = fp + 1) begin : front_planes
      for (fk = 0; fk < 3; fk = fk + 1) begin : front_vertices
        if (fp < 4) begin : plane
          assign front_vals[(3*fp + fk)*VW +: VW] =
              fp == 0 ? VW'(oz[fk]) : VW'(orgb[fk][(fp == 0 ? 0 : 8*(3-fp)) +: 8]);
        end else begin : coordinate  // S, T, Q of the ordered vertex fk (v1 and v2 swapped as the others)
          localparam integer C = fp - 4;
          assign front_vals[(3*fp + fk)*VW +: VW] = fk == 0 ? vtex[C] : (fk == 1) == swap ? vtex[6 + C] : vtex[3 + C];
        end
      end
    end
    wire [PAY-1:0] front_pay;
    wire [P_TEX-1:0] front_pay_base = {bx0[X_BITS-1:0], bx1[X_BITS-1:0], by0[Y_BITS-1:0], by1[Y_BITS-1:0], {(3*EDGE_BITS){1'b0}},
                                edge_step_x[2], edge_step_x[1], edge_step_x[0],
                                edge_step_y[2], edge_step_y[1], edge_step_y[0], vrgb_q[0], area};
    if (TEX != 0) begin : front_textured
      assign front_pay = {vtextured, front_pay_base};
    end else begin : front_untextured
      assign front_pay = front_pay_base;
    end

    // ---- Edge slots: E = 2 E + (rel_y bit ? dx : 0) + (rel_x bit ? ndy : 0), MSB first ----
    // The first real step takes the sign bits, which weigh -2^(RLB-1): it subtracts.
    reg [EDGE_STAGES*EDGES-1:0] edge_ops_q, edge_ops_next;
    reg [EDGE_STAGES*VALS-1:0] edge_vals_q;
    reg [EDGE_STAGES*PAY-1:0] edge_pay_q;
    reg [EOP-1:0] eo;
    reg signed [EDGE_BITS-1:0] e_acc, e_dx, e_ndy, e_term;
    reg [RLB-1:0] e_rx, e_ry;
    reg [31:0] edge_step_index;
    /* verilator lint_off UNSIGNED */
    always @* begin
      e_term = {EDGE_BITS{1'b0}};
      edge_step_index = 32'd0;
      eo = {EOP{1'b0}};
      e_acc = {EDGE_BITS{1'b0}};
      e_dx = {EDGE_BITS{1'b0}};
      e_ndy = {EDGE_BITS{1'b0}};
      e_rx = {RLB{1'b0}};
      e_ry = {RLB{1'b0}};
      for (j = 0; j < EDGE_STAGES; j = j + 1) begin
        // An empty slot's values are never used: don't-care, so that a simulator skips its steps
        // and synthesis adds no multiplexer.
        edge_ops_next[j*EDGES +: EDGES] = {EDGES{1'bx}};
        if (edge_valid_q[j]) for (n = 0; n < 3; n = n + 1) begin
          eo = edge_ops_q[j*EDGES + n*EOP +: EOP];
          e_acc = eo[E_ACC +: EDGE_BITS];
          e_ry = eo[E_RY +: RLB];
          e_rx = eo[E_RX +: RLB];
          e_ndy = EDGE_BITS'($signed(eo[E_NDY +: DELTA_BITS]));
          e_dx = EDGE_BITS'($signed(eo[E_DX +: DELTA_BITS]));
          for (s = 0; s < EDGE_STEPS; s = s + 1) begin
            edge_step_index = (j * I + {{(32-PHASE_BITS){1'b0}}, phase_q}) * EDGE_STEPS + s;
            if (edge_step_index >= EDGE_SKIP) begin
              e_term = (e_ry[RLB-1] ? e_dx : {EDGE_BITS{1'b0}}) + (e_rx[RLB-1] ? e_ndy : {EDGE_BITS{1'b0}});
              e_acc = {e_acc[EDGE_BITS-2:0], 1'b0} + (edge_step_index == EDGE_SKIP ? -e_term : e_term);
              e_ry = {e_ry[RLB-2:0], 1'b0};
              e_rx = {e_rx[RLB-2:0], 1'b0};
            end
          end
          edge_ops_next[j*EDGES + n*EOP +: EOP] = {eo[EOP-1:E_RX+RLB], e_rx, e_ry, e_acc};
        end
      end
    end
    /* verilator lint_on UNSIGNED */
    // A slot's registers move only when it holds a triangle (an empty slot's are don't-care): the
    // same logic with flip-flop enables, and a simulator copies only the slots in use.
    always @(posedge clk) begin
      if (advance) begin
        if (front_q) begin
          edge_ops_q[0 +: EDGES] <= front_edges;
          edge_vals_q[0 +: VALS] <= front_vals;
          edge_pay_q[0 +: PAY] <= front_pay;
        end
        for (j = 1; j < EDGE_STAGES; j = j + 1) begin
          if (edge_valid_q[j-1]) begin
            edge_ops_q[j*EDGES +: EDGES] <= edge_ops_next[(j-1)*EDGES +: EDGES];
            edge_vals_q[j*VALS +: VALS] <= edge_vals_q[(j-1)*VALS +: VALS];
            edge_pay_q[j*PAY +: PAY] <= edge_pay_q[(j-1)*PAY +: PAY];
          end
        end
      end else begin
        for (j = 0; j < EDGE_STAGES; j = j + 1)
          if (edge_valid_q[j]) edge_ops_q[j*EDGES +: EDGES] <= edge_ops_next[j*EDGES +: EDGES];
      end
    end

    // The edge values leaving the last edge slot: unbiased as the numerators' weights, biased into
    // the record; the edge steps widened to EDGE_BITS bits (sign extension) as weights of the step numerators.
    wire [EDGES-1:0] edge_last = edge_ops_next[(EDGE_STAGES-1)*EDGES +: EDGES];
    // Its edge-start field is still zero: the values are filled in here.
    /* verilator lint_off UNUSEDSIGNAL */
    wire [PAY-1:0] edge_last_pay = edge_pay_q[(EDGE_STAGES-1)*PAY +: PAY];
    /* verilator lint_on UNUSEDSIGNAL */
    wire [WTS-1:0] numer_in_wts;
    wire [3*EDGE_BITS-1:0] numer_in_starts;
    for (k = 0; k < 3; k = k + 1) begin : weights
      wire [EOP-1:0] ops = edge_last[k*EOP +: EOP];
      wire signed [EDGE_BITS-1:0] unbiased = ops[E_ACC +: EDGE_BITS];  // E at the first candidate, s.2S
      wire [EDGE_STEP_X_BITS-1:0] step_x = edge_last_pay[P_SX + k*EDGE_STEP_X_BITS +: EDGE_STEP_X_BITS];
      wire [EDGE_STEP_Y_BITS-1:0] step_y = edge_last_pay[P_SY + k*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS];
      assign numer_in_starts[k*EDGE_BITS +: EDGE_BITS] = unbiased - EDGE_BITS'(ops[E_BIAS]);
      assign numer_in_wts[k*EDGE_BITS +: EDGE_BITS] = unbiased;
      assign numer_in_wts[(3 + k)*EDGE_BITS +: EDGE_BITS] = EDGE_BITS'($signed(step_x));
      assign numer_in_wts[(6 + k)*EDGE_BITS +: EDGE_BITS] = EDGE_BITS'($signed(step_y));
    end
    wire [PAY-1:0] numer_in_pay = {edge_last_pay[PAY-1:P_ES+3*EDGE_BITS], numer_in_starts, edge_last_pay[P_ES-1:0]};

    // ---- Numerator slots: acc = 2 acc + sum over vertices of (value bit ? weight : 0), MSB first ----
    reg [NUMER_STAGES*VALS-1:0] numer_vals_q, numer_vals_next;
    reg [NUMER_STAGES*ACCS-1:0] numer_acc_q, numer_acc_next;
    reg [NUMER_STAGES*WTS-1:0] numer_wts_q;
    reg [NUMER_STAGES*PAY-1:0] numer_pay_q;
    reg [VALS-1:0] nv;
    reg [ACCS-1:0] na;
    reg [WTS-1:0] nw;
    reg [EDGE_BITS-1:0] e0, e1, e2;
    reg [NB-1:0] term;
    reg [31:0] numer_index;
    // A stage's first steps may all be real ones (no leading no-op steps): the comparison is then
    // constant.
    /* verilator lint_off UNSIGNED */
    always @* begin
      numer_index = 32'd0;
      e0 = {EDGE_BITS{1'b0}};
      e1 = {EDGE_BITS{1'b0}};
      e2 = {EDGE_BITS{1'b0}};
      term = {NB{1'b0}};
      nv = {VALS{1'b0}};
      na = {ACCS{1'b0}};
      nw = {WTS{1'b0}};
      for (j = 0; j < NUMER_STAGES; j = j + 1) begin
        numer_vals_next[j*VALS +: VALS] = {VALS{1'bx}};  // an empty slot: don't-care (as the edge slots)
        numer_acc_next[j*ACCS +: ACCS] = {ACCS{1'bx}};
        if (numer_valid_q[j]) begin
        nv = numer_vals_q[j*VALS +: VALS];
        na = numer_acc_q[j*ACCS +: ACCS];
        nw = numer_wts_q[j*WTS +: WTS];
        for (s = 0; s < NUMER_STEPS; s = s + 1) begin
          numer_index = (j * I + {{(32-PHASE_BITS){1'b0}}, phase_q}) * NUMER_STEPS + s;
          if (numer_index >= NUMER_SKIP) begin
            for (n = 0; n < NNUM; n = n + 1) begin
              // numerator n = 3p + t: v0 e1 + v1 e2 + v2 e0 with the weights of term t
              e0 = nw[(3*(n%3) + 0)*EDGE_BITS +: EDGE_BITS];
              e1 = nw[(3*(n%3) + 1)*EDGE_BITS +: EDGE_BITS];
              e2 = nw[(3*(n%3) + 2)*EDGE_BITS +: EDGE_BITS];
              term = (nv[(3*(n/3) + 0)*VW + VW-1] ? {{(NB-EDGE_BITS){e1[EDGE_BITS-1]}}, e1} : {NB{1'b0}})
                   + (nv[(3*(n/3) + 1)*VW + VW-1] ? {{(NB-EDGE_BITS){e2[EDGE_BITS-1]}}, e2} : {NB{1'b0}})
                   + (nv[(3*(n/3) + 2)*VW + VW-1] ? {{(NB-EDGE_BITS){e0[EDGE_BITS-1]}}, e0} : {NB{1'b0}});
              // With TEXTURE the values are signed: the first step, their sign bit, subtracts.
              na[n*NB +: NB] = {na[n*NB +: NB-1], 1'b0} + (TEX != 0 && numer_index == NUMER_SKIP ? -term : term);
            end
            for (n = 0; n < NNUM; n = n + 1) nv[n*VW +: VW] = {nv[n*VW +: VW-1], 1'b0};
          end
        end
        numer_vals_next[j*VALS +: VALS] = nv;
        numer_acc_next[j*ACCS +: ACCS] = na;
        end
      end
    end
    always @(posedge clk) begin
      if (advance) begin
        if (edge_valid_q[EDGE_STAGES-1]) begin
          numer_vals_q[0 +: VALS] <= edge_vals_q[(EDGE_STAGES-1)*VALS +: VALS];
          numer_acc_q[0 +: ACCS] <= {ACCS{1'b0}};
          numer_wts_q[0 +: WTS] <= numer_in_wts;
          numer_pay_q[0 +: PAY] <= numer_in_pay;
        end
        for (j = 1; j < NUMER_STAGES; j = j + 1) begin
          if (numer_valid_q[j-1]) begin
            numer_vals_q[j*VALS +: VALS] <= numer_vals_next[(j-1)*VALS +: VALS];
            numer_acc_q[j*ACCS +: ACCS] <= numer_acc_next[(j-1)*ACCS +: ACCS];
            numer_wts_q[j*WTS +: WTS] <= numer_wts_q[(j-1)*WTS +: WTS];
            numer_pay_q[j*PAY +: PAY] <= numer_pay_q[(j-1)*PAY +: PAY];
          end
        end
      end else begin
        for (j = 0; j < NUMER_STAGES; j = j + 1) begin
          if (numer_valid_q[j]) begin
            numer_vals_q[j*VALS +: VALS] <= numer_vals_next[j*VALS +: VALS];
            numer_acc_q[j*ACCS +: ACCS] <= numer_acc_next[j*ACCS +: ACCS];
          end
        end
      end
    end

    // Division operands at the end of the last numerator slot: |numerator| 2^F (2^Ft for S, T, Q) by |area2|, and
    // |edge start|, |edge_step_y| by |edge_step_x| (a horizontal edge's results are zeroed at the end).
    wire [ACCS-1:0] numer_last = numer_acc_next[(NUMER_STAGES-1)*ACCS +: ACCS];
    wire [PAY-1:0] numer_last_pay = numer_pay_q[(NUMER_STAGES-1)*PAY +: PAY];
    wire [PLANES-1:0] divide_in_planes;
    wire [SPANS-1:0] divide_in_spans;
    genvar dn, dk;
    for (dn = 0; dn < NNUM; dn = dn + 1) begin : divide_in_plane
      localparam integer G = dn < 12 ? F : FT;
      wire [NB-1:0] num = numer_last[dn*NB +: NB];
      wire [NB-1:0] magnitude = num[NB-1] ? -num : num;
      // numerator * 2^F < 2^DIVIDER_BITS (docs/widths.md; PDB >= both): the top bits are zero.
      /* verilator lint_off UNUSEDSIGNAL */
      wire [NB+G-1:0] scaled = {magnitude, {G{1'b0}}};
      /* verilator lint_on UNUSEDSIGNAL */
      assign divide_in_planes[dn*PLANE_W +: PLANE_W] = {num[NB-1], {AREA_BITS{1'b0}}, PDB'(scaled)};
    end
    for (dk = 0; dk < 3; dk = dk + 1) begin : divide_in_span
      wire [EDGE_BITS-1:0] start = numer_last_pay[P_ES + dk*EDGE_BITS +: EDGE_BITS];
      wire [EDGE_STEP_Y_BITS-1:0] step = numer_last_pay[P_SY + dk*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS];
      wire [EDGE_BITS-1:0] start_mag = start[EDGE_BITS-1] ? -start : start;
      wire [EDGE_STEP_Y_BITS-1:0] step_mag = step[EDGE_STEP_Y_BITS-1] ? -step : step;
      assign divide_in_spans[(2*dk)*SPAN_W +: SPAN_W] = {start[EDGE_BITS-1], {EDGE_STEP_X_BITS{1'b0}}, start_mag};
      assign divide_in_spans[(2*dk+1)*SPAN_W +: SPAN_W] = {step[EDGE_STEP_Y_BITS-1], {EDGE_STEP_X_BITS{1'b0}}, {(EDGE_BITS-EDGE_STEP_Y_BITS){1'b0}}, step_mag};
    end

    // ---- Divide slots: restoring steps, one quotient bit each, MSB first ----
    // One element per division, slot j's division n at [j*NNUM + n] (planes) and [j*6 + n] (spans):
    // whole elements move between slots, no part-selects into a packed vector.
    reg [PLANE_W-1:0] divide_planes_q [0:DIVIDE_STAGES*NNUM-1];
    reg [PLANE_W-1:0] divide_planes_next [0:DIVIDE_STAGES*NNUM-1];
    reg [SPAN_W-1:0] divide_spans_q [0:DIVIDE_STAGES*6-1];
    reg [SPAN_W-1:0] divide_spans_next [0:DIVIDE_STAGES*6-1];
    reg [DIVIDE_STAGES*PAY-1:0] divide_pay_q;
    reg [AREA_BITS-1:0] plane_partial, plane_divisor;
    reg [PDB-1:0] plane_bits;
    reg [AREA_BITS:0] plane_shifted, plane_difference;
    reg [EDGE_STEP_X_BITS-1:0] span_partial, span_divisor, span_step_x;
    reg [EDGE_BITS-1:0] span_bits;
    reg [EDGE_STEP_X_BITS:0] span_shifted, span_difference;
    reg [31:0] step_index;
    always @* begin
      plane_shifted = {(AREA_BITS+1){1'b0}};
      plane_difference = {(AREA_BITS+1){1'b0}};
      span_shifted = {(EDGE_STEP_X_BITS+1){1'b0}};
      span_difference = {(EDGE_STEP_X_BITS+1){1'b0}};
      step_index = 32'd0;
      plane_divisor = {AREA_BITS{1'b0}};
      plane_partial = {AREA_BITS{1'b0}};
      plane_bits = {PDB{1'b0}};
      span_step_x = {EDGE_STEP_X_BITS{1'b0}};
      span_divisor = {EDGE_STEP_X_BITS{1'b0}};
      span_partial = {EDGE_STEP_X_BITS{1'b0}};
      span_bits = {EDGE_BITS{1'b0}};
      // An empty slot's next values are don't-care (as the edge slots'). Filled in flat loops of
      // their own, ahead of the slots: plain copies in Verilator, where inside the slot loop it
      // computed each element's index with a product every cycle (12 % of its instructions).
      for (n = 0; n < DIVIDE_STAGES*NNUM; n = n + 1) divide_planes_next[n] = {PLANE_W{1'bx}};
      for (n = 0; n < DIVIDE_STAGES*6; n = n + 1) divide_spans_next[n] = {SPAN_W{1'bx}};
      for (j = 0; j < DIVIDE_STAGES; j = j + 1) begin
        if (divide_valid_q[j]) begin
        plane_divisor = divide_pay_q[j*PAY + P_AREA +: AREA_BITS];
        for (n = 0; n < NNUM; n = n + 1) begin
          plane_partial = divide_planes_q[j*NNUM + n][PDB +: AREA_BITS];
          plane_bits = divide_planes_q[j*NNUM + n][PDB-1:0];
          for (s = 0; s < DIVIDE_STEPS; s = s + 1) begin
            step_index = (j * I + {{(32-PHASE_BITS){1'b0}}, phase_q}) * DIVIDE_STEPS + s;
            if (step_index >= PLANE_SKIP) begin
              plane_shifted = {plane_partial, plane_bits[PDB-1]};
              plane_difference = plane_shifted - {1'b0, plane_divisor};
              plane_partial = plane_difference[AREA_BITS] ? plane_shifted[AREA_BITS-1:0] : plane_difference[AREA_BITS-1:0];
              plane_bits = {plane_bits[PDB-2:0], !plane_difference[AREA_BITS]};
            end
          end
          divide_planes_next[j*NNUM + n] = {divide_planes_q[j*NNUM + n][PLANE_W-1], plane_partial, plane_bits};
        end
        for (n = 0; n < 6; n = n + 1) begin
          span_step_x = divide_pay_q[j*PAY + P_SX + (n/2)*EDGE_STEP_X_BITS +: EDGE_STEP_X_BITS];
          span_divisor = span_step_x[EDGE_STEP_X_BITS-1] ? -span_step_x : span_step_x;
          span_partial = divide_spans_q[j*6 + n][EDGE_BITS +: EDGE_STEP_X_BITS];
          span_bits = divide_spans_q[j*6 + n][EDGE_BITS-1:0];
          for (s = 0; s < DIVIDE_STEPS; s = s + 1) begin
            step_index = (j * I + {{(32-PHASE_BITS){1'b0}}, phase_q}) * DIVIDE_STEPS + s;
            if (step_index >= SPAN_SKIP) begin
              span_shifted = {span_partial, span_bits[EDGE_BITS-1]};
              span_difference = span_shifted - {1'b0, span_divisor};
              span_partial = span_difference[EDGE_STEP_X_BITS] ? span_shifted[EDGE_STEP_X_BITS-1:0] : span_difference[EDGE_STEP_X_BITS-1:0];
              span_bits = {span_bits[EDGE_BITS-2:0], !span_difference[EDGE_STEP_X_BITS]};
            end
          end
          divide_spans_next[j*6 + n] = {divide_spans_q[j*6 + n][SPAN_W-1], span_partial, span_bits};
        end
        end
      end
    end
    /* verilator lint_on UNSIGNED */
    // The first product slot's division results (the record fields are formed from them below).
    reg [PLANES-1:0] out_planes_q;
    reg [SPANS-1:0] out_spans_q;
    // |area2| (the plane divisor) is not part of the record.
    /* verilator lint_off UNUSEDSIGNAL */
    reg [PAY-1:0] out_pay_q;
    /* verilator lint_on UNUSEDSIGNAL */
    always @(posedge clk) begin
      if (advance) begin
        if (numer_valid_q[NUMER_STAGES-1]) begin
          for (n = 0; n < NNUM; n = n + 1) divide_planes_q[n] <= divide_in_planes[n*PLANE_W +: PLANE_W];
          for (n = 0; n < 6; n = n + 1) divide_spans_q[n] <= divide_in_spans[n*SPAN_W +: SPAN_W];
          divide_pay_q[0 +: PAY] <= numer_last_pay;
        end
        for (j = 1; j < DIVIDE_STAGES; j = j + 1) begin
          if (divide_valid_q[j-1]) begin
            for (n = 0; n < NNUM; n = n + 1) divide_planes_q[j*NNUM + n] <= divide_planes_next[(j-1)*NNUM + n];
            for (n = 0; n < 6; n = n + 1) divide_spans_q[j*6 + n] <= divide_spans_next[(j-1)*6 + n];
            divide_pay_q[j*PAY +: PAY] <= divide_pay_q[(j-1)*PAY +: PAY];
          end
        end
        if (divide_valid_q[DIVIDE_STAGES-1]) begin
          for (n = 0; n < NNUM; n = n + 1) out_planes_q[n*PLANE_W +: PLANE_W] <= divide_planes_next[(DIVIDE_STAGES-1)*NNUM + n];
          for (n = 0; n < 6; n = n + 1) out_spans_q[n*SPAN_W +: SPAN_W] <= divide_spans_next[(DIVIDE_STAGES-1)*6 + n];
          out_pay_q <= divide_pay_q[(DIVIDE_STAGES-1)*PAY +: PAY];
        end
      end else begin
        for (j = 0; j < DIVIDE_STAGES; j = j + 1) begin
          if (divide_valid_q[j]) begin
            for (n = 0; n < NNUM; n = n + 1) divide_planes_q[j*NNUM + n] <= divide_planes_next[j*NNUM + n];
            for (n = 0; n < 6; n = n + 1) divide_spans_q[j*6 + n] <= divide_spans_next[j*6 + n];
          end
        end
      end
    end

    // ---- The record fields of the first product slot: floor for negative dividends (as
    // divider.sv), packed as the record (without the left-edge fields); with TEXTURE above it the
    // textured flag and the S, T, Q planes (TEX_BASE bits: the flag, then plane 3c + (start, step
    // x, step y) at 1 + (3c + ...) TR) ----
    localparam integer TEX_BASE = TEX != 0 ? 1 + 9 * TR : 0;
    localparam integer VIEW_BITS = BASE_BITS + TEX_BASE;
    wire [VIEW_BITS-1:0] first_rec;
    genvar on, ok;
    for (on = 0; on < NNUM; on = on + 1) begin : out_plane
      localparam integer QB = on < 3 ? Z_REG_BITS : on < 12 ? COLOR_REG_BITS : TR;
      wire negative = out_planes_q[on*PLANE_W + PLANE_W - 1];
      wire remainder_nonzero = out_planes_q[on*PLANE_W + PDB +: AREA_BITS] != {AREA_BITS{1'b0}};
      wire [QB-1:0] magnitude = out_planes_q[on*PLANE_W +: QB];
      wire [QB-1:0] quotient = !negative ? magnitude : remainder_nonzero ? ~magnitude : -magnitude;
    end
    assign first_rec[LSB_DEPTH_START +: Z_REG_BITS] = out_plane[0].quotient;
    assign first_rec[LSB_DEPTH_STEP_X +: Z_REG_BITS] = out_plane[1].quotient;
    assign first_rec[LSB_DEPTH_STEP_Y +: Z_REG_BITS] = out_plane[2].quotient;
    for (ok = 0; ok < 3; ok = ok + 1) begin : out_edge
      assign first_rec[LSB_COLOR_START + ok*COLOR_REG_BITS +: COLOR_REG_BITS] = out_plane[3 + 3*ok].quotient;
      assign first_rec[LSB_COLOR_STEP_X + ok*COLOR_REG_BITS +: COLOR_REG_BITS] = out_plane[4 + 3*ok].quotient;
      assign first_rec[LSB_COLOR_STEP_Y + ok*COLOR_REG_BITS +: COLOR_REG_BITS] = out_plane[5 + 3*ok].quotient;
      wire [EDGE_STEP_X_BITS-1:0] step_x = out_pay_q[P_SX + ok*EDGE_STEP_X_BITS +: EDGE_STEP_X_BITS];
      wire [EDGE_STEP_X_BITS-1:0] divisor = step_x[EDGE_STEP_X_BITS-1] ? -step_x : step_x;
      wire horizontal = step_x == {EDGE_STEP_X_BITS{1'b0}};
      wire [SPAN_W-1:0] start_div = out_spans_q[(2*ok)*SPAN_W +: SPAN_W];
      wire [SPAN_W-1:0] step_div = out_spans_q[(2*ok+1)*SPAN_W +: SPAN_W];
      wire start_negative = start_div[SPAN_W-1], step_negative = step_div[SPAN_W-1];
      wire [EDGE_STEP_X_BITS-1:0] start_partial = start_div[EDGE_BITS +: EDGE_STEP_X_BITS], step_partial = step_div[EDGE_BITS +: EDGE_STEP_X_BITS];
      wire [EDGE_BITS-1:0] start_magnitude = start_div[EDGE_BITS-1:0];
      wire [EDGE_STEP_Y_BITS-1:0] step_magnitude = step_div[EDGE_STEP_Y_BITS-1:0];
      wire [EDGE_BITS-1:0] start_quot = !start_negative ? start_magnitude
                               : start_partial != 0 ? ~start_magnitude : -start_magnitude;
      wire [EDGE_STEP_Y_BITS-1:0] step_quot = !step_negative ? step_magnitude
                               : step_partial != 0 ? ~step_magnitude : -step_magnitude;
      // Remainders are < |step_x| < 2^SPAN_REM_BITS: the top bit is zero.
      /* verilator lint_off UNUSEDSIGNAL */
      wire [EDGE_STEP_X_BITS-1:0] start_rem = (start_negative && start_partial != 0) ? divisor - start_partial : start_partial;
      wire [EDGE_STEP_X_BITS-1:0] step_rem = (step_negative && step_partial != 0) ? divisor - step_partial : step_partial;
      /* verilator lint_on UNUSEDSIGNAL */
      assign first_rec[LSB_EDGE_START + ok*EDGE_BITS +: EDGE_BITS] = out_pay_q[P_ES + ok*EDGE_BITS +: EDGE_BITS];
      assign first_rec[LSB_EDGE_STEP_X + ok*EDGE_STEP_X_BITS +: EDGE_STEP_X_BITS] = step_x;
      assign first_rec[LSB_EDGE_STEP_Y + ok*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS] = out_pay_q[P_SY + ok*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS];
      assign first_rec[LSB_SPAN_QUOT + ok*EDGE_BITS +: EDGE_BITS] = horizontal ? {EDGE_BITS{1'b0}} : start_quot;
      assign first_rec[LSB_SPAN_REM + ok*SPAN_REM_BITS +: SPAN_REM_BITS] = horizontal ? {SPAN_REM_BITS{1'b0}} : start_rem[SPAN_REM_BITS-1:0];
      assign first_rec[LSB_SPAN_STEP_QUOT + ok*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS] = horizontal ? {EDGE_STEP_Y_BITS{1'b0}} : step_quot;
      assign first_rec[LSB_SPAN_STEP_REM + ok*SPAN_REM_BITS +: SPAN_REM_BITS] = horizontal ? {SPAN_REM_BITS{1'b0}} : step_rem[SPAN_REM_BITS-1:0];
    end
    assign first_rec[LSB_X0 +: X_BITS] = out_pay_q[P_X0 +: X_BITS];
    assign first_rec[LSB_X1 +: X_BITS] = out_pay_q[P_X1 +: X_BITS];
    assign first_rec[LSB_Y0 +: Y_BITS] = out_pay_q[P_Y0 +: Y_BITS];
    assign first_rec[LSB_Y1 +: Y_BITS] = out_pay_q[P_Y1 +: Y_BITS];
    assign first_rec[LSB_FLAT_RGB +: 24] = out_pay_q[P_RGB +: 24];
    if (TEX != 0) begin : first_texture
      assign first_rec[BASE_BITS] = out_pay_q[P_TEX];
      for (on = 0; on < 9; on = on + 1) begin : plane
        assign first_rec[BASE_BITS + 1 + on*TR +: TR] = out_plane[12 + on].quotient;
      end
    end

    // ---- Product slots: the 16 planes along the left edges (28 with TEXTURE), base - quot * step_x
    // modulo 2^PRB (each plane in the low bits), PB multiply steps MSB first (the sign bit's
    // subtracts), side by side; product n = 4p + 2j + t (plane p, left-edge slot j, t: start, step).
    // Slot 0 holds the first slot's record fields in first_rec; later slots carry them packed. ----
    reg [VIEW_BITS-1:0] product_rec_q [0:PRODUCT_STAGES-1];  // [0] unused: first_rec stands in
    reg [PRB-1:0] product_acc_q [0:PRODUCT_STAGES*NPROD-1];
    reg [PRB-1:0] product_acc_next [0:PRODUCT_STAGES*NPROD-1];
    reg [VIEW_BITS-1:0] view;
    reg [2:0] left_edge;
    reg [PB-1:0] multipliers [0:3];  // slot 0 start, slot 0 step, slot 1 start, slot 1 step
    reg [PB-1:0] multiplier;
    reg [PRB-1:0] product_step_x, acc;
    reg [31:0] product_index;
    integer q;
    // The record fields a product reads: plane p's step_x and its base (start or step_y), and the
    // slot's quotient (span_quot or span_step_quot of the slot's edge).
    function automatic [PRB-1:0] plane_field(input [VIEW_BITS-1:0] r, input integer p, input integer which);
      // which: 0 start, 1 step x, 2 step y
      begin
        if (p == 0) plane_field = PRB'(r[(which == 0 ? LSB_DEPTH_START : which == 1 ? LSB_DEPTH_STEP_X : LSB_DEPTH_STEP_Y) +: Z_REG_BITS]);
        else if (p < 4 || TEX == 0)
          plane_field = PRB'($signed(r[(which == 0 ? LSB_COLOR_START : which == 1 ? LSB_COLOR_STEP_X : LSB_COLOR_STEP_Y)
                                       + (p - 1) * COLOR_REG_BITS +: COLOR_REG_BITS]));
        else plane_field = PRB'(r[BASE_BITS + 1 + (3 * (p - 4) + which) * TR +: TR]);
      end
    endfunction
    function automatic [PB-1:0] span_quot_of(input [VIEW_BITS-1:0] r, input integer edge_k);
      span_quot_of = PB'($signed(r[LSB_SPAN_QUOT + edge_k*EDGE_BITS +: EDGE_BITS]));
    endfunction
    function automatic [PB-1:0] span_step_quot_of(input [VIEW_BITS-1:0] r, input integer edge_k);
      span_step_quot_of = PB'($signed(r[LSB_SPAN_STEP_QUOT + edge_k*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS]));
    endfunction
    /* verilator lint_off UNSIGNED */
    always @* begin
      view = {VIEW_BITS{1'b0}};
      left_edge = 3'b000;
      for (q = 0; q < 4; q = q + 1) multipliers[q] = {PB{1'b0}};
      multiplier = {PB{1'b0}};
      product_step_x = {PRB{1'b0}};
      acc = {PRB{1'b0}};
      product_index = 32'd0;
      for (n = 0; n < PRODUCT_STAGES*NPROD; n = n + 1) product_acc_next[n] = {PRB{1'bx}};  // an empty slot: don't-care (as the divide slots')
      for (j = 0; j < PRODUCT_STAGES; j = j + 1) begin
        if (product_valid_q[j]) begin
          view = j == 0 ? first_rec : product_rec_q[j];
          for (q = 0; q < 3; q = q + 1)
            left_edge[q] = !view[LSB_EDGE_STEP_X + q*EDGE_STEP_X_BITS + EDGE_STEP_X_BITS - 1]
                           && view[LSB_EDGE_STEP_X + q*EDGE_STEP_X_BITS +: EDGE_STEP_X_BITS] != {EDGE_STEP_X_BITS{1'b0}};
          // Each slot's quotients: slot 0 the first left edge, slot 1 the second (else 0).
          multipliers[0] = left_edge[0] ? span_quot_of(view, 0) : left_edge[1] ? span_quot_of(view, 1)
                         : left_edge[2] ? span_quot_of(view, 2) : {PB{1'b0}};
          multipliers[1] = left_edge[0] ? span_step_quot_of(view, 0) : left_edge[1] ? span_step_quot_of(view, 1)
                         : left_edge[2] ? span_step_quot_of(view, 2) : {PB{1'b0}};
          multipliers[2] = left_edge[0] && left_edge[1] ? span_quot_of(view, 1)
                         : (left_edge[0] || left_edge[1]) && left_edge[2] ? span_quot_of(view, 2) : {PB{1'b0}};
          multipliers[3] = left_edge[0] && left_edge[1] ? span_step_quot_of(view, 1)
                         : (left_edge[0] || left_edge[1]) && left_edge[2] ? span_step_quot_of(view, 2) : {PB{1'b0}};
          for (n = 0; n < NPROD; n = n + 1) begin
            multiplier = multipliers[n % 4];
            product_step_x = plane_field(view, n / 4, 1);
            acc = product_acc_q[j*NPROD + n];
            for (s = 0; s < PRODUCT_STEPS; s = s + 1) begin
              product_index = (j * I + {{(32-PHASE_BITS){1'b0}}, phase_q}) * PRODUCT_STEPS + s;
              if (product_index >= PRODUCT_SKIP) begin
                if (multiplier[PB - 1 - (product_index - PRODUCT_SKIP)])
                  acc = product_index == PRODUCT_SKIP ? {acc[PRB-2:0], 1'b0} - product_step_x
                                                      : {acc[PRB-2:0], 1'b0} + product_step_x;
                else
                  acc = {acc[PRB-2:0], 1'b0};
              end
            end
            product_acc_next[j*NPROD + n] = acc;
          end
        end
      end
    end
    /* verilator lint_on UNSIGNED */
    // The output register: the record and base - acc of each product (the depth and colour ones in
    // the low bits: the top bits are unused with TEXTURE).
    reg [VIEW_BITS-1:0] out_rec_q;
    /* verilator lint_off UNUSEDSIGNAL */
    reg [PRB-1:0] out_along_q [0:NPROD-1];
    /* verilator lint_on UNUSEDSIGNAL */
    wire [VIEW_BITS-1:0] last_view = PRODUCT_STAGES == 1 ? first_rec : product_rec_q[PRODUCT_STAGES-1];
    always @(posedge clk) begin
      if (advance) begin
        if (divide_valid_q[DIVIDE_STAGES-1])
          for (n = 0; n < NPROD; n = n + 1) product_acc_q[n] <= {PRB{1'b0}};
        for (j = 1; j < PRODUCT_STAGES; j = j + 1) begin
          if (product_valid_q[j-1]) begin
            product_rec_q[j] <= j == 1 ? first_rec : product_rec_q[j-1];
            for (n = 0; n < NPROD; n = n + 1) product_acc_q[j*NPROD + n] <= product_acc_next[(j-1)*NPROD + n];
          end
        end
        if (product_valid_q[PRODUCT_STAGES-1]) begin
          out_rec_q <= last_view;
          for (n = 0; n < NPROD; n = n + 1)
            out_along_q[n] <= plane_field(last_view, n / 4, n % 2 == 1 ? 2 : 0) - product_acc_next[(PRODUCT_STAGES-1)*NPROD + n];
        end
      end else begin
        for (j = 0; j < PRODUCT_STAGES; j = j + 1)
          if (product_valid_q[j]) for (n = 0; n < NPROD; n = n + 1) product_acc_q[j*NPROD + n] <= product_acc_next[j*NPROD + n];
      end
    end
    assign out_base = out_rec_q[BASE_BITS-1:0];
    for (ok = 0; ok < 16; ok = ok + 1) begin : along
      assign out_along[ok] = out_along_q[ok][Z_REG_BITS-1:0];
    end
    // The texture record (register 3g + c: groups 0..2 the plane, 3..6 product 16 + 4c + g - 3),
    // all zero for an untextured triangle.
    if (TEX != 0) begin : texture
      wire textured = out_rec_q[BASE_BITS];
      genvar tg, tc;
      assign out_texture[0] = textured;
      for (tc = 0; tc < 3; tc = tc + 1) begin : coordinate
        for (tg = 0; tg < 7; tg = tg + 1) begin : group
          wire [TR-1:0] field;
          if (tg < 3) begin : plane
            assign field = out_rec_q[BASE_BITS + 1 + (3*tc + tg)*TR +: TR];
          end else begin : along
            assign field = out_along_q[16 + 4*tc + tg - 3][TR-1:0];
          end
          assign out_texture[1 + (3*tg + tc)*TR +: TR] = textured ? field : {TR{1'b0}};
        end
      end
    end else begin : no_texture
      assign out_texture = {rs_texture_record_bits(WIDTH, HEIGHT){1'b0}};
    end
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
      assign vtex[tv] = vtex_q[tv];
    end
    assign vtextured = textured_q;
  end else begin : no_texture_vertices
    for (tv = 0; tv < 9; tv = tv + 1) begin : values
      assign vtex[tv] = {TVB{1'b0}};
    end
    assign vtextured = 1'b0;
  end
  endgenerate
endmodule
