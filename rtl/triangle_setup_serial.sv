// The serial schedule of the triangle setup unit (triangle_setup with SETUP_INTERVAL = 0;
// docs/cycle-model.md): one shared shift-add / restoring datapath runs a program of operations, one
// triangle at a time. Accept in cycle a (in_valid & in_ready while idle); the program runs from
// a+1; DECIDE in a+2+2 DELTA_BITS decides (a rejected triangle ends there); the output is valid one
// cycle after FINAL (setup_done, a + rs_setup_serial_latency) for that one cycle, in which the core
// passes it to the walker or into the record FIFO (rastersim_core.sv); the unit is free after it.
// With TEXTURE = 1 the program inserts the S, T, Q operations for a textured triangle only.
// triangle_setup holds the vertex registers (swapped here in DECIDE), the box (in registered steps
// for this schedule) and the decision's status, and packs the record.
`include "rastersim_pkg.sv"
module triangle_setup_serial `RS_IMPORT #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer SUBPIXEL_BITS = 4,
  parameter integer Z_BITS = 24,         // the depth plane's bits (docs/arithmetic.md section 6)
  parameter integer Z_GUARD_BITS = 0,
  parameter integer TEXTURE = 0,         // 1: the S, T, Q planes (profile texture_unit)
  parameter integer PIXEL_CENTER = 0,    // rastersim_pkg::PIXEL_CENTER_*: the sample point, half or corner
  parameter integer FILL_RULE = 0        // rastersim_pkg::FILL_*: the edges that own samples on them
) (
  input  wire clk,
  input  wire rst,
  output wire free,                  // idle: no triangle in the unit
  // Command input (triangle_setup's): x, y of vertex k at [k*COORD_BITS +: COORD_BITS],
  // s(COORD_BITS-S).S subpixels.
  input  wire in_valid,
  output wire in_ready,
  input  wire [3*rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] in_x,
  input  wire [3*rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] in_y,
  // triangle_setup's vertex registers: load them from the command, or swap v1 and v2.
  output wire load_vertices,
  output wire swap_vertices,
  // Their contents, vertex k at [k*B +: B]: x, y s(COORD_BITS-S).S; z uN; rgb {r,g,b} u8; with
  // TEXTURE the texture coordinates (vertex k's c at [(3k + c) 50], S and T s8.41, Q u1.41) and the
  // textured flag, zero otherwise.
  input  wire [3*rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] vertex_x,
  input  wire [3*rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] vertex_y,
  input  wire [3*Z_BITS-1:0] vertex_z,
  input  wire [3*rastersim_pkg::RGB_BITS-1:0] vertex_rgb,
  /* verilator lint_off UNUSEDSIGNAL */
  input  wire [3*rastersim_pkg::TEXTURE_COMMAND_BITS-1:0] vertex_texture,
  input  wire vertex_textured,
  /* verilator lint_on UNUSEDSIGNAL */
  // The clipped box, registered in triangle_setup (signed pixels, COORD_BITS + 2 bits): the first
  // candidate column and row, the last ones; in 0 .. WIDTH-1 (HEIGHT-1) when drawn.
  /* verilator lint_off UNUSEDSIGNAL */
  input  wire signed [rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)+1:0] box_x0,
  input  wire signed [rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)+1:0] box_x1,
  input  wire signed [rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)+1:0] box_y0,
  input  wire signed [rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)+1:0] box_y1,
  /* verilator lint_on UNUSEDSIGNAL */
  // The decision: twice the signed area of the vertices as accepted (s.2S, the AREA operation's
  // result, read in DECIDE), and the status triangle_setup forms from it (rastersim_pkg::STATUS_*).
  output wire signed [rs_area_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] area2,
  input  `RS_TYPE(status_t) status,
  output wire decided,               // DECIDE
  output wire busy,
  // The record's fields 0..17 (rs_rec_lsb), the 16 PRODUCT results (n at [n Z_REG_BITS], the
  // colour planes in the low bits) and the texture record, valid for the one cycle out_valid.
  output wire out_valid,
  output wire [rs_rec_lsb(18, WIDTH, HEIGHT, SUBPIXEL_BITS, Z_BITS, Z_GUARD_BITS)-1:0] out_base,
  output wire [16*(Z_BITS + rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS) + 1)-1:0] out_along,
  output wire [rs_texture_record_bits(WIDTH, HEIGHT)-1:0] out_texture
);
`include "rastersim_widths.vh"
  localparam integer S = SUBPIXEL_BITS;
  localparam integer F = rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS);
  localparam integer COORD_BITS = rs_coord_bits(WIDTH, HEIGHT, S);
  localparam integer DELTA_BITS = rs_delta_bits(WIDTH, HEIGHT, S);
  localparam integer AREA_BITS = rs_area_bits(WIDTH, HEIGHT, S);
  localparam integer EDGE_BITS = rs_edge_bits(WIDTH, HEIGHT, S);
  localparam integer EDGE_STEP_X_BITS = rs_edge_step_x_bits(HEIGHT, S);
  localparam integer EDGE_STEP_Y_BITS = rs_edge_step_y_bits(WIDTH, S);
  localparam integer SPAN_REM_BITS = rs_span_rem_bits(HEIGHT, S);
  localparam integer X_BITS = rs_ubits32(WIDTH - 1);
  localparam integer Y_BITS = rs_ubits32(HEIGHT - 1);
  localparam integer BB = COORD_BITS + 2;           // bounding-box arithmetic, signed pixels
  localparam integer Z_REG_BITS = Z_BITS + F + 1;   // the depth plane's registers
  localparam integer COLOR_REG_BITS = 9 + F;        // a colour plane's registers
  // The sample point within a pixel, subpixels: half a pixel, or 0 at the corner (arithmetic.md 7).
  localparam integer SAMPLE = PIXEL_CENTER == rastersim_pkg::PIXEL_CENTER_CORNER ? 0 : 1 << (S - 1);
  localparam signed [BB-1:0] SAMPLE_B = SAMPLE[BB-1:0];
  // Which edges own the samples on them (FILL_RULE): left (else right) ones, top (else bottom) ones.
  localparam [0:0] OWN_LEFT = FILL_RULE == rastersim_pkg::FILL_TOP_LEFT || FILL_RULE == rastersim_pkg::FILL_BOTTOM_LEFT;
  localparam [0:0] OWN_TOP = FILL_RULE == rastersim_pkg::FILL_TOP_LEFT || FILL_RULE == rastersim_pkg::FILL_TOP_RIGHT;
  // Whether an edge owns the samples on it, from the signs of its -dy and dx (the ordered triangle
  // has its interior to the right as y points down: -dy > 0 is a left edge, a horizontal edge with
  // dx > 0 a top one); model/triangle_setup.cpp owns_samples_on_edge.
  function automatic owns_samples(input ndy_positive, input ndy_negative, input dx_positive, input dx_negative);
    owns_samples = ndy_positive || ndy_negative ? (OWN_LEFT ? ndy_positive : ndy_negative)
                                                : (OWN_TOP ? dx_positive : dx_negative);
  endfunction

  // The texture planes (TEXTURE = 1; docs/arithmetic.md section 5): vertex values m_t = 50 bits (S,
  // T s8.41, Q u1.41), registers s9.(P+Ft) of TR = P + Ft + 9 bits, Ft the derived guard bits.
  localparam integer TEX = TEXTURE != 0 ? 1 : 0;
  localparam integer MT = rastersim_pkg::TEXTURE_VERTEX_BITS;
  localparam integer TR = rs_texture_reg_bits(WIDTH, HEIGHT);
  localparam integer FT = rs_guard_bits(WIDTH, HEIGHT, 0);
  localparam integer TVB = TEX != 0 ? MT : 1;  // a texture vertex value (1: none, tied to 0)

  // The vertex registers as arrays.
  wire signed [COORD_BITS-1:0] vx [0:2];
  wire signed [COORD_BITS-1:0] vy [0:2];
  wire [Z_BITS-1:0] vz [0:2];
  wire [23:0] vrgb [0:2];
  wire [TVB-1:0] vtex [0:8];  // vertex k's c at [3k + c]
  wire vtextured = vertex_textured;
  genvar vk;
  for (vk = 0; vk < 3; vk = vk + 1) begin : vertices
    assign vx[vk] = vertex_x[vk*COORD_BITS +: COORD_BITS];
    assign vy[vk] = vertex_y[vk*COORD_BITS +: COORD_BITS];
    assign vz[vk] = vertex_z[vk*Z_BITS +: Z_BITS];
    assign vrgb[vk] = vertex_rgb[vk*24 +: 24];
  end
  for (vk = 0; vk < 9; vk = vk + 1) begin : texture_coordinates
    assign vtex[vk] = vertex_texture[vk*MT +: TVB];
  end
  wire swap = area2[AREA_BITS-1];  // order the vertices so that area2 > 0

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
  // A product's multiplier bits: PB for the depth and colour planes, PBt for S, T, Q; the
  // multiplier register has the larger.
  localparam integer PB = rs_setup_product_bits(WIDTH, HEIGHT, S, Z_BITS, Z_GUARD_BITS);
  localparam integer PBT = rs_setup_texture_product_bits(WIDTH, HEIGHT, S);  // PBt
  localparam integer PRODUCT_MULTIPLIER_BITS = TEX != 0 && PBT > PB ? PBT : PB;
  localparam integer PRB = TEX != 0 && TR > Z_REG_BITS ? TR : Z_REG_BITS;  // the product accumulator
  localparam integer PB_SHIFT = PRODUCT_MULTIPLIER_BITS - PB;  // a PB-bit multiplier at the register's top
  localparam integer PBT_SHIFT = PRODUCT_MULTIPLIER_BITS > PBT ? PRODUCT_MULTIPLIER_BITS - PBT : 0;

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
  // the multiplier register PRODUCT_MULTIPLIER_BITS bits with either multiplier at its top.
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
  wire [PRODUCT_MULTIPLIER_BITS-1:0] product_multiplier =
      product_texture ? PRODUCT_MULTIPLIER_BITS'(texture_multiplier) << PBT_SHIFT
                      : PRODUCT_MULTIPLIER_BITS'(plane_multiplier) << PB_SHIFT;
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
  reg [PRODUCT_MULTIPLIER_BITS-1:0] product_bits_q;  // the multiplier, consumed from the top
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
  wire product_next_bit = active_q && load_q ? product_multiplier[PRODUCT_MULTIPLIER_BITS-1]
                                              : product_bits_q[PRODUCT_MULTIPLIER_BITS-2];
  wire [PRB-1:0] product_next_step_x = active_q && load_q ? product_step_x : product_step_x_q;
  wire [PRB-1:0] product_next_addend = product_next_bit ? product_next_step_x : {PRB{1'b0}};
  reg [PRB-1:0] product_addend_q;
  always @(posedge clk) product_addend_q <= product_next_first ? ~product_next_addend : product_next_addend;
  wire [PRB-1:0] product_doubled = {product_acc_q[PRB-2:0], 1'b0};

  // ---- Operands of the load cycle ----
  wire signed [BB-1:0] centre_x = (box_x0 <<< S) + SAMPLE_B;  // the first candidate's sample point
  wire signed [BB-1:0] centre_y = (box_y0 <<< S) + SAMPLE_B;
  wire signed [BB-1:0] rel_x = centre_x - BB'(vx[edge_k]);
  wire signed [BB-1:0] rel_y = centre_y - BB'(vy[edge_k]);
  // Plane p's vertex values: depth and colour unsigned, S, T, Q m_t bits signed (Z_BITS < m_t).
  localparam integer VW = TEX != 0 ? MT : Z_BITS;
  wire [VW-1:0] value [0:2];
  genvar v;
  for (v = 0; v < 3; v = v + 1) begin : values
    wire [1:0] channel = plane_p[1:0];  // r, g, b from 1; S, T, Q from 0
    wire [7:0] color = channel == 2'd1 ? vrgb[v][23:16] : channel == 2'd2 ? vrgb[v][15:8] : vrgb[v][7:0];
    wire [TVB-1:0] coordinate = channel == 2'd0 ? vtex[3*v] : channel == 2'd1 ? vtex[3*v + 1] : vtex[3*v + 2];
    assign value[v] = plane_texture ? VW'(coordinate) : plane_p == {PPB{1'b0}} ? VW'(vz[v]) : VW'(color);
  end
  wire signed [DELTA_BITS-1:0] span_dividend_small = dx[span_k];
  wire signed [H-1:0] span_dividend = span_step ? H'(span_dividend_small) : H'(start_q[span_k]);

  // ---- Decision (DECIDE, the AREA result in ACC) ----
  assign area2 = acc_q[MB-DELTA_BITS +: AREA_BITS];
  wire deciding = active_q && load_q && op_q == OP_DECIDE;
  assign decided = deciding;
  assign swap_vertices = deciding && status == rastersim_pkg::STATUS_DRAWN && swap;

  assign load_vertices = !active_q && !out_q && in_valid;
  assign in_ready = !active_q && !out_q;
  assign free = in_ready;
  assign busy = load_vertices || active_q || out_q;
  assign out_valid = out_q;

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
        end else if (deciding && status != rastersim_pkg::STATUS_DRAWN) begin
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
      product_bits_q <= {product_bits_q[PRODUCT_MULTIPLIER_BITS-2:0], 1'b0};
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
    assign out_along[k*Z_REG_BITS +: Z_REG_BITS] = along_q[k];
  end
  assign out_depth_start = depth_q[0];
  assign out_depth_step_x = depth_q[1];
  assign out_depth_step_y = depth_q[2];
  assign out_x0 = box_x0[X_BITS-1:0];
  assign out_x1 = box_x1[X_BITS-1:0];
  assign out_y0 = box_y0[Y_BITS-1:0];
  assign out_y1 = box_y1[Y_BITS-1:0];
  assign out_flat_rgb = vrgb[0];

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
endmodule
