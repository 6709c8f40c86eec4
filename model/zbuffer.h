// Z-buffer unit: read, compare, conditional write of depth and colour, through a memory port with
// a read latency of L cycles (profile.memory_latency) to the z-buffer memory (zbuffer_memory.h).
// The walker's fragments enter a two-entry input buffer (taken in cycle t while fewer than two are
// held) and issue their reads in order from its head, at the earliest in t + 1; a fragment read in
// r gets its data and writes in r + L; a fragment to the same address may be read no earlier than
// r + L + 1 (read-after-write hazard), and none is read in a cycle in which the memory refuses reads
// (its stall pattern) (docs/cycle-model.md, "Z-buffer").
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "fast/run_kernels.h"
#include "profile.h"
#include "triangle.h"
#include "z_adder.h"
#include "zbuffer_memory.h"

namespace rastersim {

struct ZBufferCounters {
  int64_t busy = 0;   // cycles with a fragment taken, held in the input buffer or in flight
  int64_t stall = 0;  // cycles the buffer's head waited: hazards and memory back-pressure
  int64_t depth_pass = 0;
  int64_t depth_fail = 0;
};

class ZBuffer {
 public:
  // The comparator gives one of three relations; the depth function's mask says which of them pass.
  static constexpr unsigned kLess = 1, kEqual = 2, kGreater = 4;

  explicit ZBuffer(const Profile& profile);

  void clear();
  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<uint32_t>& depth() const { return memory_.depth(); }
  const std::vector<uint32_t>& color() const { return memory_.color(); }  // 0x00RRGGBB

  // Starts a new triangle whose fragments are offered in cycle `first` or later: its own fragments
  // never collide, so after L of them no check is needed; none at all when every fragment in flight
  // has been written before `first` (a hazard needs one read by its write cycle, busy_until_).
  void begin_triangle(int64_t first) { fresh_ = first > busy_until_ ? latency_ : 0; }
  // True once fragments offered one per cycle from `cycle` on are each taken in the cycle offered
  // and read in the next until the next triangle: take_run() may be used. Never with a stall
  // pattern: the memory may refuse any read.
  bool settled(int64_t cycle) const { return fresh_ >= latency_ && last_read_ <= cycle && !memory_.has_stalls(); }

  // Timing: the cycle in which a fragment offered in `cycle` for `address` is taken into the input
  // buffer (the walker moves on then): once the fragment two ahead has been read. Its own read goes
  // out from the buffer's head a cycle later at the earliest and after the fragment ahead's, once no
  // hazard holds (once free, an address stays free), in a cycle in which the memory takes it.
  int64_t take(uint32_t address, int64_t cycle) {
    const int64_t taken = std::max(cycle, read_before_last_ + 1);
    const int64_t earliest = std::max(taken, last_read_) + 1;
    int64_t read = earliest;
    if (fresh_ < latency_) {
      for (int k = 0; k < latency_; ++k)
        if (inflight_address_[k] == address && inflight_cycle_[k] + latency_ + 1 > read)
          read = inflight_cycle_[k] + latency_ + 1;
      ++fresh_;
    }
    if (memory_.has_stalls())
      while (memory_.stalls(read)) ++read;
    counters_.stall += read - earliest;
    inflight_address_[slot_] = address;
    inflight_cycle_[slot_] = read;
    slot_ = slot_ + 1 == latency_ ? 0 : slot_ + 1;
    const int64_t end = read + latency_;
    counters_.busy += end - std::max(taken, busy_until_ + 1) + 1;
    busy_until_ = end;
    read_before_last_ = last_read_;
    last_read_ = read;
    return taken;
  }

  // Timing of n fragments at consecutive addresses offered in consecutive cycles from `cycle`, when
  // settled(cycle): each is taken in the cycle it is offered and read in the next. The same state
  // and counters as n calls of take(), without the per-fragment bookkeeping.
  void take_run(uint32_t address, int64_t cycle, int64_t n) {
    // Taken in cycle .. cycle + n - 1, read in cycle + 1 .. cycle + n.
    const int64_t end = cycle + n + latency_;
    counters_.busy += end - std::max(cycle, busy_until_ + 1) + 1;
    busy_until_ = end;
    read_before_last_ = n >= 2 ? cycle + n - 1 : last_read_;
    last_read_ = cycle + n;
    // Only the last L of them stay in the ring, which is ordered by age from slot_ (and only by
    // that): when all L are new they go to slots 0..L-1, without a modulo.
    const int64_t first = std::max<int64_t>(0, n - latency_);
    int slot = first > 0 ? 0 : slot_;
    for (int64_t i = first; i < n; ++i) {
      inflight_address_[slot] = address + uint32_t(i);
      inflight_cycle_[slot] = cycle + 1 + i;
      slot = slot + 1 == latency_ ? 0 : slot + 1;
    }
    slot_ = slot;
  }

  // Function: depth test and conditional write. Returns the depth test result.
  bool test_and_write(uint32_t address, uint32_t z, Rgb c) {
    const bool pass = depth_test(pass_mask_, z, memory_.read_depth(address));
    if (pass) {
      memory_.write(address, depth_write_, z, true, packed(c));
      ++counters_.depth_pass;
    } else {
      ++counters_.depth_fail;
    }
    return pass;
  }

  // test_and_write() of n fragments at consecutive addresses, in order; fragment i's depth and
  // colour are the plane registers' outputs i x steps on from `planes`. Returns how many passed.
  // Vectorized: for runs of at least short_run_limit() fragments. The version is the one selected
  // (select_run_kernel) when the unit was constructed.
  int64_t test_and_write_run(uint32_t address, int64_t n, const ZAdder::Run& planes) {
    const int64_t passes = run_kernel_(memory_.depth_words() + address, memory_.color_words() + address, n,
                                       pass_mask_, depth_write_, planes);
    counters_.depth_pass += passes;
    counters_.depth_fail += n - passes;
    return passes;
  }
  int64_t short_run_limit() const { return short_run_limit_; }
  // The same with a kernel the caller names (inlined into the caller), for example the selected
  // one's inline form (fast/zbuffer_avx512.h) when selected_run_kernel() names it.
  template <class Kernel>
  int64_t test_and_write_run(uint32_t address, int64_t n, const ZAdder::Run& planes, Kernel kernel) {
    const int64_t passes = kernel(memory_.depth_words() + address, memory_.color_words() + address, n, pass_mask_,
                                  depth_write_, planes);
    counters_.depth_pass += passes;
    counters_.depth_fail += n - passes;
    return passes;
  }
  const std::string& selected_run_kernel() const { return run_kernel_name_; }

  // The same for short runs, one fragment at a time (colours only for those that pass);
  // fragment i's values are values.depth_at(i) and values.color_at(i).
  template <class Values>
  int64_t test_and_write_short_run(uint32_t address, int64_t n, const Values& values) {
    uint32_t* const depth = memory_.depth_words() + address;
    uint32_t* const color = memory_.color_words() + address;
    const unsigned mask = pass_mask_;  // locals: the stores below cannot change them
    const bool depth_write = depth_write_;
    int64_t passes = 0;
    for (int64_t i = 0; i < n; ++i) {
      const uint32_t z = values.depth_at(i);
      if (!depth_test(mask, z, depth[i])) continue;
      if (depth_write) depth[i] = z;
      color[i] = packed(values.color_at(i));
      ++passes;
    }
    counters_.depth_pass += passes;
    counters_.depth_fail += n - passes;
    return passes;
  }

  // Asks the caches for the words `rows` rows below a run of n: the walker most likely gets there
  // soon, and the buffers outgrow the caches (the model's main memory cost). No effect on results.
  void prefetch_rows_below(uint32_t address, int64_t n, int rows) const {
    const size_t at = size_t(address) + size_t(rows) * size_t(width_);
    if (at + size_t(n) > memory_.depth().size()) return;
    for (int64_t i = 0; i < n + 15; i += 16) {
      __builtin_prefetch(memory_.depth().data() + at + i, 1);
      __builtin_prefetch(memory_.color().data() + at + i, 1);
    }
  }

  bool depth_test(uint32_t z, uint32_t stored) const { return depth_test(pass_mask_, z, stored); }

  int64_t last_busy_cycle() const { return busy_until_; }
  int64_t last_read() const { return last_read_; }  // read cycle of the fragment take() last took
  const ZBufferCounters& counters() const { return counters_; }

 private:
  int width_, height_;
  static bool depth_test(unsigned pass_mask, uint32_t z, uint32_t stored) {
    const unsigned relation = z < stored ? kLess : (z == stored ? kEqual : kGreater);
    return (pass_mask & relation) != 0;
  }
  static uint32_t packed(Rgb c) { return (uint32_t(c.r) << 16) | (uint32_t(c.g) << 8) | c.b; }
  static constexpr unsigned pass_mask(DepthFunc func) {
    switch (func) {
      case DepthFunc::Never: return 0;
      case DepthFunc::Less: return kLess;
      case DepthFunc::Equal: return kEqual;
      case DepthFunc::LEqual: return kLess | kEqual;
      case DepthFunc::Greater: return kGreater;
      case DepthFunc::NotEqual: return kLess | kGreater;
      case DepthFunc::GEqual: return kGreater | kEqual;
      case DepthFunc::Always: return kLess | kEqual | kGreater;
    }
    return 0;
  }

  unsigned pass_mask_;
  bool depth_write_;
  int latency_;
  RunKernel run_kernel_;
  std::string run_kernel_name_;
  int64_t short_run_limit_;
  ZBufferMemory memory_;
  // The last L fragments read (a ring): the only ones that can still be in flight.
  std::vector<uint32_t> inflight_address_;
  std::vector<int64_t> inflight_cycle_;  // their read cycles
  int slot_ = 0;
  int fresh_ = 0;
  int64_t busy_until_ = -1;
  int64_t last_read_ = -2;         // read cycle of the last fragment taken
  int64_t read_before_last_ = -2;  // and of the one before it
  ZBufferCounters counters_;
};

}  // namespace rastersim
