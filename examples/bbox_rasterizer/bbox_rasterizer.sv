// An example rasterizer that is not rastersim's, checked against the model through the
// verification interface (docs/verification.md): `rastersim cosim --dut
// examples/bbox_rasterizer/bbox_rasterizer.f --top bbox_rasterizer --compare triangle`.
//
// Written from the rules of docs/arithmetic.md alone, with another micro-architecture: one
// triangle at a time; the setup's planes from wide divisions in one cycle; the bounding box walked
// column by column (x outer, y inner: another fragment order than rastersim's rows), two cycles per
// candidate (edge functions and planes evaluated per pixel in absolute form, then the depth test);
// the frame buffers inside the design. Plain Verilog plus `$signed` arithmetic, for simulation.
// z_guard_bits auto only (the guard bits are derived as docs/arithmetic.md says).
// Its 32-, 64- and 128-bit signed operands extend as Verilog's expression rules say:
/* verilator lint_off WIDTH */
module bbox_rasterizer #(
  parameter integer WIDTH = 64,
  parameter integer HEIGHT = 48,
  parameter integer SUBPIXEL_BITS = 4,
  parameter integer Z_BITS = 24,
  // A design that keeps fewer fraction bits: the depth plane's start and steps lose their lowest
  // DEPTH_DROP_BITS bits (rounded down). Its depth then lies below the model's by at most
  // floor((W + H - 1) (2^DEPTH_DROP_BITS - 1) / 2^F) + 1 LSBs (docs/verification.md "Tolerances").
  parameter integer DEPTH_DROP_BITS = 0,
  // 1: a design that samples pixel (i, j) at its corner (i, j), not at its centre; the model must
  // then be told so (profile pixel_center corner, docs/arithmetic.md section 7).
  parameter integer PIXEL_CENTER_CORNER = 0
) (
  input  wire clk,
  input  wire rst,
  input  wire [2:0]  cfg_depth_func,
  input  wire        cfg_depth_write,
  input  wire [Z_BITS-1:0] cfg_depth_clear,
  input  wire [1:0]  cfg_cull,
  input  wire        cfg_front_face,
  input  wire        cfg_shading,
  input  wire        cmd_valid,
  output wire        cmd_ready,
  input  wire [31:0] cmd_x0, cmd_y0, cmd_x1, cmd_y1, cmd_x2, cmd_y2,
  input  wire [Z_BITS-1:0] cmd_z0, cmd_z1, cmd_z2,
  input  wire [23:0] cmd_rgb0, cmd_rgb1, cmd_rgb2,
  output reg         dec_valid,
  output reg  [31:0] dec_index,
  output reg  [2:0]  dec_status,
  output reg         frag_valid,
  output reg  [31:0] frag_index,
  output reg  [15:0] frag_x, frag_y,
  output reg  [Z_BITS-1:0] frag_z,
  output reg  [23:0] frag_rgb,
  output reg         frag_pass,
  output wire        frame_done,
  input  wire [31:0] rb_addr,
  output reg  [Z_BITS-1:0] rb_depth,
  output reg  [23:0] rb_rgb
);
  localparam integer WORDS = WIDTH * HEIGHT;
  localparam integer M = 1 << SUBPIXEL_BITS;
  localparam integer HALF = 1 << (SUBPIXEL_BITS - 1);
  localparam integer SAMPLE = PIXEL_CENTER_CORNER ? 0 : HALF;  // the sample point within a pixel
  // F: the plane registers' fraction bits, the smallest with 2^F >= 2 (W + H - 1), at least 1.
  function integer guard_bits(input integer w, input integer h);
    integer f;
    begin
      f = 0;
      while ((1 << f) < 2 * (w + h - 1)) f = f + 1;
      guard_bits = f < 1 ? 1 : f;
    end
  endfunction
  localparam integer F = guard_bits(WIDTH, HEIGHT);
  localparam integer Z_REG_BITS = Z_BITS + F + 1;
  localparam integer COLOR_REG_BITS = 8 + F + 1;

  // The frame buffers, and which words were written since reset.
  reg [Z_BITS-1:0] depth_mem [0:WORDS-1];
  reg [23:0]       color_mem [0:WORDS-1];
  reg [WORDS-1:0]  written;

  localparam [1:0] IDLE = 2'd0, SETUP = 2'd1, EDGES = 2'd2, TEST = 2'd3;
  reg [1:0] state_q;
  reg [31:0] triangle_q;  // the index of the triangle taken last (accepted count - 1)
  reg signed [63:0] vx_q [0:2], vy_q [0:2];
  reg [Z_BITS-1:0] vz_q [0:2];
  reg [23:0] vrgb_q [0:2];

  assign cmd_ready = state_q == IDLE && !rst;
  assign frame_done = state_q == IDLE && !dec_valid && !frag_valid;

  // ---- Setup, from the triangle taken (combinational; used in SETUP) ----
  reg signed [63:0] area2, ox [0:2], oy [0:2], xmin, xmax, ymin, ymax, xa, xb, ya, yb;
  reg [Z_BITS-1:0] oz [0:2];
  reg [23:0] orgb [0:2];
  reg front_facing;
  reg [2:0] status;
  integer vk, ek, pk, pc, xk, xc;  // loop indices, one set per always block
  always @* begin
    area2 = (vx_q[1] - vx_q[0]) * (vy_q[2] - vy_q[0]) - (vx_q[2] - vx_q[0]) * (vy_q[1] - vy_q[0]);
    front_facing = cfg_front_face ? area2 > 0 : area2 < 0;
    // Either winding: vertices 1 and 2 swapped when area2 < 0.
    for (vk = 0; vk < 3; vk = vk + 1) begin
      ox[vk] = vx_q[vk]; oy[vk] = vy_q[vk]; oz[vk] = vz_q[vk]; orgb[vk] = vrgb_q[vk];
    end
    if (area2 < 0) begin
      ox[1] = vx_q[2]; oy[1] = vy_q[2]; oz[1] = vz_q[2]; orgb[1] = vrgb_q[2];
      ox[2] = vx_q[1]; oy[2] = vy_q[1]; oz[2] = vz_q[1]; orgb[2] = vrgb_q[1];
    end
    xmin = ox[0]; xmax = ox[0]; ymin = oy[0]; ymax = oy[0];
    for (vk = 1; vk < 3; vk = vk + 1) begin
      if (ox[vk] < xmin) xmin = ox[vk];
      if (ox[vk] > xmax) xmax = ox[vk];
      if (oy[vk] < ymin) ymin = oy[vk];
      if (oy[vk] > ymax) ymax = oy[vk];
    end
    // Columns xa..xb (rows ya..yb) have their sample point i M + SAMPLE inside [min, max].
    xa = (xmin - SAMPLE + M - 1) >>> SUBPIXEL_BITS;
    xb = (xmax - SAMPLE) >>> SUBPIXEL_BITS;
    ya = (ymin - SAMPLE + M - 1) >>> SUBPIXEL_BITS;
    yb = (ymax - SAMPLE) >>> SUBPIXEL_BITS;
    if (area2 == 0) status = 3'd1;  // degenerate
    else if ((cfg_cull == 2'd1 && !front_facing) || (cfg_cull == 2'd2 && front_facing)) status = 3'd2;  // culled
    else if (xb < 0 || yb < 0 || xa > WIDTH - 1 || ya > HEIGHT - 1) status = 3'd3;  // offscreen
    else if (xa > xb || ya > yb) status = 3'd4;  // no pixel centre
    else status = 3'd0;  // drawn
  end
  wire signed [63:0] bx0 = xa < 0 ? 64'sd0 : xa;
  wire signed [63:0] bx1 = xb > WIDTH - 1 ? WIDTH - 1 : xb;
  wire signed [63:0] by0 = ya < 0 ? 64'sd0 : ya;
  wire signed [63:0] by1 = yb > HEIGHT - 1 ? HEIGHT - 1 : yb;

  // Edge k from vertex k to vertex k + 1: E = dx (Py - Ya) - dy (Px - Xa) - bias, bias 0 on top
  // and left edges.
  reg signed [63:0] edge_dx [0:2], edge_dy [0:2], edge_bias [0:2];
  reg signed [127:0] e0 [0:2];  // unbiased, at the first candidate's sample point
  always @* begin
    for (ek = 0; ek < 3; ek = ek + 1) begin
      edge_dx[ek] = ox[(ek + 1) % 3] - ox[ek];
      edge_dy[ek] = oy[(ek + 1) % 3] - oy[ek];
      edge_bias[ek] = ((edge_dy[ek] == 0 && edge_dx[ek] > 0) || edge_dy[ek] < 0) ? 64'sd0 : 64'sd1;
      e0[ek] = 128'(edge_dx[ek]) * 128'((by0 << SUBPIXEL_BITS) + SAMPLE - oy[ek]) -
              128'(edge_dy[ek]) * 128'((bx0 << SUBPIXEL_BITS) + SAMPLE - ox[ek]);
    end
  end

  // A plane through v0, v1, v2: floor(2^F (v0 s1 + v1 s2 + v2 s0) / A) for the start (s = e0) and
  // the steps (s = -dy M, dx M).
  function signed [127:0] floor_div(input signed [127:0] n, input signed [127:0] d);
    reg signed [127:0] q;
    begin
      q = n / d;
      if (n < 0 && q * d != n) q = q - 1;
      floor_div = q;
    end
  endfunction
  function signed [127:0] plane(input [31:0] v0, input [31:0] v1, input [31:0] v2, input signed [127:0] s0,
                                input signed [127:0] s1, input signed [127:0] s2, input signed [127:0] a);
    reg signed [127:0] sum;
    begin
      sum = 128'($signed({1'b0, v0})) * s1 + 128'($signed({1'b0, v1})) * s2 + 128'($signed({1'b0, v2})) * s0;
      plane = floor_div(sum <<< F, a);
    end
  endfunction
  // Planes: 0 depth, 1..3 red, green, blue; start, x step, y step each.
  reg signed [127:0] p_start [0:3], p_sx [0:3], p_sy [0:3];
  reg signed [127:0] area, sx [0:2], sy [0:2];
  reg [31:0] pv [0:3][0:2];
  always @* begin
    area = area2 < 0 ? -128'(area2) : 128'(area2);
    for (pk = 0; pk < 3; pk = pk + 1) begin
      sx[pk] = -128'(edge_dy[pk]) * M;
      sy[pk] = 128'(edge_dx[pk]) * M;
      pv[0][pk] = 32'(oz[pk]);
      pv[1][pk] = 32'(orgb[pk][23:16]);
      pv[2][pk] = 32'(orgb[pk][15:8]);
      pv[3][pk] = 32'(orgb[pk][7:0]);
    end
    for (pc = 0; pc < 4; pc = pc + 1) begin
      p_start[pc] = plane(pv[pc][0], pv[pc][1], pv[pc][2], e0[0], e0[1], e0[2], area);
      p_sx[pc] = plane(pv[pc][0], pv[pc][1], pv[pc][2], sx[0], sx[1], sx[2], area);
      p_sy[pc] = plane(pv[pc][0], pv[pc][1], pv[pc][2], sy[0], sy[1], sy[2], area);
    end
  end

  // ---- The walk: registers of the drawn triangle ----
  reg signed [63:0] wx0_q, wy0_q, wx1_q, wy1_q, x_q, y_q;
  reg signed [63:0] dx_q [0:2], dy_q [0:2], bias_q [0:2], ax_q [0:2], ay_q [0:2];
  reg signed [127:0] start_q [0:3], step_x_q [0:3], step_y_q [0:3];
  reg [23:0] flat_q;
  reg covered_q;
  reg [Z_BITS-1:0] z_q;
  reg [23:0] rgb_q;

  // The edge functions and plane outputs at (x_q, y_q), in absolute form.
  reg signed [127:0] e_here, v_here, wrapped;
  reg covered;
  reg [Z_BITS-1:0] z_here;
  reg [7:0] channel [0:2];
  function signed [127:0] wrap(input signed [127:0] v, input integer bits);
    begin
      wrap = (v <<< (128 - bits)) >>> (128 - bits);  // two's complement in `bits` bits
    end
  endfunction
  always @* begin
    covered = 1'b1;
    for (xk = 0; xk < 3; xk = xk + 1) begin
      e_here = 128'(dx_q[xk]) * 128'((y_q << SUBPIXEL_BITS) + SAMPLE - ay_q[xk]) -
               128'(dy_q[xk]) * 128'((x_q << SUBPIXEL_BITS) + SAMPLE - ax_q[xk]) - 128'(bias_q[xk]);
      if (e_here < 0) covered = 1'b0;
    end
    v_here = wrap(start_q[0] + 128'(x_q - wx0_q) * step_x_q[0] + 128'(y_q - wy0_q) * step_y_q[0], Z_REG_BITS);
    wrapped = (v_here + (128'sd1 <<< (F - 1))) >>> F;
    z_here = wrapped < 0 ? {Z_BITS{1'b0}} : wrapped > ((128'sd1 <<< Z_BITS) - 1) ? {Z_BITS{1'b1}} : wrapped[Z_BITS-1:0];
    for (xc = 1; xc < 4; xc = xc + 1) begin
      v_here = wrap(start_q[xc] + 128'(x_q - wx0_q) * step_x_q[xc] + 128'(y_q - wy0_q) * step_y_q[xc], COLOR_REG_BITS);
      wrapped = (v_here + (128'sd1 <<< (F - 1))) >>> F;
      channel[xc - 1] = wrapped < 0 ? 8'd0 : wrapped > 255 ? 8'd255 : wrapped[7:0];
    end
  end

  wire [31:0] address = 32'(y_q) * WIDTH + 32'(x_q);
  wire [Z_BITS-1:0] stored = written[address] ? depth_mem[address] : cfg_depth_clear;
  reg pass;
  always @* begin
    case (cfg_depth_func)
      3'd0: pass = 1'b0;
      3'd1: pass = z_q < stored;
      3'd2: pass = z_q == stored;
      3'd3: pass = z_q <= stored;
      3'd4: pass = z_q > stored;
      3'd5: pass = z_q != stored;
      3'd6: pass = z_q >= stored;
      default: pass = 1'b1;
    endcase
  end

  always @(posedge clk) begin
    dec_valid <= 1'b0;
    frag_valid <= 1'b0;
    if (rst) begin
      state_q <= IDLE;
      triangle_q <= 32'hffffffff;
      written <= {WORDS{1'b0}};
    end else begin
      case (state_q)
        IDLE:
          if (cmd_valid) begin
            vx_q[0] <= 64'($signed(cmd_x0)); vy_q[0] <= 64'($signed(cmd_y0));
            vx_q[1] <= 64'($signed(cmd_x1)); vy_q[1] <= 64'($signed(cmd_y1));
            vx_q[2] <= 64'($signed(cmd_x2)); vy_q[2] <= 64'($signed(cmd_y2));
            vz_q[0] <= cmd_z0; vz_q[1] <= cmd_z1; vz_q[2] <= cmd_z2;
            vrgb_q[0] <= cmd_rgb0; vrgb_q[1] <= cmd_rgb1; vrgb_q[2] <= cmd_rgb2;
            triangle_q <= triangle_q + 32'd1;
            state_q <= SETUP;
          end
        SETUP: begin
          dec_valid <= 1'b1;
          dec_index <= triangle_q;
          dec_status <= status;
          if (status == 3'd0) begin
            wx0_q <= bx0; wx1_q <= bx1; wy0_q <= by0; wy1_q <= by1;
            x_q <= bx0; y_q <= by0;
            dx_q[0] <= edge_dx[0]; dy_q[0] <= edge_dy[0]; bias_q[0] <= edge_bias[0]; ax_q[0] <= ox[0]; ay_q[0] <= oy[0];
            dx_q[1] <= edge_dx[1]; dy_q[1] <= edge_dy[1]; bias_q[1] <= edge_bias[1]; ax_q[1] <= ox[1]; ay_q[1] <= oy[1];
            dx_q[2] <= edge_dx[2]; dy_q[2] <= edge_dy[2]; bias_q[2] <= edge_bias[2]; ax_q[2] <= ox[2]; ay_q[2] <= oy[2];
            start_q[0] <= (p_start[0] >>> DEPTH_DROP_BITS) <<< DEPTH_DROP_BITS;
            step_x_q[0] <= (p_sx[0] >>> DEPTH_DROP_BITS) <<< DEPTH_DROP_BITS;
            step_y_q[0] <= (p_sy[0] >>> DEPTH_DROP_BITS) <<< DEPTH_DROP_BITS;
            start_q[1] <= p_start[1]; step_x_q[1] <= p_sx[1]; step_y_q[1] <= p_sy[1];
            start_q[2] <= p_start[2]; step_x_q[2] <= p_sx[2]; step_y_q[2] <= p_sy[2];
            start_q[3] <= p_start[3]; step_x_q[3] <= p_sx[3]; step_y_q[3] <= p_sy[3];
            flat_q <= vrgb_q[0];  // the provoking vertex: the first as given
            state_q <= EDGES;
          end else begin
            state_q <= IDLE;
          end
        end
        EDGES: begin  // the candidate's edge functions and planes
          covered_q <= covered;
          z_q <= z_here;
          rgb_q <= cfg_shading ? {channel[0], channel[1], channel[2]} : flat_q;
          state_q <= TEST;
        end
        TEST: begin  // its depth test and write, then the next candidate: down the column, then right
          if (covered_q) begin
            frag_valid <= 1'b1;
            frag_index <= triangle_q;
            frag_x <= 16'(x_q);
            frag_y <= 16'(y_q);
            frag_z <= z_q;
            frag_rgb <= rgb_q;
            frag_pass <= pass;
            if (pass) begin
              if (cfg_depth_write || !written[address]) depth_mem[address] <= cfg_depth_write ? z_q : cfg_depth_clear;
              color_mem[address] <= rgb_q;
              written[address] <= 1'b1;
            end
          end
          if (y_q < wy1_q) begin
            y_q <= y_q + 1;
            state_q <= EDGES;
          end else if (x_q < wx1_q) begin
            y_q <= wy0_q;
            x_q <= x_q + 1;
            state_q <= EDGES;
          end else begin
            state_q <= IDLE;
          end
        end
      endcase
    end
    rb_depth <= written[rb_addr] ? depth_mem[rb_addr] : cfg_depth_clear;
    rb_rgb <= written[rb_addr] ? color_mem[rb_addr] : 24'd0;
  end
endmodule
