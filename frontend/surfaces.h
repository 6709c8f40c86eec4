// Built-in parametric surfaces, tessellated on a (u, v) grid. Every grid vertex is computed once and
// shared by index between neighbouring quads (and seams wrap to the first column or row), and rows
// shared by two pieces of a surface (a cylinder's rim) are computed from the same numbers, so the
// meshes are watertight bit for bit. Normals: the cross product of the partial derivatives.
// All are centred on the origin with +y as their axis; docs/frontend.md lists the parameters.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "frontend/mesh.h"

namespace rastersim::frontend {

// Sphere of `radius`; `segments` around the y axis, `rings` from the north (+y) to the south pole.
Mesh make_sphere(double radius, int segments, int rings);
// Torus around the y axis: tube centre circle of `major_radius` in the xz plane, tube `minor_radius`.
Mesh make_torus(double major_radius, double minor_radius, int segments, int sides);
// Closed cylinder (side and both caps), y from -height/2 to +height/2.
Mesh make_cylinder(double radius, double height, int segments, int stacks);
// Closed cone: apex at y = +height/2, base disc of `radius` at y = -height/2.
Mesh make_cone(double radius, double height, int segments, int stacks);
// Plane in xz at y = 0 facing +y: x in [-width/2, width/2], z in [-depth/2, depth/2].
Mesh make_plane(double width, double depth, int divisions_x, int divisions_z);

// The surfaces by name with their parameters, for scene files.
struct SurfaceParameter {
  std::string name;
  double default_value;
  double min, max;      // accepted closed range
  bool integer;         // a count
  std::string meaning;  // one line
};
struct SurfaceKind {
  std::string name;
  std::string description;
  std::vector<SurfaceParameter> parameters;
  // Builds the mesh from one value per parameter, in the order of `parameters`. Ranges are checked
  // by the caller; relations between parameters are returned as an error sentence ("" when fine).
  std::function<std::string(const std::vector<double>&)> check;
  std::function<Mesh(const std::vector<double>&)> build;
};
const std::vector<SurfaceKind>& surface_kinds();
const SurfaceKind* find_surface_kind(const std::string& name);

}  // namespace rastersim::frontend
