// Z-buffer unit: read, compare, conditional write of depth and colour, behind a memory port with a
// read latency of L cycles (profile.memory_latency). A fragment accepted in cycle c reads in c,
// gets its data and writes in c + L; a fragment to the same address may be accepted no earlier
// than c + L + 1 (read-after-write hazard: the unit stalls, docs/cycle-model.md).
#pragma once

#include <cstdint>
#include <vector>

#include "profile.h"
#include "triangle.h"

namespace rastersim {

struct ZBufferCounters {
  int64_t busy = 0;   // cycles with a fragment accepted or in flight
  int64_t stall = 0;  // hazard stall cycles
  int64_t depth_pass = 0;
  int64_t depth_fail = 0;
};

class ZBuffer {
 public:
  explicit ZBuffer(const Profile& profile);

  void clear();
  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<uint32_t>& depth() const { return depth_; }
  const std::vector<uint32_t>& color() const { return color_; }  // 0x00RRGGBB

  // Starts a new triangle: its own fragments never collide, so after L of them no check is needed.
  void begin_triangle() { fresh_ = 0; }

  // Timing: the cycle at which a fragment presented in `cycle` for `address` is accepted.
  int64_t accept(uint32_t address, int64_t cycle) {
    int64_t accepted = cycle;
    if (fresh_ < latency_) {
      for (int k = 0; k < latency_; ++k)
        if (inflight_address_[k] == address && inflight_cycle_[k] + latency_ + 1 > accepted)
          accepted = inflight_cycle_[k] + latency_ + 1;
      ++fresh_;
    }
    counters_.stall += accepted - cycle;
    inflight_address_[slot_] = address;
    inflight_cycle_[slot_] = accepted;
    slot_ = slot_ + 1 == latency_ ? 0 : slot_ + 1;
    const int64_t end = accepted + latency_;
    counters_.busy += end - std::max(accepted, busy_until_ + 1) + 1;
    busy_until_ = end;
    return accepted;
  }

  // Function: depth test and conditional write. Returns the depth test result.
  bool test_and_write(uint32_t address, uint32_t z, Rgb c) {
    const bool pass = depth_test(z, depth_[address]);
    if (pass) {
      if (depth_write_) depth_[address] = z;
      color_[address] = (uint32_t(c.r) << 16) | (uint32_t(c.g) << 8) | c.b;
      ++counters_.depth_pass;
    } else {
      ++counters_.depth_fail;
    }
    return pass;
  }

  bool depth_test(uint32_t z, uint32_t stored) const {
    switch (func_) {
      case DepthFunc::Never: return false;
      case DepthFunc::Less: return z < stored;
      case DepthFunc::Equal: return z == stored;
      case DepthFunc::LEqual: return z <= stored;
      case DepthFunc::Greater: return z > stored;
      case DepthFunc::NotEqual: return z != stored;
      case DepthFunc::GEqual: return z >= stored;
      case DepthFunc::Always: return true;
    }
    return false;
  }

  int64_t last_busy_cycle() const { return busy_until_; }
  const ZBufferCounters& counters() const { return counters_; }

 private:
  int width_, height_;
  DepthFunc func_;
  bool depth_write_;
  uint32_t clear_depth_;
  int latency_;
  std::vector<uint32_t> depth_, color_;
  // The last L accepted fragments (a ring): the only ones that can still be in flight.
  std::vector<uint32_t> inflight_address_;
  std::vector<int64_t> inflight_cycle_;
  int slot_ = 0;
  int fresh_ = 0;
  int64_t busy_until_ = -1;
  ZBufferCounters counters_;
};

}  // namespace rastersim
