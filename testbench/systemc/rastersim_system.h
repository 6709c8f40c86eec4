// The SystemC system model (docs/systemc.md): rastersim_core verilated with --sc at one profile's
// geometry (Vrastersim_sc), fed by the command FIFO, with the z-buffer memory model (latency and
// stall pattern) behind its memory port, the texture memory model (latency and stall pattern)
// behind its texture port (a core with the texture unit), a clock, a reset, and a monitor that turns the core's trace
// ports into the model's records (testbench/core_ports.h, as the plain verilated harness does).
// SystemC elaborates once per process: build one RastersimSystem and call run_frame() for every
// frame; each frame resets the system and takes its own runtime settings (depth test, culling,
// traversal, shading, memory latency, stall patterns, depth bias, texture and its sampling).
#pragma once

#include <systemc>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "Vrastersim_sc.h"
#include "model/core_parameters.h"
#include "model/profile.h"
#include "model/triangle.h"
#include "testbench/core_ports.h"
#include "testbench/rtl_backend.h"
#include "testbench/systemc/command_fifo.h"
#include "testbench/systemc/texture_memory_model.h"
#include "testbench/systemc/zbuffer_memory_model.h"

namespace rastersim::systemc {

class RastersimSystem : public sc_core::sc_module {
 public:
  SC_HAS_PROCESS(RastersimSystem);
  // fifo_depth: command FIFO entries.
  RastersimSystem(sc_core::sc_module_name name, int fifo_depth = 16);

  // The profile keys the verilated core was built for (width, height, subpixel_bits, z_bits,
  // z_guard_bits) and its largest memory latency.
  static Profile built_geometry();
  static int max_memory_latency();
  static CoreParameters built_parameters();  // the core's, as verilated
  static std::string built_configuration();  // "WIDTH=640 HEIGHT=480 ..."
  // Empty when run_frame can take `profile` (already valid: see validate()), else why not.
  static std::string configuration_error(const Profile& profile);
  // The part of configuration_error that a core verilated for other parameters would not have:
  // geometry, memory latency, setup_interval, texture unit, depth word and bias.
  static std::string geometry_error(const Profile& profile);

  // Runs one frame: reset, the triangles through the FIFO, until the pipeline is idle (or
  // max_cycles, 0 = a bound from the triangles). With the texture unit its memory holds
  // `texture`. Call between simulations, not from a process.
  rtl::RtlResult run_frame(const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                           int64_t max_cycles = 0, const TextureBinding& texture = {});

  int64_t simulated_cycles() const { return clock_cycles_; }  // every clock so far, resets included

 private:
  void host();     // thread: configuration, reset, triangles into the FIFO
  void monitor();  // falling edge: one cycle of trace ports into the scoreboard
  void count();    // rising edge: clock_cycles_

  sc_core::sc_clock clk_;
  sc_core::sc_signal<bool> rst_;
  // Core configuration (sampled during reset).
  sc_core::sc_signal<uint32_t> cfg_depth_func_, cfg_cull_, cfg_memory_latency_, cfg_setup_fifo_depth_;
  sc_core::sc_signal<bool> cfg_depth_write_, cfg_front_face_, cfg_traversal_, cfg_shading_;
  // Command port.
  sc_core::sc_signal<bool> frame_ready_, cmd_valid_, cmd_ready_;
  sc_core::sc_signal<uint32_t> cmd_x0_, cmd_y0_, cmd_x1_, cmd_y1_, cmd_x2_, cmd_y2_;
  sc_core::sc_signal<uint32_t> cmd_z0_, cmd_z1_, cmd_z2_, cmd_rgb0_, cmd_rgb1_, cmd_rgb2_;
  // Trace ports.
  sc_core::sc_signal<bool> trace_setup_decided_, trace_setup_busy_, trace_setup_stall_, trace_setup_done_;
  sc_core::sc_signal<uint32_t> trace_setup_status_;
  sc_core::sc_signal<bool> trace_walker_load_, trace_walker_busy_, trace_walker_candidate_, trace_walker_last_;
  sc_core::sc_signal<bool> trace_frag_valid_, trace_frag_ready_, trace_result_valid_, trace_result_pass_;
  sc_core::sc_signal<bool> trace_zbuffer_busy_, trace_zbuffer_stall_;
  sc_core::sc_signal<uint32_t> trace_frag_x_, trace_frag_y_, trace_frag_z_, trace_frag_rgb_;
  // Memory port.
  sc_core::sc_signal<bool> mem_clear_done_, mem_rd_valid_, mem_rd_ready_, mem_wr_depth_en_, mem_wr_color_en_;
  sc_core::sc_signal<uint32_t> mem_rd_addr_, mem_rd_depth_, mem_wr_addr_, mem_wr_depth_, mem_wr_rgb_;
  // The texture unit's ports (a core without one leaves them unused).
  sc_core::sc_signal<uint32_t> cfg_texture_latency_, cfg_texture_log2_width_, cfg_texture_log2_height_;
  sc_core::sc_signal<bool> cfg_texture_bilinear_, cfg_texture_clamp_, cmd_textured_;
  sc_core::sc_signal<uint64_t> cfg_depth_bias_constant_;  // the profile's (unused by a core without DEPTH_BIAS)
  sc_core::sc_signal<uint32_t> cfg_depth_bias_slope_;
  sc_core::sc_signal<sc_dt::sc_bv<150>> cmd_texture0_, cmd_texture1_, cmd_texture2_;
  sc_core::sc_signal<bool> trace_walker_frag_valid_, trace_walker_frag_ready_, trace_texture_busy_, trace_texture_stall_;
  sc_core::sc_signal<bool> tex_rd_valid_, tex_rd_ready_;
  sc_core::sc_signal<sc_dt::sc_bv<72>> tex_rd_addr_;
  sc_core::sc_signal<sc_dt::sc_bv<96>> tex_rd_texels_;

  Vrastersim_sc core_;
  CommandFifo fifo_;
  ZBufferMemoryModel memory_;
  TextureMemoryModel texture_memory_;

  // The frame being run.
  Profile profile_;
  TextureBinding texture_;
  const std::vector<SnappedTriangle>* triangles_ = nullptr;
  rtl::RtlResult* result_ = nullptr;
  std::optional<rtl::TraceObserver> observer_;
  bool frame_pending_ = false;  // run_frame asked the host for a frame
  bool observing_ = false;      // the monitor observes from the first cycle with frame_ready
  bool frame_done_ = false;
  bool stuck_ = false;          // a frame did not finish: the host may be blocked in it
  int64_t cycle_ = 0, bound_ = 0, clock_cycles_ = 0;
};

}  // namespace rastersim::systemc
