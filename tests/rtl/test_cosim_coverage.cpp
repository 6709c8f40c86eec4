// The co-simulation's functional coverage: bins counted on frames worked out by hand, reachability
// following the pinned settings, and the frames of a default `cosim` run reaching every reachable
// bin on every built geometry (through the model: that the RTL agrees is the co-simulation's job).
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "testbench/cosim_cases.h"
#include "testbench/cosim_coverage.h"
#include "testbench/rtl_backend.h"

namespace rastersim::rtl {
namespace {

Profile small_profile(int width = 64, int height = 48) {
  Profile p;
  p.width = width, p.height = height;
  return p;
}

// Hits by bin name for one frame.
std::map<std::string, int64_t> hits_of(const Profile& p, const std::vector<SnappedTriangle>& triangles,
                                       int max_latency = 8) {
  const std::vector<CoverageBin> bins = coverage_bins(p, {}, max_latency);
  const CoverageCounts counts = frame_coverage(p, triangles, run_model(p, triangles), max_latency);
  std::map<std::string, int64_t> named;
  for (size_t b = 0; b < bins.size(); ++b) named[bins[b].name] = counts[b];
  return named;
}

// Pixel coordinates (in pixels, on the half-pixel grid) to snapped subpixels.
SnappedTriangle triangle(const Profile& p, double x0, double y0, double x1, double y1, double x2, double y2) {
  const double one = double(1 << p.subpixel_bits);
  SnappedTriangle t;
  const double xy[6] = {x0, y0, x1, y1, x2, y2};
  for (int k = 0; k < 3; ++k) {
    t.v[k].x = int32_t(xy[2 * k] * one);
    t.v[k].y = int32_t(xy[2 * k + 1] * one);
    t.v[k].z = 1000;
  }
  return t;
}

// The right triangle (0.5, 0.5), (4.5, 0.5), (0.5, 4.5) (y grows downwards) has pixel centres on
// its top edge y = 0.5 at x = 1.5, 2.5, 3.5, on its left edge x = 0.5 at y = 1.5, 2.5, 3.5, on its
// hypotenuse x + y = 5 at (1.5, 3.5), (2.5, 2.5), (3.5, 1.5), and on its three vertices.
TEST(CosimCoverage, TiesAreCountedPerEdgeKind) {
  const Profile p = small_profile(8, 8);
  std::map<std::string, int64_t> h = hits_of(p, {triangle(p, 0.5, 0.5, 4.5, 0.5, 0.5, 4.5)});
  EXPECT_EQ(h["tie_top_edge"], 3);
  EXPECT_EQ(h["tie_left_edge"], 3);
  EXPECT_EQ(h["tie_right_edge"], 3);
  EXPECT_EQ(h["tie_bottom_edge"], 0);
  EXPECT_EQ(h["tie_vertex"], 3);
  // Mirrored (y -> 8 - y): the horizontal edge is a bottom edge, the interior above it.
  h = hits_of(p, {triangle(p, 0.5, 7.5, 4.5, 7.5, 0.5, 3.5)});
  EXPECT_EQ(h["tie_bottom_edge"], 3);
  EXPECT_EQ(h["tie_top_edge"], 0);
  EXPECT_EQ(h["tie_left_edge"], 3);
  EXPECT_EQ(h["tie_right_edge"], 3);
  EXPECT_EQ(h["tie_vertex"], 3);
  // Off the half-pixel grid no centre lies on an edge.
  h = hits_of(p, {triangle(p, 0.25, 0.25, 4.25, 0.25, 0.25, 4.25)});
  for (const char* bin : {"tie_top_edge", "tie_left_edge", "tie_right_edge", "tie_bottom_edge", "tie_vertex"})
    EXPECT_EQ(h[bin], 0) << bin;
}

TEST(CosimCoverage, RejectedTrianglesAndTheGuardBandAreCounted) {
  Profile p = small_profile(8, 8);
  p.cull = CullMode::Back;
  // The winding back culling keeps (the same triangle reversed is culled).
  auto kept = [&](SnappedTriangle t) {
    if (run_model(p, {t}).triangles[0].status == SetupStatus::Culled) std::swap(t.v[1], t.v[2]);
    return t;
  };
  const SnappedTriangle drawn = kept(triangle(p, 0.5, 0.5, 4.5, 0.5, 0.5, 4.5));
  SnappedTriangle back = drawn;
  std::swap(back.v[1], back.v[2]);
  const SnappedTriangle flat = triangle(p, 0.5, 0.5, 2.5, 2.5, 4.5, 4.5);            // collinear
  const SnappedTriangle beside = kept(triangle(p, -6, 1, -2, 1, -6, 5));             // left of the screen
  const SnappedTriangle between = kept(triangle(p, 1.625, 0.5, 1.875, 0.5, 1.75, 3));  // between centres 1.5, 2.5
  // Between the lines y - x = 0.44 and 0.5: its box holds centres, it covers none (y - x integral).
  const SnappedTriangle sliver = kept(triangle(p, 0.25, 0.75, 3.25, 3.75, 0.375, 0.75));
  const SnappedTriangle corner = kept(triangle(p, -8, -8, 16, -8, -8, 16));          // the guard band's limits
  const SnappedTriangle across = kept(triangle(p, -2, 0.5, 6, 0.5, -2, 6));          // a vertex off screen
  const std::vector<SnappedTriangle> frame = {drawn, back, flat, beside, sliver, corner, across, between};
  const RtlResult model = run_model(p, frame);
  const SetupStatus expected[] = {SetupStatus::Drawn,     SetupStatus::Culled, SetupStatus::Degenerate,
                                  SetupStatus::Offscreen, SetupStatus::Drawn,  SetupStatus::Drawn,
                                  SetupStatus::Drawn,     SetupStatus::NoCentre};
  for (size_t t = 0; t < frame.size(); ++t) ASSERT_EQ(model.triangles[t].status, expected[t]) << t;
  ASSERT_EQ(model.triangles[4].fragments, 0);
  const std::map<std::string, int64_t> h = hits_of(p, frame);
  EXPECT_EQ(h.at("culled"), 1);
  EXPECT_EQ(h.at("degenerate"), 1);
  EXPECT_EQ(h.at("offscreen"), 1);
  EXPECT_EQ(h.at("no_centre"), 1);
  EXPECT_EQ(h.at("drawn_without_fragment"), 1);
  EXPECT_EQ(h.at("guard_band_limit"), 1);
  EXPECT_EQ(h.at("guard_band_drawn"), 2);
}

TEST(CosimCoverage, DepthBinsCountTheFrameFunctionsFragments) {
  Profile p = small_profile(8, 8);
  p.depth_func = DepthFunc::Greater;
  p.depth_write = false;
  p.depth_clear = 500;
  SnappedTriangle near = triangle(p, 0.5, 0.5, 4.5, 0.5, 0.5, 4.5);  // z 1000 > 500: passes
  SnappedTriangle far = triangle(p, 4, 4, 8, 4, 4, 8);
  for (SnappedVertex& v : far.v) v.z = 100;  // fails
  const RtlResult model = run_model(p, {near, far});
  int64_t pass = 0;
  for (const Fragment& f : model.fragments) pass += f.pass;
  ASSERT_GT(pass, 0);
  ASSERT_GT(int64_t(model.fragments.size()), pass);
  const std::map<std::string, int64_t> h = hits_of(p, {near, far});
  EXPECT_EQ(h.at("depth_greater_write_off"), int64_t(model.fragments.size()));
  EXPECT_EQ(h.at("depth_greater_write_on"), 0);
  EXPECT_EQ(h.at("depth_greater_pass"), pass);
  EXPECT_EQ(h.at("depth_greater_fail"), int64_t(model.fragments.size()) - pass);
  EXPECT_EQ(h.at("depth_less_pass") + h.at("depth_less_fail"), 0);
}

bool reachable(const std::vector<CoverageBin>& bins, const std::string& name) {
  for (const CoverageBin& b : bins)
    if (b.name == name) return b.reachable;
  ADD_FAILURE() << "no bin " << name;
  return false;
}

TEST(CosimCoverage, PinnedSettingsMakeBinsUnreachable) {
  Profile p = small_profile();
  std::vector<CoverageBin> bins = coverage_bins(p, {}, 8);
  EXPECT_FALSE(reachable(bins, "depth_never_pass"));
  EXPECT_FALSE(reachable(bins, "depth_always_fail"));
  EXPECT_FALSE(reachable(bins, "memory_back_pressure"));
  EXPECT_TRUE(reachable(bins, "depth_greater_pass"));
  EXPECT_TRUE(reachable(bins, "zbuffer_hazard_stall_bbox"));
  EXPECT_TRUE(reachable(bins, "culled"));

  p.traversal = Traversal::Span;
  p.memory_latency = 2;
  p.cull = CullMode::None;
  p.depth_func = DepthFunc::Less;
  p.depth_clear = 0;
  bins = coverage_bins(p, {"traversal", "memory_latency", "cull", "depth_func", "depth_clear"}, 8);
  EXPECT_FALSE(reachable(bins, "zbuffer_hazard_stall_bbox"));  // span only
  // The next triangle's first fragment can follow the last one's in the next cycle: any latency.
  EXPECT_TRUE(reachable(bins, "zbuffer_hazard_stall_span"));
  EXPECT_FALSE(reachable(bins, "culled"));
  EXPECT_FALSE(reachable(bins, "depth_greater_write_on"));
  EXPECT_FALSE(reachable(bins, "depth_less_pass"));  // nothing is below 0
  EXPECT_TRUE(reachable(bins, "depth_less_fail"));
  EXPECT_FALSE(reachable(bins, "memory_latency_1"));
  EXPECT_FALSE(reachable(bins, "memory_latency_max"));

  // The serial setup with one record credit starts a triangle only after the walker took the last.
  p.setup_interval = 0;
  p.setup_fifo_depth = 1;
  bins = coverage_bins(p, {"setup_fifo_depth"}, 8);
  EXPECT_FALSE(reachable(bins, "zbuffer_hazard_stall_bbox"));
  EXPECT_FALSE(reachable(bins, "zbuffer_hazard_stall_span"));
  EXPECT_FALSE(reachable(bins, "zbuffer_hazard_stall_latency_3"));
}

// The depth bias's and the texture unit's bins exist in the builds with them; a pinned value has
// one sign; a pinned latency leaves its own hazard bin alone.
TEST(CosimCoverage, BiasTextureAndLatencyBinsFollowTheBuild) {
  Profile p = small_profile();
  std::vector<CoverageBin> bins = coverage_bins(p, {}, 8);
  for (const char* name : {"depth_bias_slope_negative", "depth_bias_constant_positive", "texture_bilinear",
                           "texture_clamp_outside", "texture_w_ratio_limit", "texture_memory_stall"})
    EXPECT_FALSE(reachable(bins, name)) << name;
  for (int latency = 1; latency <= 8; ++latency)
    EXPECT_TRUE(reachable(bins, "zbuffer_hazard_stall_latency_" + std::to_string(latency))) << latency;
  p.memory_latency = 5;
  bins = coverage_bins(p, {"memory_latency"}, 8);
  EXPECT_TRUE(reachable(bins, "zbuffer_hazard_stall_latency_5"));
  EXPECT_FALSE(reachable(bins, "zbuffer_hazard_stall_latency_4"));

  p.depth_bias_slope = 16;
  bins = coverage_bins(p, pinned_settings({"depth_bias_slope"}, false), 8);
  for (const char* name : {"depth_bias_slope_negative", "depth_bias_slope_positive", "depth_bias_constant_negative",
                           "depth_bias_constant_positive"})
    EXPECT_TRUE(reachable(bins, name)) << name;
  bins = coverage_bins(p, pinned_settings({"depth_bias_slope"}, true), 8);  // --fixed-settings
  EXPECT_FALSE(reachable(bins, "depth_bias_slope_negative"));
  EXPECT_TRUE(reachable(bins, "depth_bias_slope_positive"));
  EXPECT_FALSE(reachable(bins, "depth_bias_constant_positive"));

  p = small_profile();
  p.texture_unit = true;
  bins = coverage_bins(p, {}, 8);
  for (const char* name : {"texture_nearest", "texture_bilinear", "texture_repeat_outside", "texture_clamp_outside",
                           "texture_w_ratio_limit", "texture_memory_stall", "texture_latency_1", "texture_latency_max"})
    EXPECT_TRUE(reachable(bins, name)) << name;
  p.texture_stall_percent = 0;
  p.texture_latency = 4;
  bins = coverage_bins(p, {"texture_stall_percent", "texture_latency"}, 8);
  EXPECT_FALSE(reachable(bins, "texture_memory_stall"));
  EXPECT_FALSE(reachable(bins, "texture_latency_1"));
}

// The directed and coverage frames of `cosim` alone reach every reachable bin on each built
// configuration, run as the command line that selects it runs it (`--depth-bias-slope 1` for the
// bias, `--texture-unit true` for the texture unit).
TEST(CosimCoverage, TheDirectedFramesReachEveryReachableBin) {
  Profile biased = small_profile(), textured = small_profile(), serial = small_profile(), corner = small_profile(48);
  biased.setup_interval = 64, biased.depth_exponent_bits = 3, biased.depth_bias_slope = 16;
  textured.texture_unit = true;
  serial.setup_interval = 0;
  // Verilated on demand (latencies up to 64): samples at the pixels' corners, another fill rule.
  corner.pixel_center = PixelCenter::Corner, corner.fill_rule = FillRule::BottomLeft;
  const std::pair<Profile, std::set<std::string>> runs[] = {
      {small_profile(), {"width", "height"}},
      {Profile{}, {}},
      {serial, {"width", "height", "setup_interval"}},
      {biased, {"width", "height", "setup_interval", "depth_exponent_bits", "depth_bias_slope"}},
      {textured, {"width", "height", "texture_unit"}},
      {corner, {"width", "height", "pixel_center", "fill_rule"}}};
  for (const auto& [p, given] : runs) {
    const int max_latency = p.pixel_center == PixelCenter::Corner ? kMaxMemoryLatency : built_max_memory_latency(p);
    ASSERT_GT(max_latency, 0);
    const std::set<std::string> pinned = pinned_settings(given, false);
    const std::vector<CoverageBin> bins = coverage_bins(p, pinned, max_latency);
    const CosimPlan plan(p, pinned, max_latency, 1, 16, true);
    CoverageCounts total(bins.size(), 0);
    for (int64_t k = 0; k < plan.directed_count(); ++k) {
      const CosimCase c = plan.frame(k);
      const CoverageCounts hits =
          frame_coverage(c.profile, c.triangles, run_model(c.profile, c.triangles, c.texture), max_latency, c.texture);
      for (size_t b = 0; b < bins.size(); ++b) total[b] += hits[b];
    }
    EXPECT_EQ(coverage_holes(bins, total), std::vector<std::string>{})
        << p.width << "x" << p.height << ", setup_interval " << p.setup_interval << (p.depth_biased() ? ", biased" : "")
        << (p.texture_unit ? ", textured" : "") << ", pixel_center " << to_string(p.pixel_center);
  }
}

}  // namespace
}  // namespace rastersim::rtl
