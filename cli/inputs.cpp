#include "inputs.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "builtin_scenes.h"
#include "outputs.h"
#include "model/input_error.h"
#include "tri_reader.h"

namespace rastersim {
namespace {

bool is_3d_scene(const std::string& name) {
  for (const auto& [scene, description] : frontend::builtin_scene_list())
    if (scene == name) return true;
  return false;
}

// Camera flags on an input that is already in screen space would be ignored: refuse them instead.
void refuse_camera(const frontend::CameraOptions& c, const std::string& what) {
  if (c.eye || c.target || c.up || c.fov || c.near || c.far || c.ortho)
    throw InputError("the camera flags (--eye, --target, --up, --fov, --near, --far, --ortho) apply to 3D inputs "
                     "(.obj, .json scenes, the 3D built-in scenes); " + what + " is already in screen space");
}

std::vector<ScreenTriangle> load_builtin_scene(const std::string& name, const Profile& profile,
                                               const frontend::CameraOptions& camera) {
  const BuiltinScene* scene = find_builtin_scene(name);
  if (scene) refuse_camera(camera, "built-in scene '" + name + "'");
  if (!scene && !is_3d_scene(name))
    throw InputError("unknown scene '" + name + "'; `rastersim scenes` lists the built-in scenes");
  std::vector<ScreenTriangle> triangles =
      scene ? scene->generate(profile) : frontend::builtin_scene(name, profile, camera);
  // The generators stay inside the guard band by construction; checked so a regression is an error,
  // not a triangle the setup unit was never meant to take.
  for (size_t i = 0; i < triangles.size(); ++i) {
    const std::string problem = check_screen_triangle(triangles[i], profile);
    if (!problem.empty())
      throw InputError("built-in scene '" + name + "', triangle " + std::to_string(i) + ": " + problem);
  }
  return triangles;
}

}  // namespace

std::shared_ptr<const Texture> builtin_scene_texture(const std::string& scene_name) {
  return is_3d_scene(scene_name) ? frontend::builtin_scene_texture(scene_name) : nullptr;
}

std::vector<ScreenTriangle> load_input(const std::string& path_or_empty, const std::string& scene_name,
                                       const Profile& profile, const frontend::CameraOptions& camera) {
  if (!path_or_empty.empty() && !scene_name.empty())
    throw InputError("give either an INPUT file (" + path_or_empty + ") or --scene " + scene_name + ", not both");
  if (path_or_empty.empty()) return load_builtin_scene(scene_name.empty() ? "default" : scene_name, profile, camera);

  const std::string& path = path_or_empty;
  const std::string ext = lower_extension(path);
  if (ext == ".tri") {
    refuse_camera(camera, path);
    return read_tri_file(path, profile);
  }
  // The 3D front end guarantees every triangle it returns passes check_screen_triangle.
  if (ext == ".obj") return frontend::load_obj(path, profile, camera);
  if (ext == ".json") return frontend::load_scene_file(path, profile, camera);
  throw InputError(path, 0,
                   (ext.empty() ? std::string("has no file extension") : "unknown input type '" + ext + "'") +
                       "; expected a .tri, .obj or .json file");
}

std::vector<std::pair<std::string, std::string>> scene_list() {
  std::vector<std::pair<std::string, std::string>> scenes = frontend::builtin_scene_list();
  for (auto& [name, description] : scenes) description = "3D: " + description;
  for (const BuiltinScene& s : builtin_scenes()) scenes.emplace_back(s.name, "screen space: " + s.description);
  return scenes;
}

}  // namespace rastersim
