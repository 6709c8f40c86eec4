// Closed convex meshes through the front end and the model pipeline (depth_func always): seen from
// outside, crossing the near plane, surrounding the camera, reaching thousands of pixels off screen.
// Front layer F (cull back) and back layer B (cull front) are counted per pixel:
// - always F <= 1 and B <= 1 (no overlaps);
// - without near or far cuts F == B exactly (a closed mesh: every ray in enters and leaves), which
//   catches any crack in either layer, clipped or not;
// - for the box, each pixel away from the silhouette and cut lines (snapping moves them) matches an
//   independent ray cast: F iff the ray enters the box between near and far, B iff it leaves there.
#include <gtest/gtest.h>

#include <random>

#include "frontend/frontend.h"
#include "frontend/scene.h"
#include "frontend/surfaces.h"
#include "frontend_test_util.h"

namespace rastersim::frontend {
namespace {

// The cube [-1, 1]^3 with each face an n x n grid of quads, vertices shared by index, outward faces
// counter-clockwise.
std::string box_obj(int n) {
  std::map<std::array<int, 3>, int> index;
  std::string obj = "# subdivided cube\n";
  auto vertex = [&](std::array<int, 3> g) {
    auto it = index.find(g);
    if (it != index.end()) return it->second;
    char line[128];
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", -1 + 2.0 * g[0] / n, -1 + 2.0 * g[1] / n, -1 + 2.0 * g[2] / n);
    obj += line;
    const int i = int(index.size()) + 1;
    index[g] = i;
    return i;
  };
  std::string faces;
  for (int axis = 0; axis < 3; ++axis)
    for (int side : {0, n}) {
      // (u, v) axes with e_u x e_v = +e_axis; on the negative side the corners run backwards.
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          std::array<int, 3> g[4];
          const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
          for (int k = 0; k < 4; ++k) {
            g[k][axis] = side;
            g[k][u] = a + du[k];
            g[k][v] = b + dv[k];
          }
          int id[4];
          for (int k = 0; k < 4; ++k) id[k] = vertex(g[k]);
          faces += side == n ? "f " + std::to_string(id[0]) + " " + std::to_string(id[1]) + " " + std::to_string(id[2]) + " " + std::to_string(id[3]) + "\n"
                             : "f " + std::to_string(id[3]) + " " + std::to_string(id[2]) + " " + std::to_string(id[1]) + " " + std::to_string(id[0]) + "\n";
        }
    }
  return obj + faces;
}

struct Layers {
  std::vector<int> front, back;
};

Layers layers(const std::vector<ScreenTriangle>& triangles, Profile p) {
  p.cull = CullMode::Back;
  Layers l;
  l.front = test_util::coverage(triangles, p);
  p.cull = CullMode::Front;
  l.back = test_util::coverage(triangles, p);
  return l;
}

// Homogeneous screen point (x d, y d, d) of a world point: a line through two of them is the
// projection of the 3D line, also when a point is behind the eye.
Vec3 homogeneous(const test_util::IndependentCamera& c, const Vec3& p) {
  const Vec3 rel = p - c.eye;
  const double xe = dot(rel, c.right()), ye = dot(rel, c.true_up()), d = dot(rel, c.forward());
  if (c.ortho) {
    const double h = c.ortho_half_height();
    return {c.width * (0.5 + 0.5 * xe / (h * c.aspect())), c.height * (0.5 - 0.5 * ye / h), 1};
  }
  return {c.width * (0.5 * d + 0.5 * xe / (c.tan_half() * c.aspect())), c.height * (0.5 * d - 0.5 * ye / c.tan_half()), d};
}

double line_distance(const Vec3& line, double x, double y) {
  const double norm = std::hypot(line.x, line.y);
  return norm > 0 ? std::fabs(line.x * x + line.y * y + line.z) / norm : INFINITY;
}

// The screen lines where the box's coverage can change: its 12 edges (`edges`), and where its 6
// face planes meet the near and the far plane (`cuts`).
void box_boundary_lines(const test_util::IndependentCamera& c, std::vector<Vec3>& lines, std::vector<Vec3>& cuts) {
  for (int axis = 0; axis < 3; ++axis)
    for (double s1 : {-1.0, 1.0})
      for (double s2 : {-1.0, 1.0}) {
        Vec3 a, b;
        double* pa[3] = {&a.x, &a.y, &a.z};
        double* pb[3] = {&b.x, &b.y, &b.z};
        *pa[axis] = -1, *pb[axis] = 1;
        *pa[(axis + 1) % 3] = *pb[(axis + 1) % 3] = s1;
        *pa[(axis + 2) % 3] = *pb[(axis + 2) % 3] = s2;
        lines.push_back(cross(homogeneous(c, a), homogeneous(c, b)));
      }
  const Vec3 f = c.forward();
  for (double depth : {c.near, c.far})
    for (int axis = 0; axis < 3; ++axis)
      for (double side : {-1.0, 1.0}) {
        // Points with p[axis] = side and dot(p - eye, f) = depth.
        const double fa[3] = {f.x, f.y, f.z}, e[3] = {c.eye.x, c.eye.y, c.eye.z};
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const int solve = std::fabs(fa[u]) > std::fabs(fa[v]) ? u : v, free = solve == u ? v : u;
        if (std::fabs(fa[solve]) < 1e-12) continue;  // face plane parallel to the near plane
        Vec3 q[2];
        for (int k = 0; k < 2; ++k) {
          double p[3];
          p[axis] = side;
          p[free] = k ? 10.0 : -10.0;
          p[solve] = e[solve] + (depth - fa[axis] * (side - e[axis]) - fa[free] * (p[free] - e[free])) / fa[solve];
          q[k] = {p[0], p[1], p[2]};
        }
        cuts.push_back(cross(homogeneous(c, q[0]), homogeneous(c, q[1])));
      }
}

// Where the ray through a screen point enters and leaves the box, in view depth (slab method).
bool box_hit(const test_util::IndependentCamera& c, double sx, double sy, double& enter, double& leave) {
  Vec3 o, d;
  c.ray(sx, sy, o, d);
  enter = -INFINITY, leave = INFINITY;
  const double origin[3] = {o.x, o.y, o.z}, direction[3] = {d.x, d.y, d.z};
  for (int k = 0; k < 3; ++k) {
    if (direction[k] == 0) {
      if (std::fabs(origin[k]) > 1) return false;
      continue;
    }
    double t0 = (-1 - origin[k]) / direction[k], t1 = (1 - origin[k]) / direction[k];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  // d has unit view depth, and an orthographic ray starts on the eye plane: t is the view depth.
  return enter < leave;
}

struct Scenario {
  std::string what;
  test_util::IndependentCamera camera;
};

CameraOptions options_of(const test_util::IndependentCamera& c) {
  CameraOptions o;
  o.eye = c.eye, o.target = c.target, o.up = c.up, o.fov = c.fov, o.near = c.near, o.far = c.far;
  o.ortho = c.ortho;
  return o;
}

// Returns whether any of the box is visible.
bool check_box(const Scenario& s, const std::string& obj_path, const Profile& p) {
  SCOPED_TRACE(s.what);
  const test_util::IndependentCamera& c = s.camera;
  const std::vector<ScreenTriangle> triangles = load_obj(obj_path, p, options_of(c));
  const Layers l = layers(triangles, p);
  std::vector<Vec3> lines, cuts;
  box_boundary_lines(c, lines, cuts);
  // Snapping moves an edge by up to 0.71 subpixel; a clip-made vertex merged into a kept one moves a
  // cut line by up to 2 subpixels more (docs/frontend.md, Clipping).
  const double subpixel = std::ldexp(1.0, -p.subpixel_bits);
  const double margin = 0.05 + 0.75 * subpixel, cut_margin = 0.05 + 3 * subpixel;
  int checked = 0, front = 0, back = 0;
  for (int j = 0; j < p.height; ++j)
    for (int i = 0; i < p.width; ++i) {
      const size_t at = size_t(j) * p.width + i;
      if (l.front[at] > 1 || l.back[at] > 1) {
        ADD_FAILURE() << "a layer overlaps itself at pixel " << i << "," << j;
        return true;
      }
      const double x = i + 0.5, y = j + 0.5;
      bool near_line = false;
      for (const Vec3& line : lines) near_line = near_line || line_distance(line, x, y) < margin;
      for (const Vec3& line : cuts) near_line = near_line || line_distance(line, x, y) < cut_margin;
      if (near_line) continue;
      double enter, leave;
      const bool hit = box_hit(c, x, y, enter, leave);
      const bool want_front = hit && enter >= c.near && enter <= c.far;
      const bool want_back = hit && leave >= c.near && leave <= c.far;
      ++checked;
      front += want_front;
      back += want_back;
      if (l.front[at] != int(want_front) || l.back[at] != int(want_back)) {
        ADD_FAILURE() << "pixel " << i << "," << j << ": front " << l.front[at] << " back " << l.back[at]
                      << ", but the ray enters at depth " << enter << " and leaves at " << leave << " (near "
                      << c.near << ", far " << c.far << ")";
        return true;
      }
    }
  EXPECT_GT(checked, p.width * p.height / 3);
  return front + back > 0;
}

Profile test_profile(int subpixel_bits = 4) {
  Profile p;
  p.width = 160;
  p.height = 120;
  p.subpixel_bits = subpixel_bits;
  return p;
}

test_util::IndependentCamera camera(const Vec3& eye, const Vec3& target, double fov, double near, double far,
                                  bool ortho = false) {
  test_util::IndependentCamera c;
  c.eye = eye, c.target = target, c.up = {0, 1, 0}, c.fov = fov, c.near = near, c.far = far, c.ortho = ortho;
  c.width = 160, c.height = 120;
  return c;
}

TEST(FrontendWatertight, BoxDirectedCameras) {
  const std::string path = test_util::write_file("box.obj", box_obj(5));
  const Scenario scenarios[] = {
      {"outside, whole box in view", camera({3, 2.5, 4}, {0, 0, 0}, 50, 0.5, 20)},
      {"outside, orthographic", camera({3, 2.5, 4}, {0, 0, 0}, 50, 0.5, 20, true)},
      {"near plane cuts the box", camera({1.2, 0.9, 1.6}, {0, 0, 0}, 60, 1.1, 20)},
      {"far plane cuts the box", camera({3, 2.5, 4}, {0, 0, 0}, 50, 0.5, 5.6)},
      {"close to a face: vertices thousands of pixels off screen", camera({0.2, 0.1, 1.05}, {0.1, 0, 0}, 90, 0.02, 20)},
      {"close to a corner, near plane cutting", camera({1.1, 1.05, 1.2}, {0, 0, 0}, 100, 0.25, 20)},
      {"inside, looking at a corner", camera({0.3, -0.2, 0.1}, {1, 1, 1}, 90, 0.01, 20)},
      {"inside, near plane cutting the walls", camera({0.5, 0.5, 0.6}, {1, 0.8, 1}, 70, 0.6, 20)},
  };
  for (int subpixel_bits : {1, 4, 8})
    for (const Scenario& s : scenarios) {
      SCOPED_TRACE("S = " + std::to_string(subpixel_bits));
      EXPECT_TRUE(check_box(s, path, test_profile(subpixel_bits)));
    }
}

TEST(FrontendWatertight, BoxRandomCameras) {
  const std::string path = test_util::write_file("box4.obj", box_obj(4));
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> unit(-1, 1), fraction(0, 1);
  int visible = 0;
  for (int n = 0; n < 120; ++n) {
    test_util::IndependentCamera c;
    c.width = 160, c.height = 120;
    const double reach = n % 3 == 0 ? 0.8 : n % 3 == 1 ? 1.6 : 4.0;  // inside, close, outside
    do c.eye = reach * Vec3{unit(rng), unit(rng), unit(rng)};
    while (n % 3 != 0 && std::max({std::fabs(c.eye.x), std::fabs(c.eye.y), std::fabs(c.eye.z)}) <= 1.05);
    c.target = 0.5 * Vec3{unit(rng), unit(rng), unit(rng)};
    do c.up = Vec3{unit(rng), unit(rng), unit(rng)};
    while (length(cross(normalize(c.up), normalize(c.target - c.eye))) < 0.2);
    c.fov = 30 + 90 * fraction(rng);
    c.near = 0.01 + 1.2 * fraction(rng) * fraction(rng);
    c.far = c.near + 0.5 + 8 * fraction(rng);
    c.ortho = n % 7 == 3;
    visible += check_box({"random camera " + std::to_string(n), c}, path, test_profile(4));
  }
  EXPECT_GT(visible, 90);
}

// Surfaces from the front end's own generator: the topological check (F == B without cuts) and,
// from inside a sphere, every pixel exactly once.
Scene single_object_scene(Mesh mesh) {
  Scene scene;
  SceneObject o;
  o.mesh = std::move(mesh);
  scene.objects.push_back(o);
  return scene;
}

Camera resolved(const Scene& scene, const test_util::IndependentCamera& c, const Profile& p) {
  return resolve_camera({}, options_of(c), scene_bounds(scene), p.width, p.height);
}

TEST(FrontendWatertight, ClosedSurfacesFromOutsideHaveEqualLayers) {
  const Profile p = test_profile(4);
  const Mesh meshes[] = {make_sphere(1, 24, 12), make_torus(1, 0.35, 24, 12), make_cylinder(0.8, 1.6, 20, 3),
                         make_cone(0.9, 1.8, 20, 2)};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int m = 0; m < 4; ++m)
    for (int n = 0; n < 10; ++n) {
      const Scene scene = single_object_scene(meshes[m]);
      Vec3 eye;
      do eye = 4.0 * Vec3{unit(rng), unit(rng), unit(rng)};
      while (length(eye) < 2.8);
      // Near and far bracket the whole surface; the fov makes it reach far off screen sometimes.
      const test_util::IndependentCamera c = camera(eye, 0.4 * Vec3{unit(rng), unit(rng), unit(rng)}, n % 2 ? 20 : 60, 0.3, 10);
      const std::vector<ScreenTriangle> t = render_scene(scene, resolved(scene, c, p), p);
      const Layers l = layers(t, p);
      int covered = 0;
      for (size_t i = 0; i < l.front.size(); ++i) {
        // The polyhedral torus is not convex (near its contour a ray may cross it six times).
        if (m != 1) {
          ASSERT_LE(l.front[i], 1) << "surface " << m << " camera " << n;
        }
        ASSERT_EQ(l.front[i], l.back[i]) << "surface " << m << " camera " << n << " pixel " << i % p.width << ","
                                         << i / p.width;
        covered += l.front[i] > 0;
      }
      EXPECT_GT(covered, 100) << "surface " << m << " camera " << n;
    }
}

TEST(FrontendWatertight, InsideASphereEveryPixelOnce) {
  const Profile p = test_profile(4);
  const Scene scene = single_object_scene(make_sphere(3, 32, 16));
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int n = 0; n < 12; ++n) {
    const Vec3 eye = 1.5 * Vec3{unit(rng), unit(rng), unit(rng)};
    const Vec3 target = eye + Vec3{unit(rng), unit(rng), unit(rng)};
    const test_util::IndependentCamera c = camera(eye, target, 40 + 10 * n, 0.05, 20);
    const std::vector<ScreenTriangle> t = render_scene(scene, resolved(scene, c, p), p);
    Profile none = p;
    none.cull = CullMode::None;
    const std::vector<int> all = test_util::coverage(t, none);
    for (size_t i = 0; i < all.size(); ++i)
      ASSERT_EQ(all[i], 1) << "camera " << n << " pixel " << i % p.width << "," << i / p.width;
    Profile back = p;
    back.cull = CullMode::Back;
    const std::vector<int> front_faces = test_util::coverage(t, back);
    for (int count : front_faces) ASSERT_EQ(count, 0) << "camera " << n << ": from inside every face is a back face";
  }
}

}  // namespace
}  // namespace rastersim::frontend
