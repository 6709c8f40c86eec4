// `rastersim render` and `rastersim scenes`.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "frontend/frontend.h"
#include "model/profile.h"
#include "model/texture_unit.h"
#include "outputs.h"
#include "profile_options.h"

namespace rastersim {

struct RenderOptions {
  std::string input;
  std::string scene;
  std::string color_out;
  std::string depth_out;
  std::string fragments_out;
  std::string stats_out;
  std::string dump_tri_out;
  std::vector<double> eye, target, up;  // 3 values each when given
  std::vector<double> fov, near, far;   // 1 value each when given
  bool ortho = false;
  std::string backend = "model";
  uint64_t seed = 1;          // rtl/cosim: random power-on state
  int threads = 0;            // model without --fragments: render threads; 0: default_threads()
  WaveOptions wave;           // rtl/cosim: waveform
  std::string replay_dir;  // cosim: where a divergence's replay files go (empty: the working folder)
  std::string texture;         // texture image for textured triangles (the built-in scene's when empty)
  std::string texture_filter = "bilinear";
  std::string texture_wrap = "repeat";
  ProfileOptions profile;
};

CLI::App* add_render_command(CLI::App& app, RenderOptions& options);
// INPUT, --scene and the camera flags (shared with `rastersim sweep`).
void add_scene_options(CLI::App& command, RenderOptions& options);
// --texture, --texture-filter, --texture-wrap (`rastersim vectors` takes them too), what they bind
// for a profile (no --texture: the built-in scene's texture when there is no INPUT), and the flags
// given as command-line words (the file by its bare name; empty when none is given).
void add_texture_options(CLI::App& command, RenderOptions& options);
TextureBinding texture_binding(const RenderOptions& options, const std::string& input, const std::string& scene,
                               const Profile& profile);
std::string texture_words(const RenderOptions& options);
// The camera flags alone (`rastersim vectors` takes them too).
void add_camera_options(CLI::App& command, RenderOptions& options);
// The camera flags given, as command-line words ("--eye 3,2,4 --fov 40"; empty when none).
std::string camera_words(const RenderOptions& options);
// The camera flags given, for the front end.
frontend::CameraOptions camera_options(const RenderOptions& options);
// Returns the exit code; throws InputError (bad input or usage) and std::exception.
int run_render(const RenderOptions& options);

CLI::App* add_scenes_command(CLI::App& app);
int run_scenes();

}  // namespace rastersim
