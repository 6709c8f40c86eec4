// The worked examples of docs/frontend.md, recomputed: through the front end's code and, where the
// page gives a formula, through that formula written out here. The page's numbers were derived by
// hand with exact fractions.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "frontend/camera.h"
#include "frontend/clip.h"
#include "frontend/lighting.h"
#include "frontend/scene.h"
#include "frontend/transform.h"
#include "frontend_test_util.h"
#include "model/triangle_setup.h"

namespace rastersim::frontend {
namespace {

using Block = std::map<std::string, std::vector<double>>;

// The `key = numbers` lines of the ```frontend-example NAME block of docs/frontend.md.
Block example(const std::string& name) {
  std::ifstream in(RASTERSIM_DOCS_FRONTEND);
  EXPECT_TRUE(in) << "cannot open " << RASTERSIM_DOCS_FRONTEND;
  Block block;
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (!inside && line == "```frontend-example " + name) inside = true;
    else if (inside && line == "```") break;
    else if (inside) {
      const size_t eq = line.find(" = ");
      if (eq == std::string::npos) continue;
      std::istringstream values(line.substr(eq + 3));
      std::vector<double>& v = block[line.substr(0, eq)];
      for (double d; values >> d;) v.push_back(d);
    }
  }
  EXPECT_FALSE(block.empty()) << "no ```frontend-example " << name << " block";
  return block;
}

Vec3 vec(const Block& b, const std::string& key) {
  const std::vector<double>& v = b.at(key);
  EXPECT_EQ(v.size(), 3u) << key;
  return {v.at(0), v.at(1), v.at(2)};
}

Camera camera_of(const Block& b) {
  Camera c;
  c.eye = vec(b, "eye");
  c.target = vec(b, "target");
  c.up = vec(b, "up");
  c.fov = b.at("fov")[0];
  c.near = b.at("near")[0];
  c.far = b.at("far")[0];
  c.ortho = b.count("ortho") && b.at("ortho")[0] != 0;
  c.aspect = b.at("width")[0] / b.at("height")[0];
  return c;
}

test_util::IndependentCamera independent_of(const Block& b) {
  test_util::IndependentCamera c;
  c.eye = vec(b, "eye");
  c.target = vec(b, "target");
  c.up = vec(b, "up");
  c.fov = b.at("fov")[0];
  c.near = b.at("near")[0];
  c.far = b.at("far")[0];
  c.ortho = b.count("ortho") && b.at("ortho")[0] != 0;
  c.width = int(b.at("width")[0]);
  c.height = int(b.at("height")[0]);
  return c;
}

Profile profile_of(const Block& b) {
  Profile p;
  p.width = int(b.at("width")[0]);
  p.height = int(b.at("height")[0]);
  return p;
}

void expect_near3(const Vec3& got, const Vec3& want, double tolerance, const std::string& what) {
  EXPECT_NEAR(got.x, want.x, tolerance) << what;
  EXPECT_NEAR(got.y, want.y, tolerance) << what;
  EXPECT_NEAR(got.z, want.z, tolerance) << what;
}

void check_projection_example(const std::string& name) {
  SCOPED_TRACE(name);
  const Block b = example(name);
  const Camera camera = camera_of(b);
  const Vec3 point = vec(b, "point");
  const Vec4 eye_space = camera.view() * Vec4{point.x, point.y, point.z, 1};
  expect_near3({eye_space.x, eye_space.y, eye_space.z}, vec(b, "eye_space"), 1e-12, "eye space");
  const Vec4 clip = camera.projection() * eye_space;
  if (b.count("clip")) {
    const std::vector<double>& want = b.at("clip");
    EXPECT_NEAR(clip.x, want[0], 1e-12);
    EXPECT_NEAR(clip.y, want[1], 1e-12);
    EXPECT_NEAR(clip.z, want[2], 1e-12);
    EXPECT_NEAR(clip.w, want[3], 1e-12);
  }
  if (b.count("ndc")) expect_near3({clip.x / clip.w, clip.y / clip.w, clip.z / clip.w}, vec(b, "ndc"), 1e-12, "ndc");
  const ScreenPoint s = viewport(clip.x / clip.w, clip.y / clip.w, clip.z / clip.w, int(b.at("width")[0]),
                                 int(b.at("height")[0]));
  expect_near3({s.x, s.y, s.z}, vec(b, "screen"), 1e-9, "screen (front end)");
  expect_near3(independent_of(b).project(point), vec(b, "screen"), 1e-9, "screen (independent formula)");
  if (b.count("snapped_s4")) {
    EXPECT_EQ(snap_coordinate(s.x, 4, VertexSnap::Nearest), int64_t(b.at("snapped_s4")[0]));
    EXPECT_EQ(snap_coordinate(s.y, 4, VertexSnap::Nearest), int64_t(b.at("snapped_s4")[1]));
  }
  if (b.count("depth_z24")) {
    EXPECT_EQ(quantize_depth(s.z, 24), uint32_t(b.at("depth_z24")[0]));
  }
}

TEST(FrontendDocs, PerspectiveExample) { check_projection_example("perspective"); }
TEST(FrontendDocs, RotatedCameraExample) { check_projection_example("rotated-camera"); }
TEST(FrontendDocs, OrthographicExample) { check_projection_example("orthographic"); }

TEST(FrontendDocs, ModelMatrixExample) {
  const Block b = example("model");
  const Mat4 m = model_matrix(vec(b, "translate"), vec(b, "rotate"), vec(b, "scale"));
  const Vec3 world = transform_point(m, vec(b, "point"));
  EXPECT_EQ(world.x, vec(b, "world").x);  // quarter turns are exact
  EXPECT_EQ(world.y, vec(b, "world").y);
  EXPECT_EQ(world.z, vec(b, "world").z);
  const Mat4 scaled = model_matrix({}, {}, vec(b, "normal_scale"));
  const Vec3 n = normalize(transform_direction(normal_matrix(scaled), vec(b, "normal")));
  expect_near3(n, vec(b, "world_normal"), 1e-15, "normal");
  // The defining property of the normal matrix: a tangent t with n.t = 0 stays perpendicular.
  const Vec3 tangent{1, -1, 0};
  EXPECT_NEAR(dot(n, transform_direction(scaled, tangent)), 0.0, 1e-15);
}

// A scene of one unlit triangle through the whole front end.
std::vector<ScreenTriangle> render_triangle(const Block& b) {
  Scene scene;
  SceneObject object;
  object.mesh.add_vertex(vec(b, "a"), {}, 0);
  object.mesh.add_vertex(vec(b, "b"), {}, 1);
  object.mesh.add_vertex(vec(b, "c"), {}, 2);
  object.mesh.triangles.push_back({0, 1, 2});
  object.material.shading = SurfaceShading::Unlit;
  scene.objects.push_back(object);
  return render_scene(scene, camera_of(b), profile_of(b));
}

TEST(FrontendDocs, WindingExample) {
  const Block b = example("winding");
  const std::vector<ScreenTriangle> out = render_triangle(b);
  ASSERT_EQ(out.size(), 1u);
  const char* keys[3] = {"screen_a", "screen_b", "screen_c"};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(out[0].v[k].x, b.at(keys[k])[0], 1e-9);
    EXPECT_NEAR(out[0].v[k].y, b.at(keys[k])[1], 1e-9);
  }
  Profile p = profile_of(b);
  p.subpixel_bits = 4;
  p.front_face = FrontFace::CCW;
  const SetupResult r = TriangleSetup(p).run(snap(out[0], p));
  EXPECT_EQ(r.area2, int64_t(b.at("area2_s4")[0]));
  EXPECT_TRUE(r.front_facing);
}

void check_clip_example(const std::string& name) {
  SCOPED_TRACE(name);
  const Block b = example(name);
  const std::vector<ScreenTriangle> out = render_triangle(b);
  ASSERT_EQ(out.size(), size_t(b.at("triangles")[0]));
  for (size_t t = 0; t < out.size(); ++t) {
    const std::vector<double>& want = b.at("triangle" + std::to_string(t));
    ASSERT_EQ(want.size(), 9u);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(out[t].v[k].x, want[3 * k], 1e-9) << "triangle " << t << " vertex " << k;
      EXPECT_NEAR(out[t].v[k].y, want[3 * k + 1], 1e-9) << "triangle " << t << " vertex " << k;
      EXPECT_NEAR(out[t].v[k].z, want[3 * k + 2], 1e-12) << "triangle " << t << " vertex " << k;
    }
  }
  if (b.count("band")) {
    const Clipper clipper(profile_of(b));
    EXPECT_DOUBLE_EQ(clipper.band_x(), b.at("band")[0]);
    EXPECT_DOUBLE_EQ(clipper.band_y(), b.at("band")[1]);
  }
}

TEST(FrontendDocs, NearClipExample) { check_clip_example("near-clip"); }
TEST(FrontendDocs, GuardClipExample) { check_clip_example("guard-clip"); }

TEST(FrontendDocs, LightingExample) {
  const Block b = example("lighting");
  Material m;
  m.color = vec(b, "color");
  Lighting l;
  l.ambient = vec(b, "ambient");
  l.lights.push_back({vec(b, "light_direction"), vec(b, "light_color")});
  auto rounded = [](const Vec3& c) { return Vec3{std::floor(c.x + 0.5), std::floor(c.y + 0.5), std::floor(c.z + 0.5)}; };
  expect_near3(rounded(shade(m, l, vec(b, "normal"), vec(b, "to_eye"))), vec(b, "diffuse_rgb"), 0, "diffuse");
  expect_near3(rounded(shade(m, l, vec(b, "tilted_normal"), vec(b, "to_eye"))), vec(b, "tilted_rgb"), 0, "tilted");
  m.specular = vec(b, "specular");
  m.shininess = b.at("shininess")[0];
  expect_near3(rounded(shade(m, l, vec(b, "normal"), vec(b, "to_eye"))), vec(b, "specular_rgb"), 0, "specular");
}

TEST(FrontendDocs, AutomaticCameraExample) {
  const Block b = example("auto-camera");
  const Sphere bounds{vec(b, "centre"), b.at("radius")[0]};
  const Camera c = resolve_camera({}, {}, bounds, int(b.at("width")[0]), int(b.at("height")[0]));
  expect_near3(c.eye, vec(b, "eye"), 1e-12, "eye");
  expect_near3(c.target, vec(b, "target"), 0, "target");
  EXPECT_NEAR(c.near, b.at("near")[0], 1e-12);
  EXPECT_NEAR(c.far, b.at("far")[0], 1e-12);
  EXPECT_EQ(c.fov, kDefaultFov);
  // The sphere fits: its silhouette's angular radius asin(r / D) stays inside half the vertical fov.
  const double distance = length(c.eye - bounds.centre);
  EXPECT_LT(std::asin(bounds.radius / distance), kDefaultFov * M_PI / 360.0);
}

}  // namespace
}  // namespace rastersim::frontend
