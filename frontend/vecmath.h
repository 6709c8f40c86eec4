// Double-precision vectors and 4x4 matrices for the host-side front end (a driver's arithmetic, not
// the hardware's). Column vectors: a point p transforms as M * p; matrices are stored row-major,
// m[row][column]. docs/frontend.md fixes every convention.
#pragma once

#include <cmath>

namespace rastersim::frontend {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

struct Vec4 {
  double x = 0, y = 0, z = 0, w = 0;
};

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline Vec3 operator*(const Vec3& a, double s) { return {s * a.x, s * a.y, s * a.z}; }
// Component-wise product (colour times colour).
inline Vec3 hadamard(const Vec3& a, const Vec3& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
// The unit vector along a, or the zero vector when a is zero.
inline Vec3 normalize(const Vec3& a) {
  const double n = length(a);
  return n > 0 ? Vec3{a.x / n, a.y / n, a.z / n} : Vec3{};
}
inline bool is_finite(const Vec3& a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

struct Mat4 {
  double m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};  // identity

  static Mat4 identity() { return {}; }
  static Mat4 zero() {
    Mat4 r;
    for (auto& row : r.m)
      for (double& v : row) v = 0;
    return r;
  }
};

inline Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 r = Mat4::zero();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) r.m[i][j] += a.m[i][k] * b.m[k][j];
  return r;
}

inline Vec4 operator*(const Mat4& a, const Vec4& v) {
  return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z + a.m[0][3] * v.w,
          a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z + a.m[1][3] * v.w,
          a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z + a.m[2][3] * v.w,
          a.m[3][0] * v.x + a.m[3][1] * v.y + a.m[3][2] * v.z + a.m[3][3] * v.w};
}

// The point p (w = 1) through an affine matrix, dropping w.
inline Vec3 transform_point(const Mat4& a, const Vec3& p) {
  const Vec4 r = a * Vec4{p.x, p.y, p.z, 1.0};
  return {r.x, r.y, r.z};
}

// The upper-left 3x3 block times d (a direction: no translation).
inline Vec3 transform_direction(const Mat4& a, const Vec3& d) {
  const Vec4 r = a * Vec4{d.x, d.y, d.z, 0.0};
  return {r.x, r.y, r.z};
}

}  // namespace rastersim::frontend
