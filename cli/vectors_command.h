// `rastersim vectors`: a test-vector package for FPGA ports (docs/vectors.md) from an input file,
// a built-in scene, constrained-random triangles or a directed suite.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "profile_options.h"
#include "render_command.h"

namespace rastersim {

struct VectorsOptions {
  std::string out;
  std::string input;
  std::string scene;
  std::string suite;
  int64_t random = 0;         // triangles, with --random
  uint64_t seed = 1;          // with --random
  std::string rtl_path;       // refer to the RTL at this relative path instead of copying it
  std::string testbench_path; // refer to the testbench's folder at this relative path instead of copying it
  std::string top;            // "rastersim_top", "rastersim_core" or empty (by memory_stall_percent)
  bool force = false;         // replace an existing package
  CLI::Option* random_option = nullptr;
  CLI::Option* seed_option = nullptr;
  RenderOptions camera;       // the camera flags (3D inputs)
  ProfileOptions profile;
};

CLI::App* add_vectors_command(CLI::App& app, VectorsOptions& options);
// 0 when the package was written; throws InputError for bad usage or input (nothing is written).
int run_vectors(const VectorsOptions& options);

}  // namespace rastersim
