// Drives one unit through its unit-level interface (docs/verification.md "Checking one unit:
// cosim --unit") for one frame and collects what it reports (UnitResult). V is the verilated class
// of the unit's top; only the function of the unit the library is built for is instantiated.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "verilated.h"
#include "verilated_fst_c.h"

#include "model/zbuffer_memory.h"
#include "testbench/dut/dut_harness.h"
#include "testbench/dut/unit_records.h"

namespace rastersim::dut {

// A verilated unit with a clock, an optional FST and the stall watch. A cycle: set the inputs,
// half_cycle(0), read the cycle's outputs, half_cycle(1).
template <class V>
class UnitSim {
 public:
  explicit UnitSim(const DutRunOptions& options) : options_(options), context_(std::make_unique<VerilatedContext>()) {
    rtl::record_assertion_failures(*context_);
    context_->traceEverOn(!options.wave_path.empty());
    top_ = std::make_unique<V>(context_.get(), "dut");
    if (!options.wave_path.empty()) {
      fst_ = std::make_unique<VerilatedFstC>();
      top_->trace(fst_.get(), 99);
      rtl::open_waveform(*fst_, options.wave_path);
    }
  }
  ~UnitSim() {
    if (fst_) fst_->close();
    top_->final();
  }
  V& operator*() { return *top_; }
  V* operator->() { return top_.get(); }
  // Cycle `cycle` begins: with a window, the FST holds only the window's cycles (and no reset).
  void begin(int64_t cycle) {
    cycle_ = cycle;
    dumping_ = !options_.wave_window || (cycle >= options_.wave_from && cycle <= options_.wave_to);
  }
  void half_cycle(int clk) {
    top_->clk = clk;
    top_->eval();
    if (fst_ && dumping_) fst_->dump(time_);
    ++time_;
    if (rtl::assertion_failed(*context_)) throw std::runtime_error("the unit: " + rtl::assertion_failure_note(cycle_));
  }
  // rst high for 4 cycles; the frame's cycle 0 is the next.
  void reset() {
    top_->rst = 1;
    for (int i = 0; i < 4; ++i) half_cycle(0), half_cycle(1);
    top_->rst = 0;
  }
  // Counts cycles without progress; past the limit, throws "the unit stalled: PORT stayed low for
  // N cycles WHILE".
  void watch(bool progress, int64_t cycle, const std::string& port, const std::string& while_) {
    idle_ = progress ? 0 : idle_ + 1;
    if (idle_ > options_.max_idle_cycles)
      throw std::runtime_error("the unit stalled: " + port + " stayed low for " + std::to_string(idle_) + " cycles " +
                               while_ + " (cycle " + std::to_string(cycle) + ")");
  }

 private:
  DutRunOptions options_;
  std::unique_ptr<VerilatedContext> context_;
  std::unique_ptr<V> top_;
  std::unique_ptr<VerilatedFstC> fst_;
  uint64_t time_ = 0;  // half cycles: cycle k's rising edge at 2 k + 9
  bool dumping_ = !options_.wave_window;
  int64_t cycle_ = -1;  // the cycle begun last
  int64_t idle_ = 0;
};

template <class Port>
void put_words(Port& port, const std::vector<uint32_t>& words) {
  if constexpr (std::is_integral_v<Port>) {
    uint64_t v = 0;
    for (size_t i = 0; i < words.size() && i < 2; ++i) v |= uint64_t(words[i]) << (32 * i);
    port = Port(v);
  } else {
    for (size_t i = 0; i < words.size(); ++i) port[i] = words[i];
  }
}

// The setup unit: triangles on the command port; decisions and drawn triangles' records out.
template <class V>
UnitResult run_setup(const UnitFrame& f, const DutRunOptions& options) {
  UnitSim<V> sim(options);
  sim->cfg_cull = uint8_t(f.profile.cull);
  sim->cfg_front_face = f.profile.front_face == FrontFace::CW;
  sim->cmd_valid = 0;
  sim.reset();
  if (int(sizeof(sim->rec) / 4) != (unit_record_bits() + 31) / 32)
    throw std::runtime_error("the unit's rec port is not setup_record_t (" + std::to_string(unit_record_bits()) +
                             " bits)");
  UnitResult out;
  size_t next = 0;
  int64_t last_accept = -1;
  for (int64_t cycle = 0;; ++cycle) {
    sim.begin(cycle);
    const bool offering = next < f.triangles.size();
    sim->cmd_valid = offering;
    if (offering) drive_command(*sim, f.triangles[next]);
    sim.half_cycle(0);
    bool progress = false;
    if (offering && sim->cmd_ready) ++next, last_accept = cycle, progress = true;
    if (sim->dec_valid) {
      out.decisions.push_back(SetupStatus(sim->dec_status));
      out.decision_cycles.push_back(cycle);
      progress = true;
    }
    if (sim->rec_valid) {
      out.records.push_back(unpack_unit_record(sim->rec.data()));
      out.record_cycles.push_back(cycle);
      progress = true;
    }
    const bool done = next == f.triangles.size() && cycle > last_accept && sim->frame_done;
    sim.half_cycle(1);
    if (done) {
      out.cycles = cycle;
      return out;
    }
    sim.watch(progress, cycle, offering ? "cmd_ready" : "frame_done",
              offering ? "with triangle " + std::to_string(next) + " offered"
                       : "with no decision or record after the last triangle was taken");
  }
}

// The walker: drawn triangles' records in; fragments out, frag_ready low in a seeded pattern.
template <class V>
UnitResult run_walker(const UnitFrame& f, const std::vector<std::vector<uint32_t>>& aux, const DutRunOptions& options) {
  UnitSim<V> sim(options);
  sim->cfg_shading = f.profile.shading == Shading::Gouraud;
  sim->rec_valid = 0;
  sim->frag_ready = 0;
  sim.reset();
  if (int(sizeof(sim->rec) / 4) != (unit_record_bits() + 31) / 32)
    throw std::runtime_error("the unit's rec port is not setup_record_t (" + std::to_string(unit_record_bits()) +
                             " bits)");
  std::vector<std::vector<uint32_t>> packed;
  for (const SetupResult& r : f.records) packed.push_back(pack_unit_record(r));
  UnitResult out;
  size_t next = 0;
  int64_t last_accept = -1;
  for (int64_t cycle = 0;; ++cycle) {
    sim.begin(cycle);
    const bool offering = next < f.records.size();
    sim->rec_valid = offering;
    if (offering) {
      sim->rec_index = uint32_t(f.record_index[next]);
      put_words(sim->rec, packed[next]);
      put_words(sim->rec_aux, aux[next]);
    }
    sim->frag_ready = !memory_stalls(f.seed, kWalkerReadyLowPercent, cycle);
    sim.half_cycle(0);
    bool progress = false;
    if (offering && sim->rec_ready) ++next, last_accept = cycle, progress = true;
    if (sim->frag_valid && sim->frag_ready) {
      Fragment fr{};
      fr.tri = int64_t(uint32_t(sim->frag_index));
      fr.x = int(sim->frag_x), fr.y = int(sim->frag_y);
      fr.z = uint32_t(sim->frag_z);
      const uint32_t c = uint32_t(sim->frag_rgb);
      fr.color = Rgb{uint8_t(c >> 16), uint8_t(c >> 8), uint8_t(c)};
      fr.cycle = cycle;
      out.fragments.push_back(fr);
      progress = true;
    }
    const bool done = next == f.records.size() && cycle > last_accept && sim->frame_done;
    sim.half_cycle(1);
    if (done) {
      out.cycles = cycle;
      return out;
    }
    sim.watch(progress, cycle, offering ? "rec_ready" : "frame_done",
              offering ? "with the record of triangle " + std::to_string(f.record_index[next]) + " offered"
                       : "with no fragment after the last record was taken");
  }
}

// The z-buffer: fragments in, in order; a depth-test result per fragment out; then the final
// buffers through the read-back port.
template <class V>
UnitResult run_zbuffer(const UnitFrame& f, const DutRunOptions& options) {
  UnitSim<V> sim(options);
  sim->cfg_depth_func = uint8_t(f.profile.depth_func);
  sim->cfg_depth_write = f.profile.depth_write;
  sim->cfg_depth_clear = f.profile.depth_clear_value();
  sim->frag_valid = 0;
  sim->rb_addr = 0;
  sim.reset();
  UnitResult out;
  size_t next = 0;
  int64_t last_accept = -1;
  for (int64_t cycle = 0;; ++cycle) {
    sim.begin(cycle);
    const bool offering = next < f.fragments.size();
    sim->frag_valid = offering;
    if (offering) {
      const Fragment& fr = f.fragments[next];
      sim->frag_x = uint32_t(fr.x), sim->frag_y = uint32_t(fr.y);
      sim->frag_z = fr.z;
      sim->frag_rgb = packed_rgb(fr.color);
    }
    sim.half_cycle(0);
    bool progress = false;
    if (offering && sim->frag_ready) ++next, last_accept = cycle, progress = true;
    if (sim->res_valid) {
      out.results.push_back(sim->res_pass != 0);
      out.result_cycles.push_back(cycle);
      progress = true;
    }
    const bool done = next == f.fragments.size() && cycle > last_accept && sim->frame_done;
    sim.half_cycle(1);
    if (done) {
      out.cycles = cycle;
      break;
    }
    sim.watch(progress, cycle, offering ? "frag_ready" : "frame_done",
              offering ? "with fragment " + std::to_string(next) + " offered"
                       : "with no result after the last fragment was taken");
  }
  // As the verification interface reads them: the word of the address of the cycle before.
  const size_t words = size_t(f.profile.width) * size_t(f.profile.height);
  out.depth.resize(words);
  out.color.resize(words);
  sim->frag_valid = 0;
  for (size_t a = 0; a < words; ++a) {
    sim.begin(out.cycles + 1 + int64_t(a));
    sim->rb_addr = uint32_t(a);
    sim.half_cycle(0), sim.half_cycle(1);
    out.depth[a] = uint32_t(sim->rb_depth);
    out.color[a] = uint32_t(sim->rb_rgb) & 0xffffffu;
  }
  return out;
}

}  // namespace rastersim::dut
