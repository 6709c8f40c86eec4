#include "render_command.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <tuple>

#include "backend.h"
#include "builtin_scenes.h"
#include "fast/threaded_render.h"
#include "frontend/scene.h"
#include "inputs.h"
#include "model/input_error.h"
#include "outputs.h"
#include "texture_reader.h"
#include "tri_reader.h"

namespace rastersim {
namespace {

// "done / total triangles" on stderr, only on a terminal, only once the run has taken a second,
// and at most ten times a second. RASTERSIM_PROGRESS_DELAY_MS replaces the one-second wait (the
// tests set it to 0 so that they do not depend on how fast the machine renders).
class ProgressLine {
 public:
  ProgressLine(size_t total, bool enabled) : total_(total), enabled_(enabled), start_(Clock::now()) {
    if (const char* delay = std::getenv("RASTERSIM_PROGRESS_DELAY_MS")) delay_ = std::chrono::milliseconds(std::atoi(delay));
  }
  ~ProgressLine() { finish(); }

  void update(size_t done) {
    if (!enabled_) return;
    const Clock::time_point now = Clock::now();
    if (now - start_ < delay_ || now - last_shown_ < std::chrono::milliseconds(100)) return;
    last_shown_ = now;
    shown_ = true;
    std::fprintf(stderr, "\rrendering: %zu / %zu triangles", done, total_);
    std::fflush(stderr);
  }

  void finish() {
    if (!shown_) return;
    std::fprintf(stderr, "\r\033[K");  // erase the progress line
    std::fflush(stderr);
    shown_ = false;
  }

 private:
  using Clock = std::chrono::steady_clock;
  size_t total_;
  bool enabled_;
  Clock::time_point start_, last_shown_{};
  std::chrono::milliseconds delay_{1000};
  bool shown_ = false;
};

}  // namespace

CLI::App* add_render_command(CLI::App& app, RenderOptions& o) {
  CLI::App* cmd = app.add_subcommand("render", "render a .tri file or a built-in scene through the pipeline");
  add_scene_options(*cmd, o);
  cmd->add_option("-o,--output", o.color_out, "colour image (png, exr, tif, ...; 8-bit RGB)")->type_name("FILE");
  cmd->add_option("--depth-out", o.depth_out,
                  "depth image: float depth/(2^N-1) for exr/tif, 16-bit scaled otherwise (png)")
      ->type_name("FILE");
  cmd->add_option("--fragments", o.fragments_out, "fragment trace CSV: tri,x,y,z,pass,r,g,b,cycle")
      ->type_name("FILE");
  cmd->add_option("--stats", o.stats_out, "stats JSON: counters, per-unit busy/stall, resolved profile")
      ->type_name("FILE");
  cmd->add_option("--seed", o.seed, "rtl, cosim, systemc: seed of the random power-on state of registers and memories")
      ->check(unsigned_64_text)
      ->type_name("S");
  add_wave_options(*cmd, o.wave, "rtl, cosim: ");
  cmd->add_option("--replay-dir", o.replay_dir, "cosim: folder for the replay files of a divergence")
      ->type_name("DIR");
  cmd->add_option("--backend", o.backend,
                  "model (the C++ reference), rtl (the verilated RTL), cosim (both in lockstep, compared), "
                  "systemc (the verilated core with a command FIFO and a z-buffer memory model with latency and "
                  "stall pattern, in SystemC)")
      ->check(CLI::IsMember(backend_names()))
      ->type_name("NAME");
  cmd->add_option("--threads", o.threads,
                  "model: threads of the render, the same frame at any count (without --fragments, which "
                  "traces on one thread); cosim: 2 or more run the model beside the RTL; default: the machine's cores when the "
                  "triangles average 128 pixels or more and cover 524288 or more, else 1")
      ->check(CLI::Range(1, 256));
  add_texture_options(*cmd, o);
  cmd->add_option("--dump-tri", o.dump_tri_out,
                  "write the screen-space triangles the input produced (before snapping) as a .tri file")
      ->type_name("FILE");
  add_profile_options(*cmd, o.profile);
  return cmd;
}

void add_scene_options(CLI::App& app, RenderOptions& o) {
  CLI::App* cmd = &app;
  cmd->add_option("input", o.input, "a screen-space .tri file, a Wavefront .obj mesh or a .json scene file")
      ->type_name("INPUT")
      ->check(non_empty_name);
  cmd->add_option("--scene", o.scene, "built-in scene to render when no INPUT is given (see `rastersim scenes`)")
      ->type_name("NAME")
      ->check(non_empty_name);
  add_camera_options(app, o);
}

void add_texture_options(CLI::App& cmd, RenderOptions& o) {
  cmd.add_option("--texture", o.texture,
                 "texture image for textured triangles (with the profile's texture_unit; a power of two "
                 "up to 1024 on each side; default: the built-in scene's)")
      ->type_name("FILE");
  cmd.add_option("--texture-filter", o.texture_filter, "nearest or bilinear (default bilinear)")
      ->check(CLI::IsMember({"nearest", "bilinear"}))
      ->type_name("NAME");
  cmd.add_option("--texture-wrap", o.texture_wrap, "repeat or clamp (default repeat)")
      ->check(CLI::IsMember({"repeat", "clamp"}))
      ->type_name("NAME");
}

TextureBinding texture_binding(const RenderOptions& o, const std::string& input, const std::string& scene,
                               const Profile& profile) {
  TextureBinding texture;
  texture.filter = o.texture_filter == "nearest" ? TextureFilter::Nearest : TextureFilter::Bilinear;
  texture.wrap = o.texture_wrap == "clamp" ? TextureWrap::Clamp : TextureWrap::Repeat;
  if (!o.texture.empty()) texture.texture = std::make_shared<const Texture>(read_texture_file(o.texture));
  else if (input.empty() && profile.texture_unit)  // (the scene is made once more for its texture)
    texture.texture = builtin_scene_texture(scene.empty() ? "default" : scene);
  return texture;
}

std::string texture_words(const RenderOptions& o) {
  std::string words;
  if (!o.texture.empty()) words += " --texture " + std::filesystem::path(o.texture).filename().string();
  if (o.texture_filter != "bilinear") words += " --texture-filter " + o.texture_filter;
  if (o.texture_wrap != "repeat") words += " --texture-wrap " + o.texture_wrap;
  return words.empty() ? words : words.substr(1);
}

void add_camera_options(CLI::App& app, RenderOptions& o) {
  CLI::App* cmd = &app;
  const char* const camera = "Camera (3D inputs: .obj, .json scenes, 3D built-in scenes)";
  for (auto [flag, vec, help] : {std::tuple{"--eye", &o.eye, "camera position X,Y,Z (world space)"},
                                 std::tuple{"--target", &o.target, "point the camera looks at X,Y,Z"},
                                 std::tuple{"--up", &o.up, "up direction X,Y,Z"}})
    cmd->add_option(flag, *vec, help)->expected(3)->delimiter(',')->type_name("X,Y,Z")->group(camera);
  for (auto [flag, value, help] : {std::tuple{"--fov", &o.fov, "vertical field of view in degrees, in (0, 180)"},
                                   std::tuple{"--near", &o.near, "near plane distance, > 0"},
                                   std::tuple{"--far", &o.far, "far plane distance, > near"}})
    cmd->add_option(flag, *value, help)->expected(1)->type_name("NUMBER")->group(camera);
  cmd->add_flag("--ortho", o.ortho, "orthographic projection")->group(camera);
}

std::string camera_words(const RenderOptions& o) {
  std::ostringstream words;
  words.precision(17);
  auto vec = [&](const char* flag, const std::vector<double>& v) {
    if (!v.empty()) words << " " << flag << " " << v[0] << "," << v[1] << "," << v[2];
  };
  auto one = [&](const char* flag, const std::vector<double>& v) {
    if (!v.empty()) words << " " << flag << " " << v[0];
  };
  vec("--eye", o.eye);
  vec("--target", o.target);
  vec("--up", o.up);
  one("--fov", o.fov);
  one("--near", o.near);
  one("--far", o.far);
  if (o.ortho) words << " --ortho";
  return words.str().empty() ? "" : words.str().substr(1);
}

frontend::CameraOptions camera_options(const RenderOptions& o) {
  frontend::CameraOptions camera;
  auto vec = [](const std::vector<double>& v) { return std::optional<frontend::Vec3>(frontend::Vec3{v[0], v[1], v[2]}); };
  if (!o.eye.empty()) camera.eye = vec(o.eye);
  if (!o.target.empty()) camera.target = vec(o.target);
  if (!o.up.empty()) camera.up = vec(o.up);
  // The front end checks the values: degenerate cameras are bad input.
  if (!o.fov.empty()) camera.fov = o.fov[0];
  if (!o.near.empty()) camera.near = o.near[0];
  if (!o.far.empty()) camera.far = o.far[0];
  camera.ortho = o.ortho;
  return camera;
}

int run_render(const RenderOptions& o) {
  // Everything that can be wrong with the command line or the input is found before rendering,
  // and nothing is written until everything has been computed.
  const Profile profile = resolve_profile(o.profile);
  const Backend backend = select_backend(o.backend);
  check_backend_profile(backend, profile);

  OutputFiles outputs;
  outputs.protect(o.input);
  for (const std::string& mesh : frontend::scene_mesh_files(o.input)) outputs.protect(mesh);
  outputs.protect(o.profile.profile_file);
  outputs.protect(o.texture);
  if (!o.texture.empty() && !profile.texture_unit)
    throw InputError("--texture needs the profile's texture unit (--texture-unit true)");
  std::string color_temp, depth_temp, fragments_temp, stats_temp;
  if (!o.color_out.empty()) {
    check_image_format(o.color_out, "-o");
    color_temp = outputs.add(o.color_out, "-o");
  }
  if (!o.depth_out.empty()) {
    check_image_format(o.depth_out, "--depth-out");
    depth_temp = outputs.add(o.depth_out, "--depth-out");
  }
  if (!o.fragments_out.empty()) fragments_temp = outputs.add(o.fragments_out, "--fragments");
  if (!o.stats_out.empty()) stats_temp = outputs.add(o.stats_out, "--stats");
  std::string dump_tri_temp;
  if (!o.dump_tri_out.empty()) dump_tri_temp = outputs.add(o.dump_tri_out, "--dump-tri");
  if (!o.wave.path.empty() && backend != Backend::Rtl && backend != Backend::Cosim)
    throw InputError("--wave needs --backend rtl or cosim: the " + o.backend + " backend runs no RTL waveform");
  const WaveFiles wave = add_waveform(outputs, o.wave);
  if (!o.replay_dir.empty()) {
    if (backend != Backend::Cosim)
      throw InputError("--replay-dir needs --backend cosim: the " + o.backend + " backend writes no replay files");
    if (!std::filesystem::is_directory(o.replay_dir))
      throw InputError("--replay-dir: folder '" + o.replay_dir + "' does not exist");
  }

  const std::vector<ScreenTriangle> screen = load_input(o.input, o.scene, profile, camera_options(o));
  const TextureBinding texture = texture_binding(o, o.input, o.scene, profile);
  std::vector<SnappedTriangle> snapped;
  snapped.reserve(screen.size());
  for (const ScreenTriangle& t : screen) snapped.push_back(snap(t, profile));

  std::unique_ptr<FragmentCsvWriter> csv;
  if (!fragments_temp.empty()) csv = std::make_unique<FragmentCsvWriter>(fragments_temp, o.fragments_out);
  ProgressLine progress(snapped.size(), isatty(STDERR_FILENO) != 0);
  BackendOptions backend_options;
  backend_options.seed = o.seed;
  backend_options.wave_files = wave;
  backend_options.wave = o.wave;
  backend_options.texture = texture;
  backend_options.threads = o.threads > 0 ? o.threads : default_threads(snapped, profile);
  backend_options.replay_prefix =
      (std::filesystem::path(o.replay_dir.empty() ? "." : o.replay_dir) / "rastersim-replay").string();
  const RenderResult result = render_triangles(
      backend, profile, snapped, csv.get(), [&](size_t done) { progress.update(done); }, backend_options);
  progress.finish();
  // With an output on standard output (`-`), the human summary goes to standard error.
  std::ostream& info = outputs.writes_stdout() ? std::cerr : std::cout;
  if (result.check_failed) {
    // A divergence writes no output: the temporaries are removed when `outputs` goes out of scope.
    info << "cosim: model and RTL diverge\n" << result.report << "\n";
    return 1;
  }

  if (csv) csv->close();
  if (!color_temp.empty()) write_color_image(o.color_out, color_temp, result.buffers);
  if (!depth_temp.empty()) write_depth_image(o.depth_out, depth_temp, result.buffers, profile.z_bits);
  if (!dump_tri_temp.empty()) {
    std::ostringstream text;
    write_tri(text, screen, "screen-space triangles of " + (o.input.empty() ? "scene " + (o.scene.empty() ? std::string("default") : o.scene) : o.input));
    write_text_file(dump_tri_temp, o.dump_tri_out, text.str());
  }
  if (!stats_temp.empty()) write_text_file(stats_temp, o.stats_out, stats_to_json(result.stats, profile).dump(2) + "\n");
  check_waveform_written(wave, o.wave, result.stats.cycles);
  outputs.commit();

  const std::string source = o.input.empty() ? "scene " + (o.scene.empty() ? std::string("default") : o.scene) : o.input;
  const std::string through = backend == Backend::Cosim     ? "the model and the RTL in lockstep"
                              : backend == Backend::Systemc ? "the SystemC system (verilated core, command FIFO, memory model)"
                                                            : "the " + o.backend;
  info << "rendered " << source << " through " << through << ", " << profile.width << "x" << profile.height
       << ", " << to_string(profile.traversal) << " traversal\n";
  if (backend == Backend::Cosim) info << "cosim: every setup record, fragment, memory word and cycle count agrees\n";
  print_summary(info, result.stats);
  for (const std::string* path : {&o.color_out, &o.depth_out, &o.fragments_out, &o.stats_out, &o.dump_tri_out, &o.wave.path})
    if (!path->empty()) info << "wrote " << (*path == "-" ? "standard output" : *path) << "\n";
  return 0;
}

CLI::App* add_scenes_command(CLI::App& app) {
  return app.add_subcommand("scenes", "list the built-in scenes (rastersim render --scene NAME)");
}

int run_scenes() {
  const auto scenes = scene_list();
  size_t width = 0;
  for (const auto& [name, description] : scenes) width = std::max(width, name.size());
  for (const auto& [name, description] : scenes)
    std::cout << name << std::string(width + 2 - name.size(), ' ') << description << "\n";
  return 0;
}

}  // namespace rastersim
