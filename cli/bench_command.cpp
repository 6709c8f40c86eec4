#include "bench_command.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "builtin_scenes.h"
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

void parse_size_range(const std::string& text, double& min_size, double& max_size) {
  const size_t dots = text.find("..");
  const std::string lo = dots == std::string::npos ? text : text.substr(0, dots);
  const std::string hi = dots == std::string::npos ? text : text.substr(dots + 2);
  if (!parse_positive(lo, min_size) || !parse_positive(hi, max_size) || min_size > max_size || max_size > 1e6)
    throw InputError("--size '" + text + "': expected MIN..MAX in pixels with 0 < MIN <= MAX <= 1e6");
}

CLI::App* add_bench_command(CLI::App& app, BenchOptions& o) {
  CLI::App* cmd = app.add_subcommand("bench", "measure model throughput on random triangles (no tracing)");
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

  // Generation and snapping stay outside the timed region.
  std::vector<ScreenTriangle> screen = random_triangles(o.triangles, min_size, max_size, o.seed, profile);
  std::vector<SnappedTriangle> snapped;
  snapped.reserve(screen.size());
  for (const ScreenTriangle& t : screen) snapped.push_back(snap(t, profile));
  std::vector<ScreenTriangle>().swap(screen);  // only the snapped list is rendered

  double best_seconds = 0;
  FrameStats stats;
  for (int r = 0; r < o.repeat; ++r) {
    Pipeline pipeline(profile);
    const auto start = std::chrono::steady_clock::now();
    for (const SnappedTriangle& t : snapped) pipeline.submit(t);
    const FrameStats& run_stats = pipeline.stats();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (r == 0 || seconds < best_seconds) best_seconds = seconds;
    if (r > 0 && (run_stats.fragments != stats.fragments || run_stats.cycles != stats.cycles)) {
      std::fprintf(stderr, "rastersim: repetition %d gave different fragments or cycles: the model is not deterministic\n", r);
      return 1;
    }
    stats = run_stats;
  }

  std::printf("bench: %lld triangles of %g..%g pixels, seed %llu, %dx%d, %s traversal, best of %d\n",
              (long long)o.triangles, min_size, max_size, (unsigned long long)o.seed, profile.width, profile.height,
              to_string(profile.traversal), o.repeat);
  std::printf("wall time   %.6f s (render only)\n", best_seconds);
  std::printf("triangles   %.4g per second\n", double(o.triangles) / best_seconds);
  std::printf("fragments   %lld, %.4g per second\n", (long long)stats.fragments, double(stats.fragments) / best_seconds);
  std::printf("candidates  %lld\n", (long long)stats.candidates);
  std::printf("cycles      %lld (%.3f fragments per clock, %.4g simulated cycles per second)\n", (long long)stats.cycles,
              stats.cycles > 0 ? double(stats.fragments) / double(stats.cycles) : 0.0, double(stats.cycles) / best_seconds);
  return 0;
}

}  // namespace rastersim
