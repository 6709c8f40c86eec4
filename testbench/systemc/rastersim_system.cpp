#include "testbench/systemc/rastersim_system.h"

#include <stdexcept>
#include <string>

#include "Vrastersim_sc___024root.h"
#include "Vrastersim_sc_rastersim_core.h"
#include "testbench/built_parameters.h"
#include "model/widths.h"
#include "testbench/assertions.h"

namespace rastersim::systemc {

using Core = Vrastersim_sc_rastersim_core;

namespace {
constexpr int kResetCycles = 4;
const sc_core::sc_time kPeriod(10, sc_core::SC_NS);
}  // namespace

Profile RastersimSystem::built_geometry() {
  Profile p;
  p.width = int(Core::P_WIDTH);
  p.height = int(Core::P_HEIGHT);
  p.subpixel_bits = int(Core::P_SUBPIXEL_BITS);
  p.z_bits = int(Core::P_Z_BITS);
  p.z_guard_bits = int(Core::P_Z_GUARD_BITS);
  p.depth_exponent_bits = int(Core::P_DEPTH_EXPONENT_BITS);
  return p;
}

int RastersimSystem::max_memory_latency() { return int(Core::P_MAX_MEMORY_LATENCY); }

CoreParameters RastersimSystem::built_parameters() { return parameters_of<Core>(); }

std::string RastersimSystem::built_configuration() { return core_parameters_text(built_parameters()); }

std::string RastersimSystem::geometry_error(const Profile& p) {
  if (const std::string mismatch = core_mismatch(built_parameters(), p); !mismatch.empty())
    return "the SystemC backend is built for the core " + built_configuration() + " only: " + mismatch +
           " (RASTERSIM_SYSTEMC_CONFIG in testbench/systemc/CMakeLists.txt names the configuration it is built for; "
           "rastersim verilates others on demand)";
  return "";
}

std::string RastersimSystem::configuration_error(const Profile& p) { return geometry_error(p); }

RastersimSystem::RastersimSystem(sc_core::sc_module_name name, int fifo_depth)
    : sc_core::sc_module(name),
      clk_("clk", kPeriod),
      core_("core"),
      fifo_("command_fifo", fifo_depth, int(Core::COORD_BITS)),
      memory_("zbuffer_memory", built_geometry()),
      texture_memory_("texture_memory") {
  core_.clk(clk_);
  core_.rst(rst_);
  core_.cfg_depth_func(cfg_depth_func_);
  core_.cfg_depth_write(cfg_depth_write_);
  core_.cfg_cull(cfg_cull_);
  core_.cfg_front_face(cfg_front_face_);
  core_.cfg_traversal(cfg_traversal_);
  core_.cfg_shading(cfg_shading_);
  core_.cfg_memory_latency(cfg_memory_latency_);
  core_.cfg_setup_fifo_depth(cfg_setup_fifo_depth_);
  core_.frame_ready(frame_ready_);
  core_.cmd_valid(cmd_valid_);
  core_.cmd_ready(cmd_ready_);
  core_.cmd_x0(cmd_x0_), core_.cmd_y0(cmd_y0_), core_.cmd_x1(cmd_x1_), core_.cmd_y1(cmd_y1_);
  core_.cmd_x2(cmd_x2_), core_.cmd_y2(cmd_y2_);
  core_.cmd_z0(cmd_z0_), core_.cmd_z1(cmd_z1_), core_.cmd_z2(cmd_z2_);
  core_.cmd_rgb0(cmd_rgb0_), core_.cmd_rgb1(cmd_rgb1_), core_.cmd_rgb2(cmd_rgb2_);
  core_.trace_setup_decided(trace_setup_decided_);
  core_.trace_setup_status(trace_setup_status_);
  core_.trace_setup_busy(trace_setup_busy_);
  core_.trace_setup_stall(trace_setup_stall_);
  core_.trace_setup_done(trace_setup_done_);
  core_.trace_walker_load(trace_walker_load_);
  core_.trace_walker_busy(trace_walker_busy_);
  core_.trace_walker_candidate(trace_walker_candidate_);
  core_.trace_walker_last(trace_walker_last_);
  core_.trace_frag_valid(trace_frag_valid_);
  core_.trace_frag_ready(trace_frag_ready_);
  core_.trace_frag_x(trace_frag_x_);
  core_.trace_frag_y(trace_frag_y_);
  core_.trace_frag_z(trace_frag_z_);
  core_.trace_frag_rgb(trace_frag_rgb_);
  core_.trace_result_valid(trace_result_valid_);
  core_.trace_result_pass(trace_result_pass_);
  core_.trace_zbuffer_busy(trace_zbuffer_busy_);
  core_.trace_zbuffer_stall(trace_zbuffer_stall_);
  core_.mem_clear_done(mem_clear_done_);
  core_.mem_rd_valid(mem_rd_valid_);
  core_.mem_rd_ready(mem_rd_ready_);
  core_.mem_rd_addr(mem_rd_addr_);
  core_.mem_rd_depth(mem_rd_depth_);
  core_.mem_wr_depth_en(mem_wr_depth_en_);
  core_.mem_wr_color_en(mem_wr_color_en_);
  core_.mem_wr_addr(mem_wr_addr_);
  core_.mem_wr_depth(mem_wr_depth_);
  core_.mem_wr_rgb(mem_wr_rgb_);
  core_.cfg_texture_latency(cfg_texture_latency_);
  core_.cfg_texture_log2_width(cfg_texture_log2_width_);
  core_.cfg_texture_log2_height(cfg_texture_log2_height_);
  core_.cfg_texture_bilinear(cfg_texture_bilinear_);
  core_.cfg_texture_clamp(cfg_texture_clamp_);
  core_.cfg_depth_bias_constant(cfg_depth_bias_constant_), core_.cfg_depth_bias_slope(cfg_depth_bias_slope_);
  core_.cmd_textured(cmd_textured_);
  core_.cmd_texture0(cmd_texture0_), core_.cmd_texture1(cmd_texture1_), core_.cmd_texture2(cmd_texture2_);
  core_.trace_walker_frag_valid(trace_walker_frag_valid_);
  core_.trace_walker_frag_ready(trace_walker_frag_ready_);
  core_.trace_texture_busy(trace_texture_busy_);
  core_.trace_texture_stall(trace_texture_stall_);
  core_.tex_rd_valid(tex_rd_valid_);
  core_.tex_rd_ready(tex_rd_ready_);
  core_.tex_rd_addr(tex_rd_addr_);
  core_.tex_rd_texels(tex_rd_texels_);

  fifo_.clk(clk_);
  fifo_.rst(rst_);
  fifo_.cmd_valid(cmd_valid_);
  fifo_.cmd_ready(cmd_ready_);
  fifo_.cmd_x0(cmd_x0_), fifo_.cmd_y0(cmd_y0_), fifo_.cmd_x1(cmd_x1_), fifo_.cmd_y1(cmd_y1_);
  fifo_.cmd_x2(cmd_x2_), fifo_.cmd_y2(cmd_y2_);
  fifo_.cmd_z0(cmd_z0_), fifo_.cmd_z1(cmd_z1_), fifo_.cmd_z2(cmd_z2_);
  fifo_.cmd_rgb0(cmd_rgb0_), fifo_.cmd_rgb1(cmd_rgb1_), fifo_.cmd_rgb2(cmd_rgb2_);
  fifo_.cmd_textured(cmd_textured_);
  fifo_.cmd_texture0(cmd_texture0_), fifo_.cmd_texture1(cmd_texture1_), fifo_.cmd_texture2(cmd_texture2_);

  memory_.clk(clk_);
  memory_.rst(rst_);
  memory_.clear_done(mem_clear_done_);
  memory_.rd_valid(mem_rd_valid_);
  memory_.rd_ready(mem_rd_ready_);
  memory_.rd_addr(mem_rd_addr_);
  memory_.rd_depth(mem_rd_depth_);
  memory_.wr_depth_en(mem_wr_depth_en_);
  memory_.wr_color_en(mem_wr_color_en_);
  memory_.wr_addr(mem_wr_addr_);
  memory_.wr_depth(mem_wr_depth_);
  memory_.wr_rgb(mem_wr_rgb_);

  texture_memory_.clk(clk_);
  texture_memory_.rst(rst_);
  texture_memory_.rd_valid(tex_rd_valid_);
  texture_memory_.rd_ready(tex_rd_ready_);
  texture_memory_.rd_addr(tex_rd_addr_);
  texture_memory_.rd_texels(tex_rd_texels_);

  SC_THREAD(host);
  sensitive << clk_.posedge_event();
  SC_METHOD(monitor);
  sensitive << clk_.negedge_event();
  dont_initialize();
  SC_METHOD(count);
  sensitive << clk_.posedge_event();
  dont_initialize();
}

void RastersimSystem::count() { ++clock_cycles_; }

void RastersimSystem::host() {
  rst_.write(true);
  for (;;) {
    while (!frame_pending_) wait();
    frame_pending_ = false;
    const Profile& p = profile_;
    cfg_depth_func_.write(uint32_t(p.depth_func));
    cfg_depth_write_.write(p.depth_write);
    cfg_cull_.write(uint32_t(p.cull));
    cfg_front_face_.write(p.front_face == FrontFace::CW);
    cfg_traversal_.write(p.traversal == Traversal::Span);
    cfg_shading_.write(p.shading == Shading::Gouraud);
    cfg_memory_latency_.write(uint32_t(p.memory_latency));
    cfg_setup_fifo_depth_.write(uint32_t(p.setup_fifo_depth));
    cfg_depth_bias_constant_.write(uint64_t(p.depth_bias_constant) & ((uint64_t(1) << 33) - 1));
    cfg_depth_bias_slope_.write(uint32_t(uint8_t(p.depth_bias_slope)));
    // The texture (a core without the texture unit ignores these).
    const Texture* texture = texture_.texture.get();
    cfg_texture_latency_.write(uint32_t(p.texture_unit ? p.texture_latency : 1));
    cfg_texture_log2_width_.write(uint32_t(texture ? texture->log2_width() : 0));
    cfg_texture_log2_height_.write(uint32_t(texture ? texture->log2_height() : 0));
    cfg_texture_bilinear_.write(texture_.filter == TextureFilter::Bilinear);
    cfg_texture_clamp_.write(texture_.wrap == TextureWrap::Clamp);
    rst_.write(true);
    for (int i = 0; i < kResetCycles; ++i) wait();
    // The memory dropped clear_done at the first reset edge; the frame starts when it rises again.
    rst_.write(false);
    observing_ = true;
    for (const SnappedTriangle& t : *triangles_)
      while (!fifo_.in->nb_write(t)) wait();
  }
}

void RastersimSystem::monitor() {
  if (!observing_ || !frame_ready_.read()) return;
  if (cycle_ > bound_) {
    result_->finished = false;
    result_->note = "the RTL did not finish within " + std::to_string(bound_) + " cycles";
    observing_ = false;
    sc_core::sc_pause();
    return;
  }
  if (Verilated::gotError()) {  // an assertion failed in the last cycle (rtl/rastersim_assert.vh)
    result_->finished = false;
    result_->note = rtl::assertion_failure_note(cycle_ - 1);
    result_->assertion_cycle = cycle_ - 1;
    observing_ = false;
    sc_core::sc_pause();
    return;
  }
  const bool gouraud = profile_.shading == Shading::Gouraud;
  const rtl::TraceSample sample = rtl::sample_trace(core_);
  const bool ok = observer_->observe(cycle_, sample, [&] { return rtl::read_setup_record(*core_.rootp->rastersim_core, gouraud); });
  ++cycle_;
  if (!ok || observer_->done()) {
    frame_done_ = ok;
    observing_ = false;
    sc_core::sc_pause();
  }
}

rtl::RtlResult RastersimSystem::run_frame(const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                                          int64_t max_cycles, const TextureBinding& texture) {
  if (stuck_) throw std::runtime_error("the SystemC system did not finish an earlier frame; it needs a new process");
  const std::string error = configuration_error(profile);
  if (!error.empty()) throw std::invalid_argument(error);
  memory_.configure(profile);
  texture_memory_.configure(profile, texture);
  texture_ = texture;
  rtl::RtlResult result;
  profile_ = profile;
  triangles_ = &triangles;
  result_ = &result;
  observer_.emplace(result, triangles.size());
  cycle_ = 0;
  bound_ = max_cycles > 0 ? max_cycles : rtl::default_cycle_bound(profile, triangles, int(Core::SETUP_DRAWN_LATENCY) + 1);
  frame_done_ = false;
  frame_pending_ = true;
  // The host waits up to a clock for the request, resets, and the memory clears in one cycle.
  sc_core::sc_start(kPeriod * double(bound_ + kResetCycles + 8));
  if (!frame_done_) {
    stuck_ = true;
    observing_ = false;
    if (result.finished) {
      result.finished = false;
      result.note = "the RTL did not finish within " + std::to_string(bound_) + " cycles";
    }
  }
  if (!memory_.error().empty()) {
    result.finished = false;
    result.note = "z-buffer memory model: " + memory_.error();
  }
  if (!texture_memory_.error().empty()) {
    result.finished = false;
    result.note = "texture memory model: " + texture_memory_.error();
  }
  observer_->finish();
  result.depth = memory_.memory().depth();
  result.color = memory_.memory().color();
  result_ = nullptr;
  triangles_ = nullptr;
  return result;
}

}  // namespace rastersim::systemc
