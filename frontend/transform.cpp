#include "frontend/transform.h"

#include <cmath>

namespace rastersim::frontend {
namespace {

constexpr double kPi = 3.14159265358979323846;

// sin and cos of an angle in degrees; exact for multiples of 90 degrees so that quarter turns
// (common in scene files) move no vertex by a rounding error.
void sin_cos_degrees(double degrees, double& s, double& c) {
  const double turns = degrees / 90.0;
  if (turns == std::floor(turns) && std::fabs(turns) < 1e15) {
    const long quarter = long(std::fmod(turns, 4.0) + 4.0) % 4;
    static const double kSin[4] = {0, 1, 0, -1}, kCos[4] = {1, 0, -1, 0};
    s = kSin[quarter];
    c = kCos[quarter];
    return;
  }
  const double radians = degrees * (kPi / 180.0);
  s = std::sin(radians);
  c = std::cos(radians);
}

}  // namespace

Mat4 translation(const Vec3& o) {
  Mat4 r;
  r.m[0][3] = o.x;
  r.m[1][3] = o.y;
  r.m[2][3] = o.z;
  return r;
}

Mat4 scaling(const Vec3& f) {
  Mat4 r;
  r.m[0][0] = f.x;
  r.m[1][1] = f.y;
  r.m[2][2] = f.z;
  return r;
}

Mat4 rotation_x(double degrees) {
  double s, c;
  sin_cos_degrees(degrees, s, c);
  Mat4 r;
  r.m[1][1] = c, r.m[1][2] = -s;
  r.m[2][1] = s, r.m[2][2] = c;
  return r;
}

Mat4 rotation_y(double degrees) {
  double s, c;
  sin_cos_degrees(degrees, s, c);
  Mat4 r;
  r.m[0][0] = c, r.m[0][2] = s;
  r.m[2][0] = -s, r.m[2][2] = c;
  return r;
}

Mat4 rotation_z(double degrees) {
  double s, c;
  sin_cos_degrees(degrees, s, c);
  Mat4 r;
  r.m[0][0] = c, r.m[0][1] = -s;
  r.m[1][0] = s, r.m[1][1] = c;
  return r;
}

Mat4 model_matrix(const Vec3& translate, const Vec3& rotate_degrees, const Vec3& scale) {
  return translation(translate) * rotation_z(rotate_degrees.z) * rotation_y(rotate_degrees.y) *
         rotation_x(rotate_degrees.x) * scaling(scale);
}

double linear_determinant(const Mat4& a) {
  const auto& m = a.m;
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

Mat4 normal_matrix(const Mat4& a) {
  // inverse(A)^T = cofactor(A) / det(A); the cofactor matrix is the transpose of the adjugate.
  const auto& m = a.m;
  const double det = linear_determinant(a);
  Mat4 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      r.m[i][j] = (m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1]) / det;
    }
  return r;
}

Mat4 look_at(const Vec3& eye, const Vec3& target, const Vec3& up) {
  const Vec3 f = normalize(target - eye);
  const Vec3 s = normalize(cross(f, up));
  const Vec3 u = cross(s, f);
  Mat4 r;
  const Vec3 rows[3] = {s, u, -f};
  for (int i = 0; i < 3; ++i) {
    r.m[i][0] = rows[i].x;
    r.m[i][1] = rows[i].y;
    r.m[i][2] = rows[i].z;
    r.m[i][3] = -dot(rows[i], eye);
  }
  return r;
}

Mat4 perspective(double fov_y_degrees, double aspect, double near, double far) {
  const double f = 1.0 / std::tan(fov_y_degrees * (kPi / 360.0));  // cot(fov / 2)
  Mat4 r = Mat4::zero();
  r.m[0][0] = f / aspect;
  r.m[1][1] = f;
  r.m[2][2] = (far + near) / (near - far);
  r.m[2][3] = 2.0 * far * near / (near - far);
  r.m[3][2] = -1.0;
  return r;
}

Mat4 orthographic(double half_width, double half_height, double near, double far) {
  Mat4 r;
  r.m[0][0] = 1.0 / half_width;
  r.m[1][1] = 1.0 / half_height;
  r.m[2][2] = -2.0 / (far - near);
  r.m[2][3] = -(far + near) / (far - near);
  return r;
}

ScreenPoint viewport(double x_ndc, double y_ndc, double z_ndc, int width, int height) {
  return {(x_ndc + 1.0) * 0.5 * width, (1.0 - y_ndc) * 0.5 * height, (z_ndc + 1.0) * 0.5};
}

}  // namespace rastersim::frontend
