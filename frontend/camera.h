// The camera: settings from a scene file and the command line merged key by key, automatic values
// for what neither gives, validation, and the view and projection matrices.
#pragma once

#include <string>

#include "frontend/frontend.h"
#include "frontend/mesh.h"
#include "frontend/vecmath.h"

namespace rastersim::frontend {

// Where a setting was written, for error messages: a file and line, or the command line.
struct Origin {
  std::string file;  // empty: the command line
  int line = 0;
};

// Camera settings of a scene file with the line of each key.
struct CameraSettings {
  CameraOptions values;
  Origin eye, target, up, fov, near, far;
};

struct Camera {
  Vec3 eye, target, up;
  double fov = 45;  // vertical, degrees
  double near = 0.1, far = 100;
  bool ortho = false;
  double aspect = 1;  // width / height of the screen

  Mat4 view() const;
  Mat4 projection() const;
  // Orthographic half extents of the view volume: tan(fov / 2) * |target - eye| vertically.
  double ortho_half_height() const;
};

constexpr double kDefaultFov = 45.0;

// Merges `file` (from a scene file, may be empty) with `flags` (the command line wins), fills the
// rest automatically from the scene's bounding sphere and checks the result. Throws InputError naming
// the setting's origin for a degenerate camera, or `scene_source` (the input's name) when the scene
// is too large to frame automatically.
Camera resolve_camera(const CameraSettings& file, const CameraOptions& flags, const Sphere& bounds, int width,
                      int height, const std::string& scene_source = "the scene");

}  // namespace rastersim::frontend
