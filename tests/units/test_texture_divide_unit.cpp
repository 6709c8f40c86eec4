// Unit test: the verilated texture_divide alone against the model's divide
// (model/texture_divide.h). Fragments enter one per cycle with random gaps; each must come
// out exactly 29 rising edges later (docs/cycle-model.md, "Texture unit") with the model's u and
// v. The operands cover the registers' range at covered pixels (|S|, |T| up to 2^(P+Ft+8), Q from
// 2^(P+Ft-14) to 2^(P+Ft)) and the cases that decide: quotients at the clamp, one below and above
// it, negative exact quotients (floor without a remainder), zero.
#include <gtest/gtest.h>

#include <deque>
#include <random>

#include "model/texture_divide.h"
#include "model/widths.h"
#include "testbench/units/unit_harness.h"
#include "unit_configs.h"

namespace rastersim::units {
namespace {

struct Operands {
  int64_t s, t, q;
};

constexpr int kStages = 29;

template <class V>
void check_divide_unit(int width, int height, uint64_t seed, int64_t count) {
  const Widths w = derive_widths(width, height, 4, 24, 0);
  const int reg_bits = w.texture_reg_bits, scale = kTextureFractionBits + w.texture_guard_bits;
  std::mt19937_64 rng(seed);
  auto uniform = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
  // A coordinate's register for a quotient near `target` (in s8.20 units) with divisor q.
  auto near_quotient = [&](int64_t target, int64_t q) {
    const i128 s = (i128(target) * q) >> kUvFracBits;
    return int64_t(s) + uniform(-2, 2);
  };
  auto operands = [&]() {
    const int64_t q_max = int64_t(1) << scale, q_min = q_max >> kMaxTextureWRatioLog2;
    Operands o;
    o.q = uniform(0, 3) == 0 ? (uniform(0, 1) ? q_max : q_min) : uniform(q_min, q_max);
    const int64_t s_max = (int64_t(1) << (scale + 8)) - 1;
    auto coordinate = [&]() -> int64_t {
      switch (uniform(0, 5)) {
        case 0: return uniform(-s_max, s_max);
        case 1: return near_quotient(uniform(0, 1) ? (int64_t(1) << 27) : -(int64_t(1) << 27), o.q);  // the clamp
        case 2: return -o.q * uniform(1, 127) >> uniform(0, 20);  // negative, often exact
        case 3: return 0;
        default: return near_quotient(uniform(-(int64_t(1) << 27), (int64_t(1) << 27) - 1), o.q);
      }
    };
    o.s = coordinate();
    o.t = coordinate();
    return o;
  };
  const uint64_t mask = reg_bits == 64 ? ~uint64_t(0) : (uint64_t(1) << reg_bits) - 1;

  Unit<V> unit(seed);
  unit->rst = 1;  // one cycle clears every valid bit
  unit.tick();
  unit->rst = 0;
  std::deque<std::pair<int64_t, Operands>> in_flight;  // (cycle it must come out, operands)
  int64_t sent = 0, received = 0;
  for (int64_t cycle = 0; received < count; ++cycle) {
    unit.settle();
    // Outputs of this cycle: the fragment presented 29 cycles ago, if any.
    const bool expect = !in_flight.empty() && in_flight.front().first == cycle;
    ASSERT_EQ(bool(unit->out_valid), expect) << "cycle " << cycle;
    if (expect) {
      const Operands o = in_flight.front().second;
      in_flight.pop_front();
      const TextureCoordinate want = perspective_divide(o.s, o.t, o.q, w.texture_divide_shift);
      const int32_t u = int32_t(uint32_t(unit->out_u) << 4) >> 4, v = int32_t(uint32_t(unit->out_v) << 4) >> 4;
      ASSERT_EQ(u, want.u) << "s " << o.s << " q " << o.q;
      ASSERT_EQ(v, want.v) << "t " << o.t << " q " << o.q;
      ++received;
    }
    const bool present = sent < count && uniform(0, 7) != 0;
    unit->in_valid = present;
    if (present) {
      const Operands o = operands();
      unit->in_s = uint64_t(o.s) & mask;
      unit->in_t = uint64_t(o.t) & mask;
      unit->in_q = uint64_t(o.q) & mask;
      in_flight.push_back({cycle + kStages, o});
      ++sent;
    } else {
      // Noise on the operands of an idle cycle: nothing may come of it.
      unit->in_s = rng() & mask, unit->in_t = rng() & mask, unit->in_q = rng() & mask;
    }
    unit.tick();
  }
}

#define RASTERSIM_DIVIDE_TEST(name, V, width, height, count) \
  TEST(TextureDivideUnit, name) { check_divide_unit<V>(width, height, 20261127, unit_count(count)); }
RASTERSIM_DIVIDE_UNITS(RASTERSIM_DIVIDE_TEST)

}  // namespace
}  // namespace rastersim::units
