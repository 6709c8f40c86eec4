// `rastersim bench`: model throughput (fragments and triangles per second, render only, untraced)
// on a large random triangle list, or on the same inputs `rastersim render` takes (a file or a
// built-in scene); and the pieces the Mesa peer (bench/mesa_peer.cpp) shares with it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "model/pipeline.h"
#include "profile_options.h"

namespace rastersim {

// What to render: a file, a built-in scene, or (neither) random triangles.
struct BenchInput {
  std::string input;           // a .tri / .obj / .json file, as `rastersim render`
  std::string scene;           // or a built-in scene
  int64_t triangles = 200000;  // else this many random triangles
  std::string size = "1..32";  // triangle size range in pixels, MIN..MAX
  uint64_t seed = 1;
};

struct BenchOptions {
  BenchInput what;
  std::string backend = "model";  // rtl, cosim: simulation speed (cycles per second) instead
  int repeat = 3;
  int threads = 0;  // model: render threads; 0: default_threads() (fast/threaded_render.h)
  ProfileOptions profile;
};

CLI::App* add_bench_command(CLI::App& app, BenchOptions& options);
int run_bench(const BenchOptions& options);

void add_bench_input_options(CLI::App& cmd, BenchInput& what);
// Loads or generates the triangles and snaps them (untimed); `source` describes them.
std::vector<SnappedTriangle> load_bench_triangles(const BenchInput& what, const Profile& profile, std::string& source);

// One untraced render of the list into a fresh pipeline, timed (render only).
struct ModelRun {
  double seconds = 0, cpu_seconds = 0;
  FrameStats stats;
};
// With `threads` > 1 the threaded render (fast/threaded_render.h).
ModelRun time_model(const std::vector<SnappedTriangle>& triangles, const Profile& profile, int threads = 1);

// Renders the list untraced (as timed) and traced (every fragment through a sink, the path
// co-simulation checks against the RTL) and compares every counter, triangle record and buffer
// word. Returns "" when they are equal, else what differs.
std::string untraced_differs_from_traced(const std::vector<SnappedTriangle>& triangles, const Profile& profile,
                                         int threads = 1);

// Parses "MIN..MAX" or "SIZE" (pixels, 0 < MIN <= MAX); throws InputError.
void parse_size_range(const std::string& text, double& min_size, double& max_size);

// CPU time of the whole process, in seconds: on a shared machine it counts only the cycles the run
// got, where wall time also counts the other jobs'.
double process_cpu_seconds();

}  // namespace rastersim
