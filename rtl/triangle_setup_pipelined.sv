// The pipelined schedule of the triangle setup unit (triangle_setup with SETUP_INTERVAL = I =
// 2..64; docs/cycle-model.md): slots of I cycles counted from the first cycle of `run`; accept only
// in a slot's first cycle; FRONT slot (decision in a+1), EDGE_STAGES edge slots, NUMER_STAGES
// numerator slots, DIVIDE_STAGES divide slots, PRODUCT_STAGES product slots, then the output
// register, valid in a + I (1 + EDGE_STAGES + NUMER_STAGES + DIVIDE_STAGES + PRODUCT_STAGES).
// With TEXTURE = 1 the slots are sized for the S, T, Q planes for every triangle.
// triangle_setup holds the vertex registers (never swapped here: FRONT orders the vertices through
// multiplexers), the box and the decision's status, and packs the record.
`include "rastersim_pkg.sv"
module triangle_setup_pipelined `RS_IMPORT #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer SUBPIXEL_BITS = 4,
  parameter integer Z_BITS = 24,         // the depth plane's bits (docs/arithmetic.md section 6)
  parameter integer Z_GUARD_BITS = 0,
  parameter integer SETUP_INTERVAL = 2,  // the initiation interval I, 2..64
  parameter integer TEXTURE = 0,         // 1: the S, T, Q planes (profile texture_unit)
  parameter integer PIXEL_CENTER = 0,    // rastersim_pkg::PIXEL_CENTER_*: the sample point, half or corner
  parameter integer FILL_RULE = 0        // rastersim_pkg::FILL_*: the edges that own samples on them
) (
  input  wire clk,
  input  wire rst,
  input  wire run,                   // the frame runs (cycle 0 is its first cycle): slots count
  output wire free,                  // no triangle accepted in this slot yet
  input  wire in_valid,
  output wire in_ready,
  // triangle_setup's vertex registers: load them from the command (swap_vertices is 0).
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
  // The clipped box of the vertex registers (signed pixels, COORD_BITS + 2 bits): the first
  // candidate column and row, the last ones; in 0 .. WIDTH-1 (HEIGHT-1) when drawn.
  /* verilator lint_off UNUSEDSIGNAL */
  input  wire signed [rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)+1:0] box_x0,
  input  wire signed [rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)+1:0] box_x1,
  input  wire signed [rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)+1:0] box_y0,
  input  wire signed [rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)+1:0] box_y1,
  /* verilator lint_on UNUSEDSIGNAL */
  // The decision in the FRONT cycle: twice the signed area of the vertices as accepted (s.2S), and
  // the status triangle_setup forms from it (rastersim_pkg::STATUS_*).
  output wire signed [rs_area_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] area2,
  input  `RS_TYPE(status_t) status,
  output wire decided,               // the FRONT cycle
  output wire busy,
  // The record's fields 0..17 (rs_rec_lsb), the 16 PRODUCT results (n at [n Z_REG_BITS], the
  // colour planes in the low bits) and the texture record, valid for the one cycle out_valid.
  output wire out_valid,
  output wire [rs_rec_lsb(18, WIDTH, HEIGHT, SUBPIXEL_BITS, Z_BITS, Z_GUARD_BITS)-1:0] out_base,
  output wire [16*(Z_BITS + rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS) + 1)-1:0] out_along,
  output wire [rs_texture_record_bits(WIDTH, HEIGHT)-1:0] out_texture
);
`include "rastersim_widths.vh"
  `RS_REQUIRE(illegal_setup_interval, SETUP_INTERVAL >= 2 && SETUP_INTERVAL <= 64, "triangle_setup_pipelined: SETUP_INTERVAL must be 2..64")

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
  // Plane numerators sum_k v_k e_k, signed: v of N bits, or m_t with TEXTURE.
  localparam integer NB = (TEXTURE != 0 ? rastersim_pkg::TEXTURE_VERTEX_BITS : Z_BITS) + EDGE_BITS + 4;
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

  // The record (rastersim_widths.vh): fields 0..17 in out_base; the left-edge fields' planes in
  // out_along.
  localparam integer RECORD_Z_BITS = Z_BITS;  // the depth plane's (the core passes them as Z_BITS)
  `include "rastersim_record.vh"
  localparam integer BASE_BITS = LSB_LEFT_START;
  localparam integer Z_REG_BITS = Z_BITS + F + 1;   // the depth plane's registers
  localparam integer COLOR_REG_BITS = 9 + F;        // a colour plane's registers

  // The vertex registers as arrays.
  wire signed [COORD_BITS-1:0] vx [0:2];
  wire signed [COORD_BITS-1:0] vy [0:2];
  wire [Z_BITS-1:0] vz [0:2];
  wire [23:0] vrgb [0:2];
  // Used with TEXTURE only.
  /* verilator lint_off UNUSEDSIGNAL */
  wire [TVB-1:0] vtex [0:8];  // vertex k's c at [3k + c]
  wire vtextured = vertex_textured;
  /* verilator lint_on UNUSEDSIGNAL */
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

  // ---- FRONT: the area's two products (delta_bits x delta_bits), the only ones in one cycle ----
  wire signed [DELTA_BITS-1:0] d10x = vx[1] - vx[0];
  wire signed [DELTA_BITS-1:0] d10y = vy[1] - vy[0];
  wire signed [DELTA_BITS-1:0] d20x = vx[2] - vx[0];
  wire signed [DELTA_BITS-1:0] d20y = vy[2] - vy[0];
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
  assign ox[0] = vx[0];
  assign oy[0] = vy[0];
  assign oz[0] = vz[0];
  assign orgb[0] = vrgb[0];
  assign ox[1] = swap ? vx[2] : vx[1];
  assign oy[1] = swap ? vy[2] : vy[1];
  assign oz[1] = swap ? vz[2] : vz[1];
  assign orgb[1] = swap ? vrgb[2] : vrgb[1];
  assign ox[2] = swap ? vx[1] : vx[2];
  assign oy[2] = swap ? vy[1] : vy[2];
  assign oz[2] = swap ? vz[1] : vz[2];
  assign orgb[2] = swap ? vrgb[1] : vrgb[2];

  // The first candidate's centre, >= 0 and < 2^(COORD_BITS-1) (on screen): the top bit is a sign copy.
  /* verilator lint_off UNUSEDSIGNAL */
  wire signed [BB-1:0] centre_x = (box_x0 <<< S) + SAMPLE_B;  // the first candidate's sample point
  wire signed [BB-1:0] centre_y = (box_y0 <<< S) + SAMPLE_B;
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
  // PRODUCT_MULTIPLIER_BITS = max(PB, PBt)-bit multipliers, products in PRB bits (each plane in the
  // low bits); NPL planes. PB: a depth or colour product's multiplier bits, PBt an S, T, Q one's.
  localparam integer VW = TEX != 0 ? MT : Z_BITS;
  localparam integer TDB = rs_texture_divider_bits(WIDTH, HEIGHT, S);
  localparam integer PDB = TEX != 0 && TDB > DIVIDER_BITS ? TDB : DIVIDER_BITS;
  localparam integer PB = rs_setup_product_bits(WIDTH, HEIGHT, S, Z_BITS, Z_GUARD_BITS);
  localparam integer PBT = rs_setup_texture_product_bits(WIDTH, HEIGHT, S);
  localparam integer PRODUCT_MULTIPLIER_BITS = TEX != 0 && PBT > PB ? PBT : PB;
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
  localparam integer PRODUCT_STAGES = rs_setup_product_stages(PRODUCT_MULTIPLIER_BITS, I);
  localparam integer PRODUCT_STEPS = (PRODUCT_MULTIPLIER_BITS + I * PRODUCT_STAGES - 1) / (I * PRODUCT_STAGES);
  localparam integer PRODUCT_SKIP = I * PRODUCT_STAGES * PRODUCT_STEPS - PRODUCT_MULTIPLIER_BITS;
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
        edge_valid_q[0] <= front_q && status == rastersim_pkg::STATUS_DRAWN;
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
  assign busy = load_vertices || (front_q && (decided || status == rastersim_pkg::STATUS_DRAWN)) || edge_valid_q != 0
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
  wire [P_TEX-1:0] front_pay_base = {box_x0[X_BITS-1:0], box_x1[X_BITS-1:0], box_y0[Y_BITS-1:0], box_y1[Y_BITS-1:0],
                                     {(3*EDGE_BITS){1'b0}}, edge_step_x[2], edge_step_x[1], edge_step_x[0],
                                     edge_step_y[2], edge_step_y[1], edge_step_y[0], vrgb[0], area};
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
  // modulo 2^PRB (each plane in the low bits), PRODUCT_MULTIPLIER_BITS multiply steps MSB first (the sign bit's
  // subtracts), side by side; product n = 4p + 2j + t (plane p, left-edge slot j, t: start, step).
  // Slot 0 holds the first slot's record fields in first_rec; later slots carry them packed. ----
  reg [VIEW_BITS-1:0] product_rec_q [0:PRODUCT_STAGES-1];  // [0] unused: first_rec stands in
  reg [PRB-1:0] product_acc_q [0:PRODUCT_STAGES*NPROD-1];
  reg [PRB-1:0] product_acc_next [0:PRODUCT_STAGES*NPROD-1];
  reg [VIEW_BITS-1:0] view;
  reg [2:0] left_edge;
  reg [PRODUCT_MULTIPLIER_BITS-1:0] multipliers [0:3];  // slot 0 start, slot 0 step, slot 1 start, slot 1 step
  reg [PRODUCT_MULTIPLIER_BITS-1:0] multiplier;
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
  function automatic [PRODUCT_MULTIPLIER_BITS-1:0] span_quot_of(input [VIEW_BITS-1:0] r, input integer edge_k);
    span_quot_of = PRODUCT_MULTIPLIER_BITS'($signed(r[LSB_SPAN_QUOT + edge_k*EDGE_BITS +: EDGE_BITS]));
  endfunction
  function automatic [PRODUCT_MULTIPLIER_BITS-1:0] span_step_quot_of(input [VIEW_BITS-1:0] r, input integer edge_k);
    span_step_quot_of = PRODUCT_MULTIPLIER_BITS'($signed(r[LSB_SPAN_STEP_QUOT + edge_k*EDGE_STEP_Y_BITS +: EDGE_STEP_Y_BITS]));
  endfunction
  /* verilator lint_off UNSIGNED */
  always @* begin
    view = {VIEW_BITS{1'b0}};
    left_edge = 3'b000;
    for (q = 0; q < 4; q = q + 1) multipliers[q] = {PRODUCT_MULTIPLIER_BITS{1'b0}};
    multiplier = {PRODUCT_MULTIPLIER_BITS{1'b0}};
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
                       : left_edge[2] ? span_quot_of(view, 2) : {PRODUCT_MULTIPLIER_BITS{1'b0}};
        multipliers[1] = left_edge[0] ? span_step_quot_of(view, 0) : left_edge[1] ? span_step_quot_of(view, 1)
                       : left_edge[2] ? span_step_quot_of(view, 2) : {PRODUCT_MULTIPLIER_BITS{1'b0}};
        multipliers[2] = left_edge[0] && left_edge[1] ? span_quot_of(view, 1)
                       : (left_edge[0] || left_edge[1]) && left_edge[2] ? span_quot_of(view, 2) : {PRODUCT_MULTIPLIER_BITS{1'b0}};
        multipliers[3] = left_edge[0] && left_edge[1] ? span_step_quot_of(view, 1)
                       : (left_edge[0] || left_edge[1]) && left_edge[2] ? span_step_quot_of(view, 2) : {PRODUCT_MULTIPLIER_BITS{1'b0}};
        for (n = 0; n < NPROD; n = n + 1) begin
          multiplier = multipliers[n % 4];
          product_step_x = plane_field(view, n / 4, 1);
          acc = product_acc_q[j*NPROD + n];
          for (s = 0; s < PRODUCT_STEPS; s = s + 1) begin
            product_index = (j * I + {{(32-PHASE_BITS){1'b0}}, phase_q}) * PRODUCT_STEPS + s;
            if (product_index >= PRODUCT_SKIP) begin
              if (multiplier[PRODUCT_MULTIPLIER_BITS - 1 - (product_index - PRODUCT_SKIP)])
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
    assign out_along[ok*Z_REG_BITS +: Z_REG_BITS] = out_along_q[ok][Z_REG_BITS-1:0];
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
endmodule
