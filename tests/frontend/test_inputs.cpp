// OBJ files, scene files and camera settings: what is read, and every error path (InputError
// naming file:line and the reason).
#include <gtest/gtest.h>

#include <functional>
#include <iterator>
#include <vector>

#include "frontend/frontend.h"
#include "frontend/obj_loader.h"
#include "frontend/scene.h"
#include "frontend_test_util.h"
#include "model/input_error.h"

namespace rastersim::frontend {
namespace {

using test_util::write_file;

// Runs `f`, which must throw InputError whose message starts with `where` ("file:line: " or
// "file: ") and contains `reason`.
void expect_input_error(const std::function<void()>& f, const std::string& where, const std::string& reason) {
  try {
    f();
    ADD_FAILURE() << "no InputError; expected " << where << " ... " << reason;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(where, 0), 0u) << "message: " << message << "\nexpected to start with: " << where;
    EXPECT_NE(message.find(reason), std::string::npos) << "message: " << message << "\nexpected to contain: " << reason;
  }
}

Profile profile() {
  Profile p;
  p.width = 160;
  p.height = 120;
  return p;
}

// ---- OBJ ------------------------------------------------------------------------------------------

TEST(FrontendObj, PolygonsAreFannedWithTheirWinding) {
  const Mesh m = parse_obj_mesh(
      "# a quad and a pentagon\n"
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\n"
      "f 1 2 3 4\n"
      "f -5 -4 5 -3 -2   # negative indices count back from the last vertex\n",
      "fan.obj");
  ASSERT_EQ(m.triangles.size(), 2u + 3u);
  auto positions = [&](size_t t) {
    return std::array<uint32_t, 3>{m.position_ids[m.triangles[t][0]], m.position_ids[m.triangles[t][1]],
                                   m.position_ids[m.triangles[t][2]]};
  };
  EXPECT_EQ(positions(0), (std::array<uint32_t, 3>{0, 1, 2}));
  EXPECT_EQ(positions(1), (std::array<uint32_t, 3>{0, 2, 3}));
  EXPECT_EQ(positions(2), (std::array<uint32_t, 3>{0, 1, 4}));
  EXPECT_EQ(positions(3), (std::array<uint32_t, 3>{0, 4, 2}));
  EXPECT_EQ(positions(4), (std::array<uint32_t, 3>{0, 2, 3}));
}

// Faces are counted as the triangles they fan into before any is made: 255-corner faces (253
// triangles each) in 8 MB cross the scene's limit at face 15,811 (such a file under the size cap
// ended in bad_alloc).
TEST(FrontendObj, TheTrianglesOfManyCorneredFacesAreCountedAgainstTheLimit) {
  std::string face = "f";
  for (int k = 0; k < 255; ++k) face += " " + std::to_string(1 + k % 4);
  std::string text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  for (int f = 0; f < 15811; ++f) text += face + "\n";
  expect_input_error([&] { parse_obj_mesh(text, "corners.obj"); }, "corners.obj:15815: ",
                     "the faces make more than 4000000 triangles");
}

TEST(FrontendObj, NormalsFromTheFileAreNormalized) {
  const Mesh m = parse_obj_mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nvn 3 4 0\nf 1//1 2//2 3//1\n", "n.obj");
  ASSERT_EQ(m.triangles.size(), 1u);
  const Vec3 n0 = m.normals[m.triangles[0][0]], n1 = m.normals[m.triangles[0][1]];
  EXPECT_DOUBLE_EQ(n0.z, 1.0);
  EXPECT_DOUBLE_EQ(n1.x, 0.6);
  EXPECT_DOUBLE_EQ(n1.y, 0.8);
}

TEST(FrontendObj, MissingNormalsAreAreaWeighted) {
  // Vertex 1 (the origin) is shared by a triangle in the xy plane with area 2 (normal +z) and one in
  // the xz plane with area 1/2 (normal -y): the weighted sum is 4 (0, 0, 1) + 1 (0, -1, 0).
  const Mesh m = parse_obj_mesh("v 0 0 0\nv 2 0 0\nv 0 2 0\nv 0 0 1\nv 1 0 0\n"
                                "f 1 2 3\n"
                                "f 1 5 4\n",
                                "area.obj");
  ASSERT_EQ(m.triangles.size(), 2u);
  const Vec3 n = m.normals[m.triangles[0][0]];
  EXPECT_NEAR(n.x, 0.0, 1e-15);
  EXPECT_NEAR(n.y, -1 / std::sqrt(17.0), 1e-15);
  EXPECT_NEAR(n.z, 4 / std::sqrt(17.0), 1e-15);
  // Its other corners see one face each.
  EXPECT_NEAR(m.normals[m.triangles[0][1]].z, 1.0, 1e-15);
  EXPECT_NEAR(m.normals[m.triangles[1][1]].y, -1.0, 1e-15);
}

TEST(FrontendObj, IgnoredStatementsCommentsAndLineEndings) {
  const Mesh m = parse_obj_mesh(
      "mtllib missing.mtl\r\no thing\r\ng group\r\ns 1\r\nusemtl red\r\n"
      "v 0 0 0 # a comment after numbers\r\nv 1.5e0 +0 -0.\r\nv .5 1 0\r\nvt 0 0\r\nvt 1 0\r\nvt 0 1\r\n"
      "\r\n   \r\nl 1 2\r\np 3\r\n"
      "f 1/1 2/2 3/3 # comment after a face\r\n",
      "misc.obj");
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.positions[m.triangles[0][1]].x, 1.5);
  EXPECT_EQ(m.positions[m.triangles[0][2]].x, 0.5);
}

TEST(FrontendObj, TextureCoordinatesAreKeptPerCorner) {
  // A quad whose corner 1 has two texture coordinates (a seam): the corner becomes two vertices.
  const Mesh m = parse_obj_mesh("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.25\nvt -127.5 127.5 0.5\n"
                                "f 1/1 2/2 3/3\n"
                                "f 1/5 3/3 4/6\n",
                                "uv.obj");
  ASSERT_TRUE(m.textured());
  ASSERT_EQ(m.texcoords.size(), m.positions.size());
  ASSERT_EQ(m.positions.size(), 5u);  // 1/1 and 1/5 are two vertices
  auto uv = [&](size_t t, int k) { return m.texcoords[m.triangles[t][size_t(k)]]; };
  EXPECT_EQ(uv(0, 0), (std::array<double, 2>{0, 0}));
  EXPECT_EQ(uv(0, 1), (std::array<double, 2>{1, 0}));
  EXPECT_EQ(uv(0, 2), (std::array<double, 2>{1, 1}));
  EXPECT_EQ(uv(1, 0), (std::array<double, 2>{0.25, 0}));  // vt with u alone: v = 0
  EXPECT_EQ(uv(1, 1), (std::array<double, 2>{1, 1}));
  EXPECT_EQ(uv(1, 2), (std::array<double, 2>{-127.5, 127.5}));
  EXPECT_EQ(m.triangles[0][2], m.triangles[1][1]);  // 3/3 twice: one vertex
}

TEST(FrontendObj, TextureCoordinatesAreDroppedUnlessEveryCornerHasAUsableOne) {
  const std::string v3 = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n";
  EXPECT_FALSE(parse_obj_mesh(v3 + "f 1 2 3\n", "none.obj").textured());
  EXPECT_FALSE(parse_obj_mesh(v3 + "vt 0 0\nf 1/1 2/1 3/1\nf 2 4 3\n", "some.obj").textured());
  EXPECT_FALSE(parse_obj_mesh(v3 + "vt 0 0\nvt 128 0\nf 1/1 2/2 3/1\n", "range.obj").textured());
  EXPECT_FALSE(parse_obj_mesh(v3 + "vt 0 0\nvt 0 -128\nf 1/1 2/2 3/1\n", "range.obj").textured());
  const Mesh kept = parse_obj_mesh(v3 + "vt 0 0\nvt 127.99 -127.99\nf 1/1 2/2 3/1\n", "kept.obj");
  ASSERT_TRUE(kept.textured());
  EXPECT_EQ(kept.positions.size(), 3u);
}

TEST(FrontendObj, ErrorsNameTheLineAndTheProblem) {
  const std::string v3 = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  struct Case {
    std::string text;
    std::string where;
    std::string reason;
  };
  const Case cases[] = {
      {"v 1 2\n", "bad.obj:1: ", "takes 3 coordinates"},
      {"v 0 0 0\nv 1 2 abc\n", "bad.obj:2: ", "'abc' is not a decimal number"},
      {"v 0 0 nan\n", "bad.obj:1: ", "'nan' is not a decimal number"},
      {"v 0 0 inf\n", "bad.obj:1: ", "'inf' is not a decimal number"},
      {"v 0x10 0 0\n", "bad.obj:1: ", "'0x10' is not a decimal number"},
      {"v 1.5.2 0 0\n", "bad.obj:1: ", "is not a decimal number"},
      {"v 1e999 0 0\n", "bad.obj:1: ", "'1e999' is not a finite number"},
      {"v 1e 0 0\n", "bad.obj:1: ", "is not a decimal number"},
      {"vn 0 1\n", "bad.obj:1: ", "a normal 'vn' takes 3 values"},
      {"vt\n", "bad.obj:1: ", "takes 1 to 3 values"},
      {v3 + "f 1 2\n", "bad.obj:4: ", "needs at least 3 vertices, found 2"},
      {v3 + "f 1 2 9\n", "bad.obj:4: ", "vertex index 9 is out of range: the file has 3 vertices"},
      {v3 + "f 1 2 0\n", "bad.obj:4: ", "indices start at 1"},
      {v3 + "f 1 2 -4\n", "bad.obj:4: ", "vertex index -4 is out of range"},
      {"v 0 0 0\nf 1 2 3\nv 1 0 0\n", "bad.obj:2: ", "vertex index 3 is out of range"},
      {v3 + "vn 0 0 1\nf 1//1 2//2 3//1\n", "bad.obj:5: ", "normal index 2 is out of range"},
      {v3 + "f 1/1 2/1 3/1\n", "bad.obj:4: ", "texture coordinate index 1 is out of range"},
      {v3 + "f 1/2/ 2 3\n", "bad.obj:4: ", "not a valid normal index"},
      {v3 + "f 1/ 2 3\n", "bad.obj:4: ", "is not a face vertex"},
      {v3 + "f 1/2/3/4 2 3\n", "bad.obj:4: ", "is not a face vertex"},
      {v3 + "f a b c\n", "bad.obj:4: ", "'a' is not a valid vertex index"},
      {v3 + "f 1 2 3.0\n", "bad.obj:4: ", "'3.0' is not a valid vertex index"},
      {v3 + "f 1 2 99999999999999999999\n", "bad.obj:4: ", "out of range"},
      {v3 + "l 1\n", "bad.obj:4: ", "'l' needs at least 2 vertices"},
      {v3 + "frobnicate 1 2\n", "bad.obj:4: ", "unknown statement 'frobnicate'"},
      // Not an OBJ at all (a scene's mesh path may name any file): its content is not echoed.
      {"root:x:0:0:root:/root:/bin/bash\n", "bad.obj:1: ", "not an OBJ statement"},
      {"v 0 0 0 \\\n 1\n", "bad.obj:1: ", "line continuation"},
      // Found by fuzz_obj: tinyobjloader ends a line at a lone CR (and NUL) and separates values by
      // spaces and tabs only; "f\r 1 2 3" was accepted with no triangle drawn.
      {v3 + "f\r 1 2 3\n", "bad.obj:4: ", "control character 0x0D"},
      {v3 + "f 1 2 3\rf 1 2 3\n", "bad.obj:4: ", "control character 0x0D"},
      {v3 + "f 1\v2 3\n", "bad.obj:4: ", "control character 0x0B"},
      {v3 + std::string("f 1 2 3\0 1\n", 11), "bad.obj:4: ", "control character 0x00"},
      {v3, "bad.obj: ", "the file has no faces"},
      {"", "bad.obj: ", "the file has no faces"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    expect_input_error([&] { parse_obj_mesh(c.text, "bad.obj"); }, c.where, c.reason);
  }
  std::string big = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf";
  for (int i = 0; i < 256; ++i) big += " " + std::to_string(1 + i % 3);
  expect_input_error([&] { parse_obj_mesh(big + "\n", "bad.obj"); }, "bad.obj:4: ", "more than 255 vertices");
}

TEST(FrontendObj, FileErrors) {
  const std::string missing = test_util::scratch_path("does-not-exist.obj");
  expect_input_error([&] { load_obj(missing, profile(), {}); }, missing + ": ", "cannot open an OBJ file");
  const std::string folder = test_util::scratch_path("");
  expect_input_error([&] { load_obj(folder, profile(), {}); }, folder + ": ", "is a directory");
  const std::string bad = write_file("bad-line.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n");
  expect_input_error([&] { load_obj(bad, profile(), {}); }, bad + ":4: ", "not a valid vertex index");
}

TEST(FrontendObj, LoadObjFramesTheMeshAutomatically) {
  const std::string path = write_file("tetra.obj", "v 10 10 10\nv 12 10 10\nv 10 12 10\nv 10 10 12\n"
                                                   "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const std::vector<ScreenTriangle> t = load_obj(path, profile(), {});
  ASSERT_EQ(t.size(), 4u);  // nothing clipped or dropped: the whole mesh is in view
  for (const ScreenTriangle& s : t)
    for (const ScreenVertex& v : s.v) {
      EXPECT_GT(v.x, 0);
      EXPECT_LT(v.x, 160);
      EXPECT_GT(v.y, 0);
      EXPECT_LT(v.y, 120);
      EXPECT_GT(v.z, 0);
      EXPECT_LT(v.z, 1);
    }
}

// ---- Camera settings ------------------------------------------------------------------------------

TEST(FrontendCamera, DegenerateCommandLineCameras) {
  const std::string path = write_file("cam.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  auto with = [&](std::function<void(CameraOptions&)> set) {
    CameraOptions o;
    set(o);
    return [&path, o] { load_obj(path, profile(), o); };
  };
  expect_input_error(with([](CameraOptions& o) { o.fov = 0; }), "command line: ", "--fov 0 is outside (0, 180)");
  expect_input_error(with([](CameraOptions& o) { o.fov = 180; }), "command line: ", "--fov 180 is outside (0, 180)");
  expect_input_error(with([](CameraOptions& o) { o.fov = -5; }), "command line: ", "--fov -5 is outside");
  expect_input_error(with([](CameraOptions& o) { o.near = 0; }), "command line: ", "--near 0 must be greater than 0");
  expect_input_error(with([](CameraOptions& o) { o.near = -1; }), "command line: ", "--near -1 must be greater than 0");
  expect_input_error(with([](CameraOptions& o) { o.near = 2, o.far = 2; }), "command line: ",
                     "--far 2 must be greater than near 2");
  expect_input_error(with([](CameraOptions& o) { o.near = 3, o.far = 1; }), "command line: ",
                     "--far 1 must be greater than near 3");
  expect_input_error(with([](CameraOptions& o) { o.far = -1; }), "command line: ", "--far -1 must be greater than 0");
  expect_input_error(with([](CameraOptions& o) { o.eye = Vec3{0, 5, 0}, o.target = Vec3{0, 0, 0}, o.up = Vec3{0, 2, 0}; }),
                     "command line: ", "--up (0, 2, 0) is parallel to the view direction");
  expect_input_error(with([](CameraOptions& o) { o.eye = Vec3{0, 5, 0}, o.target = Vec3{0, 0, 0}, o.up = Vec3{0, -1, 0}; }),
                     "command line: ", "is parallel to the view direction");
  expect_input_error(with([](CameraOptions& o) { o.up = Vec3{0, 0, 0}; }), "command line: ", "--up is the zero vector");
  expect_input_error(with([](CameraOptions& o) { o.eye = Vec3{1, 2, 3}, o.target = Vec3{1, 2, 3}; }), "command line: ",
                     "eye and target are the same point");
  expect_input_error(with([](CameraOptions& o) { o.eye = Vec3{NAN, 0, 0}; }), "command line: ", "--eye has a coordinate that is not a finite number");
  expect_input_error(with([](CameraOptions& o) { o.near = INFINITY; }), "command line: ", "--near is not a finite number");
}

// An OBJ with 1e300 coordinates once blamed a `--eye` the user never gave ("command line: --eye ...").
TEST(FrontendCamera, ASceneTooLargeToFrameNamesTheInputNotAFlag) {
  const Sphere huge{{5e299, 0.5, 0}, INFINITY};
  expect_input_error([&] { resolve_camera({}, {}, huge, 160, 120, "big.obj"); }, "big.obj: ",
                     "too large or too far out to place a camera automatically");
  const Sphere far_out{{1e300, 0, 0}, 1e300};
  expect_input_error([&] { resolve_camera({}, {}, far_out, 160, 120, "big.obj"); }, "big.obj: ", "give --eye");
}

// A scene's mesh path may name any file: the loader's message must not quote what it holds.
TEST(FrontendObj, ANonObjFileIsNotEchoed) {
  try {
    parse_obj_mesh("root:x:0:0:root:/root:/bin/bash\n", "passwd");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("root"), std::string::npos) << e.what();
  }
}

TEST(FrontendCamera, AutomaticValuesAdaptToGivenOnes) {
  const Sphere bounds{{0, 0, 0}, 1};
  CameraOptions o;
  o.near = 50;  // beyond the automatic far: far follows
  Camera c = resolve_camera({}, o, bounds, 160, 120);
  EXPECT_EQ(c.near, 50);
  EXPECT_EQ(c.far, 100);
  o = {};
  o.far = 0.001;  // before the automatic near: near follows
  c = resolve_camera({}, o, bounds, 160, 120);
  EXPECT_EQ(c.far, 0.001);
  EXPECT_EQ(c.near, 0.0005);
  // Looking straight down with the automatic up: -z becomes up on screen.
  o = {};
  o.eye = Vec3{0, 10, 0};
  c = resolve_camera({}, o, bounds, 160, 120);
  EXPECT_EQ(c.up.z, -1);
  // A given value wins over the file's.
  CameraSettings file;
  file.values.fov = 30;
  file.fov = {"scene.json", 3};
  o = {};
  o.fov = 60;
  EXPECT_EQ(resolve_camera(file, o, bounds, 160, 120).fov, 60);
  EXPECT_EQ(resolve_camera(file, {}, bounds, 160, 120).fov, 30);
  // Inside the bounding sphere the automatic near stays positive.
  o = {};
  o.eye = Vec3{0.1, 0, 0};
  o.target = Vec3{1, 0, 0};
  c = resolve_camera({}, o, bounds, 160, 120);
  EXPECT_NEAR(c.far, 0.9 * 1.01, 1e-15);  // the sphere reaches depth 0.9 ahead
  EXPECT_NEAR(c.near, c.far * 1e-4, 1e-18);
}

// ---- Scene files ----------------------------------------------------------------------------------

TEST(FrontendScene, ReadsEveryKey) {
  write_file("scene-mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string path = write_file("scene.json", R"({
  "camera": {"eye": [4, 3, 6], "target": [0, 0.5, 0], "up": [0, 1, 0], "fov": 40,
             "near": 0.5, "far": 30, "ortho": true},
  "ambient": [51, 102, 0],
  "lights": [{"direction": [0.5, -1, -0.4], "color": [255, 0, 255]}, {"direction": [1, 0, 0]}],
  "objects": [
    {"surface": "sphere", "params": {"radius": 2, "segments": 5, "rings": 3},
     "translate": [1, 2, 3], "rotate": [0, 90, 0], "scale": [1, 2, 3],
     "color": [255, 0, 51], "specular": [0, 255, 0], "shininess": 7, "shading": "faceted"},
    {"mesh": "scene-mesh.obj", "scale": 2, "shading": "unlit"}
  ]
})");
  const Scene s = load_scene(path);
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.camera.values.eye->z, 6);
  EXPECT_EQ(s.camera.values.target->y, 0.5);
  EXPECT_EQ(*s.camera.values.fov, 40);
  EXPECT_EQ(*s.camera.values.near, 0.5);
  EXPECT_EQ(*s.camera.values.far, 30);
  EXPECT_TRUE(s.camera.values.ortho);
  EXPECT_EQ(s.camera.fov.line, 2);
  EXPECT_EQ(s.camera.near.line, 3);
  EXPECT_EQ(s.camera.near.file, path);
  EXPECT_DOUBLE_EQ(s.lighting.ambient.y, 0.4);
  ASSERT_EQ(s.lighting.lights.size(), 2u);
  EXPECT_EQ(s.lighting.lights[0].color.y, 0.0);
  EXPECT_EQ(s.lighting.lights[1].color.x, 1.0);  // default white
  const SceneObject& sphere = s.objects[0];
  EXPECT_EQ(sphere.mesh.triangles.size(), 20u);  // 3 rings of 5 segments: two pole fans and one band of quads
  EXPECT_EQ(sphere.material.shading, SurfaceShading::Faceted);
  EXPECT_EQ(sphere.material.shininess, 7);
  EXPECT_DOUBLE_EQ(sphere.material.color.z, 0.2);
  EXPECT_EQ(sphere.material.specular.y, 1.0);
  // (x, y, z) -> scale (x, 2y, 3z) -> Ry(90): (3z, 2y, -x) -> + (1, 2, 3).
  const Vec3 moved = transform_point(sphere.model, {1, 1, 1});
  EXPECT_EQ(moved.x, 4);
  EXPECT_EQ(moved.y, 4);
  EXPECT_EQ(moved.z, 2);
  EXPECT_EQ(s.objects[1].mesh.triangles.size(), 1u);
  EXPECT_EQ(s.objects[1].material.shading, SurfaceShading::Unlit);
  EXPECT_EQ(transform_point(s.objects[1].model, {1, 1, 1}).y, 2);
  EXPECT_FALSE(load_scene_file(path, profile(), {}).empty());
}

TEST(FrontendScene, DefaultsAndEmptyLights) {
  const std::string path = write_file("defaults.json", R"({"objects": [{"surface": "torus"}], "lights": []})");
  const Scene s = load_scene(path);
  EXPECT_TRUE(s.lighting.lights.empty());
  EXPECT_DOUBLE_EQ(s.lighting.ambient.x, 0.2);
  EXPECT_DOUBLE_EQ(s.objects[0].material.color.x, 0.8);
  EXPECT_EQ(s.objects[0].mesh.triangles.size(), size_t(48 * 24 * 2));
  EXPECT_FALSE(s.camera.values.eye.has_value());
  // Ambient only: every vertex colour is 0.8 * 0.2 * 255 = 40.8 -> 41.
  for (const ScreenTriangle& t : load_scene_file(path, profile(), {}))
    for (const ScreenVertex& v : t.v) EXPECT_EQ(v.color, (Rgb{41, 41, 41}));
}

TEST(FrontendScene, ErrorsNameTheLineOfTheKey) {
  write_file("ok-mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write_file("broken-mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  struct Case {
    std::string text;
    int line;  // 0: no line
    std::string reason;
  };
  const Case cases[] = {
      {"{\n  \"objects\": [\n    {\"surface\": \"sphere\",}\n  ]\n}\n", 3, "malformed JSON"},
      {"[1, 2]\n", 1, "a scene file must be a JSON object"},
      {"{\n  \"objects\": [{\"surface\": \"sphere\"}],\n  \"lightz\": []\n}\n", 3, "unknown key 'lightz' in the scene"},
      {"{\n  \"camera\": {}\n}\n", 1, "the scene has no 'objects' array"},
      {"{\n  \"objects\": []\n}\n", 2, "objects must be a non-empty array"},
      {"{\n  \"objects\": [\n    {\"surface\": \"sphere\",\n     \"colour\": [1, 2, 3]}\n  ]\n}\n", 4, "unknown key 'colour' in an object"},
      {"{\"objects\": [\n {\"translate\": [1, 2, 3]}\n]}\n", 2, "exactly one of 'mesh' and 'surface'"},
      {"{\"objects\": [\n {\"surface\": \"sphere\", \"mesh\": \"ok-mesh.obj\"}\n]}\n", 2, "exactly one of 'mesh' and 'surface'"},
      {"{\"objects\": [\n {\n  \"mesh\": 7}\n]}\n", 3, "mesh must be a file name"},
      {"{\"objects\": [\n {\"surface\": \"sphere\"},\n {\n  \"mesh\": \"nowhere.obj\"}\n]}\n", 4, "nowhere.obj' not found"},
      {"{\"objects\": [\n {\"mesh\": \"ok-mesh.obj\",\n  \"params\": {}}\n]}\n", 3, "params belong to a 'surface'"},
      {"{\"objects\": [\n {\"surface\": \"teapot\"}\n]}\n", 2, "surface must be one of sphere, torus, cylinder, cone, plane"},
      {"{\"objects\": [\n {\"surface\": \"sphere\", \"params\": {\n  \"radius\": 1,\n  \"sgments\": 3}}\n]}\n", 4,
       "unknown key 'sgments' in the params of a sphere"},
      {"{\"objects\": [\n {\"surface\": \"sphere\", \"params\": {\n  \"segments\": 2}}\n]}\n", 3, "segments must be in 3..1024"},
      {"{\"objects\": [\n {\"surface\": \"sphere\", \"params\": {\n  \"segments\": 3.5}}\n]}\n", 3, "segments must be an integer"},
      {"{\"objects\": [\n {\"surface\": \"sphere\", \"params\": {\n  \"radius\": 0}}\n]}\n", 3, "radius must be in"},
      {"{\"objects\": [\n {\"surface\": \"sphere\", \"params\": {\n  \"radius\": \"big\"}}\n]}\n", 3, "radius must be a number"},
      {"{\"objects\": [\n {\"surface\": \"torus\",\n  \"params\": {\"major_radius\": 1, \"minor_radius\": 1}}\n]}\n", 3,
       "minor_radius must be smaller than major_radius"},
      {"{\"objects\": [\n {\"surface\": \"plane\",\n  \"translate\": [1, 2]}\n]}\n", 3, "translate must be an array of 3 numbers"},
      {"{\"objects\": [\n {\"surface\": \"plane\",\n  \"rotate\": [1, 2, \"x\"]}\n]}\n", 3, "must be a number"},
      {"{\"objects\": [\n {\"surface\": \"plane\",\n  \"scale\": [1, 0, 1]}\n]}\n", 3, "scale must not be zero"},
      {"{\"objects\": [\n {\"surface\": \"plane\",\n  \"scale\": 0}\n]}\n", 3, "scale must not be zero"},
      {"{\"objects\": [\n {\"surface\": \"plane\",\n  \"color\": [0, 256, 0]}\n]}\n", 3, "color channels must be in 0..255"},
      {"{\"objects\": [\n {\"surface\": \"plane\",\n  \"shading\": \"gouraud\"}\n]}\n", 3, "shading must be"},
      {"{\"objects\": [\n {\"surface\": \"plane\",\n  \"shininess\": 0}\n]}\n", 3, "shininess must be in 1..10000"},
      {"{\"objects\": [{\"surface\": \"plane\"}],\n \"lights\": {}\n}\n", 2, "lights must be an array"},
      {"{\"objects\": [{\"surface\": \"plane\"}],\n \"lights\": [\n  {\"color\": [1, 2, 3]}]\n}\n", 3, "needs a 'direction'"},
      {"{\"objects\": [{\"surface\": \"plane\"}],\n \"lights\": [{\n  \"direction\": [0, 0, 0]}]\n}\n", 3, "must not be the zero vector"},
      {"{\"objects\": [{\"surface\": \"plane\"}],\n \"ambient\": [1, 2, 3, 4]\n}\n", 2, "ambient must be an array of 3 numbers"},
      {"{\"objects\": [{\"surface\": \"plane\"}],\n \"camera\": [1]\n}\n", 2, "camera must be a JSON object"},
      {"{\"objects\": [{\"surface\": \"plane\"}],\n \"camera\": {\n  \"zoom\": 2}\n}\n", 3, "unknown key 'zoom' in camera"},
      {"{\"objects\": [{\"surface\": \"plane\"}],\n \"camera\": {\n  \"ortho\": 1}\n}\n", 3, "camera ortho must be true or false"},
      {"{\"objects\": [{\"surface\": \"plane\"}],\n \"camera\": {\n  \"fov\": 180}\n}\n", 3, "camera fov 180 is outside (0, 180)"},
      {"{\"objects\": [{\"surface\": \"plane\"}],\n \"camera\": {\n  \"near\": 0}\n}\n", 3, "camera near 0 must be greater than 0"},
      {"{\"objects\": [{\"surface\": \"plane\"}],\n \"camera\": {\"near\": 5,\n  \"far\": 4}\n}\n", 3,
       "camera far 4 must be greater than near 5"},
      {"{\"objects\": [{\"surface\": \"plane\"}],\n \"camera\": {\"eye\": [0, 9, 0], \"target\": [0, 0, 0],\n  \"up\": [0, 1, 0]}\n}\n", 3,
       "camera up (0, 1, 0) is parallel to the view direction"},
      {"{\"objects\": [{\"surface\": \"plane\"}],\n \"camera\": {\"eye\": [1, 1, 1],\n  \"target\": [1, 1, 1]}\n}\n", 3,
       "eye and target are the same point"},
  };
  // A key named twice at any level (the last one silently won), also when spelled with an escape.
  const Case twice[] = {
      {"{\"objects\": [{\"surface\": \"plane\"}],\n \"objects\": [{\"surface\": \"sphere\"}]\n}\n", 2,
       "key 'objects' is given twice (first on line 1)"},
      {"{\"objects\": [\n {\"surface\": \"plane\",\n  \"surface\": \"sphere\"}\n]}\n", 3,
       "key 'surface' is given twice (first on line 2)"},
      {"{\"objects\": [{\"surface\": \"sphere\", \"params\": {\n  \"radius\": 1,\n  \"r\\u0061dius\": 2}}]}\n", 3,
       "key 'radius' is given twice (first on line 2)"},
      {"{\"objects\": [{\"surface\": \"plane\"}],\n \"camera\": {\"fov\": 40,\n  \"f\\u006fv\": 60}\n}\n", 3,
       "key 'fov' is given twice (first on line 2)"},
  };
  // Found by fuzz_scene: a number beyond a double's range escaped as an uncaught exception, and
  // deep nesting overflowed the stack of the line finder.
  const Case found_by_fuzzing[] = {
      {"{\"objects\": [{\"surface\": \"plane\"}],\n \"ambient\": [1e400, 0, 0]\n}\n", 2, "malformed JSON"},
      {"{\"objects\": [{\"surface\": \"plane\"}],\n \"extra\": " + std::string(100000, '[') + std::string(100000, ']') +
           "\n}\n",
       2, "unknown key 'extra' in the scene"},
  };
  std::vector<Case> all(std::begin(cases), std::end(cases));
  all.insert(all.end(), std::begin(found_by_fuzzing), std::end(found_by_fuzzing));
  all.insert(all.end(), std::begin(twice), std::end(twice));
  for (const Case& c : all) {
    SCOPED_TRACE(c.text.substr(0, 200));
    const std::string path = write_file("bad-scene.json", c.text);
    expect_input_error([&] { load_scene_file(path, profile(), {}); },
                       path + (c.line ? ":" + std::to_string(c.line) : std::string()) + ": ", c.reason);
  }
  // An error inside a mesh names the mesh file and its line.
  const std::string path = write_file("mesh-error.json", "{\"objects\": [{\"mesh\": \"broken-mesh.obj\"}]}");
  expect_input_error([&] { load_scene_file(path, profile(), {}); }, test_util::scratch_path("broken-mesh.obj") + ":4: ",
                     "vertex index 7 is out of range");
  // ... and the scene that named it (the user gave the scene, not the mesh).
  expect_input_error([&] { load_scene_file(path, profile(), {}); }, test_util::scratch_path("broken-mesh.obj") + ":4: ",
                     "(the mesh of " + path + ":1)");
  const std::string missing = test_util::scratch_path("no-scene.json");
  expect_input_error([&] { load_scene_file(missing, profile(), {}); }, missing + ": ", "cannot open a scene file");
}

// Twenty spheres of 1024 x 1024 once grew to 3.9 GB and died in bad_alloc: the scene's triangle
// count is bounded object by object, and the object that crosses the bound is named.
TEST(FrontendScene, TriangleCountIsBounded) {
  const std::string big = "{\"surface\": \"sphere\", \"params\": {\"segments\": 1024, \"rings\": 1024}}";
  const std::string path = write_file("huge-scene.json", "{\"objects\": [\n" + big + ",\n" + big + ",\n" + big + "]}\n");
  expect_input_error([&] { load_scene_file(path, profile(), {}); }, path + ":3: ",
                     "the scene has 4190208 triangles with this object, more than the 4000000 a scene may have");
}

TEST(FrontendScene, CommandLineOverridesAndIsBlamed) {
  const std::string path = write_file("override.json",
                                      "{\"objects\": [{\"surface\": \"sphere\"}],\n \"camera\": {\n  \"near\": 5}\n}\n");
  CameraOptions o;
  o.far = 3;
  expect_input_error([&] { load_scene_file(path, profile(), o); }, "command line: ", "--far 3 must be greater than near 5");
  o = {};
  o.near = 0.5;  // the flag replaces the file's near 5
  EXPECT_FALSE(load_scene_file(path, profile(), o).empty());
}

TEST(FrontendScene, MirroringKeepsFrontFacesCounterClockwise) {
  for (const char* scale : {"[1, 1, 1]", "[-1, 1, 1]", "[1, -2, 1]", "[-1, -1, -1]"}) {
    SCOPED_TRACE(scale);
    const std::string path = write_file(
        "mirror.json", std::string("{\"objects\": [{\"surface\": \"sphere\", \"scale\": ") + scale +
                           "}], \"camera\": {\"eye\": [0, 0, 5], \"target\": [0, 0, 0], \"near\": 1, \"far\": 10}}");
    const std::vector<ScreenTriangle> t = load_scene_file(path, profile(), {});
    Profile back = profile();
    back.cull = CullMode::Back;
    Profile front = profile();
    front.cull = CullMode::Front;
    const std::vector<int> f = test_util::coverage(t, back), b = test_util::coverage(t, front);
    int covered = 0;
    for (size_t i = 0; i < f.size(); ++i) {
      ASSERT_EQ(f[i], b[i]);
      ASSERT_LE(f[i], 1);
      covered += f[i];
    }
    EXPECT_GT(covered, 2000);
    // Lit from the default key light, the front layer is not just ambient: normals stay outward.
    Profile lit = back;
    Pipeline pipe(lit);
    for (const ScreenTriangle& s : t) pipe.submit(snap(s, lit));
    uint32_t brightest = 0;
    for (uint32_t c : pipe.zbuffer().color()) brightest = std::max(brightest, (c >> 16) & 255);
    EXPECT_GT(brightest, 150u);
  }
}

// ---- Built-in scenes ------------------------------------------------------------------------------

TEST(FrontendBuiltins, ListAndRender) {
  const auto list = builtin_scene_list();
  ASSERT_FALSE(list.empty());
  EXPECT_EQ(list[0].first, "default");
  for (const auto& [name, description] : list) {
    SCOPED_TRACE(name);
    EXPECT_FALSE(description.empty());
    for (const Profile& p : {profile(), Profile{}}) {
      const std::vector<ScreenTriangle> t = builtin_scene(name, p, {});
      EXPECT_GT(t.size(), 100u);
      for (const ScreenTriangle& s : t) ASSERT_EQ(check_screen_triangle(s, p), "");
    }
  }
  expect_input_error([] { builtin_scene("nonesuch", profile(), {}); }, "--scene: ", "unknown built-in scene 'nonesuch'");
}

}  // namespace
}  // namespace rastersim::frontend
