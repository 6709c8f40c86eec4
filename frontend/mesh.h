// An indexed triangle mesh in object space, as the front end transforms and lights it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "frontend/vecmath.h"

namespace rastersim::frontend {

struct Mesh {
  std::vector<Vec3> positions;  // per vertex, object space
  std::vector<Vec3> normals;    // per vertex, unit length, or zero when undefined (ambient light only)
  // Front faces are counter-clockwise seen from outside (the side the normals point to).
  std::vector<std::array<uint32_t, 3>> triangles;
  // Per vertex: the index of the source position it copies (the OBJ `v` line order, 0-based; for a
  // generated surface the vertex itself). Vertices that share a source have bit-identical positions.
  std::vector<uint32_t> position_ids;
  // Per vertex: the texture coordinate (u, v), (0, 0) the texture's bottom-left corner; empty when
  // the mesh has none.
  std::vector<std::array<double, 2>> texcoords;

  bool textured() const { return !texcoords.empty(); }

  uint32_t add_vertex(const Vec3& position, const Vec3& normal, uint32_t position_id) {
    positions.push_back(position);
    normals.push_back(normal);
    position_ids.push_back(position_id);
    return uint32_t(positions.size() - 1);
  }
};

// Area-weighted vertex normals: each triangle adds (p1 - p0) x (p2 - p0) (twice its area along its
// normal) to its three corners; the sums are normalized (zero stays zero).
std::vector<Vec3> area_weighted_normals(const std::vector<Vec3>& positions,
                                        const std::vector<std::array<uint32_t, 3>>& triangles);

struct Sphere {
  Vec3 centre;
  double radius = 0;
};

// A sphere holding every point: the centre of the bounding box and the largest distance from it.
// Empty input gives radius 0.
Sphere bounding_sphere(const std::vector<Vec3>& points);

}  // namespace rastersim::frontend
