// Model, view, projection and viewport transforms of the front end, OpenGL style: right-handed
// world and eye space, the camera at the eye-space origin looking down -z with +y up, column vectors,
// clip space with -w <= x, y, z <= w inside the view volume. docs/frontend.md has worked numbers.
#pragma once

#include "frontend/vecmath.h"

namespace rastersim::frontend {

Mat4 translation(const Vec3& offset);
Mat4 scaling(const Vec3& factors);
// Right-handed rotations by `degrees` about one axis (counter-clockwise looking down the axis
// towards the origin): rotation_y(90) takes +x to -z.
Mat4 rotation_x(double degrees);
Mat4 rotation_y(double degrees);
Mat4 rotation_z(double degrees);

// Object placement: scale first, then rotate about x, then y, then z, then translate:
// M = T * Rz * Ry * Rx * S.
Mat4 model_matrix(const Vec3& translate, const Vec3& rotate_degrees, const Vec3& scale);

// The inverse transpose of the upper-left 3x3 block of m (as a Mat4 without translation): the
// matrix that takes surface normals from object to world space. Requires a non-singular block.
Mat4 normal_matrix(const Mat4& m);

// Determinant of the upper-left 3x3 block; negative for a mirroring transform.
double linear_determinant(const Mat4& m);

// gluLookAt: f = normalize(target - eye), s = normalize(f x up), u = s x f; rows s, u, -f with the
// eye moved to the origin. Requires eye != target and up not parallel to f.
Mat4 look_at(const Vec3& eye, const Vec3& target, const Vec3& up);

// gluPerspective: vertical field of view in degrees, aspect = width / height, 0 < near < far.
// Eye depth d = -z_eye maps to w = d and to z_ndc = -1 at d = near, +1 at d = far.
Mat4 perspective(double fov_y_degrees, double aspect, double near, double far);

// glOrtho(-half_width, half_width, -half_height, half_height, near, far): w = 1 and
// z_ndc = -1 at eye depth near, +1 at far.
Mat4 orthographic(double half_width, double half_height, double near, double far);

// Viewport of a width x height y-down screen (docs/frontend.md): NDC x = -1 is the left screen edge
// (pixel x 0), x = +1 the right edge (x = width); NDC y = +1 is the top edge (pixel y 0), y = -1 the
// bottom edge (y = height). Depth: NDC z in [-1, 1] to [0, 1], 0 near.
struct ScreenPoint {
  double x, y, z;
};
ScreenPoint viewport(double x_ndc, double y_ndc, double z_ndc, int width, int height);

}  // namespace rastersim::frontend
