// Unit tests: the verilated texture sampler stages alone against the model's sampler
// (model/texture_sampler.h), at the texture unit's stage counts (model/texture_unit.h, docs/
// cycle-model.md "Texture unit"). texture_address: every texture size, filter and wrap mode (held
// for a batch of lookups, as the frame holds them) on random coordinates over the whole s8.20
// range and around every texel edge and centre of small textures, a lookup presented every clock,
// the columns, rows and weights three rising edges later. texture_filter: random texels, weights
// and shades, and every weight pair at the ends, the blend and modulation six rising edges later;
// the modulation alone on all 65,536 texel and shade pairs.
#include <gtest/gtest.h>

#include <deque>
#include <random>

#include "model/texture_sampler.h"
#include "model/texture_unit.h"
#include "testbench/units/unit_harness.h"
#include "unit_configs.h"

namespace rastersim::units {
namespace {

struct AddressCase {
  int32_t u, v;
  int lw, lh;
  bool bilinear, clamp;
};

TEST(TextureSamplerUnit, AddressStageEqualsTheModel) {
  std::mt19937_64 rng(20261127);
  auto uniform = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
  Unit<Vtexture_address> unit(7);
  const int32_t lo = -(int32_t(1) << (kUvBits - 1)), hi = (int32_t(1) << (kUvBits - 1)) - 1;
  auto coordinate = [&](int log2_size) -> int32_t {
    if (uniform(0, 2) == 0) return int32_t(uniform(lo, hi));
    // Near a texel edge or centre within three repeats either side, off by up to 2 in 2^-20.
    const int64_t texel = int64_t(1) << (kUvFracBits - log2_size), halves = int64_t(6) << log2_size;
    return int32_t(uniform(-halves, halves) * (texel / 2) + uniform(-2, 2));
  };
  constexpr int kStages = TextureUnit::kAddressStages;
  int64_t checked = 0;
  for (int batch = 0; batch < 600; ++batch) {
    // One configuration for the batch: the unit registers what it derives from it first.
    const int lw = int(uniform(0, kMaxTextureLog2)), lh = int(uniform(0, kMaxTextureLog2));
    const bool bilinear = uniform(0, 1) != 0, clamp = uniform(0, 1) != 0;
    unit->cfg_log2_width = uint8_t(lw), unit->cfg_log2_height = uint8_t(lh);
    unit->cfg_bilinear = bilinear, unit->cfg_clamp = clamp;
    unit.tick();
    std::deque<AddressCase> pending;  // presented, not yet out
    constexpr int kLookups = 500;
    for (int n = 0; n < kLookups + kStages; ++n) {
      unit.settle();
      if (!pending.empty() && (int(pending.size()) == kStages || n >= kLookups)) {  // then the last ones out
        const AddressCase c = pending.front();
        pending.pop_front();
        const TextureFilter filter = c.bilinear ? TextureFilter::Bilinear : TextureFilter::Nearest;
        const TextureWrap wrap = c.clamp ? TextureWrap::Clamp : TextureWrap::Repeat;
        const AxisTexels x = axis_texels(c.u, c.lw, filter, wrap), y = axis_texels(c.v, c.lh, filter, wrap);
        const std::string where = "u " + std::to_string(c.u) + " v " + std::to_string(c.v) + " sizes 2^" +
                                  std::to_string(c.lw) + " 2^" + std::to_string(c.lh) +
                                  (c.bilinear ? " bilinear" : " nearest") + (c.clamp ? " clamp" : " repeat");
        ASSERT_EQ(int(unit->x0_q), x.first) << where;
        ASSERT_EQ(int(unit->x1_q), x.second) << where;
        ASSERT_EQ(int(unit->wx_q), x.weight) << where;
        ASSERT_EQ(int(unit->y0_q), y.first) << where;
        ASSERT_EQ(int(unit->y1_q), y.second) << where;
        ASSERT_EQ(int(unit->wy_q), y.weight) << where;
        ++checked;
      }
      if (n < kLookups) {
        AddressCase c{coordinate(lw), coordinate(lh), lw, lh, bilinear, clamp};
        unit->u = uint32_t(c.u) & 0xFFFFFFFu;
        unit->v = uint32_t(c.v) & 0xFFFFFFFu;
        pending.push_back(c);
      }
      unit.tick();
    }
  }
  EXPECT_EQ(checked, 300000);
}

struct FilterCase {
  uint32_t texel[4];
  int wx, wy;
  uint32_t shade;
};

Rgb unpack(uint32_t rgb) { return Rgb{uint8_t(rgb >> 16), uint8_t(rgb >> 8), uint8_t(rgb)}; }

TEST(TextureSamplerUnit, FilterStagesEqualTheModel) {
  std::mt19937_64 rng(20261128);
  auto uniform = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
  Unit<Vtexture_filter> unit(8);
  std::deque<FilterCase> pending;  // presented, not yet out
  auto weight = [&]() { return int(uniform(0, 3) == 0 ? (uniform(0, 1) ? 0 : 255) : uniform(0, 255)); };
  int64_t checked = 0;
  for (int n = 0; n < 200000 + TextureUnit::kFilterStages; ++n) {
    unit.settle();
    if (int(pending.size()) == TextureUnit::kFilterStages) {
      const FilterCase c = pending.front();
      pending.pop_front();
      auto channel = [&](int shift) {
        const int blended = blend_channel(int(c.texel[0] >> shift) & 255, int(c.texel[1] >> shift) & 255,
                                          int(c.texel[2] >> shift) & 255, int(c.texel[3] >> shift) & 255, c.wx, c.wy);
        return modulate_channel(blended, int(c.shade >> shift) & 255);
      };
      const uint32_t want = uint32_t(channel(16) << 16 | channel(8) << 8 | channel(0));
      ASSERT_EQ(uint32_t(unit->rgb_q), want) << "case " << checked << " weights " << c.wx << " " << c.wy;
      ++checked;
    }
    FilterCase c;
    for (uint32_t& t : c.texel) t = uint32_t(rng()) & 0xFFFFFFu;
    if (uniform(0, 7) == 0) c.texel[1] = c.texel[2] = c.texel[3] = c.texel[0];  // a flat area: the blend is the texel
    c.wx = weight(), c.wy = weight();
    c.shade = uniform(0, 7) == 0 ? 0xFFFFFFu : uint32_t(rng()) & 0xFFFFFFu;
    unit->texel00 = c.texel[0], unit->texel10 = c.texel[1], unit->texel01 = c.texel[2], unit->texel11 = c.texel[3];
    unit->wx = uint8_t(c.wx), unit->wy = uint8_t(c.wy), unit->shade = c.shade;
    pending.push_back(c);
    unit.tick();
  }
  EXPECT_GE(checked, 200000);
  // The modulation on every pair: a flat texel (weights 0) of value t in every channel, shade g.
  for (int t = 0; t < 256; ++t) {
    for (int g = 0; g < 256; ++g) {
      const uint32_t texel = uint32_t(t * 0x010101), shade = uint32_t(g * 0x010101);
      unit->texel00 = unit->texel10 = unit->texel01 = unit->texel11 = texel;
      unit->wx = uint8_t(g), unit->wy = uint8_t(255 - g), unit->shade = shade;
      for (int k = 0; k < TextureUnit::kFilterStages; ++k) unit.tick();
      unit.settle();
      ASSERT_EQ(unpack(uint32_t(unit->rgb_q)).g, modulate_channel(t, g)) << "texel " << t << " shade " << g;
    }
  }
}

}  // namespace
}  // namespace rastersim::units
