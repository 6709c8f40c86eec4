// Drives one verilated rastersim_top (class V) through a frame and observes its trace ports.
// Included only by the generated per-configuration translation unit (rtl_configs.cpp).
#pragma once

#include <verilated.h>
#include <verilated_fst_c.h>

#include <algorithm>
#include <deque>
#include <memory>
#include <stdexcept>

#include "testbench/rtl_backend.h"

namespace rastersim::rtl::detail {

inline uint32_t mask_bits(int64_t value, int bits) {
  return uint32_t(uint64_t(value) & ((uint64_t(1) << bits) - 1));
}

// A bound on the cycles a correct RTL can take: per triangle the setup, plus every candidate of
// its screen-clipped bounding box and its rows, each possibly stalled by the memory latency.
inline int64_t default_cycle_bound(const Profile& p, const std::vector<SnappedTriangle>& tris, int setup_cycles) {
  int64_t bound = 16;
  for (const SnappedTriangle& t : tris) {
    int64_t x_lo = t.v[0].x, x_hi = x_lo, y_lo = t.v[0].y, y_hi = y_lo;
    for (const SnappedVertex& v : t.v) {
      x_lo = std::min<int64_t>(x_lo, v.x), x_hi = std::max<int64_t>(x_hi, v.x);
      y_lo = std::min<int64_t>(y_lo, v.y), y_hi = std::max<int64_t>(y_hi, v.y);
    }
    const int64_t columns = std::min<int64_t>(p.width, ((x_hi - x_lo) >> p.subpixel_bits) + 2);
    const int64_t rows = std::min<int64_t>(p.height, ((y_hi - y_lo) >> p.subpixel_bits) + 2);
    bound += setup_cycles + 4 + (columns + 1) * rows * (p.memory_latency + 2);
  }
  return bound;
}

template <class V>
RtlResult run_verilated(const Profile& p, const std::vector<SnappedTriangle>& tris, const RtlOptions& options,
                        int coord_bits, int setup_cycles) {
  auto context = std::make_unique<VerilatedContext>();
  context->randReset(2);
  context->randSeed(int(options.seed % 2147483647u) + 1);
  context->traceEverOn(!options.fst_path.empty());
  auto top = std::make_unique<V>(context.get(), "rastersim_top");
  std::unique_ptr<VerilatedFstC> fst;
  if (!options.fst_path.empty()) {
    fst = std::make_unique<VerilatedFstC>();
    top->trace(fst.get(), 99);
    fst->open(options.fst_path.c_str());
  }
  uint64_t time = 0;
  auto half_cycle = [&](int clk) {
    top->clk = clk;
    top->eval();
    if (fst) fst->dump(time);
    ++time;
  };

  top->cfg_depth_func = uint8_t(p.depth_func);
  top->cfg_depth_write = p.depth_write;
  top->cfg_depth_clear = p.depth_clear_value();
  top->cfg_cull = uint8_t(p.cull);
  top->cfg_front_face = p.front_face == FrontFace::CW;
  top->cfg_traversal = p.traversal == Traversal::Span;
  top->cfg_shading = p.shading == Shading::Gouraud;
  top->cfg_memory_latency = uint8_t(p.memory_latency);
  top->cmd_valid = 0;
  top->readback_addr = 0;
  top->rst = 1;
  for (int i = 0; i < 4; ++i) half_cycle(0), half_cycle(1);
  top->rst = 0;
  // The z-buffer clears its memories (one word per cycle); the frame starts when it is done.
  const int64_t clear_bound = int64_t(p.width) * p.height + 16;
  for (int64_t i = 0; !top->frame_ready; ++i) {
    if (i > clear_bound) throw std::runtime_error("RTL: the z-buffer clear did not finish");
    half_cycle(0), half_cycle(1);
  }

  RtlResult out;
  out.triangles.reserve(tris.size());
  FrameStats& stats = out.stats;
  const int64_t bound = options.max_cycles > 0 ? options.max_cycles : default_cycle_bound(p, tris, setup_cycles);
  size_t next = 0;             // next triangle to submit
  int64_t in_setup = -1;       // triangle the setup unit holds
  int64_t in_walker = -1;      // triangle the walker walks
  std::deque<size_t> in_flight;  // fragments accepted by the z-buffer, awaiting their result
  int64_t last_busy = -1;
  bool setup_output_seen = false;
  for (int64_t cycle = 0;; ++cycle) {
    if (cycle > bound) {
      out.finished = false;
      out.note = "the RTL did not finish within " + std::to_string(bound) + " cycles";
      break;
    }
    const bool submitting = next < tris.size();
    top->cmd_valid = submitting;
    if (submitting) {
      const SnappedTriangle& t = tris[next];
      auto rgb = [](const Rgb& c) { return (uint32_t(c.r) << 16) | (uint32_t(c.g) << 8) | c.b; };
      top->cmd_x0 = mask_bits(t.v[0].x, coord_bits), top->cmd_y0 = mask_bits(t.v[0].y, coord_bits);
      top->cmd_x1 = mask_bits(t.v[1].x, coord_bits), top->cmd_y1 = mask_bits(t.v[1].y, coord_bits);
      top->cmd_x2 = mask_bits(t.v[2].x, coord_bits), top->cmd_y2 = mask_bits(t.v[2].y, coord_bits);
      top->cmd_z0 = t.v[0].z, top->cmd_z1 = t.v[1].z, top->cmd_z2 = t.v[2].z;
      top->cmd_rgb0 = rgb(t.v[0].color), top->cmd_rgb1 = rgb(t.v[1].color), top->cmd_rgb2 = rgb(t.v[2].color);
    }
    half_cycle(0);

    // Observe this cycle's handshakes and decisions (before the rising edge).
    if (submitting && top->cmd_ready) {
      TriangleRecord r;
      r.index = int64_t(next);
      r.setup_accept = cycle;
      out.triangles.push_back(r);
      in_setup = int64_t(next);
      setup_output_seen = false;
      ++next;
      ++stats.triangles;
    }
    if (top->trace_setup_decided && in_setup >= 0) {
      TriangleRecord& r = out.triangles[size_t(in_setup)];
      r.status = SetupStatus(top->trace_setup_status);
      switch (r.status) {
        case SetupStatus::Drawn: ++stats.triangles_drawn; break;
        case SetupStatus::Degenerate: ++stats.triangles_degenerate, r.setup_done = cycle; break;
        case SetupStatus::Culled: ++stats.triangles_culled, r.setup_done = cycle; break;
        case SetupStatus::Offscreen: ++stats.triangles_offscreen, r.setup_done = cycle; break;
      }
    }
    const bool setup_output_valid = top->trace_setup_stall || top->trace_walker_load;
    if (setup_output_valid && !setup_output_seen && in_setup >= 0) {
      out.triangles[size_t(in_setup)].setup_done = cycle;
      setup_output_seen = true;
    }
    if (top->trace_walker_load && in_setup >= 0) {
      out.triangles[size_t(in_setup)].walker_load = cycle;
      in_walker = in_setup;
    }
    if (top->trace_frag_valid && top->trace_frag_ready) {
      Fragment f;
      f.tri = in_walker;
      f.x = int(top->trace_frag_x);
      f.y = int(top->trace_frag_y);
      f.z = uint32_t(top->trace_frag_z);
      const uint32_t c = top->trace_frag_rgb;
      f.color = Rgb{uint8_t(c >> 16), uint8_t(c >> 8), uint8_t(c)};
      f.pass = false;
      f.cycle = cycle;
      in_flight.push_back(out.fragments.size());
      out.fragments.push_back(f);
      if (in_walker >= 0) ++out.triangles[size_t(in_walker)].fragments;
    }
    if (top->trace_result_valid) {
      if (in_flight.empty()) {
        out.finished = false;
        out.note = "the z-buffer produced a depth-test result in cycle " + std::to_string(cycle) +
                   " with no fragment in flight";
        break;
      }
      Fragment& f = out.fragments[in_flight.front()];
      in_flight.pop_front();
      f.pass = top->trace_result_pass;
      if (f.tri >= 0) {
        TriangleRecord& r = out.triangles[size_t(f.tri)];
        r.depth_pass += f.pass;
        r.last_write = cycle;
      }
      ++(f.pass ? stats.depth_pass : stats.depth_fail);
    }
    if (top->trace_walker_last && in_walker >= 0) out.triangles[size_t(in_walker)].walker_end = cycle;
    if (top->trace_walker_candidate) ++stats.candidates;
    const bool stall = top->trace_frag_valid && !top->trace_frag_ready;
    stats.setup.busy += top->trace_setup_busy && !top->trace_setup_stall;
    stats.setup.stall += top->trace_setup_stall;
    stats.walker.busy += top->trace_walker_busy;
    stats.walker.stall += stall;
    stats.zbuffer.busy += top->trace_zbuffer_busy;
    stats.zbuffer.stall += stall;
    const bool busy = top->trace_setup_busy || top->trace_walker_busy || top->trace_zbuffer_busy;
    if (busy) last_busy = cycle;

    half_cycle(1);
    if (!submitting && !busy && in_flight.empty()) break;
  }
  stats.fragments = stats.depth_pass + stats.depth_fail;
  stats.cycles = last_busy + 1;
  stats.z_adder = stats.walker;

  // Read the final memories back through the synchronous read-back port.
  const size_t words = size_t(p.width) * size_t(p.height);
  out.depth.resize(words);
  out.color.resize(words);
  top->cmd_valid = 0;
  for (size_t a = 0; a < words; ++a) {
    top->readback_addr = uint32_t(a);
    half_cycle(0), half_cycle(1);
    out.depth[a] = uint32_t(top->readback_depth);
    out.color[a] = uint32_t(top->readback_rgb);
  }
  if (fst) fst->close();
  top->final();
  return out;
}

}  // namespace rastersim::rtl::detail
