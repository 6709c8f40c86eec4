// The textured built-in scene ("floor") through the model with the texture unit, perspective on and
// off: every fragment's u, v against the exact coordinates at its pixel centre (long double, from
// the screen triangle's vertices as snapped and their exact u, v, w). The correct one stays within
// the bound of docs/arithmetic.md section 5; the affine one equals the affine mean within it and
// misses the correct one by up to (rho - 1) spread / 2, as theory says, by many texels on the
// floor's near tiles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "frontend/frontend.h"
#include "model/pipeline.h"

namespace rastersim::frontend {
namespace {

struct Collect : FragmentSink {
  std::vector<Fragment> fragments;
  void on_fragment(const Fragment& f) override { fragments.push_back(f); }
};

struct Exact {
  long double perspective, affine;
};

// u (c = 0) or v (c = 1) at the centre of (x, y): the perspective-correct and the affine mean.
Exact exact_coordinate(const ScreenTriangle& tri, int x, int y, int c, int subpixel_bits) {
  long double px[3], py[3];
  for (int k = 0; k < 3; ++k) {
    px[k] = std::ldexp(static_cast<long double>(snap_coordinate(tri.v[k].x, subpixel_bits, VertexSnap::Nearest)), -subpixel_bits);
    py[k] = std::ldexp(static_cast<long double>(snap_coordinate(tri.v[k].y, subpixel_bits, VertexSnap::Nearest)), -subpixel_bits);
  }
  auto edge = [&](int a, int b, long double qx, long double qy) {
    return (px[b] - px[a]) * (qy - py[a]) - (py[b] - py[a]) * (qx - px[a]);
  };
  const long double cx = x + 0.5L, cy = y + 0.5L, area = edge(0, 1, px[2], py[2]);
  const long double b[3] = {edge(1, 2, cx, cy) / area, edge(2, 0, cx, cy) / area, edge(0, 1, cx, cy) / area};
  long double num = 0, den = 0, affine = 0;
  for (int k = 0; k < 3; ++k) {
    const long double value = c == 0 ? tri.v[k].u : tri.v[k].v;
    num += b[k] * value / tri.v[k].w, den += b[k] / tri.v[k].w, affine += b[k] * value;
  }
  return {num / den, affine};
}

TEST(TexturedScene, PerspectiveIsCorrectAndAffineWarpsAsTheoryBounds) {
  Profile profile;
  profile.width = 320, profile.height = 240, profile.texture_unit = true;
  const std::vector<ScreenTriangle> screen = builtin_scene("floor", profile, {});
  long double worst_affine_miss = 0;
  for (bool perspective : {true, false}) {
    SCOPED_TRACE(perspective ? "perspective" : "affine");
    profile.perspective = perspective;
    Pipeline pipeline(profile);
    Collect sink;
    pipeline.set_fragment_sink(&sink);
    for (const ScreenTriangle& t : screen) pipeline.submit(snap(t, profile));
    ASSERT_GT(sink.fragments.size(), 30000u);
    int64_t textured = 0;
    for (const Fragment& f : sink.fragments) {
      if (!f.textured) continue;
      ++textured;
      const ScreenTriangle& tri = screen[size_t(f.tri)];
      const double w_min = std::min({tri.v[0].w, tri.v[1].w, tri.v[2].w});
      const double w_max = std::max({tri.v[0].w, tri.v[1].w, tri.v[2].w});
      const long double rho = perspective ? static_cast<long double>(w_max) / w_min : 1.0L;
      const long double bound = 194 * rho * std::ldexp(1.0L, -kTextureFractionBits) + std::ldexp(1.0L, -20);
      for (int c = 0; c < 2; ++c) {
        const Exact exact = exact_coordinate(tri, f.x, f.y, c, profile.subpixel_bits);
        const long double got = std::ldexp(static_cast<long double>(c == 0 ? f.uv.u : f.uv.v), -20);
        const long double want = perspective ? exact.perspective : exact.affine;
        ASSERT_LE(std::fabs(got - want), bound) << "fragment at " << f.x << "," << f.y << " coordinate " << c;
        if (perspective) continue;
        // The affine coordinate misses the correct one by at most (rho - 1) spread / 2.
        long double lo = 1e9, hi = -1e9;
        for (const ScreenVertex& v : tri.v) lo = std::min<long double>(lo, c == 0 ? v.u : v.v), hi = std::max<long double>(hi, c == 0 ? v.u : v.v);
        const long double true_rho = static_cast<long double>(w_max) / w_min;
        const long double miss = std::fabs(got - exact.perspective);
        ASSERT_LE(miss, (true_rho - 1) * (hi - lo) / 2 + bound) << "fragment at " << f.x << "," << f.y;
        worst_affine_miss = std::max(worst_affine_miss, miss);
      }
    }
    EXPECT_GT(textured, 30000);
  }
  // The affine image is off by more than a whole texture width somewhere (256 texels).
  EXPECT_GT(worst_affine_miss, 1.0L);
  std::printf("affine u, v miss the perspective-correct ones by up to %.3Lf texture widths\n", worst_affine_miss);
}

}  // namespace
}  // namespace rastersim::frontend
