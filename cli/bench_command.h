// `rastersim bench`: model throughput on a large random triangle list.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "profile_options.h"

namespace rastersim {

struct BenchOptions {
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

}  // namespace rastersim
