// The texture unit's RTL twin (configuration small_texture: 64 x 48, setup_interval 4, TEXTURE 1)
// against the model in lockstep: random frames draw textured and untextured triangles, a random
// texture (or none), filter and wrap mode, texture latency and runtime settings; every fragment
// (its textured colour and the cycle the z-buffer took it), every setup record with its S, T, Q
// planes, the final memories and the counters (the texture unit's among them) must be equal.
#include <gtest/gtest.h>

#include <cstdint>
#include <set>

#include "testbench/cosim_cases.h"
#include "testbench/rtl_backend.h"

namespace rastersim::rtl {
namespace {

Profile textured_profile() {
  Profile p;
  p.width = 64, p.height = 48;
  p.texture_unit = true;
  return p;
}

CosimReport check_frame(const CosimCase& c, uint64_t seed) {
  RtlOptions options;
  options.seed = seed;
  options.texture = c.texture;
  CosimReport report = cosim(c.profile, c.triangles, options);
  EXPECT_TRUE(report.passed) << c.name << " (power-on seed " << seed << ", texture latency "
                             << c.profile.texture_latency << "): " << report.message();
  return report;
}

TEST(RtlTexture, RandomTexturedFramesMatchTheModelEveryCycle) {
  const Profile base = textured_profile();
  ASSERT_EQ(configuration_error(base), "");
  const CosimPlan plan(base, {}, 8, 20261127, 40, false);
  int64_t textured = 0, untextured = 0, bilinear = 0, clamped = 0, latency_64 = 0, textured_fragments = 0;
  int64_t busy = 0;
  for (int64_t k = 0; k < 24; ++k) {
    const CosimCase c = plan.frame(k);
    const CosimReport r = check_frame(c, uint64_t(k) + 1);
    if (!r.passed) return;
    for (size_t i = 0; i < r.model.setups.size(); ++i)
      if (r.model.triangles[i].status == SetupStatus::Drawn) ++(r.model.setups[i].textured ? textured : untextured);
    bilinear += c.texture.filter == TextureFilter::Bilinear;
    clamped += c.texture.wrap == TextureWrap::Clamp;
    latency_64 += c.profile.texture_latency == 64;
    busy += r.rtl.stats.texture.busy;
    for (const Fragment& f : r.model.fragments) textured_fragments += f.textured;
  }
  std::printf("textured triangles %lld, untextured %lld, textured fragments %lld, texture busy %lld\n",
              (long long)textured, (long long)untextured, (long long)textured_fragments, (long long)busy);
  // The frames reached what they are meant to: both kinds of triangle, filters, wraps, latencies,
  // and many textured fragments.
  EXPECT_GT(textured, 100);
  EXPECT_GT(untextured, 20);
  EXPECT_GT(bilinear, 0);
  EXPECT_LT(bilinear, 24);
  EXPECT_GT(clamped, 0);
  EXPECT_LT(clamped, 24);
  EXPECT_GT(latency_64, 0);
  EXPECT_GT(textured_fragments, 10000);
}

// The texture unit's latency extremes, bilinear, on frames of every kind of triangle.
TEST(RtlTexture, LatencyExtremesKeepOneFragmentPerClock) {
  Profile p = textured_profile();
  for (const int latency : {1, 2, 64}) {
    p.texture_latency = latency;
    CosimCase c = random_case(p, uint64_t(latency) * 31, 12);
    c.profile = p;
    c.texture.filter = TextureFilter::Bilinear;
    const CosimReport r = check_frame(c, uint64_t(latency));
    if (!r.passed) return;
    EXPECT_GT(r.rtl.stats.texture.busy, 0);
  }
}

// The texture memory's back-pressure (rastersim_top's texture_refuse, driven from the profile's
// stall pattern): reads wait, the walker is held when the unit fills, and every cycle still agrees.
TEST(RtlTexture, TextureMemoryBackPressureMatchesTheModel) {
  Profile p = textured_profile();
  int64_t stalls = 0, held = 0;
  for (const int percent : {10, 50, 90}) {
    p.texture_stall_percent = percent;
    p.texture_stall_seed = percent * 7;
    CosimCase c = random_case(p, uint64_t(percent) * 131, 30);
    c.profile = p;
    const CosimReport r = check_frame(c, uint64_t(percent));
    if (!r.passed) return;
    stalls += r.rtl.stats.texture.stall;
    held += r.rtl.stats.walker.stall;
  }
  EXPECT_GT(stalls, 1000);
  EXPECT_GT(held, 100);
}

TEST(RtlTexture, ConfigurationsWithoutTheUnitRefuseTexturedProfiles) {
  Profile p = textured_profile();
  p.setup_interval = 2;  // built without the texture unit (small_i2)
  EXPECT_NE(configuration_error(p).find("TEXTURE=1"), std::string::npos) << configuration_error(p);
}

}  // namespace
}  // namespace rastersim::rtl
