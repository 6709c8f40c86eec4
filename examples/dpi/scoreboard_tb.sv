// The golden model as the scoreboard of a SystemVerilog testbench, through DPI-C (docs/library.md).
// The design under test is the project's own rastersim_top; the testbench makes TRIANGLES random
// triangles, submits them to the model (rastersim_dpi), offers them to the DUT back to back, and
// compares every fragment the DUT presents to its z-buffer (triangle, pixel, depth, colour and the
// cycle it was accepted), every depth-test result, the frame's cycles and, through the read-back
// port, every word of the final buffers. Cycle 0 is the first cycle with frame_ready high.
// The clock comes from the C++ main (main.cpp); `done` and `failed` end the run.
`include "rastersim_pkg.sv"
module scoreboard_tb #(
  parameter integer WIDTH = 64,
  parameter integer HEIGHT = 48,
  parameter integer SUBPIXEL_BITS = 4,
  parameter integer Z_BITS = 24,
  parameter integer SETUP_INTERVAL = 2,
  parameter integer MEMORY_LATENCY = 3,
  parameter integer TRIANGLES = 300,
  parameter integer SEED = 1,
  parameter integer MAX_SHOWN = 10  // mismatches printed
) (
  input  wire clk,
  output reg  done,
  output reg  failed
);
  import rastersim_dpi::*;
`include "rastersim_widths.vh"

  localparam integer CB = rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS);
  localparam integer XB = rs_ubits32(WIDTH - 1);
  localparam integer YB = rs_ubits32(HEIGHT - 1);
  localparam integer AB = rs_ubits32(WIDTH * HEIGHT - 1);
  localparam integer M = 1 << SUBPIXEL_BITS;

  // ---- The model: triangles made and submitted at time 0, expected events read back ----
  chandle model;
  int tri_x [TRIANGLES][3];
  int tri_y [TRIANGLES][3];
  int unsigned tri_z [TRIANGLES][3];
  int unsigned tri_rgb [TRIANGLES][3];
  typedef struct packed {
    longint triangle;
    int x;
    int y;
    int unsigned z;
    int unsigned rgb;
    int pass;
    longint cycle;
  } fragment_t;
  fragment_t expected [$];
  longint model_cycles;

  int unsigned lcg = SEED;
  function automatic int unsigned next_random(input int unsigned range);
    lcg = lcg * 32'd1103515245 + 32'd12345;
    return (lcg >> 8) % range;
  endfunction

  initial begin
    string profile;
    longint index, setup_accept, setup_done, walker_load, walker_end, fragments, last_write;
    int status, x, y, pass;
    int unsigned z, rgb;
    longint cycle;
    fragment_t f;
    $sformat(profile, "{\"width\": %0d, \"height\": %0d, \"subpixel_bits\": %0d, \"z_bits\": %0d, \"setup_interval\": %0d, \"memory_latency\": %0d}",
             WIDTH, HEIGHT, SUBPIXEL_BITS, Z_BITS, SETUP_INTERVAL, MEMORY_LATENCY);
    if (rastersim_create(profile, model) != RASTERSIM_OK) $fatal(1, "scoreboard: %s", rastersim_last_error());
    for (int t = 0; t < TRIANGLES; t++) begin
      // A centre anywhere from a quarter screen off the left/top edge to a quarter off the right/bottom,
      // vertices up to 12 pixels from it (some off screen, some degenerate or tiny).
      int cx = int'(next_random(3 * WIDTH * M / 2)) - WIDTH * M / 4;
      int cy = int'(next_random(3 * HEIGHT * M / 2)) - HEIGHT * M / 4;
      for (int k = 0; k < 3; k++) begin
        tri_x[t][k] = cx + int'(next_random(24 * M)) - 12 * M;
        tri_y[t][k] = cy + int'(next_random(24 * M)) - 12 * M;
        tri_z[t][k] = next_random(1 << 20) << (Z_BITS - 20);
        tri_rgb[t][k] = next_random(1 << 24);
      end
      if (rastersim_dpi_submit_snapped(model, tri_x[t][0], tri_y[t][0], tri_z[t][0], tri_rgb[t][0],
                                       tri_x[t][1], tri_y[t][1], tri_z[t][1], tri_rgb[t][1],
                                       tri_x[t][2], tri_y[t][2], tri_z[t][2], tri_rgb[t][2], index) != RASTERSIM_OK)
        $fatal(1, "scoreboard: triangle %0d: %s", t, rastersim_last_error());
      void'(rastersim_dpi_read_triangle(model, index, status, setup_accept, setup_done, walker_load, walker_end,
                                        fragments, last_write));
      for (longint k = 0; k < fragments; k++) begin
        void'(rastersim_dpi_read_fragment(model, index, k, x, y, z, rgb, pass, cycle));
        f.triangle = index;
        f.x = x;
        f.y = y;
        f.z = z;
        f.rgb = rgb;
        f.pass = pass;
        f.cycle = cycle;
        expected.push_back(f);
      end
    end
    void'(rastersim_dpi_frame_cycles(model, model_cycles));
    $display("scoreboard: %0d triangles, %0d fragments, %0d cycles expected (%s)", TRIANGLES, expected.size(),
             model_cycles, rastersim_version());
  end

  // ---- The design under test ----
  reg rst = 1'b1;
  int next_triangle = 0;
  wire cmd_valid = !rst && next_triangle < TRIANGLES;
  wire [CB-1:0] cmd_x [3];
  wire [CB-1:0] cmd_y [3];
  wire [Z_BITS-1:0] cmd_z [3];
  wire [23:0] cmd_rgb [3];
  for (genvar k = 0; k < 3; k++) begin : command
    wire [31:0] x = tri_x[next_triangle < TRIANGLES ? next_triangle : 0][k];
    wire [31:0] y = tri_y[next_triangle < TRIANGLES ? next_triangle : 0][k];
    wire [31:0] z = tri_z[next_triangle < TRIANGLES ? next_triangle : 0][k];
    wire [31:0] rgb = tri_rgb[next_triangle < TRIANGLES ? next_triangle : 0][k];
    assign cmd_x[k] = x[CB-1:0];
    assign cmd_y[k] = y[CB-1:0];
    assign cmd_z[k] = z[Z_BITS-1:0];
    assign cmd_rgb[k] = rgb[23:0];
  end
  wire frame_ready, cmd_ready, frag_valid, frag_ready, result_valid, result_pass;
  wire [XB-1:0] frag_x;
  wire [YB-1:0] frag_y;
  wire [Z_BITS-1:0] frag_z, readback_depth;
  wire [23:0] frag_rgb, readback_rgb;
  reg [AB-1:0] readback_addr = '0;

  rastersim_top #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .SUBPIXEL_BITS(SUBPIXEL_BITS), .Z_BITS(Z_BITS),
                  .SETUP_INTERVAL(SETUP_INTERVAL)) dut (
    .clk(clk), .rst(rst),
    .cfg_depth_func(rastersim_pkg::DEPTH_LESS), .cfg_depth_write(1'b1), .cfg_depth_clear({Z_BITS{1'b1}}),
    .cfg_cull(rastersim_pkg::CULL_NONE), .cfg_front_face(rastersim_pkg::FRONT_CCW),
    .cfg_traversal(rastersim_pkg::TRAVERSAL_SPAN), .cfg_shading(rastersim_pkg::SHADING_GOURAUD),
    .cfg_memory_latency(MEMORY_LATENCY),
    .cfg_setup_fifo_depth(8),
    .frame_ready(frame_ready), .cmd_valid(cmd_valid), .cmd_ready(cmd_ready),
    .cmd_x0(cmd_x[0]), .cmd_y0(cmd_y[0]), .cmd_x1(cmd_x[1]), .cmd_y1(cmd_y[1]), .cmd_x2(cmd_x[2]), .cmd_y2(cmd_y[2]),
    .cmd_z0(cmd_z[0]), .cmd_z1(cmd_z[1]), .cmd_z2(cmd_z[2]),
    .cmd_rgb0(cmd_rgb[0]), .cmd_rgb1(cmd_rgb[1]), .cmd_rgb2(cmd_rgb[2]),
    .trace_setup_decided(), .trace_setup_status(), .trace_setup_busy(), .trace_setup_stall(), .trace_setup_done(),
    .trace_walker_load(), .trace_walker_busy(), .trace_walker_candidate(), .trace_walker_last(),
    .trace_frag_valid(frag_valid), .trace_frag_ready(frag_ready), .trace_frag_x(frag_x), .trace_frag_y(frag_y),
    .trace_frag_z(frag_z), .trace_frag_rgb(frag_rgb), .trace_result_valid(result_valid),
    .trace_result_pass(result_pass), .trace_zbuffer_busy(), .trace_zbuffer_stall(),
    // Built without the texture unit: its ports tied off.
    .cfg_texture_latency(7'd1), .cfg_texture_log2_width(4'd0), .cfg_texture_log2_height(4'd0),
    .cfg_texture_bilinear(1'b0), .cfg_texture_clamp(1'b0), .cfg_depth_bias_constant(33'd0),
    .cfg_depth_bias_slope(8'd0), .texture_load_en(1'b0), .texture_load_x(10'd0),
    .texture_load_y(10'd0), .texture_load_rgb(24'd0), .texture_refuse(1'b0), .cmd_textured(1'b0), .cmd_texture0('0), .cmd_texture1('0),
    .cmd_texture2('0), .trace_walker_frag_valid(), .trace_walker_frag_ready(), .trace_texture_busy(),
    .trace_texture_stall(),
    .readback_addr(readback_addr), .readback_depth(readback_depth), .readback_rgb(readback_rgb));

  // ---- Comparison, cycle by cycle ----
  int reset_cycles = 0, shown = 0, mismatches = 0, words_checked = 0;
  longint cycle = -1, fragments_seen = 0, results_seen = 0;
  reg reading_back = 1'b0, readback_pending = 1'b0;
  reg [AB-1:0] readback_previous;

  task automatic mismatch(input longint triangle, input int x, input int y, input string field,
                          input longint rtl, input longint expected_value, input longint at_cycle);
    mismatches++;
    if (shown < MAX_SHOWN) begin
      if (field.substr(0, 5) == "colour")  // 0xRRGGBB
        $display("scoreboard: MISMATCH triangle %0d, pixel (%0d, %0d), %s: rtl %06h, model %06h (cycle %0d)",
                 triangle, x, y, field, rtl[23:0], expected_value[23:0], at_cycle);
      else
        $display("scoreboard: MISMATCH triangle %0d, pixel (%0d, %0d), %s: rtl %0d, model %0d (cycle %0d)",
                 triangle, x, y, field, rtl, expected_value, at_cycle);
      shown++;
    end
  endtask

  initial begin
    done = 1'b0;
    failed = 1'b0;
  end

  always @(posedge clk) begin
    if (reset_cycles < 4) begin
      reset_cycles <= reset_cycles + 1;
    end else begin
      rst <= 1'b0;
    end
    if (!rst && cycle < 0 && frame_ready) cycle = 0;  // this cycle is cycle 0
    if (cycle >= 0 && !reading_back) begin
      if (cmd_valid && cmd_ready) next_triangle <= next_triangle + 1;
      if (frag_valid && frag_ready) begin
        if (fragments_seen >= expected.size()) begin
          mismatch(-1, frag_x, frag_y, "a fragment the model does not have", 1, 0, cycle);
        end else begin
          fragment_t e = expected[fragments_seen];
          if (frag_x != e.x || frag_y != e.y) mismatch(e.triangle, e.x, e.y, "pixel (x * 65536 + y)",
                                                       frag_x * 65536 + frag_y, e.x * 65536 + e.y, cycle);
          else begin
            if (frag_z != e.z) mismatch(e.triangle, e.x, e.y, "depth z", frag_z, e.z, cycle);
            if (frag_rgb != e.rgb[23:0]) mismatch(e.triangle, e.x, e.y, "colour rgb", frag_rgb, e.rgb, cycle);
            if (cycle != e.cycle) mismatch(e.triangle, e.x, e.y, "accept cycle", cycle, e.cycle, cycle);
          end
        end
        fragments_seen++;
      end
      if (result_valid) begin
        if (results_seen < expected.size()) begin
          fragment_t e = expected[results_seen];
          if (result_pass != e.pass[0]) mismatch(e.triangle, e.x, e.y, "depth test result", result_pass, e.pass, cycle);
        end
        results_seen++;
      end
      cycle++;
      if (cycle == model_cycles) begin
        // The frame is over: every event must have been seen. Then the buffers, word by word.
        if (fragments_seen != expected.size())
          mismatch(-1, -1, -1, "fragments in the frame", fragments_seen, expected.size(), cycle);
        if (results_seen != expected.size())
          mismatch(-1, -1, -1, "depth test results in the frame", results_seen, expected.size(), cycle);
        if (next_triangle != TRIANGLES) mismatch(-1, -1, -1, "triangles accepted", next_triangle, TRIANGLES, cycle);
        reading_back <= 1'b1;
      end
    end
    // Read-back: the words of readback_addr in cycle c are on readback_* in cycle c + 1.
    if (reading_back) begin
      if (readback_pending) begin
        int unsigned depth, rgb;
        int x = int'(readback_previous) % WIDTH, y = int'(readback_previous) / WIDTH;
        void'(rastersim_dpi_read_buffers(model, x, y, depth, rgb));
        if (readback_depth != depth[Z_BITS-1:0]) mismatch(-1, x, y, "depth word after the frame", readback_depth, depth, cycle);
        if (readback_rgb != rgb[23:0]) mismatch(-1, x, y, "colour word after the frame", readback_rgb, rgb, cycle);
        words_checked++;
      end
      readback_previous <= readback_addr;
      readback_pending <= 1'b1;
      if (readback_pending && int'(readback_previous) == WIDTH * HEIGHT - 1) begin
        if (mismatches == 0)
          $display("scoreboard: %0d fragments, %0d cycles and %0d buffer words agree with the model", fragments_seen,
                   model_cycles, words_checked);
        else
          $display("scoreboard: FAILED, %0d mismatches", mismatches);
        failed <= mismatches != 0;
        done <= 1'b1;
      end else if (readback_addr != AB'(WIDTH * HEIGHT - 1)) begin
        readback_addr <= readback_addr + 1'b1;
      end
    end
  end

  final rastersim_destroy(model);
endmodule
