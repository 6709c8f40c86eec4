#include "frontend/clip.h"

#include <algorithm>
#include <cmath>

#include "frontend/transform.h"

namespace rastersim::frontend {
namespace {

constexpr int kPlanes = 7;
// A triangle clipped by 7 planes has at most 3 + 7 vertices.
constexpr int kMaxPolygon = 3 + kPlanes;

struct Polygon {
  ClipVertex v[kMaxPolygon];
  int n = 0;
};

// Signed distance-like value of v to clip plane k: >= 0 inside. Linear in the clip coordinates,
// so the clipped point of an edge is found by linear interpolation.
double plane_value(int k, const Vec4& p, double band_x, double band_y) {
  switch (k) {
    case 0: return p.w - kMinClipW;
    case 1: return p.z + p.w;           // near: z_ndc >= -1
    case 2: return p.w - p.z;           // far:  z_ndc <= 1
    case 3: return p.x + band_x * p.w;  // left guard band
    case 4: return band_x * p.w - p.x;  // right
    case 5: return p.y + band_y * p.w;  // bottom (screen y = 2H - 1)
    default: return band_y * p.w - p.y; // top (screen y = -H + 1)
  }
}

// The point of the edge from an inside vertex (value > 0) to an outside vertex (value < 0) on the
// plane. Always computed in this direction so that the two triangles sharing an edge, which walk it
// in opposite orders, produce bit-identical vertices: no cracks after clipping.
ClipVertex intersect(const ClipVertex& in, double in_value, const ClipVertex& out, double out_value) {
  const double t = in_value / (in_value - out_value);
  auto lerp = [t](double a, double b) { return a + t * (b - a); };
  ClipVertex r;
  r.position = {lerp(in.position.x, out.position.x), lerp(in.position.y, out.position.y),
                lerp(in.position.z, out.position.z), lerp(in.position.w, out.position.w)};
  r.color = {lerp(in.color.x, out.color.x), lerp(in.color.y, out.color.y), lerp(in.color.z, out.color.z)};
  // Kept between the ends: a rounded lerp could step past one, and out of the sampler's range.
  auto between = [&](double a, double b) { return std::clamp(lerp(a, b), std::min(a, b), std::max(a, b)); };
  r.u = between(in.u, out.u);
  r.v = between(in.v, out.v);
  r.source = -1;
  return r;
}

bool finite(const ClipVertex& v) {
  return std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z) &&
         std::isfinite(v.position.w) && is_finite(v.color);
}

uint8_t to_channel(double c) { return uint8_t(std::floor(std::clamp(c, 0.0, 255.0) + 0.5)); }

// Corners of the polygon's triangles, as indices into its vertex list.
struct Corners {
  int a, b, c;
};

// Triangulates a clipped (convex) polygon so that it still tiles exactly once after snapping.
// Snapping moves each vertex by up to half a subpixel, which can turn a convex polygon with a very
// short edge into a non-convex one; a fan would then contain a sliver of the opposite orientation
// that overlaps its neighbour. All decisions here use the snapped integer coordinates, which are
// exactly what the setup unit will see: a convex snapped polygon is fanned, a non-convex one is
// ear-clipped. The polygon's boundary (shared with neighbouring triangles) is never changed.
void triangulate(const int64_t* x, const int64_t* y, int n, std::vector<Corners>& out) {
  using i128 = __int128;
  std::vector<int> ring;
  for (int i = 0; i < n; ++i) {
    const int prev = ring.empty() ? -1 : ring.back();
    if (prev >= 0 && x[prev] == x[i] && y[prev] == y[i]) continue;  // same snapped point
    ring.push_back(i);
  }
  while (ring.size() > 1 && x[ring.front()] == x[ring.back()] && y[ring.front()] == y[ring.back()]) ring.pop_back();
  const auto cross = [&](int a, int b, int c) {
    return i128(x[b] - x[a]) * (y[c] - y[a]) - i128(x[c] - x[a]) * (y[b] - y[a]);
  };
  if (ring.size() < 3) return;
  i128 area2 = 0;
  for (size_t i = 1; i + 1 < ring.size(); ++i) area2 += cross(ring[0], ring[i], ring[i + 1]);
  const int sign = area2 > 0 ? 1 : area2 < 0 ? -1 : 0;
  bool convex = sign != 0;
  for (size_t i = 0; convex && i < ring.size(); ++i)
    convex = sign * cross(ring[i], ring[(i + 1) % ring.size()], ring[(i + 2) % ring.size()]) >= 0;
  if (!convex && sign != 0) {
    // Ear clipping: an ear is a corner turning the polygon's way with no other vertex in or on it.
    while (ring.size() > 3) {
      bool clipped = false;
      for (size_t k = 0; k < ring.size() && !clipped; ++k) {
        const size_t m = ring.size();
        const int a = ring[(k + m - 1) % m], b = ring[k], c = ring[(k + 1) % m];
        const i128 turn = sign * cross(a, b, c);
        if (turn < 0) continue;
        bool ear = true;
        for (size_t j = 0; j < m && ear && turn > 0; ++j) {
          const int q = ring[j];
          if (q == a || q == b || q == c) continue;
          const bool on_corner = (x[q] == x[a] && y[q] == y[a]) || (x[q] == x[b] && y[q] == y[b]) ||
                                 (x[q] == x[c] && y[q] == y[c]);
          ear = on_corner || !(sign * cross(a, b, q) >= 0 && sign * cross(b, c, q) >= 0 && sign * cross(c, a, q) >= 0);
        }
        if (!ear) continue;
        if (turn > 0) out.push_back({a, b, c});  // a zero turn lies on the line a-c: drop the corner
        ring.erase(ring.begin() + long(k));
        clipped = true;
      }
      if (!clipped) break;  // not a simple polygon after snapping: fan what is left
    }
  }
  // What is left of a polygon that snapping made self-intersecting may contain a triangle of the
  // opposite orientation; drawn, it would cover pixels a neighbour covers too.
  for (size_t i = 1; i + 1 < ring.size(); ++i)
    if (sign == 0 || sign * cross(ring[0], ring[i], ring[i + 1]) >= 0) out.push_back({ring[0], ring[i], ring[i + 1]});
}

}  // namespace

Clipper::Clipper(const Profile& p)
    : width_(p.width), height_(p.height), subpixel_bits_(p.subpixel_bits), vertex_snap_(p.vertex_snap), band_x_(3.0 - 2.0 / p.width), band_y_(3.0 - 2.0 / p.height) {}

// The new vertex of an edge crossing a plane, or the inside vertex itself when the two snap within
// one subpixel of each other: such a tiny edge could reverse its direction when snapped and fold
// the polygon. The choice depends only on the edge and the plane, so both triangles sharing the edge
// make it alike.
ClipVertex Clipper::cut(const ClipVertex& in, double in_value, const ClipVertex& out, double out_value) const {
  const ClipVertex made = intersect(in, in_value, out, out_value);
  if (!(in.position.w > 0 && made.position.w > 0)) return made;
  const ScreenVertex a = to_screen(in), b = to_screen(made);
  if (!(std::fabs(a.x) < 1e7 && std::fabs(a.y) < 1e7 && std::fabs(b.x) < 1e7 && std::fabs(b.y) < 1e7)) return made;
  const int64_t dx = snap_coordinate(a.x, subpixel_bits_, vertex_snap_) - snap_coordinate(b.x, subpixel_bits_, vertex_snap_);
  const int64_t dy = snap_coordinate(a.y, subpixel_bits_, vertex_snap_) - snap_coordinate(b.y, subpixel_bits_, vertex_snap_);
  return std::max(std::abs(dx), std::abs(dy)) <= 1 ? in : made;
}

ScreenVertex Clipper::to_screen(const ClipVertex& v) const {
  const Vec4& p = v.position;
  const ScreenPoint s = viewport(p.x / p.w, p.y / p.w, p.z / p.w, width_, height_);
  ScreenVertex r;
  r.x = s.x;
  r.y = s.y;
  r.z = std::clamp(s.z, 0.0, 1.0);  // a vertex clipped at near or far may round a hair outside
  r.color = {to_channel(v.color.x), to_channel(v.color.y), to_channel(v.color.z)};
  r.u = v.u;
  r.v = v.v;
  r.w = p.w;
  return r;
}

void Clipper::clip(const ClipVertex (&triangle)[3], std::vector<ScreenTriangle>& out,
                   std::vector<CornerSources>* sources) const {
  for (const ClipVertex& v : triangle)
    if (!finite(v)) return;

  // Trivial reject against the visible frustum: every point of the triangle is a convex combination
  // of its vertices, so all three outside one of these half-spaces means no visible point.
  auto all_outside = [&](auto value) { return value(triangle[0]) && value(triangle[1]) && value(triangle[2]); };
  if (all_outside([](const ClipVertex& v) { return v.position.x + v.position.w < 0; }) ||
      all_outside([](const ClipVertex& v) { return v.position.w - v.position.x < 0; }) ||
      all_outside([](const ClipVertex& v) { return v.position.y + v.position.w < 0; }) ||
      all_outside([](const ClipVertex& v) { return v.position.w - v.position.y < 0; }))
    return;

  Polygon a, b;
  for (int k = 0; k < 3; ++k) a.v[k] = triangle[k];
  a.n = 3;
  Polygon* current = &a;
  Polygon* next = &b;
  bool clipped = false;
  for (int plane = 0; plane < kPlanes && current->n >= 3; ++plane) {
    double value[kMaxPolygon];
    bool all_inside = true;
    for (int i = 0; i < current->n; ++i) {
      value[i] = plane_value(plane, current->v[i].position, band_x_, band_y_);
      all_inside = all_inside && value[i] >= 0;
    }
    if (all_inside) continue;
    clipped = true;
    next->n = 0;
    for (int i = 0; i < current->n; ++i) {
      const int j = (i + 1) % current->n;
      const ClipVertex& vi = current->v[i];
      const ClipVertex& vj = current->v[j];
      if (value[i] >= 0) next->v[next->n++] = vi;
      // A crossing strictly inside to strictly outside (or back); a vertex exactly on the plane is
      // kept as it is and creates no duplicate.
      if (value[i] > 0 && value[j] < 0) next->v[next->n++] = cut(vi, value[i], vj, value[j]);
      else if (value[i] < 0 && value[j] > 0) next->v[next->n++] = cut(vj, value[j], vi, value[i]);
    }
    std::swap(current, next);
  }
  if (current->n < 3) return;

  ScreenVertex screen[kMaxPolygon];
  int64_t snapped_x[kMaxPolygon], snapped_y[kMaxPolygon];
  for (int i = 0; i < current->n; ++i) {
    screen[i] = to_screen(current->v[i]);
    snapped_x[i] = snap_coordinate(screen[i].x, subpixel_bits_, vertex_snap_);
    snapped_y[i] = snap_coordinate(screen[i].y, subpixel_bits_, vertex_snap_);
  }
  std::vector<Corners> corners;
  if (!clipped) corners.push_back({0, 1, 2});  // an unclipped triangle stays as it is, even degenerate
  else triangulate(snapped_x, snapped_y, current->n, corners);
  for (const Corners& c : corners) {
    ScreenTriangle t;
    t.v[0] = screen[c.a];
    t.v[1] = screen[c.b];
    t.v[2] = screen[c.c];
    out.push_back(t);
    if (sources) sources->push_back({current->v[c.a].source, current->v[c.b].source, current->v[c.c].source});
  }
}

}  // namespace rastersim::frontend
