#include "triangle.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <system_error>
#include <utility>

#include "fixed.h"
#include "widths.h"

namespace rastersim {

int64_t snap_coordinate(double v, int subpixel_bits, VertexSnap rule) {
  // a = v * 2^S is exact (a power-of-two scale), and so is its fraction a - floor(a); each rule is
  // decided on that fraction, so no rounding of a sum can move a value across an integer.
  const double a = std::ldexp(v, subpixel_bits);
  const double whole = std::floor(a), fraction = a - whole;
  const int64_t below = int64_t(whole);
  switch (rule) {
    case VertexSnap::Nearest: return below + (fraction >= 0.5 ? 1 : 0);
    case VertexSnap::NearestEven: return below + (fraction > 0.5 || (fraction == 0.5 && (below & 1)) ? 1 : 0);
    case VertexSnap::Floor: return below;
    case VertexSnap::TowardZero: return below + (a < 0 && fraction > 0 ? 1 : 0);
  }
  return below;
}

uint32_t quantize_depth(double z, int z_bits) {
  // Exact floor(z * (2^N - 1) + 1/2) for z in [0, 1]: z = m / 2^k with integer m < 2^53.
  const uint64_t scale = (uint64_t(1) << z_bits) - 1;
  if (z >= 1.0) return uint32_t(scale);
  if (z < 0x1p-40) return 0;  // z * 2^32 < 1/2
  int exponent = 0;
  const double mantissa = std::frexp(z, &exponent);  // z = mantissa * 2^exponent, mantissa in [0.5, 1)
  const i128 m = i128(std::ldexp(mantissa, 53));   // integer, z = m / 2^(53 - exponent)
  const int k = 53 - exponent;                      // k <= 93
  return uint32_t((2 * m * i128(scale) + (i128(1) << k)) >> (k + 1));
}

namespace {

// A finite double as m 2^e with the integer |m| < 2^53 (m = 0 for 0).
struct Dyadic {
  int64_t m;
  int e;
};
Dyadic dyadic(double v) {
  int exponent = 0;
  const double mantissa = std::frexp(v, &exponent);  // v = mantissa 2^exponent, |mantissa| in [0.5, 1)
  return {int64_t(std::ldexp(mantissa, 53)), exponent - 53};
}

}  // namespace

int64_t texture_q(double w_min, double w) {
  // 2^P a 2^ea / (b 2^eb) + 1/2 = (a 2^(P+1+ea-eb) + b) / (2 b); P + 1 + ea - eb >= P + 1 - 15 - 1 > 0
  // because w <= 2^14 w_min and a, b lie in [2^52, 2^53). The numerator stays below 2^(53+P+3).
  const Dyadic a = dyadic(w_min), b = dyadic(w);
  const int shift = kTextureFractionBits + 1 + a.e - b.e;
  return int64_t(((i128(a.m) << shift) + b.m) / (2 * i128(b.m)));
}

int64_t texture_scaled(double c, int64_t q) {
  if (c == 0) return 0;
  // c q = m q 2^e exactly (|m q| < 2^(53+P+1)); floor(x + 1/2) = (m q + 2^(-e-1)) >> -e when e < 0.
  const Dyadic d = dyadic(c);
  const i128 product = i128(d.m) * q;
  if (d.e >= 0) return int64_t(product * (i128(1) << d.e));  // |c| >= 2^52: not a texture coordinate
  const int k = -d.e;
  if (k > 120) return 0;  // |c q| < 2^(54+P-120) < 1/2
  return int64_t((product + (i128(1) << (k - 1))) >> k);
}

namespace {

// The shortest text that reads back as v: -640.00000001 stays that (it printed as -640.000000, which
// looks inside the guard band).
std::string exact_text(double v) {
  char text[64];
  const auto [end, error] = std::to_chars(text, text + sizeof text, v);
  return error == std::errc() ? std::string(text, end) : std::to_string(v);
}

}  // namespace

std::string check_screen_triangle(const ScreenTriangle& tri, const Profile& p) {
  static const char* const kVertex[] = {"first", "second", "third"};
  for (int k = 0; k < 3; ++k) {
    const ScreenVertex& v = tri.v[k];
    const std::string who = std::string(kVertex[k]) + " vertex ";
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      return who + "has a coordinate that is not a finite number";
    if (v.z < 0.0 || v.z > 1.0) return who + "depth " + exact_text(v.z) + " is outside [0, 1]";
    // The guard band of docs/formats.md, on the coordinate as given: x in [-W, 2W), y in [-H, 2H).
    // Snapping may then reach 2W * 2^S exactly; the width analysis covers the closed range.
    if (!(v.x >= -p.width && v.x < 2.0 * p.width))
      return who + "x " + exact_text(v.x) + " is outside the guard band [" + std::to_string(-p.width) +
             ", " + std::to_string(2 * p.width) + ")";
    if (!(v.y >= -p.height && v.y < 2.0 * p.height))
      return who + "y " + exact_text(v.y) + " is outside the guard band [" + std::to_string(-p.height) +
             ", " + std::to_string(2 * p.height) + ")";
    if (!tri.textured) continue;
    if (!std::isfinite(v.u) || !std::isfinite(v.v) || !std::isfinite(v.w))
      return who + "has a texture coordinate or w that is not a finite number";
    for (const auto& [name, value] : {std::make_pair("u ", v.u), std::make_pair("v ", v.v)})
      if (!(std::fabs(value) < kMaxTextureCoordinate))
        return who + "texture coordinate " + name + exact_text(value) + " is outside (-" +
               exact_text(kMaxTextureCoordinate) + ", " + exact_text(kMaxTextureCoordinate) + ")";
    if (!(v.w > 0)) return who + "w " + exact_text(v.w) + " is not positive";
  }
  // Without the texture unit the coordinates are ignored, and so is their w.
  if (tri.textured && p.texture_unit) return check_texture_w_ratio(tri);
  return "";
}

std::string check_texture_w_ratio(const ScreenTriangle& tri) {
  const double w_min = std::min({tri.v[0].w, tri.v[1].w, tri.v[2].w});
  const double w_max = std::max({tri.v[0].w, tri.v[1].w, tri.v[2].w});
  if (w_max > std::ldexp(w_min, kMaxTextureWRatioLog2))
    return "the largest w " + exact_text(w_max) + " is more than " + std::to_string(1 << kMaxTextureWRatioLog2) +
           " times the smallest, " + exact_text(w_min);
  return "";
}

SnappedTriangle snap(const ScreenTriangle& tri, const Profile& p) {
  SnappedTriangle out;
  for (int k = 0; k < 3; ++k) {
    out.v[k].x = int32_t(snap_coordinate(tri.v[k].x, p.subpixel_bits, p.vertex_snap));
    out.v[k].y = int32_t(snap_coordinate(tri.v[k].y, p.subpixel_bits, p.vertex_snap));
    out.v[k].z = quantize_depth(tri.v[k].z, p.depth_plane_bits());
    out.v[k].color = tri.v[k].color;
  }
  out.textured = tri.textured && p.texture_unit;
  if (out.textured) {
    const bool perspective = p.perspective;
    const double w_min = std::min({tri.v[0].w, tri.v[1].w, tri.v[2].w});
    for (int k = 0; k < 3; ++k) {
      SnappedVertex& v = out.v[k];
      v.q = perspective ? texture_q(w_min, tri.v[k].w) : int64_t(1) << kTextureFractionBits;
      v.s = texture_scaled(tri.v[k].u, v.q);
      v.t = texture_scaled(tri.v[k].v, v.q);
    }
  }
  return out;
}

}  // namespace rastersim
