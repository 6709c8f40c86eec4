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

// Bits [lo, lo + width) of a verilated signal, sign-extended when `is_signed`.
inline int64_t field_bits(uint64_t value, int lo, int width, bool is_signed) {
  uint64_t v = (value >> lo) & (width >= 64 ? ~uint64_t(0) : (uint64_t(1) << width) - 1);
  if (is_signed && width < 64 && (v >> (width - 1)) & 1) v |= ~uint64_t(0) << width;
  return int64_t(v);
}
template <std::size_t N>
int64_t field_bits(const VlWide<N>& value, int lo, int width, bool is_signed) {
  uint64_t v = 0;
  for (int i = 0; i < width; ++i) {
    const int bit = lo + i;
    v |= uint64_t((value[bit / 32] >> (bit % 32)) & 1u) << i;
  }
  return field_bits(v, 0, width, is_signed);
}

// The setup record on the setup -> walker wires (rastersim_top rec_*, public_flat_rd).
template <class V, class Top>
SetupResult read_setup_record(V& top, bool gouraud) {
  const auto& t = *top.rootp->rastersim_top;
  SetupResult r;
  r.status = SetupStatus::Drawn;
  r.x0 = int(t.rec_x0), r.x1 = int(t.rec_x1), r.y0 = int(t.rec_y0), r.y1 = int(t.rec_y1);
  const int eb = Top::EDGE_BITS, sxb = Top::EDGE_STEP_X_BITS, syb = Top::EDGE_STEP_Y_BITS, rb = Top::SPAN_REM_BITS;
  for (int k = 0; k < 3; ++k) {
    EdgeSetup& e = r.edge[k];
    e.start = field_bits(t.rec_edge_start, k * eb, eb, true);
    e.step_x = field_bits(t.rec_edge_step_x, k * sxb, sxb, true);
    e.step_y = field_bits(t.rec_edge_step_y, k * syb, syb, true);
    e.span_quot = field_bits(t.rec_span_quot, k * eb, eb, true);
    e.span_rem = field_bits(t.rec_span_rem, k * rb, rb, false);
    e.span_step_quot = field_bits(t.rec_span_step_quot, k * syb, syb, true);
    e.span_step_rem = field_bits(t.rec_span_step_rem, k * rb, rb, false);
  }
  const int zrb = Top::Z_REG_BITS, crb = Top::COLOR_REG_BITS;
  r.depth.start = field_bits(t.rec_depth_start, 0, zrb, true);
  r.depth.step_x = field_bits(t.rec_depth_step_x, 0, zrb, true);
  r.depth.step_y = field_bits(t.rec_depth_step_y, 0, zrb, true);
  if (gouraud) {
    for (int c = 0; c < 3; ++c) {
      r.color[c].start = field_bits(t.rec_color_start, c * crb, crb, true);
      r.color[c].step_x = field_bits(t.rec_color_step_x, c * crb, crb, true);
      r.color[c].step_y = field_bits(t.rec_color_step_y, c * crb, crb, true);
    }
  }
  const uint32_t flat = t.rec_flat_rgb;
  r.flat_color = Rgb{uint8_t(flat >> 16), uint8_t(flat >> 8), uint8_t(flat)};
  return r;
}

template <class V, class Top>
RtlResult run_verilated(const Profile& p, const std::vector<SnappedTriangle>& tris, const RtlOptions& options) {
  const int coord_bits = Top::COORD_BITS, setup_cycles = Top::SETUP_CYCLES;
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
  out.setups.resize(tris.size());
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
      out.setups[size_t(in_setup)] = read_setup_record<V, Top>(*top, p.shading == Shading::Gouraud);
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
      const bool depth_written = (t.zbuf__DOT__depth_written[a / 64] >> (a % 64)) & 1;
      const bool color_written = (t.zbuf__DOT__color_written[a / 64] >> (a % 64)) & 1;
      out.depth[a] = depth_written ? uint32_t(t.zbuf__DOT__depth_mem[a]) : clear;
      out.color[a] = color_written ? uint32_t(t.zbuf__DOT__color_mem[a]) : 0u;
    }
  }
  if (fst) fst->close();
  top->final();
  return out;
}

}  // namespace rastersim::rtl::detail
