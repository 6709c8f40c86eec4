// The one place where `rastersim render` inputs are dispatched: .tri files, built-in scenes, and
// (later) the 3D front end's .obj meshes and .json scene files.
#pragma once

#include <string>
#include <vector>

#include "model/profile.h"
#include "model/triangle.h"

namespace rastersim {

// Loads INPUT (a path, or empty) or the built-in scene `scene_name` (empty = "default" when no
// path is given). Every triangle returned has passed check_screen_triangle for the profile.
// Throws InputError for a bad file, an unknown scene or type, or both a path and a scene.
std::vector<ScreenTriangle> load_input(const std::string& path_or_empty, const std::string& scene_name,
                                       const Profile& profile);

}  // namespace rastersim
