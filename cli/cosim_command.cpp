#include "cosim_command.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "model/input_error.h"
#ifdef RASTERSIM_HAVE_RTL
#include "testbench/cosim_cases.h"
#include "testbench/rtl_backend.h"
#endif

namespace rastersim {

CLI::App* add_cosim_command(CLI::App& app, CosimOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "cosim", "directed and random frames through the model and the RTL in lockstep, compared at every transaction");
  cmd->add_option("--count", o.count, "random frames to run after the directed ones")->type_name("N");
  cmd->add_option("--seed", o.seed, "frame k draws its triangles and the RTL's power-on state from seed + k")
      ->type_name("S");
  cmd->add_option("--triangles", o.triangles, "triangles per random frame")->type_name("K");
  cmd->add_flag("!--no-directed", o.directed, "skip the directed frames");
  cmd->add_option("--replay-dir", o.replay_dir, "folder for the replay files of a divergence")->type_name("DIR");
  cmd->add_option("--fst", o.fst_out, "write the RTL waveform of every frame (the last one run remains)")
      ->type_name("FILE");
  add_profile_options(*cmd, o.profile);
  return cmd;
}

int run_cosim(const CosimOptions& o) {
  const Profile profile = resolve_profile(o.profile);
  if (o.count < 0) throw InputError("--count must not be negative");
  if (o.triangles < 1 || o.triangles > 100000) throw InputError("--triangles must be in 1..100000");
#ifndef RASTERSIM_HAVE_RTL
  (void)profile;
  throw InputError("cosim needs the RTL backend, which is not built in this binary (install Verilator and rebuild)");
#else
  const std::string problem = rtl::configuration_error(profile);
  if (!problem.empty()) throw InputError(problem);
  if (!std::filesystem::is_directory(o.replay_dir))
    throw InputError("--replay-dir: folder '" + o.replay_dir + "' does not exist");

  std::vector<rtl::CosimCase> cases;
  if (o.directed) cases = rtl::directed_cases(profile);
  const size_t directed = cases.size();
  const bool tty = isatty(STDERR_FILENO) != 0;
  const int64_t total = int64_t(directed) + o.count;
  int64_t passed = 0;
  for (int64_t k = 0; k < total; ++k) {
    const uint64_t frame_seed = o.seed + uint64_t(k);
    const rtl::CosimCase c = k < int64_t(directed) ? cases[size_t(k)]
                                                   : rtl::random_case(profile, frame_seed, o.triangles);
    if (tty) std::fprintf(stderr, "\rcosim: %lld / %lld frames (%s)\033[K", (long long)k, (long long)total, c.name.c_str());
    rtl::RtlOptions options;
    options.seed = frame_seed;
    options.fst_path = o.fst_out;
    const std::string prefix = (std::filesystem::path(o.replay_dir) / ("rastersim-replay-" + std::to_string(k))).string();
    const rtl::CosimReport report = rtl::cosim(profile, c.triangles, options, prefix);
    if (!report.passed) {
      if (tty) std::fprintf(stderr, "\r\033[K");
      std::cout << "frame " << k << " (" << c.name << ", " << c.triangles.size() << " triangles, power-on seed "
                << frame_seed << "): " << report.message() << "\n";
      std::cout << passed << " passed, 1 failed\n";
      return 1;
    }
    ++passed;
  }
  if (tty) std::fprintf(stderr, "\r\033[K");
  std::cout << "profile " << profile.width << "x" << profile.height << " S=" << profile.subpixel_bits
            << " N=" << profile.z_bits << ", " << to_string(profile.traversal) << ", " << to_string(profile.shading)
            << ", depth " << to_string(profile.depth_func) << ", latency " << profile.memory_latency << ": "
            << directed << " directed and " << o.count << " random frames of " << o.triangles << " triangles\n";
  std::cout << passed << " passed, 0 failed\n";
  return 0;
#endif
}

}  // namespace rastersim
