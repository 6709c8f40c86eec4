// Random OBJ meshes and cameras through load_obj, checked against an independent projection
// (camera basis and similar triangles, frontend_test_util.h): every vertex not made by clipping
// within 1e-9 px, snapped within half a subpixel, depth within 1 LSB; every vertex made by clipping
// on its source triangle (independent ray cast), at that point's depth, on a clip boundary.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "frontend/frontend.h"
#include "frontend/obj_loader.h"
#include "frontend/scene.h"
#include "frontend_test_util.h"

namespace rastersim::frontend {
namespace {

struct RandomMesh {
  std::vector<Vec3> positions;
  std::vector<std::vector<int>> faces;  // 0-based position indices
  std::string obj;
};

RandomMesh random_mesh(std::mt19937& rng, int number) {
  RandomMesh m;
  std::uniform_real_distribution<double> unit(-1, 1), scale(0.5, 3);
  std::uniform_int_distribution<int> vertex_count(8, 40), face_count(10, 40);
  const int n = vertex_count(rng);
  const double s = scale(rng);
  const Vec3 offset{2 * unit(rng), 2 * unit(rng), 2 * unit(rng)};
  const bool normals = number % 3 == 1, negative = number % 4 == 2;
  char line[200];
  m.obj = "# random mesh " + std::to_string(number) + "\n";
  for (int i = 0; i < n; ++i) {
    m.positions.push_back(offset + s * Vec3{unit(rng), unit(rng), unit(rng)});
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", m.positions.back().x, m.positions.back().y,
                  m.positions.back().z);
    m.obj += line;
    if (normals) {
      const Vec3 d = normalize(Vec3{unit(rng), unit(rng), unit(rng)});
      std::snprintf(line, sizeof line, "vn %.17g %.17g %.17g\n", d.x, d.y, d.z);
      m.obj += line;
    }
  }
  std::uniform_int_distribution<int> index(0, n - 1), corners(3, 4);
  const int faces = face_count(rng);
  for (int f = 0; f < faces; ++f) {
    std::vector<int> face;
    const int k = corners(rng);
    while (int(face.size()) < k) {
      const int i = index(rng);
      if (std::find(face.begin(), face.end(), i) == face.end()) face.push_back(i);
    }
    m.faces.push_back(face);
    m.obj += "f";
    for (int i : face) {
      const int written = negative ? i - n : i + 1;  // negative: counted back from the last vertex
      m.obj += " " + std::to_string(written) + (normals ? "//" + std::to_string(written) : "");
    }
    m.obj += "\n";
  }
  return m;
}

Profile random_profile(std::mt19937& rng) {
  static const int sizes[][2] = {{64, 48}, {320, 240}, {640, 480}, {1000, 300}, {257, 1031}};
  static const int subpixel[] = {1, 4, 8};
  static const int depth[] = {16, 24, 32};
  std::uniform_int_distribution<int> pick(0, 1000);
  Profile p;
  p.width = sizes[pick(rng) % 5][0];
  p.height = sizes[pick(rng) % 5][1];
  p.subpixel_bits = subpixel[pick(rng) % 3];
  p.z_bits = depth[pick(rng) % 3];
  return p;
}

// A camera looking at the mesh from a random direction: `close` puts the eye near or inside it
// (near-plane and guard-band clipping), otherwise well outside.
test_util::IndependentCamera random_camera(std::mt19937& rng, const RandomMesh& m, const Profile& p, bool close) {
  std::uniform_real_distribution<double> unit(-1, 1), fov(25, 100), fraction(0, 1);
  const Sphere bounds = bounding_sphere(m.positions);
  test_util::IndependentCamera c;
  c.width = p.width;
  c.height = p.height;
  c.fov = fov(rng);
  c.ortho = !close && fraction(rng) < 0.25;
  c.target = bounds.centre + 0.3 * bounds.radius * Vec3{unit(rng), unit(rng), unit(rng)};
  Vec3 direction;
  do direction = Vec3{unit(rng), unit(rng), unit(rng)};
  while (length(direction) < 0.1);
  const double distance = bounds.radius * (close ? 0.2 + 1.3 * fraction(rng) : 2.0 + 4.0 * fraction(rng));
  c.eye = c.target + distance * normalize(direction);
  do c.up = Vec3{unit(rng), unit(rng), unit(rng)};
  while (length(cross(normalize(c.up), normalize(direction))) < 0.1);
  if (close) {
    c.near = bounds.radius * (0.02 + 0.3 * fraction(rng));
    c.far = distance + bounds.radius * (0.5 + 1.5 * fraction(rng));  // sometimes cuts the back too
  } else {
    c.near = (distance - 1.8 * bounds.radius) * (0.2 + 0.7 * fraction(rng));
    c.far = distance + 2 * bounds.radius;
  }
  return c;
}

CameraOptions options_of(const test_util::IndependentCamera& c) {
  CameraOptions o;
  o.eye = c.eye;
  o.target = c.target;
  o.up = c.up;
  o.fov = c.fov;
  o.near = c.near;
  o.far = c.far;
  o.ortho = c.ortho;
  return o;
}

// Checks one output vertex that is a projected mesh position.
void check_kept_vertex(const ScreenVertex& v, const Vec3& expected, const Profile& p, const std::string& what) {
  EXPECT_NEAR(v.x, expected.x, 1e-9) << what;
  EXPECT_NEAR(v.y, expected.y, 1e-9) << what;
  EXPECT_NEAR(v.z, expected.z, 1e-9) << what;
  const double subpixel = std::ldexp(1.0, -p.subpixel_bits);
  EXPECT_LE(std::fabs(snap_coordinate(v.x, p.subpixel_bits, VertexSnap::Nearest) * subpixel - expected.x), 0.5 * subpixel + 1e-9) << what;
  EXPECT_LE(std::fabs(snap_coordinate(v.y, p.subpixel_bits, VertexSnap::Nearest) * subpixel - expected.y), 0.5 * subpixel + 1e-9) << what;
  EXPECT_LE(std::fabs(double(quantize_depth(v.z, p.z_bits)) - expected.z * double(p.depth_max())), 1.0) << what;
}

// Checks one output vertex made by clipping the world triangle t: the independent ray through it
// meets t there, at the vertex's depth, and the vertex lies on a clip boundary.
void check_made_vertex(const ScreenVertex& v, const Vec3 (&t)[3], const test_util::IndependentCamera& c,
                       const Profile& p, const std::string& what) {
  const double boundary = std::min({std::fabs(v.z), std::fabs(v.z - 1), std::fabs(v.x - (1 - p.width)),
                                    std::fabs(v.x - (2 * p.width - 1)), std::fabs(v.y - (1 - p.height)),
                                    std::fabs(v.y - (2 * p.height - 1))});
  EXPECT_LT(boundary, 1e-7) << what << ": a vertex made by clipping is on no clip boundary: " << v.x << " " << v.y << " " << v.z;
  Vec3 origin, direction;
  c.ray(v.x, v.y, origin, direction);
  const Vec3 normal = cross(t[1] - t[0], t[2] - t[0]);
  if (std::fabs(dot(normal, direction)) < 1e-3 * length(normal) * length(direction)) return;  // edge-on: ill-posed
  const Vec3 hit = origin + (dot(normal, t[0] - origin) / dot(normal, direction)) * direction;
  const double area = dot(normal, normal);
  const double k0 = dot(cross(t[1] - hit, t[2] - hit), normal) / area;
  const double k1 = dot(cross(t[2] - hit, t[0] - hit), normal) / area;
  const double k2 = 1 - k0 - k1;
  EXPECT_GE(std::min({k0, k1, k2}), -1e-6) << what << ": a vertex made by clipping is off its triangle";
  EXPECT_NEAR(c.project(hit).z, v.z, 1e-6) << what;
}

// One mesh seen by one camera: returns whether any clipping happened.
bool check_case(const RandomMesh& m, const test_util::IndependentCamera& c, const Profile& p, const std::string& what) {
  const std::string path = test_util::write_file("random.obj", m.obj);
  const std::vector<ScreenTriangle> public_output = load_obj(path, p, options_of(c));

  const Scene scene = obj_scene(load_obj_mesh(path));
  const Camera camera = resolve_camera({}, options_of(c), scene_bounds(scene), p.width, p.height);
  RenderTrace trace;
  const std::vector<ScreenTriangle> out = render_scene(scene, camera, p, &trace);
  const Mesh& mesh = scene.objects[0].mesh;
  EXPECT_EQ(out.size(), public_output.size()) << what;
  for (size_t i = 0; i < std::min(out.size(), public_output.size()); ++i)
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(out[i].v[k].x, public_output[i].v[k].x) << what;
      EXPECT_EQ(out[i].v[k].y, public_output[i].v[k].y) << what;
      EXPECT_EQ(out[i].v[k].z, public_output[i].v[k].z) << what;
    }
  // The mesh positions are the file's numbers.
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3& want = m.positions[mesh.position_ids[v]];
    EXPECT_NEAR(mesh.positions[v].x, want.x, 1e-15 * (1 + std::fabs(want.x))) << what;
    EXPECT_NEAR(mesh.positions[v].y, want.y, 1e-15 * (1 + std::fabs(want.y))) << what;
    EXPECT_NEAR(mesh.positions[v].z, want.z, 1e-15 * (1 + std::fabs(want.z))) << what;
  }

  bool clipped = false;
  for (size_t i = 0; i < out.size(); ++i) {
    EXPECT_EQ(check_screen_triangle(out[i], p), "") << what;
    const auto& source_triangle = mesh.triangles[trace.triangle[i]];
    Vec3 world[3];
    for (int k = 0; k < 3; ++k) world[k] = m.positions[mesh.position_ids[source_triangle[k]]];
    for (int k = 0; k < 3; ++k) {
      const std::string at = what + " triangle " + std::to_string(i) + " corner " + std::to_string(k);
      const int64_t source = trace.corners[i][k];
      if (source >= 0) {
        check_kept_vertex(out[i].v[k], c.project(m.positions[mesh.position_ids[size_t(source)]]), p, at);
      } else {
        clipped = true;
        check_made_vertex(out[i].v[k], world, c, p, at);
      }
    }
  }

  // When the independent projection puts every vertex inside the clip volume, nothing is clipped:
  // the output is the faces' fans in file order, minus the triangles wholly off one side of the
  // screen, each corner the projected position.
  bool inside = true;
  for (const Vec3& position : m.positions) {
    const Vec3 s = c.project(position);
    const double d = c.view_depth(position);
    inside = inside && d > c.near * (1 + 1e-9) && d < c.far * (1 - 1e-9) && s.x > 1 - p.width + 1e-6 &&
             s.x < 2 * p.width - 1 - 1e-6 && s.y > 1 - p.height + 1e-6 && s.y < 2 * p.height - 1 - 1e-6;
  }
  if (inside) {
    EXPECT_FALSE(clipped) << what;
    std::vector<std::array<Vec3, 3>> expected;
    for (const std::vector<int>& face : m.faces)
      for (size_t k = 1; k + 1 < face.size(); ++k) {
        const std::array<Vec3, 3> t = {c.project(m.positions[face[0]]), c.project(m.positions[face[k]]),
                                       c.project(m.positions[face[k + 1]])};
        auto all = [&](auto outside) { return outside(t[0]) && outside(t[1]) && outside(t[2]); };
        if (all([](const Vec3& s) { return s.x < 0; }) || all([&](const Vec3& s) { return s.x > p.width; }) ||
            all([](const Vec3& s) { return s.y < 0; }) || all([&](const Vec3& s) { return s.y > p.height; }))
          continue;
        expected.push_back(t);
      }
    EXPECT_EQ(out.size(), expected.size()) << what;
    for (size_t i = 0; i < std::min(out.size(), expected.size()); ++i)
      for (int k = 0; k < 3; ++k) check_kept_vertex(out[i].v[k], expected[i][k], p, what + " in order");
  }
  return clipped;
}

TEST(FrontendProjection, RandomMeshesSeenFromOutside) {
  std::mt19937 rng(2024);
  int unclipped = 0;
  for (int n = 0; n < 150; ++n) {
    const RandomMesh m = random_mesh(rng, n);
    const Profile p = random_profile(rng);
    const test_util::IndependentCamera c = random_camera(rng, m, p, false);
    const std::string what = "mesh " + std::to_string(n) + (c.ortho ? " (ortho)" : "");
    unclipped += !check_case(m, c, p, what);
  }
  EXPECT_GT(unclipped, 30);  // the in-order comparison ran often
}

TEST(FrontendProjection, RandomMeshesSeenFromCloseOrInside) {
  std::mt19937 rng(99);
  int clipped = 0;
  for (int n = 0; n < 150; ++n) {
    const RandomMesh m = random_mesh(rng, n);
    const Profile p = random_profile(rng);
    const test_util::IndependentCamera c = random_camera(rng, m, p, true);
    clipped += check_case(m, c, p, "close mesh " + std::to_string(n));
  }
  EXPECT_GT(clipped, 100);
}

}  // namespace
}  // namespace rastersim::frontend
