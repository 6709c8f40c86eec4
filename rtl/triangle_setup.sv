// Triangle setup unit (model/triangle_setup.cpp): snapped vertices in; edge functions with the
// top-left bias, the screen-clipped bounding box, the cull / degenerate / offscreen decision, the
// span-walker quotients, and the depth and colour planes from exact floor divisions.
//
// Cycles (docs/cycle-model.md): accept in cycle a (IDLE, in_valid & in_ready); FRONT in a+1
// decides (a rejected triangle ends there); a drawn one starts every divider at the end of a+1,
// the dividers run DIVIDER_BITS cycles (a+2 .. a+DIVIDER_BITS+1), and the output is valid from
// a+DIVIDER_BITS+2 = a + setup_cycles - 1 (setup_done) for that one cycle, in which the core passes
// it to the walker or into the record FIFO (rastersim_core.sv); the unit is free again after it.
module triangle_setup #(
  parameter integer WIDTH = 640,
  parameter integer HEIGHT = 480,
  parameter integer SUBPIXEL_BITS = 4,
  parameter integer Z_BITS = 24,
  parameter integer Z_GUARD_BITS = 0
) (
  input  wire clk,
  input  wire rst,
  input  wire [1:0] cfg_cull,        // 0 none, 1 back, 2 front
  input  wire       cfg_front_face,  // 0 ccw, 1 cw
  // Command input: vertex k at [k*B +: B]; x, y s(COORD_BITS-S).S subpixels; z uN; rgb {r,g,b} u8.
  input  wire in_valid,
  output wire in_ready,
  input  wire [3*rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] in_x,
  input  wire [3*rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] in_y,
  input  wire [3*Z_BITS-1:0] in_z,
  input  wire [3*24-1:0]     in_rgb,
  // Decision, valid in the FRONT cycle: status 0 drawn, 1 degenerate, 2 culled, 3 offscreen.
  output wire        decided,
  output wire [1:0]  decided_status,
  output wire        decided_front_facing,
  output wire signed [rs_area_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] decided_area2,  // s.2S
  output wire busy,   // accept, FRONT, DIVIDE, or OUT cycles
  // Setup record of a drawn triangle (the model's SetupResult), edge k at [k*B +: B], valid for
  // the one cycle setup_done.
  output wire out_valid,
  output reg  [rs_ubits32(WIDTH - 1)-1:0]  out_x0,
  output reg  [rs_ubits32(WIDTH - 1)-1:0]  out_x1,
  output reg  [rs_ubits32(HEIGHT - 1)-1:0] out_y0,
  output reg  [rs_ubits32(HEIGHT - 1)-1:0] out_y1,
  output wire [3*rs_edge_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] out_edge_start,   // s.2S, biased
  output wire [3*rs_edge_step_x_bits(HEIGHT, SUBPIXEL_BITS)-1:0] out_edge_step_x, // s.2S
  output wire [3*rs_edge_step_y_bits(WIDTH, SUBPIXEL_BITS)-1:0]  out_edge_step_y, // s.2S
  output wire [3*rs_edge_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] out_span_quot,
  output wire [3*rs_span_rem_bits(HEIGHT, SUBPIXEL_BITS)-1:0]    out_span_rem,
  output wire [3*rs_edge_step_y_bits(WIDTH, SUBPIXEL_BITS)-1:0]  out_span_step_quot,
  output wire [3*rs_span_rem_bits(HEIGHT, SUBPIXEL_BITS)-1:0]    out_span_step_rem,
  // Planes: depth s(N+1).F; colour r, g, b at [c*B +: B], s9.F; each start, step_x, step_y.
  output wire [Z_BITS+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS):0]     out_depth_start,
  output wire [Z_BITS+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS):0]     out_depth_step_x,
  output wire [Z_BITS+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS):0]     out_depth_step_y,
  output wire [3*(9+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS))-1:0]    out_color_start,
  output wire [3*(9+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS))-1:0]    out_color_step_x,
  output wire [3*(9+rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS))-1:0]    out_color_step_y,
  output reg  [23:0] out_flat_rgb     // provoking (first) vertex colour
);
`include "rastersim_widths.vh"

  localparam integer S = SUBPIXEL_BITS;
  localparam integer F = rs_guard_bits(WIDTH, HEIGHT, Z_GUARD_BITS);
  localparam integer CB = rs_coord_bits(WIDTH, HEIGHT, S);
  localparam integer DB = rs_delta_bits(WIDTH, HEIGHT, S);
  localparam integer AB = rs_area_bits(WIDTH, HEIGHT, S);
  localparam integer EB = rs_edge_bits(WIDTH, HEIGHT, S);
  localparam integer SXB = rs_edge_step_x_bits(HEIGHT, S);
  localparam integer SYB = rs_edge_step_y_bits(WIDTH, S);
  localparam integer RB = rs_span_rem_bits(HEIGHT, S);
  localparam integer DIVIDER_BITS = rs_divider_bits(WIDTH, HEIGHT, S, Z_BITS, Z_GUARD_BITS);
  localparam integer ZRB = Z_BITS + F + 1;
  localparam integer CRB = 9 + F;
  localparam integer XB = rs_ubits32(WIDTH - 1);
  localparam integer YB = rs_ubits32(HEIGHT - 1);
  localparam integer BB = CB + 2;           // bounding-box arithmetic, signed pixels
  localparam integer PB = DB + CB + 2;      // edge cross products before narrowing to EB
  localparam integer NB = Z_BITS + EB + 4;  // plane numerators sum_k v_k e_k, signed
  localparam integer HALF = 1 << (S - 1);   // half a pixel in subpixels
  localparam integer ONE_LESS = (1 << S) - 1;  // one pixel less one subpixel
  localparam integer X_LAST = WIDTH - 1;
  localparam integer Y_LAST = HEIGHT - 1;
  localparam integer COUNT_BITS = $clog2(DIVIDER_BITS + 1);
  localparam [COUNT_BITS-1:0] DIVIDE_CYCLES = DIVIDER_BITS[COUNT_BITS-1:0];

  localparam signed [BB-1:0] HALF_B = HALF[BB-1:0];
  localparam signed [BB-1:0] ONE_LESS_B = ONE_LESS[BB-1:0];
  localparam signed [BB-1:0] X_LAST_B = X_LAST[BB-1:0];
  localparam signed [BB-1:0] Y_LAST_B = Y_LAST[BB-1:0];

  localparam [1:0] IDLE = 2'd0, FRONT = 2'd1, DIVIDE = 2'd2, OUT = 2'd3;
  localparam [1:0] DRAWN = 2'd0, DEGENERATE = 2'd1, CULLED = 2'd2, OFFSCREEN = 2'd3;

  reg [1:0] state;
  reg [COUNT_BITS-1:0] divide_left;

  // Vertices as accepted.
  reg signed [CB-1:0] vx [0:2];
  reg signed [CB-1:0] vy [0:2];
  reg [Z_BITS-1:0]    vz [0:2];
  reg [23:0]          vrgb [0:2];

  assign in_ready = state == IDLE;
  assign out_valid = state == OUT;
  assign busy = (state == IDLE && in_valid) || state == FRONT || state == DIVIDE || state == OUT;

  // ---- FRONT: area, facing, cull, bounding box (from the registered vertices) ----
  wire signed [DB-1:0] d10x = vx[1] - vx[0];
  wire signed [DB-1:0] d10y = vy[1] - vy[0];
  wire signed [DB-1:0] d20x = vx[2] - vx[0];
  wire signed [DB-1:0] d20y = vy[2] - vy[0];
  wire signed [2*DB:0] cross_a = $signed({{(DB+1){d10x[DB-1]}}, d10x}) * $signed({{(DB+1){d20y[DB-1]}}, d20y});
  wire signed [2*DB:0] cross_b = $signed({{(DB+1){d20x[DB-1]}}, d20x}) * $signed({{(DB+1){d10y[DB-1]}}, d10y});
  // |area2| <= 9 W H M^2 fits AB bits (docs/widths.md): the top bits are sign copies.
  /* verilator lint_off UNUSEDSIGNAL */
  wire signed [2*DB:0] area2_wide = cross_a - cross_b;
  /* verilator lint_on UNUSEDSIGNAL */
  wire signed [AB-1:0] area2 = area2_wide[AB-1:0];
  wire [AB-1:0] area = area2[AB-1] ? -area2 : area2;
  // y points down: area2 > 0 is clockwise as the viewer sees the screen.
  wire front_facing = cfg_front_face == 1'b0 ? area2[AB-1] : (area2 != 0 && !area2[AB-1]);
  wire culled = (cfg_cull == 2'd1 && !front_facing) || (cfg_cull == 2'd2 && front_facing);
  wire swap = area2[AB-1];  // order the vertices so that area2 > 0

  wire signed [CB-1:0] x_min01 = vx[0] < vx[1] ? vx[0] : vx[1];
  wire signed [CB-1:0] x_max01 = vx[0] > vx[1] ? vx[0] : vx[1];
  wire signed [CB-1:0] y_min01 = vy[0] < vy[1] ? vy[0] : vy[1];
  wire signed [CB-1:0] y_max01 = vy[0] > vy[1] ? vy[0] : vy[1];
  wire signed [CB-1:0] x_min_c = x_min01 < vx[2] ? x_min01 : vx[2];
  wire signed [CB-1:0] x_max_c = x_max01 > vx[2] ? x_max01 : vx[2];
  wire signed [CB-1:0] y_min_c = y_min01 < vy[2] ? y_min01 : vy[2];
  wire signed [CB-1:0] y_max_c = y_max01 > vy[2] ? y_max01 : vy[2];
  wire signed [BB-1:0] x_min = $signed({{(BB-CB){x_min_c[CB-1]}}, x_min_c});
  wire signed [BB-1:0] x_max = $signed({{(BB-CB){x_max_c[CB-1]}}, x_max_c});
  wire signed [BB-1:0] y_min = $signed({{(BB-CB){y_min_c[CB-1]}}, y_min_c});
  wire signed [BB-1:0] y_max = $signed({{(BB-CB){y_max_c[CB-1]}}, y_max_c});
  // Pixel i is a candidate when its centre i 2^S + 2^(S-1) lies in [min, max].
  wire signed [BB-1:0] bx0_num = x_min - HALF_B + ONE_LESS_B;
  wire signed [BB-1:0] by0_num = y_min - HALF_B + ONE_LESS_B;
  wire signed [BB-1:0] bx1_num = x_max - HALF_B;
  wire signed [BB-1:0] by1_num = y_max - HALF_B;
  wire signed [BB-1:0] bx0_raw = bx0_num >>> S;
  wire signed [BB-1:0] by0_raw = by0_num >>> S;
  wire signed [BB-1:0] bx1_raw = bx1_num >>> S;
  wire signed [BB-1:0] by1_raw = by1_num >>> S;
  wire signed [BB-1:0] bx0 = bx0_raw < 0 ? 0 : bx0_raw;
  wire signed [BB-1:0] by0 = by0_raw < 0 ? 0 : by0_raw;
  wire signed [BB-1:0] bx1 = bx1_raw > X_LAST_B ? X_LAST_B : bx1_raw;
  wire signed [BB-1:0] by1 = by1_raw > Y_LAST_B ? Y_LAST_B : by1_raw;
  wire offscreen = bx0 > bx1 || by0 > by1;

  wire [1:0] status = area2 == 0 ? DEGENERATE : culled ? CULLED : offscreen ? OFFSCREEN : DRAWN;
  assign decided = state == FRONT;
  assign decided_status = status;
  assign decided_front_facing = area2 != 0 && front_facing;
  assign decided_area2 = area2;

  // ---- Edge functions at the first candidate's centre (ordered vertices) ----
  wire signed [CB-1:0] ox [0:2];
  wire signed [CB-1:0] oy [0:2];
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

  wire signed [BB-1:0] centre_x = (bx0 <<< S) + HALF_B;
  wire signed [BB-1:0] centre_y = (by0 <<< S) + HALF_B;

  wire signed [EB-1:0]  unbiased [0:2];  // E at the first candidate, s.2S
  wire signed [EB-1:0]  edge_start [0:2];
  wire signed [SXB-1:0] edge_step_x [0:2];
  wire signed [SYB-1:0] edge_step_y [0:2];
  genvar k;
  generate
    for (k = 0; k < 3; k = k + 1) begin : edges
      wire signed [CB-1:0] bx = ox[(k + 1) % 3];
      wire signed [CB-1:0] by = oy[(k + 1) % 3];
      wire signed [CB-1:0] ax = ox[k];
      wire signed [CB-1:0] ay = oy[k];
      wire signed [PB-1:0] dx = $signed({{(PB-CB){bx[CB-1]}}, bx}) - $signed({{(PB-CB){ax[CB-1]}}, ax});
      wire signed [PB-1:0] dy = $signed({{(PB-CB){by[CB-1]}}, by}) - $signed({{(PB-CB){ay[CB-1]}}, ay});
      wire signed [PB-1:0] rel_x = $signed({{(PB-BB){centre_x[BB-1]}}, centre_x}) - $signed({{(PB-CB){ax[CB-1]}}, ax});
      wire signed [PB-1:0] rel_y = $signed({{(PB-BB){centre_y[BB-1]}}, centre_y}) - $signed({{(PB-CB){ay[CB-1]}}, ay});
      // Only the low bits are kept: |E| < 2^(EB-1), |step| within SXB / SYB (docs/widths.md).
      /* verilator lint_off UNUSEDSIGNAL */
      wire signed [PB-1:0] value = dx * rel_y - dy * rel_x;
      // Interior to the right (dy < 0) is a left edge; horizontal with interior below is top.
      wire top_left = dy < 0 || (dy == 0 && dx > 0);
      wire signed [PB-1:0] step_x = -(dy <<< S);
      wire signed [PB-1:0] step_y = dx <<< S;
      /* verilator lint_on UNUSEDSIGNAL */
      assign unbiased[k] = value[EB-1:0];
      assign edge_start[k] = unbiased[k] - (top_left ? 0 : 1);
      assign edge_step_x[k] = step_x[SXB-1:0];
      assign edge_step_y[k] = step_y[SYB-1:0];
    end
  endgenerate

  // sum_k v_k e_(k+1): the plane numerator with the weights of edge k opposite vertex k+2.
  function automatic signed [NB-1:0] plane_numerator(input [Z_BITS-1:0] v0, input [Z_BITS-1:0] v1,
                                                     input [Z_BITS-1:0] v2, input signed [EB-1:0] e0,
                                                     input signed [EB-1:0] e1, input signed [EB-1:0] e2);
    reg signed [NB-1:0] a0, a1, a2, w0, w1, w2;
    begin
      a0 = $signed({{(NB-Z_BITS){1'b0}}, v0});
      a1 = $signed({{(NB-Z_BITS){1'b0}}, v1});
      a2 = $signed({{(NB-Z_BITS){1'b0}}, v2});
      w0 = $signed({{(NB-EB){e0[EB-1]}}, e0});
      w1 = $signed({{(NB-EB){e1[EB-1]}}, e1});
      w2 = $signed({{(NB-EB){e2[EB-1]}}, e2});
      plane_numerator = a0 * w1 + a1 * w2 + a2 * w0;
    end
  endfunction

  // The edge steps widened to EB bits (sign extension) as weights of the step numerators.
  wire signed [EB-1:0] weight_x [0:2];
  wire signed [EB-1:0] weight_y [0:2];
  generate
    for (k = 0; k < 3; k = k + 1) begin : weights
      assign weight_x[k] = $signed({{(EB-SXB){edge_step_x[k][SXB-1]}}, edge_step_x[k]});
      assign weight_y[k] = $signed({{(EB-SYB){edge_step_y[k][SYB-1]}}, edge_step_y[k]});
    end
  endgenerate

  // 12 plane numerators: plane p (0 depth, 1..3 r, g, b), term t (0 start, 1 step_x, 2 step_y).
  wire signed [NB-1:0] numerator [0:11];
  generate
    genvar p;
    for (p = 0; p < 4; p = p + 1) begin : planes
      wire [Z_BITS-1:0] v0 = p == 0 ? oz[0] : {{(Z_BITS-8){1'b0}}, orgb[0][(p == 0 ? 0 : 8*(3-p)) +: 8]};
      wire [Z_BITS-1:0] v1 = p == 0 ? oz[1] : {{(Z_BITS-8){1'b0}}, orgb[1][(p == 0 ? 0 : 8*(3-p)) +: 8]};
      wire [Z_BITS-1:0] v2 = p == 0 ? oz[2] : {{(Z_BITS-8){1'b0}}, orgb[2][(p == 0 ? 0 : 8*(3-p)) +: 8]};
      assign numerator[3*p + 0] = plane_numerator(v0, v1, v2, unbiased[0], unbiased[1], unbiased[2]);
      assign numerator[3*p + 1] = plane_numerator(v0, v1, v2, weight_x[0], weight_x[1], weight_x[2]);
      assign numerator[3*p + 2] = plane_numerator(v0, v1, v2, weight_y[0], weight_y[1], weight_y[2]);
    end
  endgenerate

  // ---- Dividers, all started at the end of FRONT for a drawn triangle ----
  wire start_dividers = state == FRONT && status == DRAWN;
  generate
    genvar n;
    for (n = 0; n < 12; n = n + 1) begin : plane_dividers
      localparam integer QB = n < 3 ? ZRB : CRB;
      wire [NB-1:0] magnitude = numerator[n] < 0 ? -numerator[n] : numerator[n];
      // numerator * 2^F < 2^DIVIDER_BITS (docs/widths.md): the top bits are zero.
      /* verilator lint_off UNUSEDSIGNAL */
      wire [NB+F-1:0] scaled = {magnitude, {F{1'b0}}};
      /* verilator lint_on UNUSEDSIGNAL */
      wire signed [QB-1:0] quotient;
      wire [AB-1:0] unused_remainder;
      wire unused_busy;
      divider #(.DIVIDEND_BITS(DIVIDER_BITS), .DIVISOR_BITS(AB), .QUOTIENT_BITS(QB)) div (
        .clk(clk), .start(start_dividers), .dividend_negative(numerator[n] < 0),
        .dividend_magnitude(scaled[DIVIDER_BITS-1:0]), .divisor(area), .busy(unused_busy),
        .quotient(quotient), .remainder(unused_remainder));
    end
  endgenerate
  assign out_depth_start = plane_dividers[0].quotient;
  assign out_depth_step_x = plane_dividers[1].quotient;
  assign out_depth_step_y = plane_dividers[2].quotient;
  generate
    genvar c;
    for (c = 0; c < 3; c = c + 1) begin : color_out
      assign out_color_start[c*CRB +: CRB] = plane_dividers[3 + 3*c].quotient;
      assign out_color_step_x[c*CRB +: CRB] = plane_dividers[4 + 3*c].quotient;
      assign out_color_step_y[c*CRB +: CRB] = plane_dividers[5 + 3*c].quotient;
    end
  endgenerate

  // Span walker: start = quot * d + rem and step_y = step_quot * d + step_rem, d = |step_x|.
  reg signed [EB-1:0]  rec_edge_start [0:2];
  reg signed [SXB-1:0] rec_edge_step_x [0:2];
  reg signed [SYB-1:0] rec_edge_step_y [0:2];
  generate
    for (k = 0; k < 3; k = k + 1) begin : span_dividers
      wire [SXB-1:0] divisor = edge_step_x[k] < 0 ? -edge_step_x[k] : edge_step_x[k];
      wire [EB-1:0] start_mag = edge_start[k] < 0 ? -edge_start[k] : edge_start[k];
      wire [SYB-1:0] step_mag = edge_step_y[k] < 0 ? -edge_step_y[k] : edge_step_y[k];
      wire signed [EB-1:0] start_quot;
      wire signed [SYB-1:0] step_quot;
      // Remainders are < |step_x| < 2^RB: the top bit is zero.
      /* verilator lint_off UNUSEDSIGNAL */
      wire [SXB-1:0] start_rem, step_rem;
      /* verilator lint_on UNUSEDSIGNAL */
      wire unused_busy_start, unused_busy_step;
      divider #(.DIVIDEND_BITS(EB), .DIVISOR_BITS(SXB), .QUOTIENT_BITS(EB)) div_start (
        .clk(clk), .start(start_dividers), .dividend_negative(edge_start[k] < 0),
        .dividend_magnitude(start_mag), .divisor(divisor), .busy(unused_busy_start),
        .quotient(start_quot), .remainder(start_rem));
      divider #(.DIVIDEND_BITS(SYB), .DIVISOR_BITS(SXB), .QUOTIENT_BITS(SYB)) div_step (
        .clk(clk), .start(start_dividers), .dividend_negative(edge_step_y[k] < 0),
        .dividend_magnitude(step_mag), .divisor(divisor), .busy(unused_busy_step),
        .quotient(step_quot), .remainder(step_rem));
      // A horizontal edge (step_x == 0) has no span quotients: the model sets them to 0.
      wire horizontal = rec_edge_step_x[k] == 0;
      assign out_edge_start[k*EB +: EB] = rec_edge_start[k];
      assign out_edge_step_x[k*SXB +: SXB] = rec_edge_step_x[k];
      assign out_edge_step_y[k*SYB +: SYB] = rec_edge_step_y[k];
      assign out_span_quot[k*EB +: EB] = horizontal ? {EB{1'b0}} : start_quot;
      assign out_span_rem[k*RB +: RB] = horizontal ? {RB{1'b0}} : start_rem[RB-1:0];
      assign out_span_step_quot[k*SYB +: SYB] = horizontal ? {SYB{1'b0}} : step_quot;
      assign out_span_step_rem[k*RB +: RB] = horizontal ? {RB{1'b0}} : step_rem[RB-1:0];
    end
  endgenerate

  // ---- Control ----
  integer i;
  always @(posedge clk) begin
    if (rst) begin
      state <= IDLE;
      divide_left <= {COUNT_BITS{1'b0}};
    end else begin
      case (state)
        IDLE: if (in_valid) state <= FRONT;
        FRONT: begin
          state <= status == DRAWN ? DIVIDE : IDLE;
          divide_left <= DIVIDE_CYCLES;
        end
        DIVIDE: begin
          divide_left <= divide_left - 1'b1;
          if (divide_left == 1) state <= OUT;
        end
        default: state <= IDLE;  // OUT: the core takes the record
      endcase
    end
  end

  // Datapath registers (no reset: loaded before use).
  always @(posedge clk) begin
    if (state == IDLE && in_valid) begin
      for (i = 0; i < 3; i = i + 1) begin
        vx[i] <= in_x[i*CB +: CB];
        vy[i] <= in_y[i*CB +: CB];
        vz[i] <= in_z[i*Z_BITS +: Z_BITS];
        vrgb[i] <= in_rgb[i*24 +: 24];
      end
    end
    if (start_dividers) begin
      out_x0 <= bx0[XB-1:0];
      out_x1 <= bx1[XB-1:0];
      out_y0 <= by0[YB-1:0];
      out_y1 <= by1[YB-1:0];
      out_flat_rgb <= vrgb[0];
      for (i = 0; i < 3; i = i + 1) begin
        rec_edge_start[i] <= edge_start[i];
        rec_edge_step_x[i] <= edge_step_x[i];
        rec_edge_step_y[i] <= edge_step_y[i];
      end
    end
  end
endmodule
