// The conventions a design may choose differently (docs/arithmetic.md section 7), beyond coverage
// (tests/test_coverage.cpp and test_watertight.cpp run every pixel_center and fill_rule):
// - vertex_snap: each rule equals its definition computed another way (long double arithmetic,
//   exact for these values), on random coordinates and on ties;
// - depth_rounding and color_rounding: every fragment's output is the rule applied to its plane
//   register (the absolute form), and lies within the stated bound of the exact plane value at the
//   sample point, for both pixel centres;
// - rastersim's RTL refuses every convention it does not have, naming the key.
#include <gtest/gtest.h>

#include <cfenv>
#include <cmath>
#include <random>

#include "model/core_parameters.h"
#include "model/pipeline.h"
#include "reference.h"
#include "test_util.h"

namespace rastersim {
namespace {

using test::describe;
using test::TriangleGen;

// The rule's definition on a = x 2^S in long double (64-bit mantissa: a + 1/2 is exact for the
// doubles of the guard band).
int64_t snapped_by_definition(double x, int S, VertexSnap rule) {
  const long double a = std::ldexp(static_cast<long double>(x), S);
  switch (rule) {
    case VertexSnap::Nearest: return int64_t(std::floor(a + 0.5L));
    case VertexSnap::NearestEven: {
      const int mode = std::fegetround();
      std::fesetround(FE_TONEAREST);
      const long double r = std::nearbyint(a);
      std::fesetround(mode);
      return int64_t(r);
    }
    case VertexSnap::Floor: return int64_t(std::floor(a));
    case VertexSnap::TowardZero: return int64_t(std::trunc(a));
  }
  return 0;
}

TEST(Conventions, EveryVertexSnapEqualsItsDefinition) {
  std::mt19937_64 rng(41);
  int ties = 0;
  for (int S = 1; S <= 8; ++S)
    for (int i = 0; i < 20000; ++i) {
      const int64_t k = int64_t(rng() % 2000001) - 1000000;
      // Every third value is a tie (an odd number of half subpixels), the others anywhere.
      const double x = i % 3 == 0 ? std::ldexp(double(2 * k + 1), -S - 1)
                                  : std::uniform_real_distribution<double>(-5000, 10000)(rng);
      ties += i % 3 == 0;
      for (VertexSnap rule : {VertexSnap::Nearest, VertexSnap::NearestEven, VertexSnap::Floor, VertexSnap::TowardZero})
        ASSERT_EQ(snap_coordinate(x, S, rule), snapped_by_definition(x, S, rule))
            << "x " << x << " S " << S << " " << to_string(rule);
    }
  EXPECT_GT(ties, 50000);
  // The rules differ where they should: a positive and a negative tie.
  EXPECT_EQ(snap_coordinate(0.75, 1, VertexSnap::Nearest), 2);      // 1.5
  EXPECT_EQ(snap_coordinate(0.75, 1, VertexSnap::NearestEven), 2);
  EXPECT_EQ(snap_coordinate(1.25, 1, VertexSnap::NearestEven), 2);  // 2.5
  EXPECT_EQ(snap_coordinate(-1.25, 1, VertexSnap::Nearest), -2);    // -2.5
  EXPECT_EQ(snap_coordinate(-1.25, 1, VertexSnap::Floor), -3);
  EXPECT_EQ(snap_coordinate(-1.25, 1, VertexSnap::TowardZero), -2);
}

// snap() applies the profile's rule to x and y.
TEST(Conventions, SnapTakesTheProfilesRule) {
  Profile p;
  p.subpixel_bits = 1;
  ScreenTriangle t{};
  for (ScreenVertex& v : t.v) v.x = -1.25, v.y = 1.25, v.z = 0.5;
  p.vertex_snap = VertexSnap::Floor;
  EXPECT_EQ(snap(t, p).v[0].x, -3);
  EXPECT_EQ(snap(t, p).v[0].y, 2);
  p.vertex_snap = VertexSnap::TowardZero;
  EXPECT_EQ(snap(t, p).v[0].x, -2);
  p.vertex_snap = VertexSnap::NearestEven;
  EXPECT_EQ(snap(t, p).v[0].y, 2);
  p.vertex_snap = VertexSnap::Nearest;
  EXPECT_EQ(snap(t, p).v[0].y, 3);
}

// Where an output may lie against the exact value P = num / den: nearest within 1 (strictly),
// truncate in (P - 3/2, P] (docs/arithmetic.md section 7).
bool within_bound(int64_t out, const reference::Rational& exact, Rounding rounding) {
  if (rounding == Rounding::Nearest) return reference::within_one_lsb(out, exact);
  const __int128 twice_diff = 2 * (__int128(out) * exact.den - exact.num);  // 2 (out - P) den
  return twice_diff <= 0 && twice_diff > -3 * exact.den;
}

struct RoundingChecker : FragmentSink {
  Profile profile;
  SetupResult setup;
  SnappedTriangle tri{};
  int guard_bits = 0;
  Widths widths{};
  int64_t checked = 0, truncated_lower = 0;
  std::string first_error;
  void on_fragment(const Fragment& f) override {
    if (!first_error.empty()) return;
    ++checked;
    const PlaneSetup* planes[4] = {&setup.depth, &setup.color[0], &setup.color[1], &setup.color[2]};
    const uint8_t Rgb::*channels[3] = {&Rgb::r, &Rgb::g, &Rgb::b};
    for (int k = 0; k < 4; ++k) {
      const Rounding rounding = k == 0 ? profile.depth_rounding : profile.color_rounding;
      const int64_t max = k == 0 ? int64_t(profile.depth_max()) : 255;
      const int64_t out = k == 0 ? int64_t(f.z) : int64_t(f.color.*channels[k - 1]);
      // The register holds the absolute form modulo 2^reg_bits (docs/arithmetic.md section 4).
      const int64_t value = int64_t(wrap_signed(reference::absolute_plane(*planes[k], setup, f.x, f.y),
                                                k == 0 ? widths.z_reg_bits : widths.color_reg_bits));
      uint32_t v[3];
      for (int i = 0; i < 3; ++i) v[i] = k == 0 ? tri.v[i].z : tri.v[i].color.*channels[k - 1];
      const reference::Rational exact = reference::plane_at_sample(tri, v, profile, f.x, f.y);
      const int64_t by_rule = reference::rounded_plane_output(value, guard_bits, max, rounding);
      if (out != by_rule || !within_bound(out, exact, rounding)) {
        first_error = "pixel (" + std::to_string(f.x) + ", " + std::to_string(f.y) + ") plane " + std::to_string(k) +
                      ": output " + std::to_string(out) + ", the rule gives " + std::to_string(by_rule) + ", exact " +
                      std::to_string(double(exact.num) / double(exact.den));
        return;
      }
      if (rounding == Rounding::Truncate && out != reference::rounded_plane_output(value, guard_bits, max))
        ++truncated_lower;
    }
  }
};

class Rounding_ : public ::testing::TestWithParam<std::tuple<PixelCenter, Rounding, Rounding, Traversal>> {};

TEST_P(Rounding_, OutputsFollowTheRuleAndItsBound) {
  const auto [center, depth_rounding, color_rounding, traversal] = GetParam();
  for (const auto& [width, height, S, z_bits] : {std::tuple{64, 48, 4, 16}, std::tuple{640, 480, 8, 24},
                                                 std::tuple{1000, 700, 1, 32}}) {
    Profile p = test::make_profile(width, height, S, traversal, z_bits);
    p.pixel_center = center;
    p.depth_rounding = depth_rounding;
    p.color_rounding = color_rounding;
    SCOPED_TRACE(describe(p));
    Pipeline pipe(p);
    RoundingChecker checker;
    checker.profile = p;
    checker.guard_bits = pipe.widths().guard_bits;
    checker.widths = pipe.widths();
    pipe.set_fragment_sink(&checker);
    const TriangleSetup setup(p);
    TriangleGen gen(p, uint64_t(width) + 3 * uint64_t(center) + 5 * uint64_t(depth_rounding) + 7 * uint64_t(color_rounding));
    for (int n = 0; n < 300; ++n) {
      const SnappedTriangle t = n % 3 ? gen.near_screen(20) : n % 2 ? gen.on_centres(8) : gen.sliver(40);
      checker.tri = t;
      checker.setup = setup.run(t);
      pipe.submit(t);
      ASSERT_EQ(checker.first_error, "") << describe(t);
    }
    EXPECT_GT(checker.checked, 2000);
    // Truncation must really differ from rounding on some outputs, or the test shows nothing.
    if (depth_rounding == Rounding::Truncate || color_rounding == Rounding::Truncate) {
      EXPECT_GT(checker.truncated_lower, 100);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(CentresRoundingsTraversals, Rounding_,
                         ::testing::Combine(::testing::Values(PixelCenter::Half, PixelCenter::Corner),
                                            ::testing::Values(Rounding::Nearest, Rounding::Truncate),
                                            ::testing::Values(Rounding::Nearest, Rounding::Truncate),
                                            ::testing::Values(Traversal::BBox, Traversal::Span)),
                         [](const auto& info) {
                           return std::string(to_string(std::get<0>(info.param))) + "_depth_" +
                                  to_string(std::get<1>(info.param)) + "_color_" + to_string(std::get<2>(info.param)) +
                                  "_" + to_string(std::get<3>(info.param));
                         });

// Every convention but the host's snapping is a build parameter of rastersim's core
// (docs/rtl.md), numbered as its enum.
TEST(Conventions, EachConventionOfTheCoreIsABuildParameter) {
  Profile p;
  p.pixel_center = PixelCenter::Corner;
  p.fill_rule = FillRule::BottomRight;
  p.depth_rounding = Rounding::Truncate;
  p.color_rounding = Rounding::Truncate;
  const CoreParameters core = core_parameters(p);
  EXPECT_EQ(parameter_value(core, "PIXEL_CENTER"), 1);
  EXPECT_EQ(parameter_value(core, "FILL_RULE"), 3);
  EXPECT_EQ(parameter_value(core, "DEPTH_ROUNDING"), 1);
  EXPECT_EQ(parameter_value(core, "COLOR_ROUNDING"), 1);
  for (const char* name : {"PIXEL_CENTER", "FILL_RULE", "DEPTH_ROUNDING", "COLOR_ROUNDING"})
    EXPECT_EQ(parameter_value(core_parameters(Profile{}), name), 0) << name;
  Profile snapped;  // snapping is the host's: the RTL takes snapped words
  snapped.vertex_snap = VertexSnap::TowardZero;
  EXPECT_EQ(core_parameters(snapped), core_parameters(Profile{}));
}

// cosim's profile line names the conventions that are not rastersim's.
TEST(Conventions, TextNamesTheOnesThatDiffer) {
  Profile p;
  EXPECT_EQ(conventions_text(p), "");
  p.pixel_center = PixelCenter::Corner;
  p.vertex_snap = VertexSnap::Floor;
  p.color_rounding = Rounding::Truncate;
  EXPECT_EQ(conventions_text(p), "pixel_center corner, vertex_snap floor, color_rounding truncate");
}

}  // namespace
}  // namespace rastersim
