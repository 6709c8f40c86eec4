#include "bench_command.h"

#include <time.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "builtin_scenes.h"
#include "inputs.h"
#include "model/input_error.h"
#include "model/pipeline.h"

namespace rastersim {
namespace {

bool parse_positive(const std::string& text, double& out) {
  if (text.empty()) return false;
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(out) && out > 0;
}

}  // namespace

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

void parse_size_range(const std::string& text, double& min_size, double& max_size) {
  const size_t dots = text.find("..");
  const std::string lo = dots == std::string::npos ? text : text.substr(0, dots);
  const std::string hi = dots == std::string::npos ? text : text.substr(dots + 2);
  if (!parse_positive(lo, min_size) || !parse_positive(hi, max_size) || min_size > max_size || max_size > 1e6)
    throw InputError("--size '" + text + "': expected MIN..MAX in pixels with 0 < MIN <= MAX <= 1e6");
}

CLI::App* add_bench_command(CLI::App& app, BenchOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "bench", "measure model throughput (no tracing) on random triangles, or on an INPUT or --scene as render takes");
  cmd->add_option("input", o.input, "a .tri, .obj or .json file instead of random triangles")->type_name("INPUT");
  cmd->add_option("--scene", o.scene, "a built-in scene instead of random triangles (see `rastersim scenes`)")
      ->type_name("NAME");
  cmd->add_option("--triangles", o.triangles, "number of triangles")->check(CLI::Range(int64_t(1), int64_t(10000000)))
      ->capture_default_str();
  cmd->add_option("--size", o.size, "triangle size range in pixels, MIN..MAX")->capture_default_str();
  cmd->add_option("--seed", o.seed, "random seed")->capture_default_str();
  cmd->add_option("--repeat", o.repeat, "timed repetitions; the best is reported")->check(CLI::Range(1, 100))
      ->capture_default_str();
  add_profile_options(*cmd, o.profile);
  return cmd;
}

int run_bench(const BenchOptions& o) {
  const Profile profile = resolve_profile(o.profile);
  double min_size = 0, max_size = 0;
  parse_size_range(o.size, min_size, max_size);

  // Loading, generation and snapping stay outside the timed region.
  std::vector<ScreenTriangle> screen;
  std::string source;
  if (!o.input.empty() || !o.scene.empty()) {
    screen = load_input(o.input, o.scene, profile);
    source = o.input.empty() ? "scene " + o.scene : o.input;
  } else {
    screen = random_triangles(o.triangles, min_size, max_size, o.seed, profile);
    char text[160];
    std::snprintf(text, sizeof text, "%lld random triangles of %g..%g pixels, seed %llu", (long long)o.triangles,
                  min_size, max_size, (unsigned long long)o.seed);
    source = text;
  }
  std::vector<SnappedTriangle> snapped;
  snapped.reserve(screen.size());
  for (const ScreenTriangle& t : screen) snapped.push_back(snap(t, profile));
  std::vector<ScreenTriangle>().swap(screen);  // only the snapped list is rendered

  double best_seconds = 0, best_cpu_seconds = 0;
  FrameStats stats;
  for (int r = 0; r < o.repeat; ++r) {
    Pipeline pipeline(profile);
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = process_cpu_seconds();
    for (const SnappedTriangle& t : snapped) pipeline.submit(t);
    const FrameStats& run_stats = pipeline.stats();
    const double cpu_seconds = process_cpu_seconds() - cpu_start;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (r == 0 || seconds < best_seconds) best_seconds = seconds;
    if (r == 0 || cpu_seconds < best_cpu_seconds) best_cpu_seconds = cpu_seconds;
    if (r > 0 && (run_stats.fragments != stats.fragments || run_stats.cycles != stats.cycles)) {
      std::fprintf(stderr, "rastersim: repetition %d gave different fragments or cycles: the model is not deterministic\n", r);
      return 1;
    }
    stats = run_stats;
  }

  const double n = double(snapped.size()), fragments = double(stats.fragments);
  std::printf("bench: %s, %zu triangles, %dx%d, %s traversal, %s shading, best of %d\n", source.c_str(),
              snapped.size(), profile.width, profile.height, to_string(profile.traversal), to_string(profile.shading),
              o.repeat);
  std::printf("wall time   %.6f s (render only)\n", best_seconds);
  std::printf("cpu time    %.6f s (render only, this process)\n", best_cpu_seconds);
  std::printf("triangles   %.4g per second, %.4g per cpu second\n", n / best_seconds, n / best_cpu_seconds);
  std::printf("fragments   %lld, %.4g per second, %.4g per cpu second\n", (long long)stats.fragments,
              fragments / best_seconds, fragments / best_cpu_seconds);
  std::printf("candidates  %lld\n", (long long)stats.candidates);
  std::printf("cycles      %lld (%.3f fragments per clock, %.4g simulated cycles per second)\n", (long long)stats.cycles,
              stats.cycles > 0 ? double(stats.fragments) / double(stats.cycles) : 0.0, double(stats.cycles) / best_seconds);
  return 0;
}

}  // namespace rastersim
