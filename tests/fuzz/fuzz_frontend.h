// The OBJ and scene targets' second half: render a parsed scene as the CLI does (camera from the
// scene and automatic values, no flags) and set up every screen triangle it makes.
#pragma once

#include <string>

#include "frontend/camera.h"
#include "frontend/scene.h"
#include "model/triangle_setup.h"
#include "tests/fuzz/fuzz_support.h"

namespace rastersim::fuzz {

// The 64 x 48 profile the frontend targets render with (small, so that setup is cheap).
inline Profile frontend_profile() {
  Profile profile;
  profile.width = 64, profile.height = 48;
  return profile;
}

// Throws InputError for a degenerate camera (as the CLI would report it); a WidthOverflow or
// logic_error escapes as a finding.
inline void render_and_set_up(const frontend::Scene& scene) {
  const Profile profile = frontend_profile();
  const frontend::Camera camera = frontend::resolve_camera(scene.camera, frontend::CameraOptions{},
                                                           frontend::scene_bounds(scene), profile.width, profile.height);
  const TriangleSetup setup(profile);
  for (const ScreenTriangle& t : frontend::render_scene(scene, camera, profile)) {
    const std::string problem = check_screen_triangle(t, profile);
    FUZZ_REQUIRE(problem.empty(), "the front end made a triangle the setup check refuses: " + problem);
    setup.run(snap(t, profile));
  }
}

}  // namespace rastersim::fuzz
