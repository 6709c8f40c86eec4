// A 3D scene (objects, lights, camera settings) and its rendering to screen triangles: transform,
// light per vertex, clip, map to the viewport. The public entry points are in frontend.h; these are
// the steps, exposed for tests.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "frontend/camera.h"
#include "frontend/clip.h"
#include "frontend/lighting.h"
#include "frontend/mesh.h"
#include "model/texture_sampler.h"

namespace rastersim::frontend {

struct SceneObject {
  Mesh mesh;
  Mat4 model;  // object to world
  Material material;
};

struct Scene {
  std::vector<SceneObject> objects;
  Lighting lighting = default_lighting();
  CameraSettings camera;
  std::shared_ptr<const Texture> texture;  // what the textured objects sample (one per scene), or none
};

// Per output triangle: the object and mesh triangle it came from and the mesh vertex of each
// corner (-1 when the corner was made by clipping).
struct RenderTrace {
  std::vector<int> object;
  std::vector<size_t> triangle;
  std::vector<CornerSources> corners;
};

// The world-space bounding sphere of every object's vertices.
Sphere scene_bounds(const Scene& scene);

// Objects in order, triangles in mesh order, each clipped polygon's triangles in place. A mirroring model
// matrix (negative determinant) reverses each triangle's corners so front faces stay counter-clockwise.
std::vector<ScreenTriangle> render_scene(const Scene& scene, const Camera& camera, const Profile& profile,
                                         RenderTrace* trace = nullptr);

// Scene file (JSON, docs/frontend.md) to a scene; meshes are loaded relative to the file's folder.
// The most triangles a scene may have after tessellation (a surface alone may have 2 million):
// enough for the bunny 57 times over, and within a few hundred MB through the front end.
constexpr size_t kMaxSceneTriangles = 4'000'000;
// The largest scene file read (scenes list objects; meshes are files of their own).
constexpr size_t kMaxSceneBytes = size_t(16) << 20;
// The lights of a scene: every vertex is lit by each (OpenGL's fixed function had 8).
constexpr size_t kMaxSceneLights = 64;
Scene load_scene(const std::string& path);
Scene parse_scene(const std::string& text, const std::string& file_name, const std::string& base_folder);
// The mesh files a scene file names (as load_scene resolves them), for the outputs to refuse as
// inputs; empty for a file that is not a readable scene (load_scene then says why).
std::vector<std::string> scene_mesh_files(const std::string& path);

// A built-in scene by name (builtin_scene_list); an unknown name throws InputError.
Scene make_builtin_scene(const std::string& name);

// The scene load_obj renders: the mesh, light grey, smooth, default lighting, no camera settings.
Scene obj_scene(Mesh mesh);

}  // namespace rastersim::frontend
