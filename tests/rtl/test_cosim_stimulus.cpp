// The co-simulation's stimulus reaches the runtime inputs of the build it runs on: a biased build's
// random frames draw the bias's constant and slope factor of both signs even though the command
// line gave one to select the build, the directed frames alone drive the texture unit (each filter
// and wrap mode, the w ratio limit, texture memory stalls) and read-after-write hazards at every
// memory latency. Counted on the model's runs of the frames of a `cosim` run (that the RTL agrees
// is the co-simulation's job).
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "testbench/cosim_cases.h"
#include "testbench/rtl_backend.h"

namespace rastersim::rtl {
namespace {

// The keys of `rastersim cosim --width 64 --height 48` plus those of `extra`.
std::set<std::string> given(std::set<std::string> extra) {
  extra.insert({"width", "height"});
  return extra;
}

// `cosim --width 64 --height 48 --setup-interval 64 --depth-exponent-bits 3 --depth-bias-slope 1`:
// the build with the depth bias (small_depth).
TEST(CosimStimulus, BiasedRandomFramesDrawBothSignsOfTheGivenBias) {
  Profile p;
  p.width = 64, p.height = 48, p.setup_interval = 64, p.depth_exponent_bits = 3;
  p.depth_bias_slope = 16;
  const std::set<std::string> keys = given({"setup_interval", "depth_exponent_bits", "depth_bias_slope"});
  const CosimPlan plan(p, pinned_settings(keys, false), 8, 1, 16, true);
  int slope_negative = 0, slope_positive = 0, constant_negative = 0, constant_positive = 0;
  for (int64_t k = plan.directed_count(); k < plan.directed_count() + 100; ++k) {
    const Profile f = plan.frame(k).profile;
    slope_negative += f.depth_bias_slope < 0, slope_positive += f.depth_bias_slope > 0;
    constant_negative += f.depth_bias_constant < 0, constant_positive += f.depth_bias_constant > 0;
  }
  EXPECT_GT(slope_negative, 10);
  EXPECT_GT(slope_positive, 10);
  EXPECT_GT(constant_negative, 10);
  EXPECT_GT(constant_positive, 10);
  // --fixed-settings keeps the given bias in every frame.
  const CosimPlan fixed(p, pinned_settings(keys, true), 8, 1, 16, false);
  for (int64_t k = 0; k < 20; ++k) {
    EXPECT_EQ(fixed.frame(k).profile.depth_bias_slope, 16) << k;
    EXPECT_EQ(fixed.frame(k).profile.depth_bias_constant, 0) << k;
  }
}

// `cosim --width 64 --height 48 --texture-unit true`: the directed and coverage frames alone.
TEST(CosimStimulus, DirectedFramesDriveEveryTextureFilterWrapAndStall) {
  Profile p;
  p.width = 64, p.height = 48, p.texture_unit = true;
  const CosimPlan plan(p, pinned_settings(given({"texture_unit"}), false), 8, 1, 16, true);
  // Textured fragments with u or v outside [0, 1), per filter and wrap mode.
  std::map<std::pair<TextureFilter, TextureWrap>, int64_t> outside;
  int64_t at_ratio_limit = 0, stalls_latency_1 = 0, stalls_latency_max = 0;
  for (int64_t k = 0; k < plan.directed_count(); ++k) {
    const CosimCase c = plan.frame(k);
    const RtlResult model = run_model(c.profile, c.triangles, c.texture);
    if (c.texture.texture) {
      constexpr int32_t one = int32_t(1) << 20;  // u, v are s8.20
      for (const Fragment& f : model.fragments)
        if (f.textured && (f.uv.u < 0 || f.uv.u >= one || f.uv.v < 0 || f.uv.v >= one))
          ++outside[{c.texture.filter, c.texture.wrap}];
    }
    for (size_t t = 0; t < c.triangles.size(); ++t) {
      const SnappedTriangle& tri = c.triangles[t];
      if (!tri.textured || model.triangles[t].fragments == 0) continue;
      int64_t q_min = tri.v[0].q, q_max = tri.v[0].q;
      for (const SnappedVertex& v : tri.v) q_min = std::min(q_min, v.q), q_max = std::max(q_max, v.q);
      at_ratio_limit += q_min <= (q_max >> 14);  // w ratio 2^14: q spans 2^14
    }
    if (c.profile.texture_latency == 1) stalls_latency_1 += model.stats.texture.stall;
    if (c.profile.texture_latency == kMaxTextureLatency) stalls_latency_max += model.stats.texture.stall;
  }
  for (const TextureFilter filter : {TextureFilter::Nearest, TextureFilter::Bilinear})
    for (const TextureWrap wrap : {TextureWrap::Repeat, TextureWrap::Clamp})
      EXPECT_GT((outside[{filter, wrap}]), 0) << "filter " << int(filter) << ", wrap " << int(wrap);
  EXPECT_GT(at_ratio_limit, 0);
  EXPECT_GT(stalls_latency_1, 0);
  EXPECT_GT(stalls_latency_max, 0);
}

// The directed and coverage frames of `cosim` hold a read-after-write hazard stall at every memory
// latency the build allows, on the small geometry with either setup and on the default one.
TEST(CosimStimulus, DirectedFramesHaveHazardsAtEveryMemoryLatency) {
  Profile small;
  small.width = 64, small.height = 48;
  Profile serial = small;
  serial.setup_interval = 0;
  for (const Profile& p : {small, serial, Profile{}}) {
    const int max_latency = built_max_memory_latency(p);
    ASSERT_GT(max_latency, 0);
    const CosimPlan plan(p, pinned_settings(given({}), false), max_latency, 1, 16, true);
    std::map<int, int64_t> stalls;
    for (int64_t k = 0; k < plan.directed_count(); ++k) {
      const CosimCase c = plan.frame(k);
      stalls[c.profile.memory_latency] += run_model(c.profile, c.triangles, c.texture).stats.zbuffer.stall;
    }
    for (int latency = 1; latency <= max_latency; ++latency)
      EXPECT_GT(stalls[latency], 0) << p.width << "x" << p.height << ", setup_interval " << p.setup_interval
                                    << ", memory_latency " << latency;
  }
}

}  // namespace
}  // namespace rastersim::rtl
