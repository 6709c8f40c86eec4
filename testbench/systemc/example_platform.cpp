// Example: rastersim's SystemC modules in a platform of one's own (docs/systemc.md). The verilated
// core (Vrastersim_sc: rastersim_core at the default profile), the command FIFO and the z-buffer
// memory model (latency 4, back-pressure in about 20 % of the cycles) are wired by signals; a host
// thread resets the platform and writes two overlapping triangles into the FIFO; a counter measures
// the frame. The final buffers and the cycle count are checked against the C++ model, which
// predicts them exactly. Built and run by ctest (systemc.platform_example); exit 0 when they agree.
#include <systemc>

#include <cstdio>
#include <vector>

#include "Vrastersim_sc.h"
#include "Vrastersim_sc_rastersim_core.h"
#include "model/pipeline.h"
#include "testbench/systemc/command_fifo.h"
#include "testbench/systemc/zbuffer_memory_model.h"

using namespace sc_core;
using rastersim::SnappedTriangle;

// Resets the platform, then writes the triangles into the command FIFO (blocking when it is full).
SC_MODULE(Host) {
  sc_in<bool> clk;
  sc_out<bool> rst;
  sc_port<sc_fifo_out_if<SnappedTriangle>> commands;
  std::vector<SnappedTriangle> triangles;

  SC_CTOR(Host) {
    SC_THREAD(run);
    sensitive << clk.pos();
  }
  void run() {
    rst.write(true);
    for (int i = 0; i < 4; ++i) wait();
    rst.write(false);
    for (const SnappedTriangle& t : triangles) commands->write(t);
  }
};

// Frame cycles as the cycle model counts them: cycle 0 is the first with frame_ready high; the
// frame lasts until the last cycle with a unit busy.
SC_MODULE(FrameCounter) {
  sc_in<bool> clk, frame_ready, setup_busy, walker_busy, zbuffer_busy;
  int64_t cycle = 0, last_busy = -1;

  SC_CTOR(FrameCounter) {
    SC_METHOD(sample);
    sensitive << clk.neg();
    dont_initialize();
  }
  void sample() {
    if (!frame_ready.read()) return;
    if (setup_busy.read() || walker_busy.read() || zbuffer_busy.read()) last_busy = cycle;
    ++cycle;
  }
};

int sc_main(int, char*[]) {
  // The geometry the core was verilated for (the default profile's), other keys as chosen here.
  using Core = Vrastersim_sc_rastersim_core;
  rastersim::Profile profile;
  profile.width = int(Core::P_WIDTH), profile.height = int(Core::P_HEIGHT);
  profile.subpixel_bits = int(Core::P_SUBPIXEL_BITS), profile.z_bits = int(Core::P_Z_BITS);
  profile.memory_latency = 4;
  profile.memory_stall_percent = 20;
  profile.memory_stall_seed = 7;
  // Two Gouraud triangles that cross in depth, in screen fractions.
  const double w = profile.width, h = profile.height;
  const rastersim::ScreenTriangle screen[2] = {
      {{{0.15 * w, 0.1 * h, 0.2, {255, 0, 0}}, {0.45 * w, 0.85 * h, 0.8, {0, 255, 0}}, {0.8 * w, 0.25 * h, 0.5, {0, 0, 255}}}},
      {{{0.2 * w, 0.8 * h, 0.9, {255, 255, 0}}, {0.8 * w, 0.6 * h, 0.1, {0, 255, 255}}, {0.4 * w, 0.1 * h, 0.4, {255, 0, 255}}}}};

  sc_clock clk("clk", 10, SC_NS);
  sc_signal<bool> rst, frame_ready, cmd_valid, cmd_ready;
  sc_signal<uint32_t> cfg_depth_func, cfg_cull, cfg_memory_latency, cfg_setup_fifo_depth;
  sc_signal<bool> cfg_depth_write, cfg_front_face, cfg_traversal, cfg_shading;
  sc_signal<uint32_t> cmd[12];
  sc_signal<bool> setup_decided, setup_busy, setup_stall, setup_done, walker_load, walker_busy, walker_candidate, walker_last;
  sc_signal<bool> frag_valid, frag_ready, result_valid, result_pass, zbuffer_busy, zbuffer_stall;
  sc_signal<uint32_t> setup_status, frag_x, frag_y, frag_z, frag_rgb;
  sc_signal<bool> mem_clear_done, mem_rd_valid, mem_rd_ready, mem_wr_depth_en, mem_wr_color_en;
  sc_signal<uint32_t> mem_rd_addr, mem_rd_depth, mem_wr_addr, mem_wr_depth, mem_wr_rgb;
  // The texture unit's ports: this core is built without one (the FIFO drives the texture command
  // words anyway: zero for untextured triangles; no texture memory model is needed).
  sc_signal<uint32_t> cfg_texture_latency, cfg_texture_log2_width, cfg_texture_log2_height;
  sc_signal<bool> cfg_texture_bilinear, cfg_texture_clamp, cmd_textured, walker_frag_valid, walker_frag_ready;
  sc_signal<bool> texture_busy, texture_stall, tex_rd_valid, tex_rd_ready;
  sc_signal<uint64_t> cfg_depth_bias_constant;  // and without the depth bias
  sc_signal<uint32_t> cfg_depth_bias_slope;
  sc_signal<sc_dt::sc_bv<150>> cmd_texture[3];
  sc_signal<sc_dt::sc_bv<72>> tex_rd_addr;
  sc_signal<sc_dt::sc_bv<96>> tex_rd_texels;

  // The core samples its configuration during reset; the memory takes the same latency.
  cfg_depth_func.write(uint32_t(profile.depth_func));
  cfg_depth_write.write(profile.depth_write);
  cfg_cull.write(uint32_t(profile.cull));
  cfg_front_face.write(profile.front_face == rastersim::FrontFace::CW);
  cfg_traversal.write(profile.traversal == rastersim::Traversal::Span);
  cfg_shading.write(profile.shading == rastersim::Shading::Gouraud);
  cfg_memory_latency.write(uint32_t(profile.memory_latency));
  cfg_setup_fifo_depth.write(uint32_t(profile.setup_fifo_depth));

  Vrastersim_sc core("core");
  core.clk(clk), core.rst(rst);
  core.cfg_depth_func(cfg_depth_func), core.cfg_depth_write(cfg_depth_write), core.cfg_cull(cfg_cull);
  core.cfg_front_face(cfg_front_face), core.cfg_traversal(cfg_traversal), core.cfg_shading(cfg_shading);
  core.cfg_memory_latency(cfg_memory_latency), core.cfg_setup_fifo_depth(cfg_setup_fifo_depth);
  core.frame_ready(frame_ready), core.cmd_valid(cmd_valid), core.cmd_ready(cmd_ready);
  core.cmd_x0(cmd[0]), core.cmd_y0(cmd[1]), core.cmd_x1(cmd[2]), core.cmd_y1(cmd[3]);
  core.cmd_x2(cmd[4]), core.cmd_y2(cmd[5]), core.cmd_z0(cmd[6]), core.cmd_z1(cmd[7]), core.cmd_z2(cmd[8]);
  core.cmd_rgb0(cmd[9]), core.cmd_rgb1(cmd[10]), core.cmd_rgb2(cmd[11]);
  core.trace_setup_decided(setup_decided), core.trace_setup_status(setup_status);
  core.trace_setup_busy(setup_busy), core.trace_setup_stall(setup_stall), core.trace_setup_done(setup_done);
  core.trace_walker_load(walker_load), core.trace_walker_busy(walker_busy);
  core.trace_walker_candidate(walker_candidate), core.trace_walker_last(walker_last);
  core.trace_frag_valid(frag_valid), core.trace_frag_ready(frag_ready);
  core.trace_frag_x(frag_x), core.trace_frag_y(frag_y), core.trace_frag_z(frag_z), core.trace_frag_rgb(frag_rgb);
  core.trace_result_valid(result_valid), core.trace_result_pass(result_pass), core.trace_zbuffer_busy(zbuffer_busy);
  core.trace_zbuffer_stall(zbuffer_stall);
  core.mem_clear_done(mem_clear_done), core.mem_rd_valid(mem_rd_valid), core.mem_rd_ready(mem_rd_ready);
  core.mem_rd_addr(mem_rd_addr), core.mem_rd_depth(mem_rd_depth);
  core.mem_wr_depth_en(mem_wr_depth_en), core.mem_wr_color_en(mem_wr_color_en);
  core.mem_wr_addr(mem_wr_addr), core.mem_wr_depth(mem_wr_depth), core.mem_wr_rgb(mem_wr_rgb);
  core.cfg_texture_latency(cfg_texture_latency), core.cfg_texture_log2_width(cfg_texture_log2_width);
  core.cfg_texture_log2_height(cfg_texture_log2_height), core.cfg_texture_bilinear(cfg_texture_bilinear);
  core.cfg_texture_clamp(cfg_texture_clamp), core.cmd_textured(cmd_textured);
  core.cfg_depth_bias_constant(cfg_depth_bias_constant), core.cfg_depth_bias_slope(cfg_depth_bias_slope);
  core.cmd_texture0(cmd_texture[0]), core.cmd_texture1(cmd_texture[1]), core.cmd_texture2(cmd_texture[2]);
  core.trace_walker_frag_valid(walker_frag_valid), core.trace_walker_frag_ready(walker_frag_ready);
  core.trace_texture_busy(texture_busy), core.trace_texture_stall(texture_stall);
  core.tex_rd_valid(tex_rd_valid), core.tex_rd_ready(tex_rd_ready), core.tex_rd_addr(tex_rd_addr);
  core.tex_rd_texels(tex_rd_texels);

  rastersim::systemc::CommandFifo fifo("fifo", 8, int(Core::COORD_BITS));
  fifo.clk(clk), fifo.rst(rst), fifo.cmd_valid(cmd_valid), fifo.cmd_ready(cmd_ready);
  fifo.cmd_x0(cmd[0]), fifo.cmd_y0(cmd[1]), fifo.cmd_x1(cmd[2]), fifo.cmd_y1(cmd[3]);
  fifo.cmd_x2(cmd[4]), fifo.cmd_y2(cmd[5]), fifo.cmd_z0(cmd[6]), fifo.cmd_z1(cmd[7]), fifo.cmd_z2(cmd[8]);
  fifo.cmd_rgb0(cmd[9]), fifo.cmd_rgb1(cmd[10]), fifo.cmd_rgb2(cmd[11]);
  fifo.cmd_textured(cmd_textured);
  fifo.cmd_texture0(cmd_texture[0]), fifo.cmd_texture1(cmd_texture[1]), fifo.cmd_texture2(cmd_texture[2]);

  rastersim::systemc::ZBufferMemoryModel memory("memory", profile);
  memory.clk(clk), memory.rst(rst), memory.clear_done(mem_clear_done);
  memory.rd_valid(mem_rd_valid), memory.rd_ready(mem_rd_ready), memory.rd_addr(mem_rd_addr);
  memory.rd_depth(mem_rd_depth);
  memory.wr_depth_en(mem_wr_depth_en), memory.wr_color_en(mem_wr_color_en), memory.wr_addr(mem_wr_addr);
  memory.wr_depth(mem_wr_depth), memory.wr_rgb(mem_wr_rgb);

  Host host("host");
  host.clk(clk), host.rst(rst), host.commands(fifo.in);
  for (const rastersim::ScreenTriangle& t : screen) host.triangles.push_back(rastersim::snap(t, profile));
  FrameCounter counter("counter");
  counter.clk(clk), counter.frame_ready(frame_ready);
  counter.setup_busy(setup_busy), counter.walker_busy(walker_busy), counter.zbuffer_busy(zbuffer_busy);

  sc_start(2, SC_MS);  // 200000 cycles: far more than the frame needs

  // The C++ model predicts the same frame: buffers and cycles.
  rastersim::Pipeline model(profile);
  for (const SnappedTriangle& t : host.triangles) model.submit(t);
  const int64_t predicted = model.stats().cycles, measured = counter.last_busy + 1;
  const bool same = model.zbuffer().depth() == memory.memory().depth() &&
                    model.zbuffer().color() == memory.memory().color();
  std::printf("frame: %lld cycles (model: %lld), %lld reads refused by the memory, buffers %s the model's\n",
              static_cast<long long>(measured), static_cast<long long>(predicted),
              static_cast<long long>(memory.refused_reads()), same ? "equal" : "DIFFER FROM");
  return same && measured == predicted && fifo.taken() == 2 ? 0 : 1;
}
