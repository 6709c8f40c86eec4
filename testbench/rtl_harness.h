// Drives one verilated rastersim_top (class V) through a frame and observes its trace ports
// (core_ports.h). Included by the generated per-configuration translation unit
// (rtl_configs.cpp) and the mutant check.
#pragma once

#include <verilated.h>
#include <verilated_fst_c.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <type_traits>

#include "testbench/assertions.h"
#include "testbench/rtl_backend.h"
#include "testbench/core_ports.h"
#include "testbench/frame_config.h"
#include "testbench/waveform.h"
#include "model/zbuffer_memory.h"

namespace rastersim::rtl::detail {

// The verilated class of rastersim_core inside rastersim_top (its name carries the parameters).
template <class V>
using CoreOf = std::remove_pointer_t<decltype(std::declval<V&>().rootp->rastersim_top->core)>;

template <class V>
RtlResult run_verilated(const Profile& p, const std::vector<SnappedTriangle>& tris, const RtlOptions& options) {
  using Core = CoreOf<V>;
  if (p.memory_stall_percent > 0)
    throw std::invalid_argument("rastersim_top's on-chip memory has no back-pressure (memory_stall_percent)");
  if (p.texture_unit != (int(Core::P_TEXTURE) != 0) || p.texture_latency > int(Core::P_MAX_TEXTURE_LATENCY))
    throw std::invalid_argument("the RTL configuration's texture unit differs from the profile's");
  if (depth_plane_bits(p.z_bits, p.depth_exponent_bits) !=
          depth_plane_bits(int(Core::P_Z_BITS), int(Core::P_DEPTH_EXPONENT_BITS)) ||
      (p.depth_exponent_bits >= 2) != (int(Core::P_DEPTH_EXPONENT_BITS) >= 2) ||
      (p.depth_biased() && int(Core::P_DEPTH_BIAS) == 0))
    throw std::invalid_argument("the RTL configuration's depth word or depth bias differs from the profile's");
  if (p.setup_fifo_depth > int(Core::P_MAX_SETUP_FIFO_DEPTH))
    throw std::invalid_argument("setup_fifo_depth " + std::to_string(p.setup_fifo_depth) +
                                " exceeds the RTL's MAX_SETUP_FIFO_DEPTH " + std::to_string(int(Core::P_MAX_SETUP_FIFO_DEPTH)));
  const int coord_bits = Core::COORD_BITS;
  const int setup_cycles = int(Core::SETUP_TEXTURED_DRAWN_LATENCY) + 1;
  auto context = std::make_unique<VerilatedContext>();
  record_assertion_failures(*context);
  context->randReset(2);
  context->randSeed(int(options.seed % 2147483647u) + 1);
  context->traceEverOn(!options.wave_path.empty());
  auto top = std::make_unique<V>(context.get(), "rastersim_top");
  // A VCD is the FST rewritten once the frame is done.
  const std::string fst_path = !options.wave_vcd               ? options.wave_path
                               : options.wave_fst_scratch.empty() ? options.wave_path + ".fst-part"
                                                                  : options.wave_fst_scratch;
  std::unique_ptr<VerilatedFstC> fst;
  if (!options.wave_path.empty()) {
    fst = std::make_unique<VerilatedFstC>();
    top->trace(fst.get(), 99);
    open_waveform(*fst, fst_path);
  }
  const bool windowed = options.wave_from >= 0 || options.wave_to >= 0;
  bool dumping = !windowed;  // reset and the memory clear are in the dump only without a window
  uint64_t time = 0;
  auto half_cycle = [&](int clk) {
    top->clk = clk;
    top->eval();
    if (fst && dumping) fst->dump(time);
    ++time;
  };

  drive_frame_config(*top, p);
  top->cfg_traversal = p.traversal == Traversal::Span;
  top->cfg_memory_latency = uint8_t(p.memory_latency);
  top->cfg_setup_fifo_depth = uint8_t(p.setup_fifo_depth);
  // The texture: its size and sampling, and its texels through the load port during reset (none
  // bound: one white texel, as the model samples then). A build without the texture unit gets
  // constants, whatever the options (its waveform does not depend on them).
  const bool textures = int(Core::P_TEXTURE) != 0;
  const Texture* texture = textures ? options.texture.texture.get() : nullptr;
  top->cfg_texture_latency = uint8_t(textures ? p.texture_latency : 1);
  top->cfg_texture_log2_width = uint8_t(texture ? texture->log2_width() : 0);
  top->cfg_texture_log2_height = uint8_t(texture ? texture->log2_height() : 0);
  top->cfg_texture_bilinear = textures && options.texture.filter == TextureFilter::Bilinear;
  top->cfg_texture_clamp = textures && options.texture.wrap == TextureWrap::Clamp;
  top->texture_load_en = 0, top->texture_load_x = 0, top->texture_load_y = 0, top->texture_load_rgb = 0;
  top->texture_refuse = 0;
  // The depth bias (0 without DEPTH_BIAS: rtl_backend.cpp refuses a biased profile for such a core).
  top->cfg_depth_bias_constant = uint64_t(p.depth_bias_constant) & ((uint64_t(1) << 33) - 1);
  top->cfg_depth_bias_slope = uint8_t(p.depth_bias_slope);
  drive_texture_command(*top, SnappedTriangle{});
  top->cmd_valid = 0;
  top->readback_addr = 0;
  top->rst = 1;
  for (int i = 0; i < 4; ++i) half_cycle(0), half_cycle(1);
  if (textures) {
    const int texture_width = texture ? 1 << texture->log2_width() : 1, texture_height = texture ? 1 << texture->log2_height() : 1;
    top->texture_load_en = 1;
    for (int j = 0; j < texture_height; ++j)
      for (int i = 0; i < texture_width; ++i) {
        top->texture_load_x = uint16_t(i), top->texture_load_y = uint16_t(j);
        top->texture_load_rgb = texture ? texture->texel(i, j) : 0xFFFFFFu;
        half_cycle(0), half_cycle(1);
      }
    top->texture_load_en = 0;
  }
  top->rst = 0;
  // The z-buffer memory clears its written bits (64 words per cycle); the frame starts when it is done.
  const int64_t clear_bound = int64_t(p.width) * p.height + 16;
  for (int64_t i = 0; !top->frame_ready; ++i) {
    if (i > clear_bound) throw std::runtime_error("RTL: the z-buffer clear did not finish");
    half_cycle(0), half_cycle(1);
    if (assertion_failed(*context))
      throw std::runtime_error("RTL: an assertion failed while the z-buffer memory was cleared (the simulator's message names it)");
  }

  RtlResult out;
  TraceObserver observer(out, tris.size());
  const Core& core = *top->rootp->rastersim_top->core;
  const bool gouraud = p.shading == Shading::Gouraud;
  const int64_t bound = options.max_cycles > 0 ? options.max_cycles : default_cycle_bound(p, tris, setup_cycles);
  const int64_t frame_time = int64_t(time);  // frame cycle c: its low phase at frame_time + 2 c, its edge 1 later
  int64_t last_cycle = 0;
  for (int64_t cycle = 0;; ++cycle) {
    last_cycle = cycle;
    if (cycle > bound) {
      out.finished = false;
      out.note = "the RTL did not finish within " + std::to_string(bound) + " cycles";
      break;
    }
    if (windowed) dumping = cycle >= std::max<int64_t>(0, options.wave_from) && (options.wave_to < 0 || cycle <= options.wave_to);
    const size_t next = observer.next_triangle();
    top->cmd_valid = next < tris.size();
    if (next < tris.size()) {
      drive_command(*top, tris[next], coord_bits);
      if (textures) drive_texture_command(*top, tris[next]);  // a bit loop: only where the core uses it
    }
    // The texture memory's back-pressure: the profile's stall pattern (docs/cycle-model.md).
    if (textures) top->texture_refuse = memory_stalls(uint64_t(p.texture_stall_seed), p.texture_stall_percent, cycle);
    half_cycle(0);
    // Observe this cycle's handshakes and decisions (before the rising edge).
    if (!observer.observe(cycle, sample_trace(*top), [&] { return read_setup_record(core, gouraud); })) break;
    half_cycle(1);
    if (assertion_failed(*context)) {
      out.finished = false;
      out.note = assertion_failure_note(cycle);
      out.assertion_cycle = cycle;
      break;
    }
    if (observer.done()) break;
  }
  observer.finish();
  if (windowed) dumping = options.wave_to < 0;

  // The final memories: a word not written since the clear reads as the clear value (depth) or 0.
  const size_t words = size_t(p.width) * size_t(p.height);
  out.depth.resize(words);
  out.color.resize(words);
  top->cmd_valid = 0;
  if (options.readback_through_port) {
    for (size_t a = 0; a < words; ++a) {
      top->readback_addr = uint32_t(a);
      half_cycle(0), half_cycle(1);
      out.depth[a] = uint32_t(top->readback_depth);
      out.color[a] = uint32_t(top->readback_rgb);
    }
  } else {
    const auto& t = *top->rootp->rastersim_top;
    const uint32_t clear = p.depth_clear_value();
    for (size_t a = 0; a < words; ++a) {
      const bool depth_written = (t.zmem__DOT__depth_written[a / 64] >> (a % 64)) & 1;
      const bool color_written = (t.zmem__DOT__color_written[a / 64] >> (a % 64)) & 1;
      out.depth[a] = depth_written ? uint32_t(t.zmem__DOT__depth_mem[a]) : clear;
      out.color[a] = color_written ? uint32_t(t.zmem__DOT__color_mem[a]) : 0u;
    }
  }
  if (fst) {
    fst->close();
    if (!options.gtkwave_save_path.empty()) {
      WaveView view;
      if (windowed) {
        view.start = frame_time + 2 * std::max<int64_t>(0, options.wave_from);
        view.end = frame_time + 2 * (options.wave_to >= 0 ? std::min(options.wave_to, last_cycle) : last_cycle) + 1;
        view.markers = {{"window_start", view.start}, {"window_end", view.end}};
      }
      if (options.wave_marker >= 0) {
        view.primary_marker = frame_time + 2 * options.wave_marker + 1;
        view.markers.emplace_back("mismatch", view.primary_marker);
      }
      write_gtkwave_save(fst_path, options.wave_name.empty() ? options.wave_path : options.wave_name,
                         options.gtkwave_save_path, view);
    }
    if (options.wave_vcd) {
      fst_to_vcd(fst_path, options.wave_path);
      std::remove(fst_path.c_str());
    }
  }
  top->final();
  return out;
}

}  // namespace rastersim::rtl::detail
