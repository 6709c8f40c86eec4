// The z-buffer's fast path: runs of fragments at consecutive addresses taken at once, leaving the
// unit's registers, counters and words (ZBufferState) as ZBuffer::take() and test_and_write() one
// fragment at a time would (model/zbuffer.h; tests/test_fast_path.cpp checks it).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

// Relative, as in model/: installed, these headers are reached as <rastersim/fast/...>.
#include "../model/z_adder.h"
#include "../model/zbuffer.h"

namespace rastersim {

class ZBufferRuns {
 public:
  explicit ZBufferRuns(ZBuffer& zbuffer) : z_(zbuffer.state()) {}

  // True when n fragments at consecutive addresses from `address`, offered one per cycle from
  // `cycle`, are each taken in the cycle offered and read in the next: take_run() may be used.
  // That holds when none waits for a read ahead of it, no hazard can hold one (the triangle's
  // first L fragments are checked against the fragments in flight: none of these may have an
  // address of the run), and the memory has no stall pattern (it may refuse any read).
  bool can_take_run(uint32_t address, int64_t n, int64_t cycle) const {
    if (z_.last_read_ > cycle || z_.memory_.has_stalls()) return false;
    if (z_.fresh_ >= z_.latency_) return true;
    for (int k = 0; k < z_.latency_; ++k)
      if (uint64_t(z_.inflight_address_[size_t(k)] - address) < uint64_t(n)) return false;
    return true;
  }

  // Timing of n fragments at consecutive addresses offered in consecutive cycles from `cycle`, when
  // can_take_run(): each is taken in the cycle it is offered and read in the next. The same state
  // and counters as n calls of take(), without the per-fragment bookkeeping.
  void take_run(uint32_t address, int64_t cycle, int64_t n) {
    z_.fresh_ = int(std::min<int64_t>(z_.latency_, z_.fresh_ + n));
    // Taken in cycle .. cycle + n - 1, read in cycle + 1 .. cycle + n.
    const int64_t end = cycle + n + z_.latency_;
    z_.counters_.busy += end - std::max(cycle, z_.busy_until_ + 1) + 1;
    z_.busy_until_ = end;
    z_.read_before_last_ = n >= 2 ? cycle + n - 1 : z_.last_read_;
    z_.last_read_ = cycle + n;
    // Only the last L of them stay in the ring, which is ordered by age from slot_ (and only by
    // that): when all L are new they go to slots 0..L-1, without a modulo.
    const int64_t first = std::max<int64_t>(0, n - z_.latency_);
    int slot = first > 0 ? 0 : z_.slot_;
    for (int64_t i = first; i < n; ++i) {
      z_.inflight_address_[slot] = address + uint32_t(i);
      z_.inflight_cycle_[slot] = cycle + 1 + i;
      slot = slot + 1 == z_.latency_ ? 0 : slot + 1;
    }
    z_.slot_ = slot;
  }

  // test_and_write() of n fragments at consecutive addresses, in order, by a run kernel
  // (fast/run_kernels.h; a function or one the caller inlines); fragment i's depth and colour are
  // the plane registers' outputs i x steps on from `planes`. Returns how many passed.
  template <class Kernel>
  int64_t test_and_write_run(uint32_t address, int64_t n, const ZAdder::Run& planes, Kernel kernel) {
    const int64_t passes = kernel(z_.memory_.depth_words() + address, z_.memory_.color_words() + address, n,
                                  z_.pass_mask_, z_.depth_write_, planes);
    z_.counters_.depth_pass += passes;
    z_.counters_.depth_fail += n - passes;
    return passes;
  }

  // The same for short runs, one fragment at a time (colours only for those that pass);
  // fragment i's values are values.depth_at(i) and values.color_at(i).
  template <class Values>
  int64_t test_and_write_short_run(uint32_t address, int64_t n, const Values& values) {
    uint32_t* const depth = z_.memory_.depth_words() + address;
    uint32_t* const color = z_.memory_.color_words() + address;
    const unsigned mask = z_.pass_mask_;  // locals: the stores below cannot change them
    const bool depth_write = z_.depth_write_;
    int64_t passes = 0;
    for (int64_t i = 0; i < n; ++i) {
      const uint32_t z = values.depth_at(i);
      if (!ZBuffer::depth_test(mask, z, depth[i])) continue;
      if (depth_write) depth[i] = z;
      color[i] = ZBuffer::packed(values.color_at(i));
      ++passes;
    }
    z_.counters_.depth_pass += passes;
    z_.counters_.depth_fail += n - passes;
    return passes;
  }

  // Asks the caches for the words of rows [y, y + rows) and columns [x0, x1] (clipped to the
  // buffer). No effect on results.
  __attribute__((always_inline)) void prefetch_box(int64_t x0, int64_t x1, int64_t y, int rows) const {
    x0 = std::max<int64_t>(x0, 0), x1 = std::min<int64_t>(x1, z_.width_ - 1);
    if (x0 > x1) return;
    for (int64_t r = std::max<int64_t>(y, 0); r < std::min<int64_t>(y + rows, z_.height_); ++r) {
      const size_t at = size_t(r) * size_t(z_.width_) + size_t(x0);
      for (int64_t i = 0; i <= x1 - x0 + 15; i += 16) {
        __builtin_prefetch(z_.memory_.depth().data() + at + i, 1);
        __builtin_prefetch(z_.memory_.color().data() + at + i, 1);
      }
    }
  }

  // Asks the caches for the words `rows` rows below a run of n: the walker most likely gets there
  // soon, and the buffers outgrow the caches (the model's main memory cost). No effect on results.
  // Always inlined: a call to it GCC finds pure (a prefetch has no effect it tracks) and deletes.
  __attribute__((always_inline)) void prefetch_rows_below(uint32_t address, int64_t n, int rows) const {
    const size_t at = size_t(address) + size_t(rows) * size_t(z_.width_);
    if (at + size_t(n) > z_.memory_.depth().size()) return;
    for (int64_t i = 0; i < n + 15; i += 16) {
      __builtin_prefetch(z_.memory_.depth().data() + at + i, 1);
      __builtin_prefetch(z_.memory_.color().data() + at + i, 1);
    }
  }

 private:
  ZBufferState& z_;
};

}  // namespace rastersim
