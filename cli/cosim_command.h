// `rastersim cosim`: directed and constrained-random frames through the model and the RTL in
// lockstep; the first divergence is reported with a replay command.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "profile_options.h"

namespace rastersim {

struct CosimOptions {
  int64_t count = 100;        // random frames (after the directed ones)
  uint64_t seed = 1;          // frame k uses seed + k for its triangles and its power-on state
  int triangles = 16;         // triangles per random frame
  bool directed = true;
  std::string replay_dir = ".";
  std::string fst_out;
  ProfileOptions profile;
};

CLI::App* add_cosim_command(CLI::App& app, CosimOptions& options);
// 0 when every frame agrees, 1 at the first divergence; throws InputError for bad usage.
int run_cosim(const CosimOptions& options);

}  // namespace rastersim
