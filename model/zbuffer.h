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
#include <vector>

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

// The unit's registers and memory words. ZBuffer is the specification over them; the fast paths
// beside the model (fast/zbuffer_runs.h) take many fragments at once and must leave them as ZBuffer
// would one fragment at a time.
struct ZBufferState {
  ZBufferState(const Profile& p, unsigned pass_mask)
      : width_(p.width), height_(p.height), pass_mask_(pass_mask), depth_write_(p.depth_write),
        latency_(p.memory_latency), memory_(p), inflight_address_(size_t(p.memory_latency)),
        inflight_cycle_(size_t(p.memory_latency)) {}

  int width_, height_;
  unsigned pass_mask_;
  bool depth_write_;
  int latency_;
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

class ZBuffer : private ZBufferState {
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

  bool depth_test(uint32_t z, uint32_t stored) const { return depth_test(pass_mask_, z, stored); }
  static bool depth_test(unsigned pass_mask, uint32_t z, uint32_t stored) {
    const unsigned relation = z < stored ? kLess : (z == stored ? kEqual : kGreater);
    return (pass_mask & relation) != 0;
  }
  static uint32_t packed(Rgb c) { return (uint32_t(c.r) << 16) | (uint32_t(c.g) << 8) | c.b; }

  int64_t last_busy_cycle() const { return busy_until_; }
  int64_t last_read() const { return last_read_; }  // read cycle of the fragment take() last took
  const ZBufferCounters& counters() const { return counters_; }
  // The registers and words, for the fast paths (fast/zbuffer_runs.h).
  ZBufferState& state() { return *this; }

 private:
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
};

}  // namespace rastersim
