// Without a fragment sink the pipeline takes whole runs of fragments at once when no hazard can
// stall them (fast/fast_walk.cpp, fast/zbuffer_runs.h). The traced path handles every fragment one
// at a time and is the one co-simulation checks against the RTL; this test requires the fast walk
// to give the same frame: every counter, every triangle record, every buffer word, also under a
// memory stall pattern (which may refuse any read, so no run is taken at once: ZBufferRuns::settled).
#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <tuple>

#include "fast/fast_setup.h"
#include "fast/fast_walk.h"
#include "fast/run_kernels.h"
#include "test_util.h"

namespace rastersim::test {
namespace {

// Traced: the specification's walk with a fragment sink; Plain: the same without one; Fast: the
// fast walk (fast_walk_runner), which must apply.
enum class Walk { Traced, Plain, Fast };

Frame render(const Profile& profile, const std::vector<SnappedTriangle>& triangles, Walk walk) {
  Pipeline pipeline(profile);
  FragmentLog log;
  Frame frame;
  const bool traced = walk == Walk::Traced;
  pipeline.set_walk_runner(walk == Walk::Fast ? fast_walk_runner(pipeline) : nullptr);
  if (walk == Walk::Fast) {
    EXPECT_NE(pipeline.walk_runner(), nullptr) << "the fast walk must apply";
  }
  if (traced) pipeline.set_fragment_sink(&log);
  pipeline.set_triangle_log(&frame.records);
  for (const SnappedTriangle& t : triangles) pipeline.submit(t);
  frame.stats = pipeline.stats();
  frame.depth = pipeline.zbuffer().depth();
  frame.color = pipeline.zbuffer().color();
  if (traced) {
    EXPECT_EQ(int64_t(log.fragments.size()), frame.stats.fragments);
  }
  return frame;
}

using Param = std::tuple<Traversal, DepthFunc, int /*memory_latency*/, int /*memory_stall_percent*/>;

class FastPath : public ::testing::TestWithParam<Param> {};

TEST_P(FastPath, UntracedFrameEqualsTracedFrame) {
  const auto [traversal, depth_func, latency, stall_percent] = GetParam();
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    // z_bits 32 and 16 as well: the widest and narrowest depth registers.
    Profile profile = make_profile(96, 64, seed % 2 ? 4 : 8, traversal, seed == 5 ? 32 : seed == 6 ? 16 : 24);
    // The widest colour register the avx512-masked kernel holds in 32-bit lanes (9 + 23 bits), and
    // one bit wider (that kernel hands the run to the compiled loop).
    if (seed >= 7) profile.z_guard_bits = seed == 7 ? 23 : 24;
    profile.depth_func = depth_func;
    profile.memory_latency = latency;
    profile.memory_stall_percent = stall_percent;
    profile.memory_stall_seed = int(seed);
    profile.shading = seed % 3 ? Shading::Gouraud : Shading::Flat;
    profile.depth_write = seed != 4;
    // Other conventions (docs/arithmetic.md section 7): the fast paths round and sample as the model.
    if (seed == 2 || seed == 7) profile.depth_rounding = profile.color_rounding = Rounding::Truncate;
    if (seed == 3) profile.pixel_center = PixelCenter::Corner, profile.fill_rule = FillRule::BottomRight;
    TriangleGen gen(profile, seed * 7919 + uint64_t(latency));
    // Overlapping large triangles (long runs, depth tests both ways), back-to-back tiny ones
    // (hazard stalls inside and across triangles), slivers and off-screen ones.
    std::vector<SnappedTriangle> triangles;
    for (int i = 0; i < 60; ++i) {
      switch (gen.uniform(0, 5)) {
        case 5: {
          // A wide triangle whose last row ends near pixel (bx, by), then a small one over the end
          // of that row: its first fragments hit addresses still in flight from the wide one's last
          // run (a hazard stall that depends on the run's recorded cycles).
          const int64_t M = gen.M(), bx = gen.uniform(40, 90), by = gen.uniform(20, 62);
          triangles.push_back(gen.triangle((bx - 20) * M, (by - 18) * M, (bx - 40) * M, by * M, (bx + 1) * M, by * M));
          triangles.push_back(gen.triangle((bx - 4) * M, (by - 2) * M, (bx - 4) * M, by * M, (bx + 1) * M, by * M));
          break;
        }
        case 0: triangles.push_back(gen.near_screen(48)); break;
        case 1: triangles.push_back(gen.tiny()); break;
        case 2: triangles.push_back(gen.sliver(30)); break;
        case 3: triangles.push_back(gen.on_centres(6)); break;
        default: triangles.push_back(gen.guard_band()); break;
      }
    }
    const Frame traced = render(profile, triangles, Walk::Traced);
    ASSERT_GT(traced.stats.fragments, 0);
    {
      SCOPED_TRACE(describe(profile) + " seed " + std::to_string(seed) + ", the specification's walk untraced");
      expect_same_frame(traced, render(profile, triangles, Walk::Plain));
    }
    for (const std::string& kernel : run_kernel_versions()) {
      select_run_kernel(kernel);
      SCOPED_TRACE(describe(profile) + " seed " + std::to_string(seed) + ", run kernel " + kernel);
      expect_same_frame(traced, render(profile, triangles, Walk::Fast));
    }
    select_run_kernel(run_kernel_versions().front());
    if (stall_percent > 0) {  // the pattern must bite: the same frame without it is shorter
      Profile unstalled = profile;
      unstalled.memory_stall_percent = 0;
      const Frame unstalled_frame = render(unstalled, triangles, Walk::Fast);
      EXPECT_GT(traced.stats.cycles, unstalled_frame.stats.cycles);
      EXPECT_GT(traced.stats.zbuffer.stall, unstalled_frame.stats.zbuffer.stall);
      EXPECT_TRUE(unstalled_frame.depth == traced.depth) << "a stall pattern changed the depth buffer";
    }
  }
}

// What fast_set_up must equal: every field of the specification's setup but the planes along the
// left edges, or the same WidthOverflow message.
std::string setup_fields(const SnappedTriangle& t, const std::function<void(SetupResult&)>& set_up) {
  SetupResult r;
  try {
    set_up(r);
  } catch (const WidthOverflow& e) {
    return std::string("WidthOverflow: ") + e.what();
  }
  std::ostringstream out;
  auto plane = [&](const PlaneSetup& p) { out << " " << p.start << "," << p.step_x << "," << p.step_y; };
  out << to_string(r.status) << " " << r.front_facing << " " << r.area2 << " " << r.x0 << " " << r.y0 << " "
      << r.x1 << " " << r.y1 << " " << int(r.flat_color.r) << "," << int(r.flat_color.g) << ","
      << int(r.flat_color.b) << " " << r.textured;
  for (const EdgeSetup& e : r.edge)
    out << " " << e.start << "," << e.step_x << "," << e.step_y << "," << e.owns_samples << "," << e.span_quot
        << "," << e.span_rem << "," << e.span_step_quot << "," << e.span_step_rem;
  plane(r.depth);
  for (const PlaneSetup& p : r.color) plane(p);
  for (const PlaneSetup& p : r.texture) plane(p);
  out << " (" << describe(t) << ")";
  return out.str();
}

// The fast setup's planes come from the vertex differences in 64 bits where the values fit, and
// from the specification's planes where they do not (the largest profile's wide numerators, the
// texture unit); both must give the specification's record, and the same errors for depths beyond
// the profile's range (the dividend limits of a small profile's divider).
TEST(FastPath, FastSetupEqualsTheSpecificationsSetup) {
  struct Case {
    int width, height, subpixel_bits, z_bits, z_guard_bits;
    Shading shading;
    bool texture_unit;
  };
  const Case cases[] = {{640, 480, 4, 24, 0, Shading::Gouraud, false}, {96, 64, 8, 32, 0, Shading::Gouraud, false},
                        {16, 12, 1, 16, 1, Shading::Gouraud, false},   {4096, 4096, 8, 32, 24, Shading::Gouraud, false},
                        {1024, 768, 6, 16, 0, Shading::Flat, false},    {64, 48, 4, 24, 0, Shading::Gouraud, true}};
  int compared = 0, overflows = 0;
  for (const Case& c : cases) {
    Profile profile = make_profile(c.width, c.height, c.subpixel_bits, Traversal::Span, c.z_bits);
    profile.z_guard_bits = c.z_guard_bits;
    profile.shading = c.shading;
    profile.texture_unit = c.texture_unit;
    if (c.subpixel_bits == 1) profile.pixel_center = PixelCenter::Corner, profile.fill_rule = FillRule::TopRight;
    const TriangleSetup setup(profile);
    TriangleGen gen(profile, uint64_t(c.width) * 31 + uint64_t(c.z_bits));
    for (int i = 0; i < 3000; ++i) {
      SnappedTriangle t;
      switch (i % 6) {
        case 0: t = gen.guard_band(); break;
        case 1: t = gen.tiny(); break;
        case 2: t = gen.sliver(40); break;
        case 3: t = gen.degenerate(); break;
        case 4: t = gen.near_screen(c.width / 4); break;
        default: {
          // Depths beyond the profile's word: the dividends may leave the divider's width.
          t = gen.near_screen(c.width / 2);
          for (SnappedVertex& v : t.v) v.z = uint32_t(gen.uniform(0, 0xffffffff));
          break;
        }
      }
      if (c.texture_unit && i % 2) {
        t.textured = true;
        for (SnappedVertex& v : t.v)
          v.s = gen.uniform(-(int64_t(1) << 24), int64_t(1) << 24), v.t = gen.uniform(-(int64_t(1) << 24), int64_t(1) << 24),
          v.q = gen.uniform(1, int64_t(1) << kTextureFractionBits);
      }
      const std::string spec = setup_fields(t, [&](SetupResult& r) { setup.run(t, r); });
      const std::string fast = setup_fields(t, [&](SetupResult& r) { fast_set_up(setup, t, r); });
      ASSERT_EQ(spec, fast) << describe(profile);
      ++compared;
      overflows += spec.rfind("WidthOverflow", 0) == 0;
    }
  }
  EXPECT_EQ(compared, 18000);
  EXPECT_GT(overflows, 0) << "no case reached a dividend limit";
}

// After use_fast_walk() a pipeline takes the fast walk unless given a fragment sink, except where it
// does not apply: with a texture unit or another depth output.
TEST(FastPath, PipelinesTakeTheFastWalkWhereItApplies) {
  const Profile profile = make_profile(96, 64, 4, Traversal::Span, 24);
  const WalkRunnerChoice before = Pipeline::walk_runner_choice();
  EXPECT_EQ(Pipeline(profile).walk_runner() != nullptr, before != nullptr) << "the choice applies to new pipelines";
  use_fast_walk();
  ASSERT_EQ(Pipeline::walk_runner_choice(), &fast_walk_runner);
  EXPECT_NE(Pipeline(profile).walk_runner(), nullptr);
  Profile textured = profile, biased = profile, float_word = profile;
  textured.texture_unit = true;
  biased.depth_bias_constant = 3;
  float_word.depth_exponent_bits = 4;
  for (const Profile& p : {textured, biased, float_word}) {
    EXPECT_EQ(fast_walk_runner(Pipeline(p)), nullptr) << describe(p);
    EXPECT_EQ(Pipeline(p).walk_runner(), nullptr) << describe(p);
  }
  Pipeline::set_walk_runner_choice(before);
}

// The run kernels compute a plane register's output without a 64-bit arithmetic shift: equal to
// PlaneFormat::output() for every register value, wrapped or not, in or out of the output range,
// rounded or truncated.
TEST(FastPath, UnsignedOutputEqualsOutput) {
  std::mt19937_64 rng(11);
  for (const auto& [reg_bits, guard_bits, out_max] :
       {std::tuple{58, 24, (int64_t(1) << 32) - 1}, std::tuple{41, 16, (int64_t(1) << 24) - 1},
        std::tuple{26, 9, (int64_t(1) << 16) - 1}, std::tuple{30, 21, int64_t(255)}})
  for (const Rounding rounding : {Rounding::Nearest, Rounding::Truncate}) {
    const PlaneFormat format(reg_bits, guard_bits, out_max, rounding);
    const UnsignedPlaneOutput output_unsigned(format);
    for (int i = 0; i < 200000; ++i) {
      // Random words, and values near 0 and near the output's top, where rounding and clamping act.
      const uint64_t word = rng();
      const uint64_t near = uint64_t((int64_t(word % 4096) - 2048) + ((i & 1) ? out_max << guard_bits : 0));
      for (const uint64_t value : {word, near})
        ASSERT_EQ(int64_t(output_unsigned(value)), format.output(value)) << "value " << value;
    }
  }
}

// The setup's divider: a 64-bit division when both operands fit, 128-bit otherwise; checked
// against the definition (n = q d + r, 0 <= r < d) on both sides of 2^64.
TEST(FastPath, FloorDivisionAndBitCountsAgreeWithTheirDefinitions) {
  std::mt19937_64 rng(12);
  for (int i = 0; i < 100000; ++i) {
    const int n_shift = int(rng() % 100), d_shift = int(rng() % 70);
    i128 n = i128((unsigned __int128)rng() << 64 | rng()) >> (27 + n_shift % 100);
    const i128 d = (i128((unsigned __int128)rng() << 64 | rng()) & ((i128(1) << (d_shift + 1)) - 1)) + 1;
    if (i % 7 == 0) n = -n;
    const FloorDiv q = floor_div(n, d);
    ASSERT_TRUE(q.quotient * d + q.remainder == n && q.remainder >= 0 && q.remainder < d)
        << to_string_i128(n) << " / " << to_string_i128(d);
    const i128 v = n < 0 ? -n : n;
    const int bits = unsigned_bits(v);
    ASSERT_TRUE(v < (i128(1) << bits) && (bits == 1 || v >= (i128(1) << (bits - 1)))) << to_string_i128(v);
  }
  EXPECT_EQ(unsigned_bits(0), 1);
  EXPECT_EQ(unsigned_bits(1), 1);
  EXPECT_EQ(unsigned_bits(2), 2);
  EXPECT_EQ(unsigned_bits(i128(1) << 64), 65);
  EXPECT_EQ(unsigned_bits((i128(1) << 64) - 1), 64);
}

// The setup's divider by a reciprocal (FloorDivider): equal to floor_div for every sign and size,
// including divisors 1, powers of two (the reciprocal is then one short) and 2^64 - 1, dividends
// up to 2^64 - 1 (the largest taken by multiplication) and beyond (taken by division).
TEST(FastPath, ReciprocalFloorDivisionEqualsFloorDivision) {
  std::mt19937_64 rng(13);
  const uint64_t max64 = ~uint64_t(0);
  std::vector<i128> divisors = {1, 2, 3, 7, i128(1) << 32, (i128(1) << 63) - 1, i128(1) << 63, i128(max64), i128(1) << 64};
  for (int i = 0; i < 300; ++i) divisors.push_back(i128(rng() >> (rng() % 64)) + 1);
  for (const i128 d : divisors) {
    const FloorDivider divider(d);
    std::vector<i128> dividends = {0, 1, -1, d, -d, d - 1, -(d - 1), d + 1, i128(max64), -i128(max64),
                                   i128(max64) - 1, i128(1) << 64, -(i128(1) << 64), i128(1) << 70};
    for (int i = 0; i < 200; ++i) {
      const i128 n = i128(rng() >> (rng() % 64));
      dividends.push_back(rng() % 2 ? n : -n);
    }
    for (const i128 n : dividends) {
      const FloorDiv expected = floor_div(n, d), got = divider(n);
      ASSERT_TRUE(got.quotient == expected.quotient && got.remainder == expected.remainder)
          << to_string_i128(n) << " / " << to_string_i128(d);
      ASSERT_TRUE(got.quotient * d + got.remainder == n && got.remainder >= 0 && got.remainder < d);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllPaths, FastPath,
                         ::testing::Combine(::testing::Values(Traversal::BBox, Traversal::Span),
                                            ::testing::Values(DepthFunc::Less, DepthFunc::Equal, DepthFunc::GEqual,
                                                              DepthFunc::Always, DepthFunc::Never),
                                            ::testing::Values(1, 2, 5, 64), ::testing::Values(0)));
INSTANTIATE_TEST_SUITE_P(StallPatterns, FastPath,
                         ::testing::Combine(::testing::Values(Traversal::BBox, Traversal::Span),
                                            ::testing::Values(DepthFunc::Less, DepthFunc::Always),
                                            ::testing::Values(1, 5), ::testing::Values(30, 75)));

}  // namespace
}  // namespace rastersim::test
