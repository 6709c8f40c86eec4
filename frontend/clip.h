// Homogeneous clipping (Sutherland-Hodgman, before the perspective divide), viewport mapping and
// triangulation into screen triangles the setup unit accepts. docs/frontend.md "Clipping".
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "frontend/vecmath.h"
#include "model/profile.h"
#include "model/triangle.h"

namespace rastersim::frontend {

struct ClipVertex {
  Vec4 position;         // clip space
  Vec3 color;            // 0..255 per channel, not yet rounded
  int64_t source = -1;   // the caller's vertex id; -1 for a vertex made by clipping
  double u = 0, v = 0;   // texture coordinate (affine in clip space, so clipping interpolates it)
};

// Where each corner of an output triangle came from: a ClipVertex::source, -1 if made by clipping.
using CornerSources = std::array<int64_t, 3>;

// Smallest clip-space w kept: the plane w = kMinClipW removes the points at and behind the eye
// (w <= 0) before any other plane, so the divide never sees w <= 0. Perspective clip w is the
// eye-space depth, so near > kMinClipW makes this plane inactive.
constexpr double kMinClipW = 1e-9;

class Clipper {
 public:
  // The clip volume: w >= kMinClipW, near (z >= -w), far (z <= w), and the guard band
  // |x| <= band_x w, |y| <= band_y w with band_x = 3 - 2/W, band_y = 3 - 2/H, i.e. screen
  // x in [-W + 1, 2W - 1], y in [-H + 1, 2H - 1]: one pixel inside the setup unit's range
  // [-W, 2W) x [-H, 2H) so no rounding or snapping can leave it.
  explicit Clipper(const Profile& profile);

  // Clips the triangle, maps the pieces to the screen and appends them to `out` (the clipped
  // polygon triangulated with its winding: a fan, or ear clipping where snapping to the profile's
  // subpixel grid would make a fan fold over); the corner sources to `sources` when given. Each
  // screen vertex carries its texture coordinate and clip-space w; the caller marks the triangles
  // textured.
  // A triangle wholly outside one side of the visible screen frustum (|x| <= w, |y| <= w) produces
  // nothing, since it cannot cover a pixel centre. Nor does a triangle with a non-finite coordinate.
  void clip(const ClipVertex (&triangle)[3], std::vector<ScreenTriangle>& out,
            std::vector<CornerSources>* sources = nullptr) const;

  double band_x() const { return band_x_; }
  double band_y() const { return band_y_; }

 private:
  ScreenVertex to_screen(const ClipVertex& v) const;
  ClipVertex cut(const ClipVertex& in, double in_value, const ClipVertex& out, double out_value) const;
  int width_, height_, subpixel_bits_;
  VertexSnap vertex_snap_;
  double band_x_, band_y_;
};

}  // namespace rastersim::frontend
