// Z-buffer memory (rtl/zbuffer_memory.sv on chip; any memory on the ports of rtl/rastersim_core.sv):
// the depth and colour words behind the z-buffer's memory port. It reads with latency
// L = profile.memory_latency, takes every write, and may refuse read requests (back-pressure):
// in frame cycle c it is not ready when memory_stalls(seed, percent, c), a seeded, deterministic
// stall pattern (docs/cycle-model.md), so the cycle model predicts its effect exactly. The
// on-chip memory never stalls (memory_stall_percent 0); the model and every memory behind the
// core's port (SystemC, vector packages, --dut designs) apply the pattern. Header-only: the SystemC
// library uses it as is.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "profile.h"

namespace rastersim {

// splitmix64's finalizer of seed * golden ratio + cycle: a pure function of (seed, cycle).
constexpr uint64_t memory_stall_hash(uint64_t seed, uint64_t cycle) {
  uint64_t x = seed * 0x9E3779B97F4A7C15ull + cycle;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// True when the memory refuses read requests in frame cycle `cycle` (cycle 0 = the first cycle
// of the frame): on average `percent` of the cycles.
constexpr bool memory_stalls(uint64_t seed, int percent, int64_t cycle) {
  return percent > 0 && int(memory_stall_hash(seed, uint64_t(cycle)) % 100) < percent;
}

class ZBufferMemory {
 public:
  explicit ZBufferMemory(const Profile& p)
      : clear_depth_(p.depth_clear_value()), latency_(p.memory_latency), stall_seed_(p.memory_stall_seed),
        stall_percent_(p.memory_stall_percent), depth_(size_t(p.width) * p.height),
        color_(size_t(p.width) * p.height) {
    clear();
  }

  // Every word reads as the depth clear value and colour 0.
  void clear() {
    std::fill(depth_.begin(), depth_.end(), clear_depth_);
    std::fill(color_.begin(), color_.end(), 0u);
  }

  int latency() const { return latency_; }
  bool stalls(int64_t cycle) const { return memory_stalls(stall_seed_, stall_percent_, cycle); }
  bool has_stalls() const { return stall_percent_ > 0; }

  uint32_t read_depth(uint32_t address) const { return depth_[address]; }
  void write(uint32_t address, bool depth_enable, uint32_t depth, bool color_enable, uint32_t rgb) {
    if (depth_enable) depth_[address] = depth;
    if (color_enable) color_[address] = rgb;
  }

  // The words themselves, for the z-buffer's tight loop over a run of consecutive addresses.
  uint32_t* depth_words() { return depth_.data(); }
  uint32_t* color_words() { return color_.data(); }

  const std::vector<uint32_t>& depth() const { return depth_; }
  const std::vector<uint32_t>& color() const { return color_; }  // 0x00RRGGBB

 private:
  uint32_t clear_depth_;
  int latency_;
  uint64_t stall_seed_;
  int stall_percent_;
  std::vector<uint32_t> depth_, color_;
};

}  // namespace rastersim
