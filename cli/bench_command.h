// `rastersim bench`: model throughput (fragments and triangles per second, render only) on a large
// random triangle list, or on the same inputs `rastersim render` takes (a file or a built-in scene).
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "profile_options.h"

namespace rastersim {

struct BenchOptions {
  std::string input;           // a .tri / .obj / .json file, as `rastersim render`
  std::string scene;           // or a built-in scene; neither: random triangles
  int64_t triangles = 200000;
  std::string size = "1..32";  // triangle size range in pixels, MIN..MAX
  uint64_t seed = 1;
  int repeat = 3;
  ProfileOptions profile;
};

CLI::App* add_bench_command(CLI::App& app, BenchOptions& options);
int run_bench(const BenchOptions& options);

// Parses "MIN..MAX" or "SIZE" (pixels, 0 < MIN <= MAX); throws InputError.
void parse_size_range(const std::string& text, double& min_size, double& max_size);

// CPU time of the whole process, in seconds: on a shared machine it counts only the cycles the run
// got, where wall time also counts the other jobs'.
double process_cpu_seconds();

}  // namespace rastersim
