// Triangles as the pipeline takes them: screen-space (floating point, as read from .tri or made by
// the front end) and snapped (the fixed-point words the setup unit accepts).
#pragma once

#include <cstdint>
#include <string>

#include "profile.h"

namespace rastersim {

struct Rgb {
  uint8_t r = 255, g = 255, b = 255;
  bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
};

struct ScreenVertex {
  double x = 0, y = 0;  // pixels, y down
  double z = 0;         // [0, 1], 0 is near
  Rgb color;
  // Texture coordinate, (0, 0) the texture's bottom-left corner and (1, 1) its top-right one, and
  // the clip-space w of the vertex (> 0; 1 without a perspective projection). Meaningful when the
  // triangle is textured (docs/design/texturing.md).
  double u = 0, v = 0, w = 1;
};

// |u| and |v| of a textured vertex stay below this: the texture sampler's coordinates are s8.20
// (model/texture_sampler.h).
constexpr double kMaxTextureCoordinate = 128;

struct ScreenTriangle {
  ScreenVertex v[3];
  bool textured = false;  // the vertices' u, v and w are given (an OBJ with vt, a .tri uvw section)
};

struct SnappedVertex {
  int32_t x = 0, y = 0;  // subpixels, s(coord_bits-S).S: floor(v * 2^S + 1/2)
  uint32_t z = 0;        // depth, uN: floor(z * (2^N - 1) + 1/2)
  Rgb color;             // u8.0 per channel
  // Textured only (docs/arithmetic.md section 5), P = kTextureFractionBits:
  int64_t q = 0;         // 1/w scaled by the triangle's smallest w, u1.P: floor(2^P w_min / w + 1/2)
  int64_t s = 0, t = 0;  // u/w and v/w in that scale, s8.P: floor(u q + 1/2), floor(v q + 1/2)
};

struct SnappedTriangle {
  SnappedVertex v[3];
  bool textured = false;
};

// Why a screen triangle is not acceptable to the setup unit, or an empty string.
// Checks: finite numbers, z in [0, 1], and every coordinate inside the guard band x in [-W, 2W),
// y in [-H, 2H) (docs/formats.md); snapped, that is within [-W*2^S, 2W*2^S]. A textured triangle's
// u and v lie in (-128, 128), its w are positive and, with the profile's texture unit, within
// check_texture_w_ratio.
std::string check_screen_triangle(const ScreenTriangle& tri, const Profile& profile);
// Why a textured triangle's w spread is beyond the texture divide's bound (the largest more than
// 2^14 times the smallest; docs/arithmetic.md section 5), or an empty string.
std::string check_texture_w_ratio(const ScreenTriangle& tri);

// Snaps a checked triangle to the fixed-point grid of docs/arithmetic.md section 1, and with the
// profile's texture unit a textured one's texture coordinates as section 5 says (without it they
// are dropped: the hardware has nowhere to put them).
SnappedTriangle snap(const ScreenTriangle& tri, const Profile& profile);

// X subpixels of a coordinate x by the profile's vertex_snap rule (docs/arithmetic.md section 7).
int64_t snap_coordinate(double v, int subpixel_bits, VertexSnap rule);
uint32_t quantize_depth(double z, int z_bits);
// floor(2^P w_min / w + 1/2) and floor(c q + 1/2), exact (no rounding before the last one);
// 0 < w_min <= w <= 2^14 w_min, |c| < 128, 0 < q <= 2^P.
int64_t texture_q(double w_min, double w);
int64_t texture_scaled(double c, int64_t q);

}  // namespace rastersim
