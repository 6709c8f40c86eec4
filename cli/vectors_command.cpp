#include "vectors_command.h"

#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "inputs.h"
#include "outputs.h"
#include "model/input_error.h"
#include "model/pipeline.h"
#include "frontend/scene.h"
#ifdef RASTERSIM_HAVE_VECTORS
#include "testbench/cosim_cases.h"
#include "testbench/vectors/package.h"
#include "testbench/vectors/suites.h"
#endif

namespace rastersim {

CLI::App* add_vectors_command(CLI::App& app, VectorsOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "vectors", "write a test-vector package for FPGA ports: $readmemh files of the model's expected words, a "
                 "manifest, a self-checking Verilog testbench and scripts for Icarus and Verilator (docs/vectors.md)");
  cmd->add_option("--out", o.out, "the package folder to write (missing or empty; see --force)")
      ->type_name("DIR")
      ->required();
  cmd->add_option("input", o.input, "a screen-space .tri file, a Wavefront .obj mesh or a .json scene file")
      ->type_name("INPUT")
      ->check(non_empty_name);
  cmd->add_option("--scene", o.scene, "a built-in scene (see `rastersim scenes`); the default scene when no "
                                      "INPUT, --random or --suite is given")
      ->type_name("NAME")
      ->check(non_empty_name);
  o.random_option = cmd->add_option("--random", o.random, "N constrained-random triangles (rastersim cosim's generator)")
                        ->type_name("N");
  o.seed_option = cmd->add_option("--seed", o.seed, "seed of --random (default 1)")->type_name("S")->check(unsigned_64_text);
  cmd->add_option("--suite", o.suite, "a directed suite: rules (rasterization corner cases) or depth (for every "
                                      "depth function)")
      ->type_name("NAME");
  cmd->add_option("--rtl-path", o.rtl_path, "do not copy the RTL into the package; its scripts use this folder, "
                                            "relative to the package (the checked-in vectors/ use ../../rtl)")
      ->type_name("REL");
  cmd->add_option("--testbench-path", o.testbench_path,
                  "do not copy the testbench (rastersim_vectors_tb.v) into the package; its scripts use the one in "
                  "this folder, relative to the package (the checked-in vectors/ use ../../testbench/vectors)")
      ->type_name("REL");
  cmd->add_option("--top", o.top, "the module the package tests: rastersim_top (on-chip memory) or rastersim_core "
                                  "(a memory model with the profile's latency and back-pressure on its memory port); "
                                  "default rastersim_core when --memory-stall-percent is above 0, else rastersim_top")
      ->type_name("MODULE");
  cmd->add_flag("--force", o.force, "replace the package already in --out");
  add_camera_options(*cmd, o.camera);
  add_texture_options(*cmd, o.camera);
  add_profile_options(*cmd, o.profile);
  return cmd;
}

namespace {
// The package's scripts, README and Makefile-like text name the folder as written: only characters
// that mean nothing to sh, make or Markdown are taken (`$(touch X)rtl` would run when the package runs).
void check_package_relative_path(const std::string& option, const std::string& path) {
  for (const char c : path) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '/' ||
                       c == '.' || c == '_' || c == '-' || c == '+';
    if (!plain)
      throw InputError(option + " '" + path + "': only letters, digits and / . _ - + may name the folder (the "
                       "package's run scripts name it as written)");
  }
  if (!path.empty() && path[0] == '-') throw InputError(option + " '" + path + "' must not start with '-'");
}
}  // namespace

int run_vectors(const VectorsOptions& o) {
  const Profile profile = resolve_profile(o.profile);
  const bool random = o.random_option && o.random_option->count() > 0;
  const int sources = int(!o.input.empty()) + int(!o.scene.empty()) + int(random) + int(!o.suite.empty());
  if (sources > 1) throw InputError("give one of INPUT, --scene, --random and --suite");
  if ((random || !o.suite.empty()) && !camera_words(o.camera).empty())
    throw InputError("the camera flags apply to 3D inputs (.obj, .json scenes, 3D built-in scenes), not to --random "
                     "or --suite");
  if (o.seed_option && o.seed_option->count() > 0 && !random) throw InputError("--seed goes with --random");
  if (random && (o.random < 1 || o.random > 1000000)) throw InputError("--random must be in 1..1000000");
  check_package_relative_path("--rtl-path", o.rtl_path);
  check_package_relative_path("--testbench-path", o.testbench_path);
  if (!o.rtl_path.empty() && std::filesystem::path(o.rtl_path).is_absolute())
    throw InputError("--rtl-path must be relative to the package folder (a package must not depend on where it was made)");
  if (!o.top.empty() && o.top != "rastersim_top" && o.top != "rastersim_core")
    throw InputError("--top must be rastersim_top or rastersim_core, not '" + o.top + "'");
  const std::string texture_flags = texture_words(o.camera);
  if (!texture_flags.empty() && !profile.texture_unit)
    throw InputError("the texture flags (" + texture_flags + ") need the profile's texture_unit");
  if (!texture_flags.empty() && (random || !o.suite.empty()))
    throw InputError("the texture flags apply to INPUT and --scene (--random draws its own texture, the suites are "
                     "untextured)");
  if (o.top == "rastersim_top" && profile.memory_stall_percent > 0)
    throw InputError("--top rastersim_top with memory_stall_percent " + std::to_string(profile.memory_stall_percent) +
                     ": its on-chip memory has no back-pressure; use --top rastersim_core");
  if (!o.testbench_path.empty() && std::filesystem::path(o.testbench_path).is_absolute())
    throw InputError("--testbench-path must be relative to the package folder (a package must not depend on where it was "
                     "made)");
#ifndef RASTERSIM_HAVE_VECTORS
  (void)profile;
  throw InputError("vectors needs the RTL library, which is not built in this binary (install Verilator and rebuild)");
#else
  // The folder is checked before the model runs, and written only when everything is computed. It
  // is replaced as a whole, so no input may lie inside it.
  OutputFiles inputs;
  inputs.protect(o.input);
  for (const std::string& mesh : frontend::scene_mesh_files(o.input)) inputs.protect(mesh);
  inputs.protect(o.profile.profile_file);
  inputs.protect(o.camera.texture);
  inputs.refuse_inputs_inside(o.out, "the package");
  vectors::check_package_dir(o.out, o.force);
  vectors::Source source;
  std::vector<SnappedTriangle> triangles;
  TextureBinding texture;
  if (random) {
    source = {"random", "", o.random, o.seed, "", ""};
    rtl::CosimCase drawn = rtl::random_case(profile, o.seed, int(o.random));
    triangles = std::move(drawn.triangles);
    texture = drawn.texture;
  } else if (!o.suite.empty()) {
    source = {"suite", o.suite, 0, 0, "", ""};
    try {
      triangles = vectors::suite_triangles(o.suite, profile);
    } catch (const std::invalid_argument& e) {
      throw InputError(std::string("--suite: ") + e.what());
    }
  } else {
    if (o.input.empty()) source = {"scene", o.scene.empty() ? "default" : o.scene, 0, 0, "", ""};
    else source = {"file", std::filesystem::path(o.input).filename().string(), 0, 0, "", ""};
    source.camera = camera_words(o.camera);
    source.texture = texture_flags;
    texture = texture_binding(o.camera, o.input, o.scene, profile);
    for (const ScreenTriangle& t : load_input(o.input, o.scene, profile, camera_options(o.camera)))
      triangles.push_back(snap(t, profile));
  }
  // The package's size is known only once the frame is rendered: count its fragments with the
  // model first (no trace: little memory) and refuse, before anything is held, a frame beyond the
  // limit.
  {
    Pipeline count(profile);
    for (size_t t = 0; t < triangles.size(); ++t) {
      count.submit(triangles[t]);
      const int64_t fragments = count.stats().fragments;
      if (fragments > vectors::kMaxPackageFragments)
        throw InputError("the package would hold more than " + std::to_string(vectors::kMaxPackageFragments) +
                         " fragments, the limit (" + std::to_string(fragments) + " already by triangle " +
                         std::to_string(t) + " of " + std::to_string(triangles.size()) +
                         "; a package holds every expected fragment, about 175 bytes each in memory while it is "
                         "built): give fewer triangles or a smaller screen, or split the input into several packages");
    }
  }
  vectors::PackageOptions options;
  options.rtl_path = o.rtl_path;
  options.testbench_path = o.testbench_path;
  options.external_memory = o.top == "rastersim_core" || (o.top.empty() && profile.memory_stall_percent > 0);
  const vectors::Package package = vectors::build_package(profile, triangles, source, options, texture);
  vectors::write_package(package, o.out, o.force, remember_temporary_folder);
  std::cout << "wrote " << o.out << ": " << package.triangles << " triangles (" << package.drawn << " drawn), "
            << package.fragments << " fragments, " << package.cycles << " cycles, " << profile.width << "x"
            << profile.height << "\n"
            << "replay: " << o.out << "/run_icarus.sh or " << o.out << "/run_verilator.sh\n";
  return 0;
#endif
}

}  // namespace rastersim
