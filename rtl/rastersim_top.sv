// The pipeline with its z-buffer memory on chip: rastersim_core (setup -> walker + Z adder ->
// z-buffer, model/pipeline.cpp) with zbuffer_memory behind its memory port, which never applies
// back-pressure. Same ports as the core, except that the depth clear value goes to the memory and
// the final memories are read through the read-back port instead of a memory port.
// Cycle 0 of a frame is the first cycle with frame_ready high (the memory clear has finished).
// With TEXTURE = 1 the texture memory (texture_memory) sits behind the texture unit's port, loaded
// through the texture_load_* port before the frame.
`include "rastersim_pkg.sv"
`include "rastersim_core_parameters.vh"  // its build parameters
module rastersim_top `RS_IMPORT #(`RASTERSIM_CORE_PARAMETERS) (
  input  wire clk,
  input  wire rst,
  input  `RS_TYPE(depth_func_t) cfg_depth_func,  // rastersim_pkg::DEPTH_*
  input  wire       cfg_depth_write,
  input  wire [Z_BITS-1:0] cfg_depth_clear,
  input  `RS_TYPE(cull_t) cfg_cull,              // rastersim_pkg::CULL_*
  input  wire       cfg_front_face,        // rastersim_pkg::FRONT_*
  input  wire       cfg_traversal,         // rastersim_pkg::TRAVERSAL_*
  input  wire       cfg_shading,           // rastersim_pkg::SHADING_*
  input  wire [rs_ubits32(MAX_MEMORY_LATENCY)-1:0] cfg_memory_latency,  // 1 .. MAX_MEMORY_LATENCY
  input  wire [rs_ubits32(MAX_SETUP_FIFO_DEPTH)-1:0] cfg_setup_fifo_depth,  // record credits, 1 .. MAX
  input  wire [rastersim_pkg::TEXTURE_LATENCY_BITS-1:0] cfg_texture_latency,   // as rastersim_core's (TEXTURE builds)
  input  wire [rastersim_pkg::TEXTURE_LOG2_BITS-1:0] cfg_texture_log2_width,
  input  wire [rastersim_pkg::TEXTURE_LOG2_BITS-1:0] cfg_texture_log2_height,
  input  wire       cfg_texture_bilinear,
  input  wire       cfg_texture_clamp,
  input  wire [rastersim_pkg::DEPTH_BIAS_CONSTANT_BITS-1:0] cfg_depth_bias_constant,  // as rastersim_core's (DEPTH_BIAS builds)
  input  wire [rastersim_pkg::DEPTH_BIAS_SLOPE_BITS-1:0] cfg_depth_bias_slope,
  // Texture load port: texel (column, row), written at the end of the cycle (TEXTURE builds).
  input  wire texture_load_en,
  input  wire [rastersim_pkg::TEXTURE_COORD_BITS-1:0] texture_load_x,
  input  wire [rastersim_pkg::TEXTURE_COORD_BITS-1:0] texture_load_y,
  input  `RS_TYPE(rgb_t) texture_load_rgb,
  // The texture memory refuses read requests in this cycle: a verification hook (the co-simulation
  // drives the profile's stall pattern on it); tie it to 0.
  input  wire texture_refuse,
  output wire frame_ready,
  // Triangle command: snapped vertices, x and y s(COORD_BITS-S).S, z u(depth plane bits), rgb {r, g, b}.
  input  wire cmd_valid,
  output wire cmd_ready,
  input  wire [rs_coord_bits(WIDTH, HEIGHT, SUBPIXEL_BITS)-1:0] cmd_x0, cmd_y0, cmd_x1, cmd_y1, cmd_x2, cmd_y2,
  input  wire [rs_depth_plane_bits(Z_BITS, DEPTH_EXPONENT_BITS)-1:0] cmd_z0, cmd_z1, cmd_z2,
  input  `RS_TYPE(rgb_t) cmd_rgb0, cmd_rgb1, cmd_rgb2,
  input  wire cmd_textured,
  input  `RS_TYPE(texture_vertex_t) cmd_texture0, cmd_texture1, cmd_texture2,  // S, T, Q as rastersim_core's
  // Trace: setup decision (FRONT cycle) and activity.
  output wire trace_setup_decided,
  output `RS_TYPE(status_t) trace_setup_status,    // 0 drawn, 1 degenerate, 2 culled, 3 offscreen, 4 no centre
  output wire trace_setup_busy,
  output wire trace_setup_stall,           // a triangle offered, the unit free, every record credit held
  output wire trace_setup_done,            // a drawn triangle's record is in the setup output register
  output wire trace_walker_load,           // record -> walker handshake
  output wire trace_walker_busy,
  output wire trace_walker_candidate,
  output wire trace_walker_last,
  output wire trace_walker_frag_valid,
  output wire trace_walker_frag_ready,
  output wire trace_texture_busy,
  output wire trace_texture_stall,
  // Trace: the z-buffer's fragment handshake and the depth test result L cycles later.
  output wire trace_frag_valid,
  output wire trace_frag_ready,
  output wire [rs_ubits32(WIDTH - 1)-1:0]  trace_frag_x,
  output wire [rs_ubits32(HEIGHT - 1)-1:0] trace_frag_y,
  output wire [Z_BITS-1:0] trace_frag_z,
  output `RS_TYPE(rgb_t)   trace_frag_rgb,
  output wire trace_result_valid,
  output wire trace_result_pass,
  output wire trace_zbuffer_busy,
  output wire trace_zbuffer_stall,
  // Final memories, read back after the frame.
  input  wire [rs_ubits32(WIDTH * HEIGHT - 1)-1:0] readback_addr,
  output wire [Z_BITS-1:0] readback_depth,
  output `RS_TYPE(rgb_t)   readback_rgb
);
`include "rastersim_widths.vh"

  wire mem_clear_done, mem_rd_valid, mem_rd_ready, mem_wr_depth_en, mem_wr_color_en;
  wire [rs_ubits32(WIDTH * HEIGHT - 1)-1:0] mem_rd_addr, mem_wr_addr;
  wire [Z_BITS-1:0] mem_rd_depth, mem_wr_depth;
  `RS_TYPE(rgb_t) mem_wr_rgb;
  wire tex_rd_valid, tex_rd_ready;
  wire [rastersim_pkg::TEXTURE_BANKS*rastersim_pkg::TEXEL_WORD_BITS-1:0] tex_rd_addr;
  wire [rastersim_pkg::TEXTURE_BANKS*rastersim_pkg::TEXEL_BITS-1:0] tex_rd_texels;

  rastersim_core #(`RASTERSIM_CORE_PARAMETERS_PASSED) core (
    .clk(clk), .rst(rst), .cfg_depth_func(cfg_depth_func), .cfg_depth_write(cfg_depth_write),
    .cfg_cull(cfg_cull), .cfg_front_face(cfg_front_face), .cfg_traversal(cfg_traversal),
    .cfg_shading(cfg_shading), .cfg_memory_latency(cfg_memory_latency),
    .cfg_setup_fifo_depth(cfg_setup_fifo_depth), .cfg_texture_latency(cfg_texture_latency),
    .cfg_texture_log2_width(cfg_texture_log2_width), .cfg_texture_log2_height(cfg_texture_log2_height),
    .cfg_texture_bilinear(cfg_texture_bilinear), .cfg_texture_clamp(cfg_texture_clamp),
    .cfg_depth_bias_constant(cfg_depth_bias_constant), .cfg_depth_bias_slope(cfg_depth_bias_slope), .frame_ready(frame_ready),
    .cmd_valid(cmd_valid), .cmd_ready(cmd_ready),
    .cmd_x0(cmd_x0), .cmd_y0(cmd_y0), .cmd_x1(cmd_x1), .cmd_y1(cmd_y1), .cmd_x2(cmd_x2), .cmd_y2(cmd_y2),
    .cmd_z0(cmd_z0), .cmd_z1(cmd_z1), .cmd_z2(cmd_z2), .cmd_rgb0(cmd_rgb0), .cmd_rgb1(cmd_rgb1), .cmd_rgb2(cmd_rgb2),
    .cmd_textured(cmd_textured), .cmd_texture0(cmd_texture0), .cmd_texture1(cmd_texture1), .cmd_texture2(cmd_texture2),
    .trace_setup_decided(trace_setup_decided), .trace_setup_status(trace_setup_status),
    .trace_setup_busy(trace_setup_busy), .trace_setup_stall(trace_setup_stall),
    .trace_setup_done(trace_setup_done),
    .trace_walker_load(trace_walker_load), .trace_walker_busy(trace_walker_busy),
    .trace_walker_candidate(trace_walker_candidate), .trace_walker_last(trace_walker_last),
    .trace_walker_frag_valid(trace_walker_frag_valid), .trace_walker_frag_ready(trace_walker_frag_ready),
    .trace_texture_busy(trace_texture_busy), .trace_texture_stall(trace_texture_stall),
    .trace_frag_valid(trace_frag_valid), .trace_frag_ready(trace_frag_ready),
    .trace_frag_x(trace_frag_x), .trace_frag_y(trace_frag_y), .trace_frag_z(trace_frag_z),
    .trace_frag_rgb(trace_frag_rgb), .trace_result_valid(trace_result_valid),
    .trace_result_pass(trace_result_pass), .trace_zbuffer_busy(trace_zbuffer_busy),
    .trace_zbuffer_stall(trace_zbuffer_stall),
    .mem_clear_done(mem_clear_done), .mem_rd_valid(mem_rd_valid), .mem_rd_ready(mem_rd_ready),
    .mem_rd_addr(mem_rd_addr), .mem_rd_depth(mem_rd_depth), .mem_wr_depth_en(mem_wr_depth_en),
    .mem_wr_color_en(mem_wr_color_en), .mem_wr_addr(mem_wr_addr), .mem_wr_depth(mem_wr_depth),
    .mem_wr_rgb(mem_wr_rgb), .tex_rd_valid(tex_rd_valid), .tex_rd_ready(tex_rd_ready), .tex_rd_addr(tex_rd_addr),
    .tex_rd_texels(tex_rd_texels));

  generate
    if (TEXTURE != 0) begin : texturing
      texture_memory #(.MAX_TEXTURE_LATENCY(MAX_TEXTURE_LATENCY)) tmem (
        .clk(clk), .rst(rst), .cfg_texture_latency(cfg_texture_latency), .refuse(texture_refuse), .rd_valid(tex_rd_valid),
        .rd_ready(tex_rd_ready), .rd_addr(tex_rd_addr), .rd_texels(tex_rd_texels), .load_en(texture_load_en),
        .load_x(texture_load_x), .load_y(texture_load_y), .load_rgb(texture_load_rgb));
    end else begin : no_texture
      /* verilator lint_off UNUSEDSIGNAL */
      wire unused = ^{tex_rd_valid, tex_rd_addr, texture_load_en, texture_load_x, texture_load_y, texture_load_rgb,
                      texture_refuse};
      /* verilator lint_on UNUSEDSIGNAL */
      assign tex_rd_ready = 1'b0;
      assign tex_rd_texels = {4*24{1'b0}};
    end
  endgenerate

  zbuffer_memory #(.WIDTH(WIDTH), .HEIGHT(HEIGHT), .Z_BITS(Z_BITS), .MAX_MEMORY_LATENCY(MAX_MEMORY_LATENCY)) zmem (
    .clk(clk), .rst(rst), .cfg_depth_clear(cfg_depth_clear), .cfg_memory_latency(cfg_memory_latency),
    .clear_done(mem_clear_done), .rd_valid(mem_rd_valid), .rd_ready(mem_rd_ready), .rd_addr(mem_rd_addr),
    .rd_depth(mem_rd_depth), .wr_depth_en(mem_wr_depth_en), .wr_color_en(mem_wr_color_en),
    .wr_addr(mem_wr_addr), .wr_depth(mem_wr_depth), .wr_rgb(mem_wr_rgb),
    .readback_addr(readback_addr), .readback_depth(readback_depth), .readback_rgb(readback_rgb));
endmodule
