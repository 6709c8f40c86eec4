// Drives a design through the verification interface (docs/verification.md "The verification
// interface") for one frame and turns what it reports into the records the model produces
// (rtl::RtlResult): its decisions, its retired fragments with their cycles, its final buffers read
// back through rb_addr. V is the verilated class of the design's top.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "verilated.h"
#include "verilated_fst_c.h"

#include "testbench/dut/dut_run.h"
#include "testbench/frame_config.h"

namespace rastersim::dut {

// The command port (cmd_x0 .. cmd_rgb2): one triangle's snapped vertex words, shared by the
// verification interface and the setup unit's.
template <class V>
void drive_command(V& top, const SnappedTriangle& t) {
  top.cmd_x0 = uint32_t(t.v[0].x), top.cmd_y0 = uint32_t(t.v[0].y);
  top.cmd_x1 = uint32_t(t.v[1].x), top.cmd_y1 = uint32_t(t.v[1].y);
  top.cmd_x2 = uint32_t(t.v[2].x), top.cmd_y2 = uint32_t(t.v[2].y);
  top.cmd_z0 = t.v[0].z, top.cmd_z1 = t.v[1].z, top.cmd_z2 = t.v[2].z;
  top.cmd_rgb0 = packed_rgb(t.v[0].color), top.cmd_rgb1 = packed_rgb(t.v[1].color), top.cmd_rgb2 = packed_rgb(t.v[2].color);
}

template <class V>
rtl::RtlResult run(const Profile& p, const std::vector<SnappedTriangle>& tris, const DutRunOptions& options) {
  auto context = std::make_unique<VerilatedContext>();
  context->traceEverOn(!options.wave_path.empty());
  auto top = std::make_unique<V>(context.get(), "dut");
  std::unique_ptr<VerilatedFstC> fst;
  if (!options.wave_path.empty()) {
    fst = std::make_unique<VerilatedFstC>();
    top->trace(fst.get(), 99);
    fst->open(options.wave_path.c_str());
  }
  uint64_t time = 0;
  bool dumping = !options.wave_window;  // a window starts at its first cycle after the first handshake
  auto half_cycle = [&](int clk) {
    top->clk = clk;
    top->eval();
    if (fst && dumping) fst->dump(time);
    ++time;
  };
  drive_frame_config(*top, p);
  top->cmd_valid = 0;
  top->rb_addr = 0;
  top->rst = 1;
  for (int i = 0; i < 4; ++i) half_cycle(0), half_cycle(1);
  top->rst = 0;

  rtl::RtlResult out;
  out.interface_only = true;
  size_t next = 0;
  int64_t idle = 0, last_accept = -1, first_accept = 0;
  for (int64_t cycle = 0;; ++cycle) {
    if (options.wave_window) {
      // Cycles from the first handshake; before it every cycle counts as -1 (in a window from a
      // negative cycle), and the cycle whose ready (as the last edge left it) takes triangle 0 as 0.
      const int64_t relative = next > 0 ? cycle - first_accept : (top->cmd_ready ? 0 : -1);
      dumping = relative >= options.wave_from && relative <= options.wave_to;
    }
    const bool offering = next < tris.size();
    top->cmd_valid = offering;
    if (offering) {
      drive_command(*top, tris[next]);
    }
    half_cycle(0);
    // This cycle's handshakes and retirements, before the rising edge.
    bool progress = false;
    if (offering && top->cmd_ready) {
      if (next == 0) first_accept = cycle;
      ++next;
      last_accept = cycle;
      progress = true;
      ++out.stats.triangles;
    }
    if (top->dec_valid) {
      TriangleRecord r;
      r.index = int64_t(uint32_t(top->dec_index));
      r.status = SetupStatus(top->dec_status);
      r.setup_decided = cycle;
      out.triangles.push_back(r);
      progress = true;
    }
    if (top->frag_valid) {
      Fragment f;
      f.tri = int64_t(uint32_t(top->frag_index));
      f.x = int(top->frag_x), f.y = int(top->frag_y);
      f.z = uint32_t(top->frag_z);
      const uint32_t c = uint32_t(top->frag_rgb);
      f.color = Rgb{uint8_t(c >> 16), uint8_t(c >> 8), uint8_t(c)};
      f.pass = top->frag_pass;
      f.cycle = -1;  // the interface has no take; the retirement is the depth test's cycle
      f.tested = cycle;
      out.fragments.push_back(f);
      ++(f.pass ? out.stats.depth_pass : out.stats.depth_fail);
      progress = true;
    }
    const bool done = next == tris.size() && cycle > last_accept && top->frame_done;
    half_cycle(1);
    if (done) {
      out.stats.cycles = cycle;
      break;
    }
    idle = progress ? 0 : idle + 1;
    if (idle > options.max_idle_cycles) {
      if (fst) fst->close();
      throw std::runtime_error(
          next < tris.size()
              ? "the design stalled: cmd_ready stayed low for " + std::to_string(idle) + " cycles with triangle " +
                    std::to_string(next) + " offered (cycle " + std::to_string(cycle) + ")"
              : "the design stalled: frame_done stayed low for " + std::to_string(idle) +
                    " cycles with no decision or fragment after the last triangle was taken (cycle " +
                    std::to_string(cycle) + ")");
    }
  }
  out.stats.fragments = out.stats.depth_pass + out.stats.depth_fail;
  // Cycles from the first handshake, as docs/cycle-model.md numbers them (the design may spend
  // cycles after reset before it takes a triangle: rastersim's core clears its buffers).
  out.first_handshake = first_accept;
  for (TriangleRecord& r : out.triangles) r.setup_decided -= first_accept;
  for (Fragment& f : out.fragments) f.tested -= first_accept;
  out.stats.cycles -= first_accept;
  // The final buffers, a word a cycle: rb_depth and rb_rgb hold the word of the address of the
  // cycle before.
  const size_t words = size_t(p.width) * size_t(p.height);
  out.depth.resize(words);
  out.color.resize(words);
  top->cmd_valid = 0;
  dumping = !options.wave_window;
  for (size_t a = 0; a < words; ++a) {
    top->rb_addr = uint32_t(a);
    half_cycle(0), half_cycle(1);
    out.depth[a] = uint32_t(top->rb_depth);
    out.color[a] = uint32_t(top->rb_rgb) & 0xffffffu;
  }
  if (fst) fst->close();
  top->final();
  return out;
}

}  // namespace rastersim::dut
