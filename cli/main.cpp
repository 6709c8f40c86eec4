// rastersim: one executable, subcommands (README.md, `rastersim COMMAND --help`).
// Exit codes: 0 success, 1 a check failed, 2 bad usage or bad input.
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "bench_command.h"
#include "cosim_command.h"
#include "fast/fast_walk.h"
#include "model/input_error.h"
#include "outputs.h"
#include "profile_command.h"
#include "render_command.h"
#include "sweep_command.h"
#include "vectors_command.h"

namespace {
constexpr int kExitBadInput = 2;
}

int main(int argc, char** argv) {
  using namespace rastersim;
  CLI::App app{"rastersim: bit-accurate fixed-point triangle rasterizer model (exit 0 ok, 1 check failed, 2 bad usage or input)",
               "rastersim"};
  app.set_version_flag("--version", std::string("rastersim ") + RASTERSIM_VERSION + " (" + RASTERSIM_GIT_DESCRIBE + ")");
  app.require_subcommand(1);
  remove_temporaries_on_signals();  // an interrupted run leaves no hidden temporary
  use_fast_walk();                  // untraced renders take the fast path (tests/test_fast_path.cpp)
  RenderOptions render_options;
  BenchOptions bench_options;
  CosimOptions cosim_options;
  VectorsOptions vectors_options;
  SweepOptions sweep_options;
  JunitMergeOptions junit_merge_options;
  ProfileCommandOptions profile_options;
  CLI::App* render = add_render_command(app, render_options);
  CLI::App* bench = add_bench_command(app, bench_options);
  CLI::App* scenes = add_scenes_command(app);
  CLI::App* cosim = add_cosim_command(app, cosim_options);
  CLI::App* vectors = add_vectors_command(app, vectors_options);
  CLI::App* sweep = add_sweep_command(app, sweep_options);
  CLI::App* junit_merge = add_junit_merge_command(app, junit_merge_options);
  CLI::App* profile = add_profile_command(app, profile_options);

  // CLI11 would report an unknown subcommand as a missing one; name it instead.
  bool known_subcommand = false;
  for (const CLI::App* sub : {render, bench, scenes, cosim, vectors, sweep, junit_merge, profile}) known_subcommand |= argc > 1 && sub->check_name(argv[1]);
  if (argc > 1 && argv[1][0] != '-' && !known_subcommand) {
    std::cerr << "rastersim: unknown subcommand '" << argv[1] << "' (render, cosim, junit-merge, vectors, sweep, bench, scenes, profile; see --help)\n";
    return kExitBadInput;
  }
  try {
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      const int code = app.exit(e);  // prints help (code 0) or the error
      return code == 0 ? 0 : kExitBadInput;
    }
    if (render->parsed()) return run_render(render_options);
    if (bench->parsed()) return run_bench(bench_options);
    if (scenes->parsed()) return run_scenes();
    if (cosim->parsed()) return run_cosim(cosim_options);
    if (vectors->parsed()) return run_vectors(vectors_options);
    if (sweep->parsed()) return run_sweep(sweep_options);
    if (junit_merge->parsed()) return run_junit_merge(junit_merge_options);
    if (profile->parsed()) return run_profile(profile_options);
  } catch (const InputError& e) {
    std::cerr << "rastersim: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    // Anything else (an output that cannot be written, out of memory) still must not crash.
    std::cerr << "rastersim: error: " << e.what() << "\n";
    return kExitBadInput;
  }
  std::cerr << "rastersim: no subcommand\n";
  return kExitBadInput;
}
