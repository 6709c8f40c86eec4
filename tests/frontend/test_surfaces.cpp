// The parametric surfaces: closed ones are watertight bit for bit (every directed edge, by exact
// position, has exactly one reverse partner), faces turn counter-clockwise about the outward side,
// and vertex normals agree with the faces and with the analytic surface.
#include <gtest/gtest.h>

#include <map>
#include <tuple>

#include "frontend/surfaces.h"

namespace rastersim::frontend {
namespace {

using Key = std::tuple<double, double, double>;
Key key(const Vec3& p) { return {p.x, p.y, p.z}; }

// Directed edges by exact endpoint positions; zero-area triangles (two equal positions) are skipped.
std::map<std::pair<Key, Key>, int> directed_edges(const Mesh& m, int& degenerate) {
  std::map<std::pair<Key, Key>, int> edges;
  degenerate = 0;
  for (const auto& t : m.triangles) {
    const Vec3 p[3] = {m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]};
    if (key(p[0]) == key(p[1]) || key(p[1]) == key(p[2]) || key(p[2]) == key(p[0])) {
      ++degenerate;
      continue;
    }
    for (int k = 0; k < 3; ++k) ++edges[{key(p[k]), key(p[(k + 1) % 3])}];
  }
  return edges;
}

void expect_closed(const Mesh& m, const std::string& what) {
  int degenerate = 0;
  const auto edges = directed_edges(m, degenerate);
  EXPECT_EQ(degenerate, 0) << what;
  for (const auto& [edge, count] : edges) {
    ASSERT_EQ(count, 1) << what << ": an edge used twice in one direction (a fold)";
    const auto reverse = edges.find({edge.second, edge.first});
    ASSERT_TRUE(reverse != edges.end()) << what << ": an edge without its reverse (a crack)";
  }
}

// Faces turn counter-clockwise about the outside: the face normal points away from `inside`, and
// each corner's vertex normal is on the same side as the face.
void expect_outward(const Mesh& m, const std::function<Vec3(const Vec3&)>& inside_of, const std::string& what) {
  for (const auto& t : m.triangles) {
    const Vec3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
    const Vec3 face = cross(b - a, c - a);
    const Vec3 centroid = (1.0 / 3.0) * (a + b + c);
    ASSERT_GT(dot(face, centroid - inside_of(centroid)), 0) << what << ": a face turns clockwise seen from outside";
    for (uint32_t corner : t) {
      EXPECT_NEAR(length(m.normals[corner]), 1.0, 1e-12) << what;
      ASSERT_GT(dot(m.normals[corner], face), 0) << what << ": a vertex normal against its face";
    }
  }
}

TEST(FrontendSurfaces, SphereIsClosedOutwardAndOnTheSphere) {
  for (int segments : {3, 7, 32})
    for (int rings : {2, 5, 16}) {
      const std::string what = "sphere " + std::to_string(segments) + "x" + std::to_string(rings);
      const Mesh m = make_sphere(1.5, segments, rings);
      expect_closed(m, what);
      expect_outward(m, [](const Vec3&) { return Vec3{}; }, what);
      EXPECT_EQ(m.triangles.size(), size_t(2 * segments * (rings - 1)));
      for (size_t v = 0; v < m.positions.size(); ++v) {
        EXPECT_NEAR(length(m.positions[v]), 1.5, 1e-12) << what;
        // The analytic normal of a sphere is the radial direction (poles: the axis).
        if (m.positions[v].x != 0 || m.positions[v].z != 0) {
          const Vec3 radial = normalize(m.positions[v]);
          EXPECT_NEAR(dot(radial, m.normals[v]), 1.0, 1e-12) << what;
        }
      }
    }
}

TEST(FrontendSurfaces, TorusIsClosedOutward) {
  const double major = 1.2, minor = 0.4;
  const Mesh m = make_torus(major, minor, 20, 9);
  expect_closed(m, "torus");
  // Inside of a torus point: the nearest point of the tube's centre circle.
  auto tube_centre = [&](const Vec3& p) { return major * normalize(Vec3{p.x, 0, p.z}); };
  expect_outward(m, tube_centre, "torus");
  for (size_t v = 0; v < m.positions.size(); ++v) {
    const Vec3 radial = m.positions[v] - tube_centre(m.positions[v]);
    EXPECT_NEAR(length(radial), minor, 1e-12);
    EXPECT_NEAR(dot(normalize(radial), m.normals[v]), 1.0, 1e-12);
  }
  EXPECT_EQ(m.positions.size(), size_t(20 * 9));  // every grid vertex once: both seams wrap
}

TEST(FrontendSurfaces, CylinderAndConeAreClosedOutward) {
  for (int stacks : {1, 4}) {
    const Mesh cylinder = make_cylinder(0.7, 2.0, 11, stacks);
    expect_closed(cylinder, "cylinder");
    expect_outward(cylinder, [](const Vec3& p) { return Vec3{0, p.y * 0.5, 0}; }, "cylinder");
    const Mesh cone = make_cone(0.7, 2.0, 11, stacks);
    expect_closed(cone, "cone");
    expect_outward(cone, [](const Vec3&) { return Vec3{0, -0.5, 0}; }, "cone");
    // Side normals: horizontal on the cylinder; on the cone tilted up by atan(r / h).
    for (size_t v = 0; v < cone.positions.size(); ++v) {
      const Vec3 n = cone.normals[v];
      if (n.y > -0.99) {
        EXPECT_NEAR(n.y, 0.7 / std::sqrt(0.49 + 4.0), 1e-12);
      }
    }
    for (const Vec3& n : cylinder.normals) EXPECT_TRUE(std::fabs(n.y) < 1e-15 || std::fabs(std::fabs(n.y) - 1) < 1e-15);
  }
}

TEST(FrontendSurfaces, PlaneFacesUpAndSharesGridVertices) {
  const Mesh m = make_plane(4, 2, 3, 5);
  EXPECT_EQ(m.positions.size(), size_t(4 * 6));
  EXPECT_EQ(m.triangles.size(), size_t(2 * 3 * 5));
  int degenerate = 0;
  const auto edges = directed_edges(m, degenerate);
  int boundary = 0;
  for (const auto& [edge, count] : edges) {
    ASSERT_EQ(count, 1);
    boundary += edges.count({edge.second, edge.first}) == 0;
  }
  EXPECT_EQ(boundary, 2 * (3 + 5));  // only the rim is open
  for (const auto& t : m.triangles) {
    const Vec3 face = cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
    EXPECT_GT(face.y, 0);
    EXPECT_EQ(face.x, 0);
    EXPECT_EQ(face.z, 0);
  }
  EXPECT_EQ(m.positions.front().x, -2);
  EXPECT_EQ(m.positions.back().x, 2);
  EXPECT_EQ(m.positions.front().z, 1);
  EXPECT_EQ(m.positions.back().z, -1);
}

TEST(FrontendSurfaces, RegistryBuildsEveryKindWithDefaults) {
  for (const SurfaceKind& kind : surface_kinds()) {
    std::vector<double> values;
    for (const SurfaceParameter& p : kind.parameters) {
      EXPECT_GE(p.default_value, p.min) << kind.name << " " << p.name;
      EXPECT_LE(p.default_value, p.max) << kind.name << " " << p.name;
      values.push_back(p.default_value);
    }
    EXPECT_EQ(kind.check(values), "") << kind.name;
    const Mesh m = kind.build(values);
    EXPECT_FALSE(m.triangles.empty()) << kind.name;
    if (kind.name != "plane") expect_closed(m, kind.name);
    EXPECT_EQ(find_surface_kind(kind.name), &kind);
  }
  EXPECT_EQ(find_surface_kind("teapot"), nullptr);
}

}  // namespace
}  // namespace rastersim::frontend
