// The 3D front end: the host-side, floating-point part of the pipeline, as a driver would do it.
// It turns an OBJ mesh, a JSON scene file or a built-in scene into the screen-space triangles
// (rastersim::ScreenTriangle: pixels, y down, depth in [0, 1], per-vertex colour) that the model
// then checks and snaps. Conventions, formats and worked numbers: docs/frontend.md.
//
// Every triangle returned passes rastersim::check_screen_triangle for the profile: the front end
// clips in homogeneous space to the near and far planes and to a guard band one pixel inside the
// setup unit's range. Winding is preserved (front faces counter-clockwise on screen); culling is the
// hardware's, by the profile. Bad input throws rastersim::InputError naming the file, the line (where
// there is one) and the problem: malformed or missing OBJ and scene files, and degenerate cameras
// (eye = target, up parallel to the view direction, near <= 0, near >= far, fov outside (0, 180)).
// Camera values given here come from the command line and are reported as such.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "frontend/vecmath.h"
#include "model/profile.h"
#include "model/texture_sampler.h"
#include "model/triangle.h"

namespace rastersim::frontend {

// Camera settings from the command line; each one left empty is taken from the scene file, or else
// chosen automatically so that the scene's bounding sphere fills the view (docs/frontend.md).
struct CameraOptions {
  std::optional<Vec3> eye, target, up;        // world space; up need not be unit or orthogonal
  std::optional<double> fov;                  // vertical field of view, degrees, in (0, 180)
  std::optional<double> near, far;            // eye-space distances, 0 < near < far
  bool ortho = false;                         // orthographic: the view at the target keeps the fov's size
};

// A Wavefront OBJ (v, vn, f; polygons fanned from their first corner; normals computed when a face
// corner has none), light grey, lit by the default key light.
std::vector<ScreenTriangle> load_obj(const std::string& path, const Profile& profile, const CameraOptions& camera);

// A JSON scene file (objects, camera, lights; format in docs/frontend.md). Camera options override
// the file's camera key by key.
std::vector<ScreenTriangle> load_scene_file(const std::string& path, const Profile& profile,
                                            const CameraOptions& camera);

// The built-in 3D scenes: name and a one-line description, "default" first.
std::vector<std::pair<std::string, std::string>> builtin_scene_list();

// One built-in scene; an unknown name throws InputError.
std::vector<ScreenTriangle> builtin_scene(const std::string& name, const Profile& profile, const CameraOptions& camera);
// The texture a built-in scene's textured objects sample, or nullptr (an unknown name throws).
std::shared_ptr<const Texture> builtin_scene_texture(const std::string& name);

}  // namespace rastersim::frontend
