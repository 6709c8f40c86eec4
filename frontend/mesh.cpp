#include "frontend/mesh.h"

#include <algorithm>

namespace rastersim::frontend {

std::vector<Vec3> area_weighted_normals(const std::vector<Vec3>& positions,
                                        const std::vector<std::array<uint32_t, 3>>& triangles) {
  std::vector<Vec3> sum(positions.size());
  for (const auto& t : triangles) {
    const Vec3 n = cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
    for (uint32_t corner : t) sum[corner] = sum[corner] + n;
  }
  for (Vec3& n : sum) n = normalize(n);
  return sum;
}

Sphere bounding_sphere(const std::vector<Vec3>& points) {
  if (points.empty()) return {};
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  Sphere s;
  s.centre = 0.5 * (lo + hi);
  for (const Vec3& p : points) s.radius = std::max(s.radius, length(p - s.centre));
  return s;
}

}  // namespace rastersim::frontend
