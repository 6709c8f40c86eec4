#include "reference.h"

#include <algorithm>

namespace rastersim::reference {
namespace {

using i128 = __int128;

struct Point {
  i128 x, y;
};

i128 cross(Point a, Point b, Point p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

// Does edge a->b of the triangle whose third vertex is c own the samples on it under `rule`?
// Decided from where the triangle lies, not from the edge's direction.
bool owns(Point a, Point b, Point c, FillRule rule) {
  const bool top_rule = rule == FillRule::TopLeft || rule == FillRule::TopRight;
  const bool left_rule = rule == FillRule::TopLeft || rule == FillRule::BottomLeft;
  if (a.y == b.y) return (c.y > a.y) == top_rule;  // horizontal: a top edge when the triangle is below (y down)
  // A left edge when the triangle lies to the right of it: compare c.x with the edge's x at c.y.
  const i128 lhs = (c.x - a.x) * (b.y - a.y), rhs = (b.x - a.x) * (c.y - a.y);
  const bool triangle_right = (b.y - a.y) > 0 ? lhs > rhs : lhs < rhs;
  return triangle_right == left_rule;
}

Point vertex(const SnappedTriangle& t, int k) { return {t.v[k].x, t.v[k].y}; }
// The sample point of pixel (i, j): its centre, or its corner with pixel_center corner.
Point sample(int subpixel_bits, PixelCenter center, int i, int j) {
  const i128 one = i128(1) << subpixel_bits, offset = center == PixelCenter::Half ? one / 2 : 0;
  return {i128(i) * one + offset, i128(j) * one + offset};
}
Point centre(int subpixel_bits, int i, int j) { return sample(subpixel_bits, PixelCenter::Half, i, j); }
Point sample(const Profile& p, int i, int j) { return sample(p.subpixel_bits, p.pixel_center, i, j); }

bool covers_sample(const SnappedTriangle& tri, Point p, FillRule rule) {
  const Point v[3] = {vertex(tri, 0), vertex(tri, 1), vertex(tri, 2)};
  if (cross(v[0], v[1], v[2]) == 0) return false;
  for (int k = 0; k < 3; ++k) {
    const Point a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
    const i128 side_c = cross(a, b, c), side_p = cross(a, b, p);
    if (side_p == 0) {
      if (!owns(a, b, c, rule)) return false;
    } else if ((side_p > 0) != (side_c > 0)) {
      return false;
    }
  }
  return true;
}

}  // namespace

bool covers(const SnappedTriangle& tri, int subpixel_bits, int i, int j) {
  return covers_sample(tri, centre(subpixel_bits, i, j), FillRule::TopLeft);
}

bool covers(const SnappedTriangle& tri, const Profile& profile, int i, int j) {
  return covers_sample(tri, sample(profile, i, j), profile.fill_rule);
}

namespace {

Rational plane_at(const SnappedTriangle& tri, const uint32_t value[3], Point p) {
  // Solve value = a x + b y + c through the three vertices by Cramer's rule, then evaluate.
  const i128 x0 = tri.v[0].x, y0 = tri.v[0].y, x1 = tri.v[1].x, y1 = tri.v[1].y, x2 = tri.v[2].x, y2 = tri.v[2].y;
  const i128 z0 = value[0], z1 = value[1], z2 = value[2];
  const i128 det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
  const i128 a_num = (z1 - z0) * (y2 - y0) - (z2 - z0) * (y1 - y0);
  const i128 b_num = (x1 - x0) * (z2 - z0) - (x2 - x0) * (z1 - z0);
  Rational r{z0 * det + a_num * (p.x - x0) + b_num * (p.y - y0), det};
  if (r.den < 0) r.num = -r.num, r.den = -r.den;
  return r;
}

}  // namespace

Rational plane_at_centre(const SnappedTriangle& tri, const uint32_t value[3], int subpixel_bits, int i, int j) {
  return plane_at(tri, value, centre(subpixel_bits, i, j));
}

Rational plane_at_sample(const SnappedTriangle& tri, const uint32_t value[3], const Profile& profile, int i, int j) {
  return plane_at(tri, value, sample(profile, i, j));
}

std::vector<Pixel> covered_pixels(const SnappedTriangle& tri, const Profile& profile) {
  std::vector<Pixel> out;
  // Scan only the pixels whose centres can be inside: the vertices' extent, clipped to the screen.
  const int S = profile.subpixel_bits;
  auto pixel_of = [&](int64_t v) { return int((v >> S) ); };
  const int64_t x_min = std::min({tri.v[0].x, tri.v[1].x, tri.v[2].x}), x_max = std::max({tri.v[0].x, tri.v[1].x, tri.v[2].x});
  const int64_t y_min = std::min({tri.v[0].y, tri.v[1].y, tri.v[2].y}), y_max = std::max({tri.v[0].y, tri.v[1].y, tri.v[2].y});
  const int i0 = std::max(0, pixel_of(x_min) - 1), i1 = std::min(profile.width - 1, pixel_of(x_max) + 1);
  const int j0 = std::max(0, pixel_of(y_min) - 1), j1 = std::min(profile.height - 1, pixel_of(y_max) + 1);
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i)
      if (covers(tri, profile, i, j)) out.push_back({i, j});
  return out;
}

bool within_one_lsb(int64_t integer, const Rational& exact) {
  const i128 diff = i128(integer) * exact.den - exact.num;
  return (diff < 0 ? -diff : diff) < exact.den;
}

i128 twice_area(const SnappedTriangle& tri) {
  return cross(vertex(tri, 0), vertex(tri, 1), vertex(tri, 2));
}

PixelRect bounding_box(const SnappedTriangle& tri, const Profile& profile) {
  const i128 x_min = std::min({tri.v[0].x, tri.v[1].x, tri.v[2].x}), x_max = std::max({tri.v[0].x, tri.v[1].x, tri.v[2].x});
  const i128 y_min = std::min({tri.v[0].y, tri.v[1].y, tri.v[2].y}), y_max = std::max({tri.v[0].y, tri.v[1].y, tri.v[2].y});
  PixelRect r{profile.width, profile.height, -1, -1};
  for (int i = 0; i < profile.width; ++i) {
    const i128 c = sample(profile, i, 0).x;
    if (c >= x_min && c <= x_max) r.x0 = std::min(r.x0, i), r.x1 = std::max(r.x1, i);
  }
  for (int j = 0; j < profile.height; ++j) {
    const i128 c = sample(profile, 0, j).y;
    if (c >= y_min && c <= y_max) r.y0 = std::min(r.y0, j), r.y1 = std::max(r.y1, j);
  }
  return r;
}

bool beyond_outer_centres(const SnappedTriangle& tri, const Profile& profile) {
  const i128 x_min = std::min({tri.v[0].x, tri.v[1].x, tri.v[2].x}), x_max = std::max({tri.v[0].x, tri.v[1].x, tri.v[2].x});
  const i128 y_min = std::min({tri.v[0].y, tri.v[1].y, tri.v[2].y}), y_max = std::max({tri.v[0].y, tri.v[1].y, tri.v[2].y});
  return x_max < sample(profile, 0, 0).x || x_min > sample(profile, profile.width - 1, 0).x ||
         y_max < sample(profile, 0, 0).y || y_min > sample(profile, 0, profile.height - 1).y;
}

std::vector<int> covered_in_row(const SnappedTriangle& tri, const Profile& profile, int j) {
  std::vector<int> out;
  for (int i = 0; i < profile.width; ++i)
    if (covers(tri, profile, i, j)) out.push_back(i);
  return out;
}

i128 absolute_plane(const PlaneSetup& plane, const SetupResult& s, int x, int y) {
  return i128(plane.start) + i128(x - s.x0) * plane.step_x + i128(y - s.y0) * plane.step_y;
}

int64_t rounded_plane_output(int64_t register_value, int guard_bits, int64_t max, Rounding rounding) {
  const i128 addend = rounding == Rounding::Nearest ? i128(1) << (guard_bits - 1) : 0;
  const i128 rounded = (i128(register_value) + addend) >> guard_bits;
  return int64_t(rounded < 0 ? 0 : rounded > max ? max : rounded);
}

}  // namespace rastersim::reference
