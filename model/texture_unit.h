// Texture unit: between the walker and the z-buffer when the profile has one (texture_unit). Every
// fragment passes through it in order: the perspective divide (model/texture_divide.h), the
// sampler's texel addresses, the texture memory read (textured fragments), the blend and the
// modulation (model/texture_sampler.h), an output buffer the z-buffer takes from. Its cycles are
// docs/cycle-model.md, "Texture unit"; this class computes them, the pipeline the colours.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "profile.h"
#include "texture_sampler.h"
#include "zbuffer_memory.h"

namespace rastersim {

// What the unit samples: one texture for the frame, its filter and wrap mode. No texture: every
// texel white, so a textured fragment keeps its Gouraud colour.
struct TextureBinding {
  std::shared_ptr<const Texture> texture;
  TextureFilter filter = TextureFilter::Nearest;
  TextureWrap wrap = TextureWrap::Repeat;
};

struct TextureUnitCounters {
  int64_t busy = 0;   // cycles holding a fragment: the union of [take, z-buffer take]
  int64_t stall = 0;  // cycles a read waited for the texture memory
};

class TextureUnit {
 public:
  static constexpr int kDivideCycles = 29;   // take t -> u, v in the divider's output register (end of t + 29)
  static constexpr int kAddressStages = 3;   // the address registers at the end of t + 32
  static constexpr int kReadAfterTake = kDivideCycles + kAddressStages + 1;  // reads from t + 33
  static constexpr int kFilterStages = 6;    // texels in s + Lt; the modulated colour at the end of s + Lt + 5
  static constexpr int kOfferAfterData = kFilterStages;  // offered from s + Lt + 6
  // From take to offer without waiting, and the capacity that lets one fragment per clock through.
  static constexpr int latency(int texture_latency) { return kReadAfterTake + texture_latency + kOfferAfterData; }
  static constexpr int capacity(int texture_latency) { return latency(texture_latency) + 1; }

  explicit TextureUnit(const Profile& p)
      : latency_(p.texture_latency), stall_seed_(uint64_t(p.texture_stall_seed)),
        stall_percent_(p.texture_stall_percent), left_(size_t(capacity(p.texture_latency)), -1) {}

  void reset() {
    std::fill(left_.begin(), left_.end(), -1);
    count_ = 0, last_read_ = -1, busy_until_ = -1, counters_ = {};
  }

  // Fragment i offered by the walker in `offered`: the cycle the unit takes it (it holds fewer than
  // C fragments at the cycle's start: the one C ahead has left) and the cycle it offers it to the
  // z-buffer. `textured` fragments read the texture memory, in the first cycle it takes the read.
  struct Passage {
    int64_t taken, offered;
  };
  Passage pass(int64_t offered, bool textured) {
    const int64_t taken = std::max(offered, left_[size_t(count_ % int64_t(left_.size()))] + 1);
    const int64_t earliest = std::max(taken + kReadAfterTake, last_read_ + 1);
    int64_t read = earliest;
    if (textured)
      while (memory_stalls(stall_seed_, stall_percent_, read)) ++read;
    counters_.stall += read - earliest;
    last_read_ = read;
    taken_ = taken;
    return {taken, read + latency_ + kOfferAfterData};
  }
  // The cycle the z-buffer took the fragment pass() last handled.
  void left(int64_t cycle) {
    left_[size_t(count_++ % int64_t(left_.size()))] = cycle;
    counters_.busy += std::max<int64_t>(0, cycle - std::max(taken_ - 1, busy_until_));
    busy_until_ = std::max(busy_until_, cycle);
  }

  int64_t last_busy_cycle() const { return busy_until_; }
  const TextureUnitCounters& counters() const { return counters_; }

 private:
  int latency_;
  uint64_t stall_seed_;
  int stall_percent_;
  std::vector<int64_t> left_;  // ring: the z-buffer take of the last C fragments
  int64_t count_ = 0;          // fragments so far
  int64_t last_read_ = -1;     // read (or place in the read order) of the previous fragment
  int64_t taken_ = 0;
  int64_t busy_until_ = -1;
  TextureUnitCounters counters_;
};

}  // namespace rastersim
