// The built-in 3D scenes. Every one is lit by one key light plus ambient and has its own camera
// (reported as "built-in scene 'NAME'" should a command-line override make it degenerate).
#include <functional>
#include <memory>

#include "frontend/frontend.h"
#include "frontend/scene.h"
#include "frontend/surfaces.h"
#include "frontend/transform.h"
#include "model/input_error.h"

namespace rastersim::frontend {
namespace {

Vec3 rgb(double r, double g, double b) { return {r / 255.0, g / 255.0, b / 255.0}; }

SceneObject object(Mesh mesh, const Vec3& translate, const Vec3& rotate, const Vec3& color, double scale = 1.0) {
  SceneObject o;
  o.mesh = std::move(mesh);
  o.model = model_matrix(translate, rotate, {scale, scale, scale});
  o.material.color = color;
  return o;
}

void set_camera(Scene& scene, const std::string& name, const Vec3& eye, const Vec3& target, double fov) {
  const Origin origin{"built-in scene '" + name + "'", 0};
  scene.camera.values.eye = eye;
  scene.camera.values.target = target;
  scene.camera.values.fov = fov;
  scene.camera.eye = scene.camera.target = scene.camera.fov = origin;
  scene.camera.up = scene.camera.near = scene.camera.far = origin;
}

Lighting key_light() {
  Lighting l;
  l.ambient = {0.22, 0.22, 0.24};
  l.lights.push_back({{0.55, -1.0, -0.35}, {0.9, 0.88, 0.82}});  // from the upper left, slightly in front
  return l;
}

// A red sphere sunk into a grey floor, a blue torus threaded through it and a green cylinder
// piercing both: every pair meets along a curve the z-buffer has to find.
Scene default_scene() {
  Scene s;
  s.lighting = key_light();
  s.objects.push_back(object(make_plane(9, 9, 12, 12), {0, 0, 0}, {0, 0, 0}, rgb(175, 172, 160)));
  SceneObject sphere = object(make_sphere(1.0, 48, 24), {0, 0.75, 0}, {0, 0, 0}, rgb(215, 60, 45));
  sphere.material.specular = {0.5, 0.5, 0.5};
  sphere.material.shininess = 40;
  s.objects.push_back(sphere);
  SceneObject torus = object(make_torus(0.95, 0.24, 64, 24), {0.8, 1.0, 0.1}, {70, 0, -35}, rgb(55, 105, 225));
  torus.material.specular = {0.35, 0.35, 0.35};
  s.objects.push_back(torus);
  s.objects.push_back(object(make_cylinder(0.22, 3.4, 32, 1), {-0.3, 0.9, 0.2}, {0, -30, 68}, rgb(240, 190, 40)));
  s.objects.push_back(object(make_cone(0.55, 1.5, 40, 1), {-1.9, 0.5, 1.3}, {0, 0, 14}, rgb(70, 175, 95)));
  set_camera(s, "default", {3.6, 3.4, 6.2}, {-0.3, 0.7, 0.2}, 42);
  return s;
}

// The five surfaces side by side, faceted and smooth.
Scene shapes_scene() {
  Scene s;
  s.lighting = key_light();
  s.objects.push_back(object(make_plane(10, 5, 1, 1), {0, -0.8, 0}, {0, 0, 0}, rgb(160, 160, 160)));
  s.objects.push_back(object(make_sphere(0.7, 24, 12), {-3.2, 0, 0}, {0, 0, 0}, rgb(220, 70, 60)));
  s.objects.push_back(object(make_torus(0.55, 0.2, 32, 16), {-1.6, 0, 0}, {60, 0, 0}, rgb(60, 110, 220)));
  s.objects.push_back(object(make_cylinder(0.5, 1.4, 24, 1), {0, 0, 0}, {0, 0, 0}, rgb(235, 185, 50)));
  SceneObject cone = object(make_cone(0.6, 1.4, 24, 1), {1.6, 0, 0}, {0, 0, 0}, rgb(70, 175, 95));
  cone.material.shading = SurfaceShading::Faceted;
  s.objects.push_back(cone);
  SceneObject ball = object(make_sphere(0.7, 12, 6), {3.2, 0, 0}, {0, 0, 0}, rgb(180, 90, 200));
  ball.material.shading = SurfaceShading::Faceted;
  s.objects.push_back(ball);
  set_camera(s, "shapes", {0.5, 3.0, 7.5}, {0, -0.1, 0}, 45);
  return s;
}

// The default scene seen from inside the torus's reach, close to the sphere: the near plane cuts
// the objects and the floor's triangles reach thousands of pixels off screen.
Scene closeup_scene() {
  Scene s = default_scene();
  set_camera(s, "closeup", {0.95, 1.2, 1.45}, {0.0, 0.8, 0.0}, 70);
  s.camera.values.near = 0.3;
  return s;
}

// Inside a large sphere (seen from inside, every face of it is a back face: render with --cull none)
// with a torus in front: the sphere's triangles around the view are clipped to the near plane and
// the guard band.
Scene inside_scene() {
  Scene s;
  s.lighting = key_light();
  s.lighting.ambient = {0.35, 0.35, 0.35};
  s.lighting.lights.push_back({{0.1, -0.2, -1.0}, {0.5, 0.5, 0.5}});  // from behind the camera, for the torus
  SceneObject room = object(make_sphere(6.0, 36, 18), {0, 0, 0}, {0, 0, 0}, rgb(200, 200, 185));
  room.material.shading = SurfaceShading::Faceted;
  s.objects.push_back(room);
  s.objects.push_back(object(make_torus(1.0, 0.35, 48, 20), {0, 0, -3}, {75, 0, 0}, rgb(55, 105, 225)));
  set_camera(s, "inside", {0, 0.5, 2}, {0, 0, -3}, 75);
  s.camera.values.near = 0.1;
  s.camera.values.far = 20;
  return s;
}

// A checkerboard of 2^log2_size texels square, `checks` by `checks` squares, light and dark, with
// a coloured texel row and column along its bottom-left edges (to show the texture's orientation).
std::shared_ptr<const Texture> checkerboard(int log2_size, int checks) {
  const int size = 1 << log2_size, check = size / checks;
  std::vector<uint32_t> texels(size_t(size) * size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      uint32_t texel = ((i / check + j / check) % 2 == 0) ? 0xE8E4D8 : 0x30343C;
      if (j == 0) texel = 0xD04030;       // bottom row: red
      else if (i == 0) texel = 0x3060D0;  // left column: blue
      texels[texel_address(i, j, log2_size)] = texel;
    }
  return std::make_shared<const Texture>(log2_size, log2_size, std::move(texels));
}

// A long checkerboard floor receding to the horizon, in two triangles per tile of 10 x 10 units,
// and a textured cube on it: with few, large triangles spanning a w ratio of hundreds, affine
// texture interpolation (profile perspective false) visibly bends the checks' lines.
Scene floor_scene() {
  Scene s;
  s.lighting = key_light();
  s.lighting.ambient = {0.45, 0.45, 0.45};
  Mesh floor = make_plane(40, 200, 4, 20);
  for (const Vec3& p : floor.positions) floor.texcoords.push_back({(p.x + 20) / 4, (100 - p.z) / 4});
  s.objects.push_back(object(std::move(floor), {0, 0, -96}, {0, 0, 0}, rgb(255, 255, 255)));
  // The cube: each face the whole texture once (four vertices of its own), upright on the sides.
  Mesh cube;
  const Vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const Vec3& n : normals) {
    // Axes a (u) and b (v) across the face with a x b = n: counter-clockwise seen from outside.
    const bool side = n.y == 0;
    const Vec3 b = side ? Vec3{0, 1, 0} : cross(n, Vec3{1, 0, 0});
    const Vec3 a = side ? cross(b, n) : Vec3{1, 0, 0};
    const uint32_t first = uint32_t(cube.positions.size());
    const double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const auto& c : corners) {
      cube.add_vertex(n * 0.5 + a * (0.5 * c[0]) + b * (0.5 * c[1]), n, uint32_t(cube.positions.size()));
      cube.texcoords.push_back({(c[0] + 1) / 2, (c[1] + 1) / 2});
    }
    cube.triangles.push_back({first, first + 1, first + 2});
    cube.triangles.push_back({first, first + 2, first + 3});
  }
  s.objects.push_back(object(std::move(cube), {1.6, 0.8, -6}, {0, 35, 0}, rgb(255, 235, 200), 1.6));
  s.texture = checkerboard(8, 4);
  set_camera(s, "floor", {0, 1.6, 3}, {0, 0.9, -20}, 60);
  s.camera.values.near = 0.5;
  s.camera.values.far = 300;
  return s;
}

struct Builtin {
  const char* name;
  const char* description;
  std::function<Scene()> make;
};

const std::vector<Builtin>& builtins() {
  static const std::vector<Builtin> list = {
      {"default", "lit sphere, torus, cylinder and cone interpenetrating on a floor (z-buffer intersections)",
       default_scene},
      {"shapes", "the five built-in surfaces side by side, smooth and faceted", shapes_scene},
      {"closeup", "the default scene from close up: near-plane and guard-band clipping", closeup_scene},
      {"inside", "camera inside a faceted sphere (render with --cull none), a torus in front: heavy clipping",
       inside_scene},
      {"floor", "checkerboard floor receding to the horizon and a textured cube (profile texture_unit; perspective "
                "true or false)",
       floor_scene},
  };
  return list;
}

}  // namespace

Scene make_builtin_scene(const std::string& name) {
  for (const Builtin& b : builtins())
    if (name == b.name) return b.make();
  std::string names;
  for (const Builtin& b : builtins()) names += (names.empty() ? "" : ", ") + std::string(b.name);
  throw InputError("--scene", 0, "unknown built-in scene '" + name + "' (known: " + names + ")");
}

std::vector<std::pair<std::string, std::string>> builtin_scene_list() {
  std::vector<std::pair<std::string, std::string>> out;
  for (const Builtin& b : builtins()) out.emplace_back(b.name, b.description);
  return out;
}

}  // namespace rastersim::frontend
