// Drives a design through the verification interface (docs/verification.md "The verification
// interface") for one frame and turns what it reports into the records the model produces
// (rtl::RtlResult): its decisions, its retired fragments with their cycles, its final buffers (read
// back through rb_addr, or the harness's own memory behind the design's memory port). V is the
// verilated class of the design's top.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "verilated.h"
#include "verilated_fst_c.h"

#include "model/zbuffer_memory.h"
#include "testbench/assertions.h"
#include "testbench/dut/dut_run.h"
#include "testbench/frame_config.h"
#include "testbench/waveform.h"

namespace rastersim::dut {

// Whether the design's top has the memory port (mem_*; then the harness's memory serves it and
// there is no read-back) or keeps its buffers and has the read-back port (rb_*).
template <class V, class = void>
struct HasMemoryPort : std::false_type {};
template <class V>
struct HasMemoryPort<V, std::void_t<decltype(std::declval<V&>().mem_rd_valid)>> : std::true_type {};

// The memory behind a design's memory port (docs/verification.md "The memory port"): the model's
// z-buffer memory (clear words, latency L and refusal pattern from the profile). A read taken in
// cycle c returns the word as it was before that cycle's writes, on mem_rd_depth in cycle c + L;
// writes land at the end of their cycle.
class HarnessMemory {
 public:
  explicit HarnessMemory(const Profile& p)
      : memory_(p), words_(uint64_t(p.width) * uint64_t(p.height)), due_(size_t(memory_.latency()) + 1) {}

  // The inputs of cycle `cycle` (0 = the first after reset), before the design settles.
  template <class V>
  void drive(V& top, int64_t cycle) {
    Due& due = due_[size_t(cycle) % due_.size()];
    top.mem_clear_done = 1;
    top.mem_rd_ready = !memory_.stalls(cycle);
    top.mem_rd_depth = due.cycle == cycle ? due.depth : 0u;
  }

  // The requests of cycle `cycle`, from the settled outputs: a read taken, then the writes.
  template <class V>
  void take(V& top, int64_t cycle) {
    if (top.mem_rd_valid && top.mem_rd_ready) {
      const uint32_t address = checked(uint32_t(top.mem_rd_addr), "read", cycle);
      due_[size_t(cycle + memory_.latency()) % due_.size()] = Due{cycle + memory_.latency(), memory_.read_depth(address)};
    }
    if (top.mem_wr_depth_en || top.mem_wr_color_en)
      memory_.write(checked(uint32_t(top.mem_wr_addr), "write", cycle), top.mem_wr_depth_en, uint32_t(top.mem_wr_depth),
                    top.mem_wr_color_en, uint32_t(top.mem_wr_rgb) & 0xffffffu);
  }

  const ZBufferMemory& words() const { return memory_; }

 private:
  struct Due {
    int64_t cycle = -1;
    uint32_t depth = 0;
  };
  uint32_t checked(uint32_t address, const char* what, int64_t cycle) const {
    if (address >= words_)
      throw std::runtime_error("the design's memory " + std::string(what) + " in cycle " + std::to_string(cycle) +
                               " addresses word " + std::to_string(address) + ", outside the " +
                               std::to_string(words_) + " words of the buffers");
    return address;
  }
  ZBufferMemory memory_;
  uint64_t words_;
  std::vector<Due> due_;  // the read returning in each of the next L + 1 cycles
};

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
  rtl::record_assertion_failures(*context);
  context->traceEverOn(!options.wave_path.empty());
  auto top = std::make_unique<V>(context.get(), "dut");
  std::unique_ptr<VerilatedFstC> fst;
  if (!options.wave_path.empty()) {
    fst = std::make_unique<VerilatedFstC>();
    top->trace(fst.get(), 99);
    rtl::open_waveform(*fst, options.wave_path);
  }
  uint64_t time = 0;
  bool dumping = !options.wave_window;  // a window starts at its first cycle after the first handshake
  auto half_cycle = [&](int clk) {
    top->clk = clk;
    top->eval();
    if (fst && dumping) fst->dump(time);
    ++time;
  };
  constexpr bool memory_port = HasMemoryPort<V>::value;
  std::unique_ptr<HarnessMemory> memory;
  drive_frame_config(*top, p);
  top->cmd_valid = 0;
  if constexpr (memory_port) {
    memory = std::make_unique<HarnessMemory>(p);
    top->mem_clear_done = 0, top->mem_rd_ready = 0, top->mem_rd_depth = 0;
  } else {
    if (p.memory_stall_percent > 0)
      throw std::runtime_error("memory_stall_percent " + std::to_string(p.memory_stall_percent) +
                               ": the design has no memory port (it keeps its buffers), so nothing refuses its reads");
    top->rb_addr = 0;
  }
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
    if constexpr (memory_port) memory->drive(*top, cycle);
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
    if constexpr (memory_port) memory->take(*top, cycle);
    const bool done = next == tris.size() && cycle > last_accept && top->frame_done;
    half_cycle(1);
    if (rtl::assertion_failed(*context)) {
      if (fst) fst->close();
      throw std::runtime_error("the design: " + rtl::assertion_failure_note(cycle - first_accept) +
                               ", counted from the first command handshake");
    }
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
  if constexpr (memory_port) {
    out.depth = memory->words().depth();
    out.color = memory->words().color();
  } else {
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
  }
  if (fst) fst->close();
  top->final();
  return out;
}

}  // namespace rastersim::dut
