// Homogeneous clipping on hand-made clip-space triangles: w = 0, all-negative w, mixed-sign w,
// vertices on planes, and far outside the guard band. The expectations come from solving, per
// screen point, which point of the input triangle projects there (no clipping involved).
#include <gtest/gtest.h>

#include <random>

#include "frontend/clip.h"
#include "frontend/transform.h"
#include "frontend_test_util.h"

namespace rastersim::frontend {
namespace {

// The point of the clip-space triangle that projects to NDC (X, Y): barycentric weights k (summing
// to 1) with x = X w and y = Y w. False when the triangle is seen edge-on there.
struct OnTriangle {
  double k[3];
  Vec4 point;
  Vec3 color;
  double u, v;
};
bool solve(const ClipVertex (&t)[3], double X, double Y, OnTriangle& out) {
  double e[3], f[3];
  for (int i = 0; i < 3; ++i) {
    e[i] = t[i].position.x - X * t[i].position.w;
    f[i] = t[i].position.y - Y * t[i].position.w;
  }
  // a (e0 - e2) + b (e1 - e2) = -e2, a (f0 - f2) + b (f1 - f2) = -f2
  const double m00 = e[0] - e[2], m01 = e[1] - e[2], m10 = f[0] - f[2], m11 = f[1] - f[2];
  const double det = m00 * m11 - m01 * m10;
  const double scale = std::fabs(m00 * m11) + std::fabs(m01 * m10);
  if (!(std::fabs(det) > 1e-9 * scale)) return false;
  const double a = (-e[2] * m11 + f[2] * m01) / det;
  const double b = (-f[2] * m00 + e[2] * m10) / det;
  out.k[0] = a, out.k[1] = b, out.k[2] = 1 - a - b;
  out.point = {0, 0, 0, 0};
  out.color = {};
  out.u = out.v = 0;
  for (int i = 0; i < 3; ++i) {
    out.u += out.k[i] * t[i].u;
    out.v += out.k[i] * t[i].v;
    const Vec4& p = t[i].position;
    out.point = {out.point.x + out.k[i] * p.x, out.point.y + out.k[i] * p.y, out.point.z + out.k[i] * p.z,
                 out.point.w + out.k[i] * p.w};
    out.color = out.color + out.k[i] * t[i].color;
  }
  return true;
}

// Is the screen point (pixels) covered by the visible part of the triangle?
bool visible_at(const ClipVertex (&t)[3], double sx, double sy, int width, int height) {
  OnTriangle o;
  if (!solve(t, 2 * sx / width - 1, 1 - 2 * sy / height, o)) return false;
  return o.k[0] >= 0 && o.k[1] >= 0 && o.k[2] >= 0 && o.point.w > kMinClipW && o.point.z >= -o.point.w &&
         o.point.z <= o.point.w;
}

ClipVertex vertex(double x, double y, double z, double w, int64_t source, const Vec3& color = {}) {
  return {{x, y, z, w}, color, source};
}

std::vector<ScreenTriangle> clip_one(const ClipVertex (&t)[3], const Profile& p, std::vector<CornerSources>* sources = nullptr) {
  std::vector<ScreenTriangle> out;
  Clipper(p).clip(t, out, sources);
  return out;
}

// Every output vertex is a point of the input triangle with w > 0 inside near/far and the guard
// band, with the depth, colour, texture coordinate and w of that point; vertices kept from the
// input are exact. (The triangle is given texture coordinates of its own here.)
void check_vertices(const ClipVertex (&untextured)[3], const Profile& p) {
  ClipVertex t[3];
  const double us[3] = {1, -2, 3.5}, vs[3] = {0.5, 4, -1};
  for (int i = 0; i < 3; ++i) t[i] = untextured[i], t[i].u = us[i], t[i].v = vs[i];
  std::vector<CornerSources> sources;
  const std::vector<ScreenTriangle> out = clip_one(t, p, &sources);
  ASSERT_EQ(out.size(), sources.size());
  for (size_t i = 0; i < out.size(); ++i) {
    EXPECT_EQ(check_screen_triangle(out[i], p), "");
    for (int k = 0; k < 3; ++k) {
      const ScreenVertex& v = out[i].v[k];
      EXPECT_GE(v.x, -p.width + 1 - 1e-6);
      EXPECT_LE(v.x, 2 * p.width - 1 + 1e-6);
      EXPECT_GE(v.y, -p.height + 1 - 1e-6);
      EXPECT_LE(v.y, 2 * p.height - 1 + 1e-6);
      if (sources[i][k] >= 0) {
        const Vec4& q = t[sources[i][k]].position;
        const ScreenPoint s = viewport(q.x / q.w, q.y / q.w, q.z / q.w, p.width, p.height);
        EXPECT_EQ(v.x, s.x);
        EXPECT_EQ(v.y, s.y);
        EXPECT_EQ(v.z, s.z);
        EXPECT_EQ(v.u, us[sources[i][k]]);
        EXPECT_EQ(v.v, vs[sources[i][k]]);
        EXPECT_EQ(v.w, q.w);
        continue;
      }
      OnTriangle o;
      ASSERT_TRUE(solve(t, 2 * v.x / p.width - 1, 1 - 2 * v.y / p.height, o));
      for (double k_i : o.k) EXPECT_GE(k_i, -1e-9);
      EXPECT_GT(o.point.w, 0.0);
      const double depth = (o.point.z / o.point.w + 1) / 2;
      EXPECT_GE(depth, -1e-9);
      EXPECT_LE(depth, 1 + 1e-9);
      EXPECT_NEAR(v.z, std::clamp(depth, 0.0, 1.0), 1e-9);
      EXPECT_NEAR(v.color.r, o.color.x, 0.5 + 1e-6);
      EXPECT_NEAR(v.color.g, o.color.y, 0.5 + 1e-6);
      EXPECT_NEAR(v.color.b, o.color.z, 0.5 + 1e-6);
      // Texture coordinates are affine in clip space: the clip point's barycentric mix.
      EXPECT_NEAR(v.u, o.u, 1e-7);
      EXPECT_NEAR(v.v, o.v, 1e-7);
      EXPECT_NEAR(v.w, o.point.w, 1e-9 * std::max(1.0, std::fabs(o.point.w)));
    }
  }
}

std::string describe(const ClipVertex (&t)[3]) {
  std::string s;
  char buffer[160];
  for (const ClipVertex& v : t) {
    std::snprintf(buffer, sizeof buffer, " (%.17g, %.17g, %.17g, %.17g)", v.position.x, v.position.y, v.position.z,
                  v.position.w);
    s += buffer;
  }
  return s;
}

// Distance in pixels from a screen point to the nearest line bounding the visible part of the
// triangle: the projections of its three edges and of the lines where it meets the planes
// w = kMinClipW, z = -w and z = w. Each line is found from homogeneous points, so vertices with
// w <= 0 are handled.
double boundary_distance(const ClipVertex (&t)[3], double sx, double sy, int width, int height) {
  auto homogeneous = [&](const Vec4& p) { return Vec3{(p.x + p.w) * 0.5 * width, (p.w - p.y) * 0.5 * height, p.w}; };
  auto distance = [&](const Vec4& p, const Vec4& q) {
    const Vec3 line = cross(homogeneous(p), homogeneous(q));
    const double norm = std::hypot(line.x, line.y);
    return norm > 0 ? std::fabs(line.x * sx + line.y * sy + line.z) / norm : INFINITY;
  };
  auto mix = [](const Vec4& p, double a, const Vec4& q, double b) {
    return Vec4{a * p.x + b * q.x, a * p.y + b * q.y, a * p.z + b * q.z, a * p.w + b * q.w};
  };
  double best = INFINITY;
  for (int i = 0; i < 3; ++i) best = std::min(best, distance(t[i].position, t[(i + 1) % 3].position));
  const auto planes = {+[](const Vec4& p) { return p.w - kMinClipW; }, +[](const Vec4& p) { return p.z + p.w; },
                       +[](const Vec4& p) { return p.w - p.z; }};
  for (auto g : planes) {
    // Where g = 0 on the lines through two of the vertices: two such points span the line.
    std::vector<Vec4> roots;
    for (int i = 0; i < 3; ++i) {
      const Vec4& p = t[i].position;
      const Vec4& q = t[(i + 1) % 3].position;
      const double gp = g(p), gq = g(q);
      if (gp != gq) roots.push_back(mix(p, gq / (gq - gp), q, -gp / (gq - gp)));
    }
    if (roots.size() >= 2) best = std::min(best, distance(roots[0], roots[1]));
  }
  return best;
}

// The pixels the pipeline covers are exactly those whose centre sees the visible part of the
// triangle, except within 0.15 px of a boundary line (snapping moves a vertex by up to 0.044 px,
// and a vertex made within a subpixel of a kept one is merged with it, S = 4).
void check_coverage(const ClipVertex (&t)[3], const Profile& p, const std::string& label) {
  const std::string what = label + describe(t);
  const std::vector<int> count = test_util::coverage(clip_one(t, p), p);
  int checked = 0;
  for (int j = 0; j < p.height; ++j)
    for (int i = 0; i < p.width; ++i) {
      const int n = count[size_t(j) * p.width + i];
      ASSERT_LE(n, 1) << what << ": pixel " << i << "," << j << " covered twice (the triangulation overlaps)";
      if (boundary_distance(t, i + 0.5, j + 0.5, p.width, p.height) < 0.15) continue;
      ++checked;
      ASSERT_EQ(n, visible_at(t, i + 0.5, j + 0.5, p.width, p.height) ? 1 : 0) << what << ": pixel " << i << "," << j;
    }
  EXPECT_GT(checked, p.width * p.height / 2) << what;
}

Profile small_profile() {
  Profile p;
  p.width = 64;
  p.height = 48;
  p.subpixel_bits = 4;
  p.cull = CullMode::None;
  return p;
}

TEST(FrontendClip, InsideTriangleIsPassedThroughExactly) {
  const Profile p = small_profile();
  const ClipVertex t[3] = {vertex(-0.5, -0.5, 0.1, 1, 0), vertex(0.5, -0.25, 0.2, 2, 1), vertex(0.1, 0.7, -0.3, 1.5, 2)};
  std::vector<CornerSources> sources;
  const auto out = clip_one(t, p, &sources);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(sources[0], (CornerSources{0, 1, 2}));
  check_vertices(t, p);
}

TEST(FrontendClip, AllNegativeWProducesNothing) {
  const Profile p = small_profile();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-3, 3), w(-3, -1e-6);
  for (int n = 0; n < 2000; ++n) {
    ClipVertex t[3];
    for (int k = 0; k < 3; ++k) t[k] = vertex(coord(rng), coord(rng), coord(rng), w(rng), k);
    EXPECT_TRUE(clip_one(t, p).empty()) << n;
    // The negated triangle is the same set of projective points, but with w < 0 it is not drawn
    // (OpenGL semantics); its positive twin is drawn as usual.
    for (ClipVertex& v : t) v.position = {-v.position.x, -v.position.y, -v.position.z, -v.position.w};
    check_vertices(t, p);
  }
  // The negation of a visible triangle.
  const ClipVertex negative[3] = {vertex(0.5, 0.5, -0.1, -1, 0), vertex(-0.5, 0.5, -0.2, -1, 1), vertex(0, -0.5, -0.3, -1, 2)};
  EXPECT_TRUE(clip_one(negative, p).empty());
}

TEST(FrontendClip, AllZeroWProducesNothing) {
  const Profile p = small_profile();
  const ClipVertex t[3] = {vertex(0.5, 0.1, 0, 0, 0), vertex(-0.5, 0.2, 0, 0, 1), vertex(0, 0.6, 0, 0, 2)};
  EXPECT_TRUE(clip_one(t, p).empty());
  const ClipVertex origin[3] = {vertex(0, 0, 0, 0, 0), vertex(0, 0, 0, 0, 1), vertex(0, 0, 0, 0, 2)};
  EXPECT_TRUE(clip_one(origin, p).empty());
}

// Directed cases with w = 0 and mixed-sign w: vertex positions and coverage against the solve.
TEST(FrontendClip, DirectedWCases) {
  const Profile p = small_profile();
  const Vec3 red{255, 0, 0}, green{0, 255, 0}, blue{0, 0, 255};
  struct Case {
    const char* what;
    ClipVertex t[3];
  };
  const Case cases[] = {
      {"one vertex at infinity (w = 0, on the near and far planes)",
       {vertex(-0.5, -0.5, 0, 1, 0, red), vertex(0.5, -0.5, 0, 1, 1, green), vertex(0.3, 0.8, 0, 0, 2, blue)}},
      {"one vertex with w = 0 and z != 0",
       {vertex(-0.5, -0.5, 0.2, 1, 0, red), vertex(0.5, -0.5, 0.3, 1, 1, green), vertex(0.1, 0.2, -0.5, 0, 2, blue)}},
      {"two vertices at w = 0",
       {vertex(-0.2, -0.3, 0.1, 1, 0, red), vertex(1, -0.2, 0, 0, 1, green), vertex(-0.3, 1, 0, 0, 2, blue)}},
      {"one vertex behind the eye",
       {vertex(-0.5, -0.5, 0.5, 1, 0, red), vertex(0.6, -0.4, 0.5, 1, 1, green), vertex(0.2, 0.9, -0.9, -1, 2, blue)}},
      {"two vertices behind the eye",
       {vertex(-0.4, -0.6, 0.5, 1.2, 0, red), vertex(1.5, 0.3, -1.5, -1, 1, green), vertex(-0.7, 2, -1, -0.5, 2, blue)}},
      {"behind the eye and far outside the band",
       {vertex(40, -30, 1, 1.5, 0, red), vertex(-60, -2, 0.5, -2, 1, green), vertex(3, 50, 0.1, 0.8, 2, blue)}},
      {"a vertex exactly on the near plane",
       {vertex(-0.5, -0.5, -1, 1, 0, red), vertex(0.5, -0.5, 0.5, 1, 1, green), vertex(0, 0.6, -1.5, 1, 2, blue)}},
      {"an edge exactly on the far plane",
       {vertex(-0.5, -0.5, 1, 1, 0, red), vertex(0.5, -0.5, 2, 2, 1, green), vertex(0, 0.6, 1.4, 1, 2, blue)}},
      {"covering the whole screen, vertices thousands of pixels away",
       {vertex(-900, -900, 0.2, 1, 0, red), vertex(900, -900, 0.3, 1, 1, green), vertex(0, 1000, 0.4, 1, 2, blue)}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    check_vertices(c.t, p);
    check_coverage(c.t, p, c.what);
    // Vertices kept on a plane make no duplicate: no output triangle has two equal corners.
    for (const ScreenTriangle& s : clip_one(c.t, p))
      for (int k = 0; k < 3; ++k)
        EXPECT_FALSE(s.v[k].x == s.v[(k + 1) % 3].x && s.v[k].y == s.v[(k + 1) % 3].y && s.v[k].z == s.v[(k + 1) % 3].z);
  }
}

// A triangle through the clip-space origin (the eye point) lies in a plane through the eye: seen
// edge-on, it projects to a line.
TEST(FrontendClip, TriangleThroughTheEyePointIsEdgeOn) {
  const Profile p = small_profile();
  const ClipVertex t[3] = {vertex(0, 0, 0, 0, 0), vertex(0.8, 0.3, 0.5, 1, 1), vertex(-0.3, 0.8, -0.5, -1, 2)};
  for (const ScreenTriangle& s : clip_one(t, p)) {
    EXPECT_EQ(check_screen_triangle(s, p), "");
    const double area2 = (s.v[1].x - s.v[0].x) * (s.v[2].y - s.v[0].y) - (s.v[2].x - s.v[0].x) * (s.v[1].y - s.v[0].y);
    EXPECT_NEAR(area2, 0.0, 1e-6);
  }
}

TEST(FrontendClip, RandomTrianglesWithAnyW) {
  const Profile p = small_profile();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coord(-2.5, 2.5), depth(-2, 2), w(-1.5, 2), channel(0, 255);
  std::uniform_int_distribution<int> pick(0, 9);
  for (int n = 0; n < 1500; ++n) {
    ClipVertex t[3];
    for (int k = 0; k < 3; ++k) {
      t[k] = vertex(coord(rng), coord(rng), depth(rng), w(rng), k, {channel(rng), channel(rng), channel(rng)});
      if (pick(rng) == 0) t[k].position.w = 0;  // exactly at the eye plane
    }
    SCOPED_TRACE("random triangle " + std::to_string(n));
    check_vertices(t, p);
    check_coverage(t, p, "random triangle " + std::to_string(n));
  }
}

// The two triangles on either side of an edge walk it in opposite directions; the vertices clipping
// makes on it must be bit-identical, or the mesh cracks.
TEST(FrontendClip, SharedEdgeGetsBitIdenticalVertices) {
  const Profile p = small_profile();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coord(-6, 6), depth(-3, 3), w(-1, 2);
  int shared_made = 0;
  for (int n = 0; n < 3000; ++n) {
    const ClipVertex a = vertex(coord(rng), coord(rng), depth(rng), w(rng), 0);
    const ClipVertex b = vertex(coord(rng), coord(rng), depth(rng), w(rng), 1);
    const ClipVertex c = vertex(coord(rng), coord(rng), depth(rng), w(rng), 2);
    const ClipVertex d = vertex(coord(rng), coord(rng), depth(rng), w(rng), 3);
    const ClipVertex left[3] = {a, b, c}, right[3] = {b, a, d};
    const auto l = clip_one(left, p), r = clip_one(right, p);
    // Vertices of the left output on edge ab (weight of c zero) must appear in the right output,
    // unless the right triangle was dropped whole for lying off one side of the screen.
    for (const ScreenTriangle& s : l)
      for (const ScreenVertex& v : s.v) {
        OnTriangle o;
        if (!solve(left, 2 * v.x / p.width - 1, 1 - 2 * v.y / p.height, o) || std::fabs(o.k[2]) > 1e-12) continue;
        bool found = false;
        for (const ScreenTriangle& q : r)
          for (const ScreenVertex& u : q.v) found = found || (u.x == v.x && u.y == v.y && u.z == v.z);
        const bool off_screen = v.x <= 0 || v.x >= p.width || v.y <= 0 || v.y >= p.height;
        EXPECT_TRUE(found || (r.empty() && off_screen)) << "case " << n << ": vertex (" << v.x << ", " << v.y << ") on the shared edge";
        ++shared_made;
      }
  }
  EXPECT_GT(shared_made, 1000);
}

// Two clipped triangles sharing an edge tile like one surface: no pixel twice, and away from the
// boundary lines each pixel covered exactly when one of them is visible there. The pair is the
// two halves of a planar quadrilateral in clip space (so the visible parts cannot overlap).
TEST(FrontendClip, TrianglesSharingAnEdgeTileWithoutGapOrOverlap) {
  const Profile p = small_profile();
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> coord(-3, 3), depth(-2, 2), w(-1, 2), side(0.05, 2), along(-1, 2);
  auto random4 = [&]() { return Vec4{coord(rng), coord(rng), depth(rng), w(rng)}; };
  const int cases = 600;
  int grazing = 0;
  for (int n = 0; n < cases; ++n) {
    const Vec4 origin = random4(), e1 = random4(), e2 = random4();
    auto at = [&](double u, double v, int64_t id) {
      return vertex(origin.x + u * e1.x + v * e2.x, origin.y + u * e1.y + v * e2.y, origin.z + u * e1.z + v * e2.z,
                    origin.w + u * e1.w + v * e2.w, id);
    };
    // a = (0, 0), b = (1, 0) in the quad's plane; c above the line ab, d below it.
    const ClipVertex a = at(0, 0, 0), b = at(1, 0, 1), c = at(along(rng), side(rng), 2), d = at(along(rng), -side(rng), 3);
    const ClipVertex left[3] = {a, b, c}, right[3] = {b, a, d};
    // Seen nearly edge-on, any pair of thin triangles may fold over once snapped, clipped or not
    // (a snapping limit, not a clipping one): skip planes that pass the eye at a grazing angle.
    // In (x, y, w) the screen position is a central projection from the origin.
    auto xyw = [](const ClipVertex& v) { return Vec3{v.position.x, v.position.y, v.position.w}; };
    const Vec3 normal = cross(xyw(b) - xyw(a), xyw(c) - xyw(a));
    const double reach = std::max({length(xyw(a)), length(xyw(b)), length(xyw(c)), length(xyw(d))});
    if (std::fabs(dot(normal, xyw(a))) < 2e-2 * length(normal) * reach) {
      ++grazing;
      continue;
    }
    std::vector<ScreenTriangle> both = clip_one(left, p);
    for (const ScreenTriangle& t : clip_one(right, p)) both.push_back(t);
    const std::vector<int> count = test_util::coverage(both, p);
    const std::string what = "case " + std::to_string(n) + describe(left) + " d" + describe(right);
    for (int j = 0; j < p.height; ++j)
      for (int i = 0; i < p.width; ++i) {
        const int covered = count[size_t(j) * p.width + i];
        ASSERT_LE(covered, 1) << what << ": pixel " << i << "," << j;
        const double x = i + 0.5, y = j + 0.5;
        if (std::min(boundary_distance(left, x, y, p.width, p.height), boundary_distance(right, x, y, p.width, p.height)) < 0.15)
          continue;
        const bool l = visible_at(left, x, y, p.width, p.height), r = visible_at(right, x, y, p.width, p.height);
        ASSERT_FALSE(l && r) << what << ": the halves of a planar quadrilateral overlap";
        ASSERT_EQ(covered, l || r ? 1 : 0) << what << ": pixel " << i << "," << j;
      }
  }
  EXPECT_LT(grazing, cases / 10);
}

// Found by RandomTrianglesWithAnyW: the far plane cuts edge v2-v0 0.04 px from v2, and snapped,
// that tiny edge points the wrong way and turns the clipped quadrilateral into a bow-tie that
// overlaps the neighbour across edge v1-v2. The new vertex is merged into v2 (edge-consistently).
TEST(FrontendClip, VertexMadeWithinASubpixelOfAKeptOneIsMerged) {
  const Profile p = small_profile();
  const ClipVertex t[3] = {vertex(2.4591715067258431, -1.6313058097186304, 1.817500936678786, -0.43386410971039679, 0),
                           vertex(0.50874968879692384, -0.90656710025718978, 1.3758472301638984, 1.9803277781439479, 1),
                           vertex(-2.076223118291876, 1.6404630959686957, 0.8948282561720462, 0.89658996044163652, 2)};
  // The neighbour across v1-v2 completes a planar parallelogram.
  const Vec4 x{t[1].position.x + t[2].position.x - t[0].position.x, t[1].position.y + t[2].position.y - t[0].position.y,
               t[1].position.z + t[2].position.z - t[0].position.z, t[1].position.w + t[2].position.w - t[0].position.w};
  const ClipVertex neighbour[3] = {t[2], t[1], vertex(x.x, x.y, x.z, x.w, 3)};
  std::vector<ScreenTriangle> both = clip_one(t, p);
  for (const ScreenTriangle& s : clip_one(neighbour, p)) both.push_back(s);
  const std::vector<int> count = test_util::coverage(both, p);
  for (int j = 0; j < p.height; ++j)
    for (int i = 0; i < p.width; ++i) EXPECT_LE(count[size_t(j) * p.width + i], 1) << "pixel " << i << "," << j;
  check_vertices(t, p);
}

TEST(FrontendClip, NonFiniteInputProducesNothing) {
  const Profile p = small_profile();
  const ClipVertex t[3] = {vertex(0, 0, 0, 1, 0), vertex(NAN, 0, 0, 1, 1), vertex(0, 1, 0, 1, 2)};
  EXPECT_TRUE(clip_one(t, p).empty());
  const ClipVertex u[3] = {vertex(0, 0, 0, 1, 0), vertex(1, 0, 0, INFINITY, 1), vertex(0, 1, 0, 1, 2)};
  EXPECT_TRUE(clip_one(u, p).empty());
}

TEST(FrontendClip, GuardBandIsOnePixelInsideTheSetupRange) {
  for (int width : {1, 2, 640, 4096})
    for (int height : {1, 3, 480, 4096}) {
      Profile p;
      p.width = width;
      p.height = height;
      const Clipper c(p);
      EXPECT_DOUBLE_EQ((c.band_x() + 1) / 2 * width, 2.0 * width - 1);
      EXPECT_DOUBLE_EQ((1 - c.band_x()) / 2 * width, -width + 1.0);
      EXPECT_DOUBLE_EQ((1 + c.band_y()) / 2 * height, 2.0 * height - 1);
      EXPECT_DOUBLE_EQ((1 - c.band_y()) / 2 * height, -height + 1.0);
      // A huge triangle through the whole band: every output vertex snaps inside the setup range.
      const ClipVertex t[3] = {vertex(-1e6, -1e6, 0, 1, 0), vertex(1e6, -1e6, 0, 1, 1), vertex(0, 1e6, 0, 1, 2)};
      std::vector<ScreenTriangle> out;
      c.clip(t, out);
      EXPECT_FALSE(out.empty());
      for (const ScreenTriangle& s : out) EXPECT_EQ(check_screen_triangle(s, p), "") << width << "x" << height;
    }
}

}  // namespace
}  // namespace rastersim::frontend
