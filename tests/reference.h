// Independent brute-force reference for the rasterization rules of docs/arithmetic.md, written from the
// rules rather than from the model: per pixel centre, exact integer cross products; top and left
// edges classified geometrically from the third vertex; depth as an exact rational.
#pragma once

#include <cstdint>
#include <vector>

#include "model/profile.h"
#include "model/triangle.h"
#include "model/triangle_setup.h"

namespace rastersim::reference {

// True when the centre of pixel (i, j) is covered by the snapped triangle (top-left rule).
bool covers(const SnappedTriangle& tri, int subpixel_bits, int i, int j);
// The same with the profile's conventions: its pixel_center's sample point and its fill_rule
// (docs/arithmetic.md section 7).
bool covers(const SnappedTriangle& tri, const Profile& profile, int i, int j);

// Exact depth of the plane through the three vertex depths at the centre of pixel (i, j), as
// numerator / denominator with denominator > 0. Requires a non-degenerate triangle.
struct Rational {
  __int128 num;
  __int128 den;
};
Rational plane_at_centre(const SnappedTriangle& tri, const uint32_t value[3], int subpixel_bits, int i, int j);
// The same at the profile's sample point of pixel (i, j).
Rational plane_at_sample(const SnappedTriangle& tri, const uint32_t value[3], const Profile& profile, int i, int j);

// All covered on-screen pixels, row by row, left to right; this and the functions below follow the
// profile's pixel_center and fill_rule.
struct Pixel {
  int x, y;
};
std::vector<Pixel> covered_pixels(const SnappedTriangle& tri, const Profile& profile);

// |integer - exact| < 1, i.e. within 1 LSB.
bool within_one_lsb(int64_t integer, const Rational& exact);

// Twice the signed area of the snapped triangle (subpixels squared); 0 means degenerate.
__int128 twice_area(const SnappedTriangle& tri);

// The candidate pixels of docs/arithmetic.md: those whose centre lies within the vertices' extent (closed),
// on screen. Found by testing every column and row centre, not by a formula.
struct PixelRect {
  int x0, y0, x1, y1;  // inclusive; empty when x0 > x1 or y0 > y1
  bool empty() const { return x0 > x1 || y0 > y1; }
  int64_t rows() const { return empty() ? 0 : int64_t(y1) - y0 + 1; }
  int64_t area() const { return empty() ? 0 : (int64_t(x1) - x0 + 1) * (int64_t(y1) - y0 + 1); }
};
PixelRect bounding_box(const SnappedTriangle& tri, const Profile& profile);
// True when the vertices' extent lies beyond the screen's outermost pixel centres: left of column
// 0's, right of the last column's, above row 0's or below the last row's (an empty box is then
// "offscreen"; an empty box otherwise is "no_centre", docs/arithmetic.md).
bool beyond_outer_centres(const SnappedTriangle& tri, const Profile& profile);

// The covered pixels of row j (left to right), testing every pixel of the row.
std::vector<int> covered_in_row(const SnappedTriangle& tri, const Profile& profile, int j);

// A setup plane's absolute form at pixel (x, y), exact (docs/arithmetic.md, section 3):
// start + (x - x0) step_x + (y - y0) step_y.
i128 absolute_plane(const PlaneSetup& plane, const SetupResult& s, int x, int y);

// The rounded, clamped output of a plane register (docs/arithmetic.md sections 3 and 7):
// clamp((V + 2^(F-1)) >> F, 0, max) to nearest, clamp(V >> F, 0, max) truncated.
int64_t rounded_plane_output(int64_t register_value, int guard_bits, int64_t max, Rounding rounding = Rounding::Nearest);

}  // namespace rastersim::reference
