// The one place where `rastersim render` inputs are dispatched: .tri files, built-in scenes, and
// the 3D front end's .obj meshes, .json scene files and 3D scenes.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "frontend/frontend.h"
#include "model/profile.h"
#include "model/texture_sampler.h"
#include "model/triangle.h"

namespace rastersim {

// Loads INPUT (a path, or empty) or the built-in scene `scene_name` (empty = "default" when no
// path is given): a screen-space scene of this folder, or else a 3D scene of the front end.
// `camera` applies to 3D inputs. Every triangle returned has passed check_screen_triangle for the profile.
// Throws InputError for a bad file, an unknown scene or type, or both a path and a scene.
// The texture a built-in scene's textured objects sample; nullptr for a scene without one.
std::shared_ptr<const Texture> builtin_scene_texture(const std::string& scene_name);

// A check for INPUT and --scene options: an empty name is refused (it meant the default scene).
inline std::string non_empty_name(const std::string& value) {
  return value.empty() ? "an empty name names no file and no scene" : "";
}

std::vector<ScreenTriangle> load_input(const std::string& path_or_empty, const std::string& scene_name,
                                       const Profile& profile, const frontend::CameraOptions& camera = {});

// Every built-in scene (3D ones first), name and one-line description.
std::vector<std::pair<std::string, std::string>> scene_list();

}  // namespace rastersim
