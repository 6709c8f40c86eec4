// Depth and colour accuracy: every fragment's z, and every Gouraud channel, lies strictly within
// 1 LSB of the exact plane through the three vertex values at the pixel centre (exact rationals in
// tests/reference.h), anywhere on the largest screen (4096 x 4096, S = 8) and for z_bits 16, 24, 32:
// random triangles, slivers with huge gradients, far bounding-box starts, extreme depths.
#include <gtest/gtest.h>

#include <sstream>
#include <tuple>

#include "model/pipeline.h"
#include "reference.h"
#include "test_util.h"

namespace rastersim {
namespace {

using test::describe;
using test::TriangleGen;

std::string rational_text(const reference::Rational& r) {
  std::ostringstream out;
  out << double(r.num) / double(r.den) << " (" << to_string_i128(r.num) << "/" << to_string_i128(r.den) << ")";
  return out.str();
}

// Checks every `stride`-th fragment of the current triangle against the exact planes.
struct PlaneChecker : FragmentSink {
  SnappedTriangle tri{};
  int subpixel_bits = 0;
  int64_t stride = 1;
  int64_t seen = 0, checked = 0;
  std::string first_error;
  void start(const SnappedTriangle& t, int64_t every) {
    tri = t, stride = every, seen = checked = 0, first_error.clear();
  }
  void on_fragment(const Fragment& f) override {
    if (seen++ % stride != 0 || !first_error.empty()) return;
    ++checked;
    const uint32_t z[3] = {tri.v[0].z, tri.v[1].z, tri.v[2].z};
    const reference::Rational exact_z = reference::plane_at_centre(tri, z, subpixel_bits, f.x, f.y);
    if (!reference::within_one_lsb(f.z, exact_z)) {
      std::ostringstream out;
      out << "pixel (" << f.x << ", " << f.y << "): z " << f.z << ", exact " << rational_text(exact_z);
      first_error = out.str();
      return;
    }
    const uint8_t Rgb::*channels[3] = {&Rgb::r, &Rgb::g, &Rgb::b};
    for (int c = 0; c < 3; ++c) {
      const uint32_t value[3] = {tri.v[0].color.*channels[c], tri.v[1].color.*channels[c], tri.v[2].color.*channels[c]};
      const reference::Rational exact = reference::plane_at_centre(tri, value, subpixel_bits, f.x, f.y);
      if (!reference::within_one_lsb(f.color.*channels[c], exact)) {
        std::ostringstream out;
        out << "pixel (" << f.x << ", " << f.y << "): colour channel " << "rgb"[c] << " "
            << int(f.color.*channels[c]) << ", exact " << rational_text(exact);
        first_error = out.str();
        return;
      }
    }
  }
};

class DepthAccuracy : public ::testing::TestWithParam<std::tuple<int, Traversal>> {};

TEST_P(DepthAccuracy, WithinOneLsbOfTheExactPlaneOn4096S8) {
  const auto [z_bits, traversal] = GetParam();
  const Profile p = test::make_profile(4096, 4096, 8, traversal, z_bits);
  const uint64_t seed = 31 * uint64_t(z_bits) + uint64_t(traversal);
  SCOPED_TRACE(::testing::Message() << describe(p) << " seed " << seed);
  Pipeline pipe(p);
  PlaneChecker checker;
  checker.subpixel_bits = p.subpixel_bits;
  pipe.set_fragment_sink(&checker);
  TriangleGen gen(p, seed);
  const int64_t M = gen.M(), W = int64_t(p.width) * M, H = int64_t(p.height) * M;
  const uint32_t z_max = p.depth_max();
  int64_t total_checked = 0;
  auto run = [&](SnappedTriangle t, int64_t stride, const char* family) {
    checker.start(t, stride);
    pipe.submit(t);
    ASSERT_EQ(checker.first_error, "") << family << " " << describe(t);
    total_checked += checker.checked;
  };
  auto extreme = [&](SnappedTriangle t) {  // vertex depths and colours at the ends of their ranges
    for (SnappedVertex& v : t.v) {
      v.z = gen.coin() ? z_max : 0;
      v.color = gen.coin() ? Rgb{255, 0, 255} : Rgb{0, 255, 0};
    }
    return t;
  };
  for (int n = 0; n < 200; ++n) run(gen.near_screen(40), 1, "medium");
  for (int n = 0; n < 200; ++n) run(extreme(gen.tiny()), 1, "tiny, extreme depths");
  // Slivers: two far-apart vertices and a third one to three subpixels (or up to two pixels) off
  // their edge, depth 0 along the edge and the maximum at the third vertex: huge gradients.
  for (int n = 0; n < 60; ++n) {
    SnappedTriangle t = gen.sliver(3000);
    if (n % 2) t.v[2].x += int32_t(gen.uniform(-2 * M, 2 * M)), t.v[2].y += int32_t(gen.uniform(-2 * M, 2 * M));
    t.v[2].x = int32_t(gen.clamp_x(t.v[2].x)), t.v[2].y = int32_t(gen.clamp_y(t.v[2].y));
    t.v[0].z = t.v[1].z = 0, t.v[2].z = z_max;
    run(t, 1, "sliver with a huge gradient");
  }
  // Anti-diagonal slivers: the bounding box is the whole screen, its first candidate (0, 0) is far
  // from every covered pixel, so the plane start is a far extrapolation that wraps.
  for (int n = 0; n < 8; ++n) {
    const int64_t off = gen.uniform(1, 3 * M);
    SnappedTriangle t = gen.triangle(W - gen.uniform(0, M), gen.uniform(0, M), gen.uniform(0, M), H - gen.uniform(0, M),
                                     W / 2 + off, H / 2 + off);
    run(n % 2 ? extreme(t) : t, 1, "anti-diagonal sliver");
  }
  // Huge triangles (guard band), every 97th fragment.
  for (int n = 0; n < 4; ++n) run(n % 2 ? extreme(gen.guard_band()) : gen.guard_band(), 97, "guard band");
  EXPECT_GT(total_checked, 100000);
}

INSTANTIATE_TEST_SUITE_P(ZBitsAndTraversals, DepthAccuracy,
                         ::testing::Combine(::testing::Values(16, 24, 32),
                                            ::testing::Values(Traversal::BBox, Traversal::Span)),
                         [](const auto& info) {
                           return "N" + std::to_string(std::get<0>(info.param)) + "_" +
                                  to_string(std::get<1>(info.param));
                         });

// With fewer guard bits than derived the bound is not promised (docs/arithmetic.md, section 4):
// the test above must be able to see an error of 1 LSB or more. A long row with a gradient whose
// floor error accumulates shows it at F = 1.
TEST(DepthAccuracyProbe, TooFewGuardBitsAreVisible) {
  Profile p = test::make_profile(4096, 16, 8, Traversal::Span, 16);
  p.z_guard_bits = 1;
  Pipeline pipe(p);
  PlaneChecker checker;
  checker.subpixel_bits = p.subpixel_bits;
  pipe.set_fragment_sink(&checker);
  TriangleGen gen(p, 5);
  int failures = 0;
  for (int n = 0; n < 50; ++n) {
    const SnappedTriangle t = gen.triangle(0, 0, 4096 * 256, 0, 0, 16 * 256);
    checker.start(t, 1);
    pipe.submit(t);
    failures += !checker.first_error.empty();
  }
  EXPECT_GT(failures, 0);
}

}  // namespace
}  // namespace rastersim
