#include "frontend/frontend.h"

#include "frontend/obj_loader.h"
#include "frontend/scene.h"

namespace rastersim::frontend {
namespace {

std::vector<ScreenTriangle> render(const Scene& scene, const Profile& profile, const CameraOptions& camera,
                                   const std::string& source) {
  const Camera resolved =
      resolve_camera(scene.camera, camera, scene_bounds(scene), profile.width, profile.height, source);
  return render_scene(scene, resolved, profile);
}

}  // namespace

std::vector<ScreenTriangle> load_obj(const std::string& path, const Profile& profile, const CameraOptions& camera) {
  return render(obj_scene(load_obj_mesh(path)), profile, camera, path);
}

std::vector<ScreenTriangle> load_scene_file(const std::string& path, const Profile& profile,
                                            const CameraOptions& camera) {
  return render(load_scene(path), profile, camera, path);
}

std::vector<ScreenTriangle> builtin_scene(const std::string& name, const Profile& profile, const CameraOptions& camera) {
  return render(make_builtin_scene(name), profile, camera, "scene " + name);
}

std::shared_ptr<const Texture> builtin_scene_texture(const std::string& name) { return make_builtin_scene(name).texture; }

}  // namespace rastersim::frontend
