// Texture coordinates of textured triangles (docs/arithmetic.md section 5): the snapped Q, S, T
// against their defining inequalities, and every covered pixel's divided u, v against a
// perspective-correct reference in long double from the vertices' exact u, v, w and the exact
// pixel centre, within the documented bound 202 rho 2^-P + 2^-20 and 1/256 texel of a 1024-texel
// texture, on random perspective triangles at S = 1, 4 and 8.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>
#include <random>

#include "model/texture_divide.h"
#include "model/pipeline.h"
#include "model/triangle.h"
#include "model/triangle_setup.h"
#include "model/widths.h"

namespace rastersim {
namespace {

constexpr int P = kTextureFractionBits;

// v = m 2^e with m an integer (|m| < 2^64), written without the model's helper.
struct Exact {
  i128 m;
  int e;
};
Exact exact(double v) {
  int e = 0;
  const long double mantissa = std::frexp(static_cast<long double>(v), &e);
  return {i128(std::ldexp(mantissa, 64)), e - 64};
}
// Compares a 2^ea with b 2^eb exactly (a, b integers, the shifted one stays below 2^127).
int compare(i128 a, int ea, i128 b, int eb) {
  if (ea > eb) a *= i128(1) << (ea - eb);  // a product: a left shift of a negative value is undefined
  else b *= i128(1) << (eb - ea);
  return a < b ? -1 : a > b ? 1 : 0;
}

TEST(TextureSnap, QIsTheRoundedScaledInverseOfW) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> log_ratio(0, kMaxTextureWRatioLog2), log_w(-20, 20);
  for (int n = 0; n < 200000; ++n) {
    const double w_min = std::exp2(log_w(rng));
    const double w = n % 1000 == 0 ? w_min : n % 1000 == 1 ? std::ldexp(w_min, kMaxTextureWRatioLog2)
                                                           : w_min * std::exp2(log_ratio(rng));
    if (w > std::ldexp(w_min, kMaxTextureWRatioLog2)) continue;
    const int64_t q = texture_q(w_min, w);
    // q - 1/2 <= 2^P w_min / w < q + 1/2, that is (2q - 1) w <= 2^(P+1) w_min < (2q + 1) w.
    const Exact a = exact(w), b = exact(w_min);
    ASSERT_LE(compare((2 * i128(q) - 1) * a.m, a.e, b.m, b.e + P + 1), 0) << w_min << " " << w;
    ASSERT_LT(compare(b.m, b.e + P + 1, (2 * i128(q) + 1) * a.m, a.e), 0) << w_min << " " << w;
  }
  EXPECT_EQ(texture_q(3.0, 3.0), int64_t(1) << P);
  EXPECT_EQ(texture_q(1.0, 16384.0), int64_t(1) << (P - 14));
  EXPECT_EQ(texture_q(1.0, 3.0), ((int64_t(1) << P) + 1) / 3);  // 2^41 / 3 = 733007751850.67 rounds up
}

TEST(TextureSnap, ScaledCoordinateIsRoundedHalfUp) {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> coordinate(-128, 128);
  std::uniform_int_distribution<int64_t> q_values(int64_t(1) << (P - 14), int64_t(1) << P);
  for (int n = 0; n < 200000; ++n) {
    const double c = n % 3 == 0 ? std::ldexp(std::round(std::ldexp(coordinate(rng), 8)), -8) : coordinate(rng);
    const int64_t q = n % 7 == 0 ? int64_t(1) << P : q_values(rng);
    const int64_t s = texture_scaled(c, q);
    // s - 1/2 <= c q < s + 1/2: (2s - 1) <= 2 c q < (2s + 1), with c = m 2^e.
    const Exact x = exact(c);
    ASSERT_LE(compare(2 * i128(s) - 1, 0, 2 * x.m * q, x.e), 0) << c << " " << q;
    ASSERT_LT(compare(2 * x.m * q, x.e, 2 * i128(s) + 1, 0), 0) << c << " " << q;
  }
  EXPECT_EQ(texture_scaled(0.5, 3), 2);    // 1.5 rounds half up
  EXPECT_EQ(texture_scaled(-0.5, 3), -1);  // -1.5 too
  EXPECT_EQ(texture_scaled(1e-300, int64_t(1) << P), 0);
  EXPECT_EQ(texture_scaled(-1e-300, int64_t(1) << P), 0);
}

TEST(TextureSnap, WRatioAboveTheLimitIsBadInput) {
  Profile profile;
  profile.texture_unit = true;
  ScreenTriangle tri;
  tri.textured = true;
  tri.v[0] = {10, 10, 0.5, {}, 0, 0, 2.0};
  tri.v[1] = {100, 10, 0.5, {}, 1, 0, 2.0 * 16384};
  tri.v[2] = {10, 100, 0.5, {}, 0, 1, 3.0};
  EXPECT_EQ(check_screen_triangle(tri, profile), "");
  tri.v[1].w = std::nextafter(2.0 * 16384, 1e9);
  EXPECT_NE(check_screen_triangle(tri, profile).find("more than 16384 times the smallest"), std::string::npos)
      << check_screen_triangle(tri, profile);
  profile.texture_unit = false;  // the limit is the texture unit's: without it w means nothing
  EXPECT_EQ(check_screen_triangle(tri, profile), "");
  profile.texture_unit = true;
  tri.textured = false;  // nor without texture coordinates
  EXPECT_EQ(check_screen_triangle(tri, profile), "");
}

struct ErrorStats {
  long double worst_over_bound = 0;  // largest |u - u*| / bound seen
  long double worst_texels = 0;      // largest |u - u*| 2^10
  int64_t fragments = 0;
};

// The u, v the setup's planes give every covered pixel, in the absolute form.
struct PixelCoordinate {
  int x, y;
  TextureCoordinate uv;
};
std::vector<PixelCoordinate> absolute_coordinates(const SetupResult& r, const Widths& w) {
  std::vector<PixelCoordinate> out;
  for (int y = r.y0; y <= r.y1; ++y)
    for (int x = r.x0; x <= r.x1; ++x) {
      const int64_t i = x - r.x0, j = y - r.y0;
      bool covered = true;
      for (const EdgeSetup& e : r.edge) covered = covered && int64_t(e.start) + i * e.step_x + j * e.step_y >= 0;
      if (!covered) continue;
      auto reg = [&](const PlaneSetup& p) {
        return wrap_signed(i128(p.start) + i128(i) * p.step_x + i128(j) * p.step_y, w.texture_reg_bits);
      };
      out.push_back({x, y, perspective_divide(reg(r.texture[0]), reg(r.texture[1]), reg(r.texture[2]), w.texture_divide_shift)});
    }
  return out;
}

// Every covered pixel of one triangle: its u, v from the setup's planes (register values in the
// absolute form the walker's additions equal, docs/arithmetic.md section 3) against the reference.
void check_triangle(const ScreenTriangle& tri, const Profile& profile, bool perspective, ErrorStats& stats) {
  Profile textured = profile;
  textured.texture_unit = true, textured.perspective = perspective;
  const TriangleSetup setup(textured);
  const SetupResult r = setup.run(snap(tri, textured));
  if (r.status != SetupStatus::Drawn) return;
  ASSERT_TRUE(r.textured);
  double w_min = 1, w_max = 1;
  if (perspective) {
    w_min = std::min({tri.v[0].w, tri.v[1].w, tri.v[2].w});
    w_max = std::max({tri.v[0].w, tri.v[1].w, tri.v[2].w});
  }
  const long double rho = static_cast<long double>(w_max) / w_min;
  const long double bound = 202 * rho * std::ldexp(1.0L, -P) + std::ldexp(1.0L, -kUvFracBits);
  const long double one_256th_texel = std::ldexp(1.0L, -8 - kMaxTextureLog2);
  // The vertices' screen positions are on the subpixel grid: these doubles are the snapped ones.
  const ScreenVertex* v = tri.v;
  auto edge = [&](int a, int b, long double px, long double py) {
    return (static_cast<long double>(v[b].x) - v[a].x) * (py - v[a].y) -
           (static_cast<long double>(v[b].y) - v[a].y) * (px - v[a].x);
  };
  for (const auto& [x, y, got] : absolute_coordinates(r, setup.widths())) {
    // Barycentric weights of the centre: b_k = E_{k+1 -> k+2}(centre) / (2 area), either winding.
    const long double px = x + 0.5L, py = y + 0.5L;
    const long double area = edge(0, 1, v[2].x, v[2].y);
    const long double b[3] = {edge(1, 2, px, py) / area, edge(2, 0, px, py) / area, edge(0, 1, px, py) / area};
    long double num_u = 0, num_v = 0, den = 0;
    for (int k = 0; k < 3; ++k) {
      const long double weight = b[k] / (perspective ? static_cast<long double>(v[k].w) : 1.0L);
      num_u += weight * v[k].u, num_v += weight * v[k].v, den += weight;
    }
    for (const auto& [value, exact_value] : {std::make_pair(got.u, num_u / den), std::make_pair(got.v, num_v / den)}) {
      const long double error = std::fabs(std::ldexp(static_cast<long double>(value), -kUvFracBits) - exact_value);
      ASSERT_LE(error, bound) << "pixel " << x << "," << y << " rho " << double(rho);
      ASSERT_LE(error, one_256th_texel) << "pixel " << x << "," << y << " rho " << double(rho);
      stats.worst_over_bound = std::max(stats.worst_over_bound, error / bound);
      stats.worst_texels = std::max(stats.worst_texels, std::ldexp(error, kMaxTextureLog2));
    }
    ++stats.fragments;
  }
}

// Random triangles on the subpixel grid of a 96 x 64 screen (some reaching its corners), w ratios
// up to 2^14 (a third at the limit), coordinates small or near +-128.
void check_random_triangles(int subpixel_bits, bool perspective) {
  Profile profile;
  profile.width = 96, profile.height = 64, profile.subpixel_bits = subpixel_bits;
  std::mt19937_64 rng(1000 + subpixel_bits + (perspective ? 0 : 50));
  const double grid = std::ldexp(1.0, -subpixel_bits);
  std::uniform_real_distribution<double> px(0, profile.width), py(0, profile.height), unit(0, 1);
  std::uniform_real_distribution<double> small(-4, 4), large(-127.99, 127.99), log_w(-3, 3);
  ErrorStats stats;
  for (int n = 0; n < 3000; ++n) {
    ScreenTriangle tri;
    tri.textured = true;
    const double w_min = std::exp2(log_w(rng));
    const bool large_coordinates = n % 2 == 1;
    for (int k = 0; k < 3; ++k) {
      ScreenVertex& vertex = tri.v[k];
      vertex.x = std::round(px(rng) / grid) * grid;
      vertex.y = std::round(py(rng) / grid) * grid;
      vertex.z = unit(rng);
      vertex.u = large_coordinates ? large(rng) : small(rng);
      vertex.v = large_coordinates ? large(rng) : small(rng);
      const double log_ratio = n % 3 == 0 ? (k == 0 ? 0 : k == 1 ? kMaxTextureWRatioLog2 : unit(rng) * 14)
                                          : unit(rng) * kMaxTextureWRatioLog2;
      vertex.w = w_min * std::exp2(log_ratio);
    }
    ASSERT_EQ(check_screen_triangle(tri, profile), "");
    check_triangle(tri, profile, perspective, stats);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(stats.fragments, 100000);
  std::printf("S = %d, %s: %lld fragments, worst error %.6Lg of the bound, %.3Lg texel of 1024\n", subpixel_bits,
              perspective ? "perspective" : "affine", static_cast<long long>(stats.fragments),
              stats.worst_over_bound, stats.worst_texels);
}

TEST(TexturePlanes, PerspectiveCoordinatesWithinTheBoundAtS1) { check_random_triangles(1, true); }
TEST(TexturePlanes, PerspectiveCoordinatesWithinTheBoundAtS4) { check_random_triangles(4, true); }
TEST(TexturePlanes, PerspectiveCoordinatesWithinTheBoundAtS8) { check_random_triangles(8, true); }
TEST(TexturePlanes, AffineCoordinatesWithinTheBound) { check_random_triangles(4, false); }

// Without perspective every Q is 2^P: the Q plane is constant and u is the affine mean.
TEST(TexturePlanes, AffineQPlaneIsConstant) {
  Profile profile;
  ScreenTriangle tri;
  tri.textured = true;
  tri.v[0] = {10, 10, 0.5, {}, 0.25, 0, 1.0};
  tri.v[1] = {100, 20, 0.5, {}, 1, 0.5, 50.0};
  tri.v[2] = {30, 90, 0.5, {}, 0, 1, 3.0};
  profile.texture_unit = true, profile.perspective = false;
  const SetupResult r = TriangleSetup(profile).run(snap(tri, profile));
  const int Ft = derive_widths(profile).texture_guard_bits;
  EXPECT_EQ(int64_t(r.texture[2].start), int64_t(1) << (P + Ft));
  EXPECT_EQ(int64_t(r.texture[2].step_x), 0);
  EXPECT_EQ(int64_t(r.texture[2].step_y), 0);
}

TEST(PerspectiveDivide, FloorsAndClamps) {
  const int64_t q = int64_t(3) << 20;
  EXPECT_EQ(divide_texture_coordinate(int64_t(1) << 20, q), 349525);    // 2^20 / 3 = 349525.33
  EXPECT_EQ(divide_texture_coordinate(-(int64_t(1) << 20), q), -349526);  // floor, not toward zero
  EXPECT_EQ(divide_texture_coordinate(int64_t(128) * q, q), (1 << 27) - 1);  // 128 clamps
  EXPECT_EQ(divide_texture_coordinate(-int64_t(128) * q, q), -(1 << 27));   // -128 is representable
  EXPECT_THROW(divide_texture_coordinate(1, 0), WidthOverflow);
}

// The registers' low bits dropped before the divide are floors of both operands: (-2^20 - 1) / 2^3
// floors to -2^17 - 1 and (3 2^20 + 7) / 2^3 to 3 2^17, and (-2^37 - 2^20) / (3 2^17) = -349528
// exactly (a dividend shifted toward zero would give floor(-2^20 / 3) = -349526).
TEST(PerspectiveDivide, DropsLowBitsAsFloors) {
  const TextureCoordinate uv = perspective_divide(-(int64_t(1) << 20) - 1, int64_t(1) << 20, (int64_t(3) << 20) + 7, 3);
  EXPECT_EQ(uv.u, -349528);
  EXPECT_EQ(uv.v, 349525);
  EXPECT_THROW(perspective_divide(0, 0, 7, 3), WidthOverflow);  // 7 / 2^3 floors to 0
}

// The divide keeps 4 of the texture registers' guard bits: none dropped up to Ft = 4.
TEST(PerspectiveDivide, ShiftKeepsFourGuardBits) {
  EXPECT_EQ(derive_widths(4, 2, 4, 24, 0).texture_guard_bits, 4);
  EXPECT_EQ(derive_widths(4, 2, 4, 24, 0).texture_divide_shift, 0);
  EXPECT_EQ(derive_widths(640, 480, 4, 24, 0).texture_guard_bits, 12);
  EXPECT_EQ(derive_widths(640, 480, 4, 24, 0).texture_divide_shift, 8);
  EXPECT_EQ(derive_widths(4096, 4096, 4, 24, 0).texture_divide_shift, 10);
}

}  // namespace
}  // namespace rastersim

namespace rastersim {
namespace {

struct Collect : FragmentSink {
  std::vector<Fragment> fragments;
  void on_fragment(const Fragment& f) override { fragments.push_back(f); }
};

// The walker steps the S, T, Q registers with the others (x steps, rows, span starts on left
// edges): every fragment the pipeline reports carries the u, v of the absolute form, in both
// traversals, and an untextured triangle's fragments none.
TEST(TexturePlanes, PipelineFragmentsCarryTheAbsoluteFormsCoordinates) {
  for (Traversal traversal : {Traversal::BBox, Traversal::Span}) {
    Profile profile;
    profile.width = 96, profile.height = 64, profile.traversal = traversal;
    profile.depth_func = DepthFunc::Always;
    profile.texture_unit = true;
    Pipeline pipeline(profile);
    Collect sink;
    pipeline.set_fragment_sink(&sink);
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> px(-20, 116), py(-20, 84), coordinate(-127, 127), log_w(0, 14);
    int64_t textured_fragments = 0;
    for (int n = 0; n < 400; ++n) {
      ScreenTriangle tri;
      tri.textured = n % 5 != 0;
      for (ScreenVertex& v : tri.v) v = {px(rng), py(rng), 0.5, {}, coordinate(rng), coordinate(rng), std::exp2(log_w(rng))};
      ASSERT_EQ(check_screen_triangle(tri, profile), "");
      sink.fragments.clear();
      pipeline.submit(snap(tri, profile));
      std::map<std::pair<int, int>, TextureCoordinate> want;
      if (tri.textured)
        for (const PixelCoordinate& p : absolute_coordinates(pipeline.last_setup(), pipeline.widths()))
          want[{p.x, p.y}] = p.uv;
      for (const Fragment& f : sink.fragments) {
        ASSERT_EQ(f.textured, tri.textured);
        if (!tri.textured) continue;
        const auto it = want.find({f.x, f.y});
        ASSERT_NE(it, want.end()) << "pixel " << f.x << "," << f.y;
        ASSERT_EQ(f.uv.u, it->second.u) << "triangle " << n << " pixel " << f.x << "," << f.y;
        ASSERT_EQ(f.uv.v, it->second.v) << "triangle " << n << " pixel " << f.x << "," << f.y;
        ++textured_fragments;
      }
      if (tri.textured) {
        ASSERT_EQ(int64_t(sink.fragments.size()), int64_t(want.size())) << "triangle " << n;
      }
    }
    EXPECT_GT(textured_fragments, 50000);
  }
}

}  // namespace
}  // namespace rastersim
