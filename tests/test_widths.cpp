// Register widths at the extremes (docs/widths.md).
// - Every width derive_widths gives holds the exact maximum of its quantity, found here by brute
//   force over the extreme points (each quantity is affine in every vertex, in the pixel centre and
//   in each vertex depth separately, so its extremes are at the corners of their ranges).
// - With the model's width checks on, the setup never throws for the largest profile on triangles
//   at the range limits.
// - The checks can fire: values just outside a width, and vertices outside the guard band.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "model/fixed.h"
#include "model/pipeline.h"
#include "model/triangle_setup.h"
#include "model/widths.h"
#include "test_util.h"

namespace rastersim {
namespace {

using i128 = __int128;

struct P2 {
  i128 x, y;
};

i128 cross(P2 a, P2 b, P2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }
i128 magnitude(i128 v) { return v < 0 ? -v : v; }

// Smallest two's-complement width holding v (counted independently of model/fixed.h).
int bits_for_signed(i128 v) {
  int bits = 1;
  while (v < -(i128(1) << (bits - 1)) || v >= (i128(1) << (bits - 1))) ++bits;
  return bits;
}
int bits_for_unsigned(i128 v) {
  int bits = 1;
  while (v >= (i128(1) << bits)) ++bits;
  return bits;
}

struct Extremes {
  i128 coord_max = 0, delta_max = 0, area_max = 0, product_max = 0, edge_max = 0;
  i128 step_x_max = 0, step_y_max = 0, dividend_max = 0;
};

// Exact maxima over vertices at the guard band's corners, pixel centres at the screen's corner
// centres and vertex depths in {0, Zmax}.
Extremes exact_extremes(int W, int H, int S, int N, int F) {
  const i128 M = i128(1) << S, h = M / 2, z_max = (i128(1) << N) - 1;
  const std::vector<P2> guard = {{-W * M, -H * M}, {2 * W * M, -H * M}, {-W * M, 2 * H * M}, {2 * W * M, 2 * H * M}};
  const std::vector<P2> centres = {{h, h}, {W * M - h, h}, {h, H * M - h}, {W * M - h, H * M - h}};
  Extremes e;
  for (const P2& a : guard) {
    e.coord_max = std::max({e.coord_max, magnitude(a.x), magnitude(a.y)});
    for (const P2& b : guard) {
      e.delta_max = std::max({e.delta_max, magnitude(b.x - a.x), magnitude(b.y - a.y)});
      e.step_x_max = std::max(e.step_x_max, magnitude((b.y - a.y) * M));
      e.step_y_max = std::max(e.step_y_max, magnitude((b.x - a.x) * M));
      for (const P2& p : centres) e.edge_max = std::max(e.edge_max, magnitude(cross(a, b, p)));
      for (const P2& c : guard) {
        e.area_max = std::max(e.area_max, magnitude(cross(a, b, c)));
        e.product_max = std::max(e.product_max, magnitude((b.x - a.x) * (c.y - a.y)));
        const P2 v[3] = {a, b, c};
        for (int zs = 0; zs < 8; ++zs) {
          const i128 z[3] = {zs & 1 ? z_max : 0, zs & 2 ? z_max : 0, zs & 4 ? z_max : 0};
          // Plane dividends: 2^F (Z0 E1 + Z1 E2 + Z2 E0) at a centre, and the step numerators.
          i128 step_x = 0, step_y = 0;
          for (int k = 0; k < 3; ++k) {
            const P2& ea = v[(k + 1) % 3];
            const P2& eb = v[(k + 2) % 3];
            step_x += z[k] * (-(eb.y - ea.y) * M);
            step_y += z[k] * ((eb.x - ea.x) * M);
          }
          e.dividend_max = std::max({e.dividend_max, magnitude(step_x) << F, magnitude(step_y) << F});
          for (const P2& p : centres) {
            i128 start = 0;
            for (int k = 0; k < 3; ++k) start += z[k] * cross(v[(k + 1) % 3], v[(k + 2) % 3], p);
            e.dividend_max = std::max(e.dividend_max, magnitude(start) << F);
          }
        }
      }
    }
  }
  return e;
}

struct ProfileCase {
  int width, height, S, N, F;
};

TEST(Widths, DerivedWidthsHoldTheExactMaxima) {
  const ProfileCase cases[] = {{4096, 4096, 8, 32, 0}, {4096, 4096, 8, 32, 24}, {640, 480, 4, 24, 0}, {16, 12, 4, 16, 0},
                               {1, 1, 1, 16, 0},       {4096, 1, 8, 16, 0},     {1, 4096, 1, 32, 0},  {1920, 1080, 8, 24, 0},
                               {64, 48, 1, 16, 3}};
  for (const ProfileCase& c : cases) {
    const Widths w = derive_widths(c.width, c.height, c.S, c.N, c.F);
    SCOPED_TRACE(::testing::Message() << c.width << "x" << c.height << " S=" << c.S << " N=" << c.N << " F=" << c.F);
    const int F = w.guard_bits;
    if (c.F > 0) {
      EXPECT_EQ(F, c.F);
    }
    const Extremes e = exact_extremes(c.width, c.height, c.S, c.N, F);
    const i128 M = i128(1) << c.S;
    EXPECT_GE(w.coord_bits, bits_for_signed(e.coord_max));
    EXPECT_GE(w.coord_bits, bits_for_signed(-e.coord_max));
    EXPECT_GE(w.delta_bits, bits_for_signed(e.delta_max));
    EXPECT_GE(w.delta_bits, bits_for_signed(-e.delta_max));
    EXPECT_GE(w.area_bits, bits_for_signed(e.area_max));
    EXPECT_GE(w.area_bits, bits_for_signed(-e.area_max));
    EXPECT_GE(w.area_bits, bits_for_signed(e.product_max));
    EXPECT_GE(w.area_bits, bits_for_signed(-e.product_max));
    // The biased edge value reaches -(max) - 1.
    EXPECT_GE(w.edge_bits, bits_for_signed(-e.edge_max - 1));
    EXPECT_GE(w.edge_bits, bits_for_signed(e.edge_max));
    EXPECT_GE(w.edge_step_x_bits, bits_for_signed(-3 * c.height * M * M));
    EXPECT_GE(w.edge_step_x_bits, bits_for_signed(e.step_x_max));
    EXPECT_GE(w.edge_step_y_bits, bits_for_signed(e.step_y_max));
    EXPECT_GE(w.edge_step_y_bits, bits_for_signed(-e.step_y_max));
    EXPECT_GE(w.span_rem_bits, bits_for_unsigned(e.step_x_max - 1));
    EXPECT_GE(w.divider_bits, bits_for_unsigned(e.dividend_max));
    // The guard bits keep the accumulated floor error within half an LSB (docs/arithmetic.md, 4):
    // 1 + (W - 1) + (H - 1) units of 2^-F at most 1/2, unless the profile chose F itself.
    if (c.F == 0) {
      EXPECT_GE(i128(1) << F, i128(2) * (c.width + c.height - 1));
    }
    // Plane registers hold [-2^F, 2^(N+F)) and, for colour, [-2^F, 2^(8+F)).
    EXPECT_GE(w.z_reg_bits, bits_for_signed((i128(1) << (c.N + F)) - 1));
    EXPECT_GE(w.z_reg_bits, bits_for_signed(-(i128(1) << F)));
    EXPECT_GE(w.color_reg_bits, bits_for_signed((i128(1) << (8 + F)) - 1));
    EXPECT_LE(w.z_reg_bits, 63) << "the model keeps plane registers in int64_t";
    EXPECT_LE(w.edge_bits, 63) << "the model keeps edge values in int64_t";
    EXPECT_LE(w.divider_bits, 126) << "the model keeps dividends in __int128";
    EXPECT_GE(w.x_bits, bits_for_unsigned(c.width - 1));
    EXPECT_GE(w.y_bits, bits_for_unsigned(c.height - 1));
    EXPECT_GE(w.addr_bits, bits_for_unsigned(i128(c.width) * c.height - 1));
    // The serial setup's accumulator (docs/cycle-model.md): H bits above the multiplier's m bits hold
    // a sum of three products of an unbiased edge value (|e| <= edge_max) by an N-bit vertex value,
    // and the low bits it keeps as quotients cover every record register.
    const int H = serial_setup_datapath_bits(w);
    const i128 numerator_max = 3 * (e.edge_max + 1) * ((i128(1) << c.N) - 1);
    EXPECT_GE(H + c.N, bits_for_signed(numerator_max));
    EXPECT_GE(H + c.N, bits_for_signed(-numerator_max));
    EXPECT_GE(H + 8 + F, w.color_reg_bits);
    EXPECT_GE(H, w.edge_bits);
    // The inputs' widths are exact: a bigger value would be a wasted register bit.
    EXPECT_EQ(w.coord_bits, bits_for_signed(e.coord_max));
    EXPECT_EQ(w.delta_bits, bits_for_signed(e.delta_max));
  }
}

// Setup with every check on, for the largest profile: triangles through the extreme points.
TEST(Widths, LargestProfileNeverOverflowsAtTheRangeLimits) {
  for (int guard : {0, 24}) {
    Profile p = test::make_profile(4096, 4096, 8, Traversal::Span, 32);
    p.z_guard_bits = guard;
    const TriangleSetup setup(p);
    const int64_t M = 256, W = 4096 * M, H = 4096 * M;
    // Guard-band corners and edge midpoints, screen corners, a pixel centre next to each corner,
    // and points one subpixel inside the limits.
    const std::vector<std::pair<int64_t, int64_t>> points = {
        {-W, -H}, {2 * W, -H}, {-W, 2 * H}, {2 * W, 2 * H}, {W / 2, -H}, {-W, H / 2}, {2 * W, H / 2}, {W / 2, 2 * H},
        {0, 0},   {W, H},      {W, 0},      {0, H},         {M / 2, M / 2}, {W - M / 2, H - M / 2}, {-W + 1, 2 * H - 1},
        {2 * W - 1, -H + 1}};
    int64_t setups = 0, drawn = 0;
    for (const auto& a : points)
      for (const auto& b : points)
        for (const auto& c : points)
          for (int zs = 0; zs < 8; zs += 3) {
            SnappedTriangle t;
            const std::pair<int64_t, int64_t> v[3] = {a, b, c};
            for (int k = 0; k < 3; ++k) {
              t.v[k].x = int32_t(v[k].first), t.v[k].y = int32_t(v[k].second);
              t.v[k].z = (zs >> k) & 1 ? p.depth_max() : 0;
              t.v[k].color = (zs >> k) & 1 ? Rgb{255, 255, 255} : Rgb{0, 0, 0};
            }
            SetupResult r;
            ASSERT_NO_THROW(r = setup.run(t)) << test::describe(t) << " z_guard_bits " << guard;
            ++setups;
            drawn += r.status == SetupStatus::Drawn;
          }
    // Slivers and the longest rows: a full-guard-band-wide edge one subpixel from the third vertex.
    test::TriangleGen gen(p, 12);
    for (int n = 0; n < 3000; ++n) {
      const int64_t y = gen.uniform(-H, 2 * H - 1);
      SnappedTriangle t = gen.triangle(-W, y, 2 * W, y + gen.uniform(0, 1), gen.uniform(-W, 2 * W), y + gen.uniform(-1, 1));
      if (n % 2) t = gen.sliver(12000);
      for (SnappedVertex& v : t.v) v.z = gen.coin() ? p.depth_max() : 0;
      SetupResult r;
      ASSERT_NO_THROW(r = setup.run(t)) << test::describe(t) << " z_guard_bits " << guard;
      drawn += r.status == SetupStatus::Drawn;
    }
    EXPECT_GT(setups, 10000);
    EXPECT_GT(drawn, 5000);
  }
  // The whole pipeline on the largest triangle (area 4.5 W H, its slanted edges through the
  // screen's top corners) and on the longest row: a sliver from the left guard band to the right
  // one, centred on row 2048's centres.
  Profile p = test::make_profile(4096, 4096, 8, Traversal::Span, 32);
  Pipeline pipe(p);
  const int32_t M = 256, W = 4096 * M, H = 4096 * M, row = 2048 * M + M / 2;
  SnappedTriangle largest, longest_row;
  largest.v[0].x = W / 2, largest.v[0].y = -H, largest.v[1].x = 2 * W, largest.v[1].y = 2 * H;
  largest.v[2].x = -W, largest.v[2].y = 2 * H, largest.v[2].z = p.depth_max();
  longest_row.v[0].x = -W, longest_row.v[0].y = row - 3, longest_row.v[1].x = 2 * W, longest_row.v[1].y = row;
  longest_row.v[2].x = -W, longest_row.v[2].y = row + 3, longest_row.v[1].z = p.depth_max();
  ASSERT_NO_THROW(pipe.submit(largest));
  ASSERT_NO_THROW(pipe.submit(longest_row));
  const FrameStats& stats = pipe.stats();
  EXPECT_EQ(stats.triangles_drawn, 2);
  EXPECT_EQ(stats.fragments, int64_t(4096) * 4096 + 4096);  // the whole screen, then one whole row
}

TEST(Widths, CheckSignedFiresExactlyOutsideTheWidth) {
  for (int bits : {2, 8, 23, 45, 63, 100}) {
    const i128 lo = -(i128(1) << (bits - 1)), hi = (i128(1) << (bits - 1)) - 1;
    EXPECT_NO_THROW(check_signed(lo, bits, "test value"));
    EXPECT_NO_THROW(check_signed(hi, bits, "test value"));
    EXPECT_THROW(check_signed(lo - 1, bits, "test value"), WidthOverflow);
    EXPECT_THROW(check_signed(hi + 1, bits, "test value"), WidthOverflow);
  }
  try {
    check_signed(128, 8, "edge start");
    FAIL() << "no WidthOverflow";
  } catch (const WidthOverflow& e) {
    EXPECT_NE(std::string(e.what()).find("edge start"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("128"), std::string::npos) << e.what();
  }
}

// Vertices outside the guard band, snapped anyway, make the setup's checks fire.
TEST(Widths, SetupChecksFireOutsideTheGuardBand) {
  auto expect_overflow = [](const Profile& p, SnappedTriangle t, const std::string& what) {
    const TriangleSetup setup(p);
    try {
      setup.run(t);
      ADD_FAILURE() << "no WidthOverflow for " << test::describe(t);
    } catch (const WidthOverflow& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  {
    // Largest profile: coord_bits 23 holds [-2^22, 2^22); 2^22 subpixels is 4W pixels.
    const Profile p = test::make_profile(4096, 4096, 8, Traversal::Span, 32);
    ASSERT_EQ(derive_widths(p).coord_bits, 23);
    SnappedTriangle t;
    t.v[0].x = 1 << 22, t.v[1].x = 0, t.v[1].y = 1000, t.v[2].x = 1000, t.v[2].y = 1000;
    expect_overflow(p, t, "vertex x");
    t.v[0].x = 0, t.v[0].y = -(1 << 22) - 1;
    expect_overflow(p, t, "vertex y");
  }
  {
    // 640 x 480, S = 4: coordinates fit s16 but two far vertices give a difference beyond 3 W M.
    const Profile p = test::make_profile(640, 480, 4, Traversal::Span, 24);
    const Widths w = derive_widths(p);
    ASSERT_EQ(w.coord_bits, 16);
    SnappedTriangle t;
    t.v[0].x = 32767, t.v[0].y = 0, t.v[1].x = -32768, t.v[1].y = 10, t.v[2].x = 0, t.v[2].y = 100;
    expect_overflow(p, t, "does not fit");
  }
}

}  // namespace
}  // namespace rastersim
