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
  r.source = -1;
  return r;
}

bool finite(const ClipVertex& v) {
  return std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z) &&
         std::isfinite(v.position.w) && is_finite(v.color);
}

uint8_t to_channel(double c) { return uint8_t(std::floor(std::clamp(c, 0.0, 255.0) + 0.5)); }

}  // namespace

Clipper::Clipper(const Profile& p)
    : width_(p.width), height_(p.height), band_x_(3.0 - 2.0 / p.width), band_y_(3.0 - 2.0 / p.height) {}

ScreenVertex Clipper::to_screen(const ClipVertex& v) const {
  const Vec4& p = v.position;
  const ScreenPoint s = viewport(p.x / p.w, p.y / p.w, p.z / p.w, width_, height_);
  ScreenVertex r;
  r.x = s.x;
  r.y = s.y;
  r.z = std::clamp(s.z, 0.0, 1.0);  // a vertex clipped at near or far may round a hair outside
  r.color = {to_channel(v.color.x), to_channel(v.color.y), to_channel(v.color.z)};
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
  for (int plane = 0; plane < kPlanes && current->n >= 3; ++plane) {
    double value[kMaxPolygon];
    bool all_inside = true;
    for (int i = 0; i < current->n; ++i) {
      value[i] = plane_value(plane, current->v[i].position, band_x_, band_y_);
      all_inside = all_inside && value[i] >= 0;
    }
    if (all_inside) continue;
    next->n = 0;
    for (int i = 0; i < current->n; ++i) {
      const int j = (i + 1) % current->n;
      const ClipVertex& vi = current->v[i];
      const ClipVertex& vj = current->v[j];
      if (value[i] >= 0) next->v[next->n++] = vi;
      // A crossing strictly inside to strictly outside (or back); a vertex exactly on the plane is
      // kept as it is and creates no duplicate.
      if (value[i] > 0 && value[j] < 0) next->v[next->n++] = intersect(vi, value[i], vj, value[j]);
      else if (value[i] < 0 && value[j] > 0) next->v[next->n++] = intersect(vj, value[j], vi, value[i]);
    }
    std::swap(current, next);
  }
  if (current->n < 3) return;

  ScreenVertex screen[kMaxPolygon];
  for (int i = 0; i < current->n; ++i) screen[i] = to_screen(current->v[i]);
  for (int i = 1; i + 1 < current->n; ++i) {
    ScreenTriangle t;
    t.v[0] = screen[0];
    t.v[1] = screen[i];
    t.v[2] = screen[i + 1];
    out.push_back(t);
    if (sources) sources->push_back({current->v[0].source, current->v[i].source, current->v[i + 1].source});
  }
}

}  // namespace rastersim::frontend
