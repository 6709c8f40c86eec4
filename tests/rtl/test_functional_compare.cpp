// The compare modes for designs that are not rastersim's (testbench/functional_compare.h): each
// mode accepts exactly the differences its contract allows (timing, order within a triangle, any
// order) and reports the first one it does not, at its triangle, pixel and field.
#include <gtest/gtest.h>

#include <algorithm>

#include "testbench/cosim_cases.h"
#include "testbench/functional_compare.h"
#include "testbench/rtl_backend.h"

namespace rastersim::verify {
namespace {

using rtl::RtlResult;

Profile small_profile() {
  Profile p;
  p.width = 64;
  p.height = 48;
  p.memory_latency = 4;
  return p;
}

constexpr CompareMode kModes[] = {CompareMode::Cycle, CompareMode::Stream, CompareMode::Triangle, CompareMode::Frame};

// A random frame of the suite's cosim and the model's result for it.
struct Frame {
  Profile profile = small_profile();
  std::vector<SnappedTriangle> triangles;
  RtlResult model;
};
Frame random_frame(uint64_t seed) {
  Frame f;
  const rtl::CosimCase c = rtl::random_case(f.profile, seed, 40);
  f.profile = c.profile;
  f.triangles = c.triangles;
  f.model = rtl::run_model(f.profile, f.triangles, c.texture);
  return f;
}

TEST(FunctionalCompare, RastersimsOwnRtlPassesEveryMode) {
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    const Frame f = random_frame(seed);
    ASSERT_EQ(rtl::configuration_error(f.profile), "");
    const RtlResult design = rtl::run_rtl(f.profile, f.triangles);
    for (CompareMode mode : kModes) {
      const FunctionalReport r = compare(f.profile, f.model, design, mode);
      EXPECT_TRUE(r.passed()) << to_string(mode) << ": " << r.summary();
      if (mode != CompareMode::Frame) {
        EXPECT_EQ(r.fragments_compared, int64_t(f.model.fragments.size()));
      }
      EXPECT_EQ(r.words_compared, f.profile.width * f.profile.height);
    }
  }
}

TEST(FunctionalCompare, OtherTimingPassesAllButCycle) {
  const Frame f = random_frame(4);
  ASSERT_FALSE(f.model.fragments.empty());
  RtlResult design = f.model;
  for (Fragment& fr : design.fragments) fr.cycle = 2 * fr.cycle + 7;  // a design at half the rate
  EXPECT_FALSE(compare(f.profile, f.model, design, CompareMode::Cycle).passed());
  for (CompareMode mode : {CompareMode::Stream, CompareMode::Triangle, CompareMode::Frame})
    EXPECT_TRUE(compare(f.profile, f.model, design, mode).passed()) << to_string(mode);
}

// What the verification interface reports of the model's own frame: decisions with their cycles,
// retirements, frame_done; no take cycles, no walker records.
RtlResult as_interface_reports(const RtlResult& model) {
  RtlResult d;
  d.interface_only = true;
  for (const TriangleRecord& m : model.triangles) {
    TriangleRecord r;
    r.index = m.index, r.status = m.status, r.setup_decided = m.setup_decided;
    d.triangles.push_back(r);
  }
  d.fragments = model.fragments;
  for (Fragment& fr : d.fragments) fr.cycle = -1;
  d.depth = model.depth, d.color = model.color;
  d.stats.cycles = model.stats.cycles;
  return d;
}

// Cycle mode through the interface: the same events at the same cycles pass; one decision, one
// retirement or the frame's end a cycle off is named.
TEST(FunctionalCompare, CycleModeThroughTheInterfaceComparesEachEventsCycle) {
  const Frame f = random_frame(6);
  ASSERT_GT(f.model.fragments.size(), 10u);
  const RtlResult same = as_interface_reports(f.model);
  EXPECT_TRUE(compare(f.profile, f.model, same, CompareMode::Cycle).passed())
      << compare(f.profile, f.model, same, CompareMode::Cycle).summary();
  RtlResult late_decision = same;
  ++late_decision.triangles[3].setup_decided;
  FunctionalReport r = compare(f.profile, f.model, late_decision, CompareMode::Cycle);
  ASSERT_FALSE(r.passed());
  EXPECT_EQ(r.mismatches.front().field, "decision cycle");
  EXPECT_EQ(r.mismatches.front().triangle, 3);
  RtlResult early_retirement = same;
  --early_retirement.fragments[7].tested;
  r = compare(f.profile, f.model, early_retirement, CompareMode::Cycle);
  ASSERT_FALSE(r.passed());
  EXPECT_EQ(r.mismatches.front().field, "retirement cycle");
  EXPECT_EQ(r.mismatches.front().x, f.model.fragments[7].x);
  RtlResult late_end = same;
  ++late_end.stats.cycles;
  r = compare(f.profile, f.model, late_end, CompareMode::Cycle);
  ASSERT_FALSE(r.passed());
  EXPECT_EQ(r.mismatches.front().field, "frame_done cycle");
  RtlResult other_colour = same;
  other_colour.fragments[2].color.r ^= 1;
  EXPECT_FALSE(compare(f.profile, f.model, other_colour, CompareMode::Cycle).passed());
}

TEST(FunctionalCompare, AnotherOrderWithinATrianglePassesTriangleAndFrameOnly) {
  const Frame f = random_frame(5);
  RtlResult design = f.model;
  // Each triangle's fragments reversed: another walk over the same pixels.
  auto begin = design.fragments.begin();
  while (begin != design.fragments.end()) {
    auto end = std::find_if(begin, design.fragments.end(), [&](const Fragment& x) { return x.tri != begin->tri; });
    std::reverse(begin, end);
    begin = end;
  }
  const FunctionalReport stream = compare(f.profile, f.model, design, CompareMode::Stream);
  ASSERT_FALSE(stream.passed());
  EXPECT_EQ(stream.mismatches.front().field.rfind("fragment", 0), 0u) << stream.summary();
  EXPECT_TRUE(compare(f.profile, f.model, design, CompareMode::Triangle).passed());
  EXPECT_TRUE(compare(f.profile, f.model, design, CompareMode::Frame).passed());
}

TEST(FunctionalCompare, TriangleModeNamesAMissingPixelAndTrianglesOutOfOrder) {
  const Frame f = random_frame(6);
  RtlResult design = f.model;
  ASSERT_GT(design.fragments.size(), 10u);
  const Fragment dropped = design.fragments[10];
  design.fragments.erase(design.fragments.begin() + 10);
  const FunctionalReport missing = compare(f.profile, f.model, design, CompareMode::Triangle);
  ASSERT_FALSE(missing.passed());
  EXPECT_EQ(missing.mismatches.front().field, "missing fragment");
  EXPECT_EQ(missing.mismatches.front().triangle, dropped.tri);
  EXPECT_EQ(missing.mismatches.front().x, dropped.x);
  EXPECT_EQ(missing.mismatches.front().y, dropped.y);
  // The last triangle's fragments moved to the front.
  design = f.model;
  const int64_t last = design.fragments.back().tri;
  std::stable_partition(design.fragments.begin(), design.fragments.end(), [&](const Fragment& x) { return x.tri == last; });
  const FunctionalReport order = compare(f.profile, f.model, design, CompareMode::Triangle);
  ASSERT_FALSE(order.passed());
  EXPECT_EQ(order.mismatches.front().field, "triangle order") << order.summary();
}

// The depth test's `<` written as `<=` in a design: two coplanar overlapping triangles of different
// colours; with less the first keeps the pixels, with lequal the second takes them.
TEST(FunctionalCompare, FrameModeCatchesLessWrittenAsLessOrEqual) {
  Profile p = small_profile();
  const auto triangle = [&](Rgb colour) {
    ScreenTriangle t;
    const double xy[3][2] = {{4, 4}, {40, 6}, {10, 40}};
    for (int k = 0; k < 3; ++k) t.v[k] = ScreenVertex{xy[k][0], xy[k][1], 0.5, colour};
    return snap(t, p);
  };
  const std::vector<SnappedTriangle> tris = {triangle(Rgb{255, 0, 0}), triangle(Rgb{0, 0, 255})};
  const RtlResult model = rtl::run_model(p, tris);
  Profile buggy = p;
  buggy.depth_func = DepthFunc::LEqual;
  const RtlResult design = rtl::run_model(buggy, tris);
  const FunctionalReport r = compare(p, model, design, CompareMode::Frame);
  ASSERT_FALSE(r.passed());
  EXPECT_EQ(r.mismatches.front().field, "colour word");
  EXPECT_EQ(r.mismatches.front().expected, "ff0000");
  EXPECT_EQ(r.mismatches.front().actual, "0000ff");
  EXPECT_FALSE(compare(p, model, design, CompareMode::Stream).passed()) << "the second triangle's pass bits differ";
}

TEST(FunctionalCompare, ToleranceBoundsDepthAndReportsTheDistribution) {
  const Frame f = random_frame(7);
  RtlResult design = f.model;
  int64_t changed = 0;
  for (size_t i = 0; i < design.fragments.size(); i += 3) {
    Fragment& fr = design.fragments[i];
    if (fr.z == 0) continue;
    fr.z -= 1;  // a design whose planes keep fewer fraction bits truncates lower now and then
    ++changed;
  }
  ASSERT_GT(changed, 0);
  const FunctionalReport exact = compare(f.profile, f.model, design, CompareMode::Triangle);
  EXPECT_FALSE(exact.passed());
  EXPECT_EQ(exact.mismatches.front().field, "z");
  const FunctionalReport bounded = compare(f.profile, f.model, design, CompareMode::Triangle, Tolerance{1, 0});
  EXPECT_TRUE(bounded.passed()) << bounded.summary();
  EXPECT_EQ(bounded.depth_error.max_abs(), 1);
  EXPECT_EQ(bounded.depth_error.counts.at(-1), changed);
  EXPECT_EQ(bounded.depth_error.samples(), int64_t(f.model.fragments.size()));
}

TEST(FunctionalCompare, ParsesModesAndTolerances) {
  for (CompareMode mode : kModes) EXPECT_EQ(parse_compare_mode(to_string(mode)), mode);
  EXPECT_FALSE(parse_compare_mode("pixel"));
  Tolerance t;
  EXPECT_EQ(parse_tolerance("depth=3,color=2", t), "");
  EXPECT_EQ(t.depth, 3);
  EXPECT_EQ(t.color, 2);
  EXPECT_NE(parse_tolerance("depth=-1", t), "");
  EXPECT_NE(parse_tolerance("alpha=1", t), "");
  EXPECT_NE(parse_tolerance("depth", t), "");
}

}  // namespace
}  // namespace rastersim::verify
