#include "bench_command.h"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "backend.h"
#include "builtin_scenes.h"
#include "fast/threaded_render.h"
#include "inputs.h"
#include "tri_reader.h"
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

void add_bench_input_options(CLI::App& cmd, BenchInput& o) {
  CLI::Option* input =
      cmd.add_option("input", o.input, "a .tri, .obj or .json file instead of random triangles")->type_name("INPUT");
  CLI::Option* scene =
      cmd.add_option("--scene", o.scene, "a built-in scene instead of random triangles (see `rastersim scenes`)")
          ->type_name("NAME");
  // The random list's options describe a list that an INPUT or a scene replaces: given with one,
  // they would be ignored, so they are refused.
  for (CLI::Option* random : {cmd.add_option("--triangles", o.triangles, "number of random triangles")
                                  ->check(CLI::Range(int64_t(1), int64_t(kMaxTriTriangles)))  // a frame's limit, as for a .tri file
                                  ->capture_default_str(),
                              cmd.add_option("--size", o.size, "random triangle size range in pixels, MIN..MAX")
                                  ->capture_default_str(),
                              cmd.add_option("--seed", o.seed, "random seed")->capture_default_str()->check(unsigned_64_text)})
    random->excludes(input)->excludes(scene);
}

CLI::App* add_bench_command(CLI::App& app, BenchOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "bench", "measure model throughput (no tracing) on random triangles, or on an INPUT or --scene as render takes");
  add_bench_input_options(*cmd, o.what);
  cmd->add_option("--backend", o.backend,
                  "model: untraced model speed; rtl, cosim: simulation speed of the verilated RTL alone or in "
                  "lockstep with the model")
      ->check(CLI::IsMember(backend_names()))
      ->capture_default_str();
  cmd->add_option("--repeat", o.repeat, "timed repetitions; the best is reported")->check(CLI::Range(1, 100))
      ->capture_default_str();
  cmd->add_option("--threads", o.threads,
                  "model: threads of the timed render (checked equal to a traced one); default: the machine's cores when the "
                  "triangles average 128 pixels or more and cover 524288 or more, else 1")
      ->check(CLI::Range(1, 256));
  add_profile_options(*cmd, o.profile);
  return cmd;
}

std::vector<SnappedTriangle> load_bench_triangles(const BenchInput& o, const Profile& profile, std::string& source) {
  double min_size = 0, max_size = 0;
  parse_size_range(o.size, min_size, max_size);
  std::vector<ScreenTriangle> screen;
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
  return snapped;
}

ModelRun time_model(const std::vector<SnappedTriangle>& triangles, const Profile& profile, int threads) {
  Pipeline pipeline(profile);  // allocated and cleared outside the timed region
  ModelRun run;
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = process_cpu_seconds();
  render_threaded(pipeline, triangles, threads);
  run.stats = pipeline.stats();
  run.cpu_seconds = process_cpu_seconds() - cpu_start;
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

namespace {

struct CountingSink : FragmentSink {
  int64_t fragments = 0;
  void on_fragment(const Fragment&) override { ++fragments; }
};

struct RenderedFrame {
  FrameStats stats;
  std::vector<TriangleRecord> records;
  std::vector<uint32_t> depth, color;
};

RenderedFrame render_frame(const std::vector<SnappedTriangle>& triangles, const Profile& profile, FragmentSink* sink,
                           int threads) {
  Pipeline pipeline(profile);
  RenderedFrame frame;
  pipeline.set_fragment_sink(sink);
  pipeline.set_triangle_log(&frame.records);
  if (sink) {
    for (const SnappedTriangle& t : triangles) pipeline.submit(t);
  } else {
    render_threaded(pipeline, triangles, threads);
  }
  frame.stats = pipeline.stats();
  frame.depth = pipeline.zbuffer().depth();
  frame.color = pipeline.zbuffer().color();
  return frame;
}

bool same_records(const TriangleRecord& a, const TriangleRecord& b) {
  return a.status == b.status && a.setup_accept == b.setup_accept && a.setup_done == b.setup_done &&
         a.walker_load == b.walker_load && a.walker_end == b.walker_end && a.fragments == b.fragments &&
         a.depth_pass == b.depth_pass && a.last_write == b.last_write;
}

bool same_stats(const FrameStats& a, const FrameStats& b) {
  auto same_unit = [](const UnitCounters& x, const UnitCounters& y) { return x.busy == y.busy && x.stall == y.stall; };
  return a.triangles == b.triangles && a.triangles_culled == b.triangles_culled &&
         a.triangles_degenerate == b.triangles_degenerate && a.triangles_offscreen == b.triangles_offscreen &&
         a.triangles_no_centre == b.triangles_no_centre &&
         a.triangles_drawn == b.triangles_drawn && a.candidates == b.candidates && a.fragments == b.fragments &&
         a.depth_pass == b.depth_pass && a.depth_fail == b.depth_fail && a.cycles == b.cycles &&
         same_unit(a.setup, b.setup) && same_unit(a.walker, b.walker) && same_unit(a.z_adder, b.z_adder) &&
         same_unit(a.zbuffer, b.zbuffer) && same_unit(a.texture, b.texture);
}

}  // namespace

std::string untraced_differs_from_traced(const std::vector<SnappedTriangle>& triangles, const Profile& profile,
                                         int threads) {
  CountingSink sink;
  const RenderedFrame traced = render_frame(triangles, profile, &sink, 1);
  const RenderedFrame untraced = render_frame(triangles, profile, nullptr, threads);
  if (sink.fragments != traced.stats.fragments) return "the traced render's sink saw a different fragment count";
  if (!same_stats(traced.stats, untraced.stats)) return "frame counters differ";
  if (traced.records.size() != untraced.records.size()) return "triangle record counts differ";
  for (size_t i = 0; i < traced.records.size(); ++i)
    if (!same_records(traced.records[i], untraced.records[i])) return "triangle " + std::to_string(i) + "'s record differs";
  if (traced.depth != untraced.depth) return "depth buffers differ";
  if (traced.color != untraced.color) return "colour buffers differ";
  return "";
}

namespace {

// Simulation speed: whole frames through the RTL backend (model construction, memory clear,
// frame, final memories) or through co-simulation (the same plus the traced model and the
// comparison), best of `repeat`.
int run_simulation_bench(const BenchOptions& o, Backend backend, const Profile& profile,
                         const std::vector<SnappedTriangle>& snapped, const std::string& source) {
  check_backend_profile(backend, profile);
  double best = 0, best_cpu = 0;
  RenderResult result;
  for (int r = 0; r < o.repeat; ++r) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = process_cpu_seconds();
    result = render_triangles(backend, profile, snapped, nullptr, nullptr);
    const double cpu_seconds = process_cpu_seconds() - cpu_start;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (result.check_failed) {
      std::fprintf(stderr, "rastersim: %s\n", result.report.c_str());
      return 1;
    }
    if (r == 0 || seconds < best) best = seconds;
    if (r == 0 || cpu_seconds < best_cpu) best_cpu = cpu_seconds;
  }
  const double cycles = double(result.stats.cycles);
  std::printf("bench: %s, %zu triangles, %dx%d, %s traversal, backend %s, best of %d\n", source.c_str(), snapped.size(),
              profile.width, profile.height, to_string(profile.traversal), o.backend.c_str(), o.repeat);
  std::printf("wall time   %.6f s (whole frame)\n", best);
  std::printf("cpu time    %.6f s (whole frame, this process)\n", best_cpu);
  std::printf("cycles      %lld, %.4g per second, %.4g per cpu second\n", (long long)result.stats.cycles, cycles / best,
              cycles / best_cpu);
  std::printf("fragments   %lld\n", (long long)result.stats.fragments);
  if (backend == Backend::Cosim) std::printf("verified    model and RTL agree on every event and word\n");
  return 0;
}

}  // namespace

int run_bench(const BenchOptions& o) {
  const Profile profile = resolve_profile(o.profile);
  const Backend backend = select_backend(o.backend);
  std::string source;
  const std::vector<SnappedTriangle> snapped = load_bench_triangles(o.what, profile, source);
  if (backend != Backend::Model) return run_simulation_bench(o, backend, profile, snapped, source);

  const int threads = o.threads > 0 ? o.threads : default_threads(snapped, profile);
  ModelRun best;
  for (int r = 0; r < o.repeat; ++r) {
    const ModelRun run = time_model(snapped, profile, threads);
    if (r > 0 && (run.stats.fragments != best.stats.fragments || run.stats.cycles != best.stats.cycles)) {
      std::fprintf(stderr, "rastersim: repetition %d gave different fragments or cycles: the model is not deterministic\n", r);
      return 1;
    }
    if (r == 0 || run.seconds < best.seconds) best.seconds = run.seconds;
    if (r == 0 || run.cpu_seconds < best.cpu_seconds) best.cpu_seconds = run.cpu_seconds;
    best.stats = run.stats;
  }
  const std::string difference = untraced_differs_from_traced(snapped, profile, threads);
  if (!difference.empty()) {
    std::fprintf(stderr, "rastersim: the untraced (timed) render differs from the traced one: %s\n", difference.c_str());
    return 1;
  }

  const FrameStats& stats = best.stats;
  const double n = double(snapped.size()), fragments = double(stats.fragments);
  std::printf("bench: %s, %zu triangles, %dx%d, %s traversal, %s shading, %d thread%s, best of %d\n", source.c_str(),
              snapped.size(), profile.width, profile.height, to_string(profile.traversal), to_string(profile.shading),
              threads, threads == 1 ? "" : "s", o.repeat);
  std::printf("wall time   %.6f s (render only)\n", best.seconds);
  std::printf("cpu time    %.6f s (render only, this process, every thread)\n", best.cpu_seconds);
  std::printf("triangles   %.4g per second, %.4g per cpu second\n", n / best.seconds, n / best.cpu_seconds);
  std::printf("fragments   %lld, %.4g per second, %.4g per cpu second\n", (long long)stats.fragments,
              fragments / best.seconds, fragments / best.cpu_seconds);
  std::printf("candidates  %lld\n", (long long)stats.candidates);
  std::printf("cycles      %lld (%.3f fragments per clock, %.4g simulated cycles per second)\n", (long long)stats.cycles,
              stats.cycles > 0 ? double(stats.fragments) / double(stats.cycles) : 0.0, double(stats.cycles) / best.seconds);
  // The hardware's view (cycles are the model's, which the RTL equals): where the clocks went.
  const SetupTiming setup = setup_timing(profile);
  const double cycles = double(std::max<int64_t>(stats.cycles, 1));
  const int64_t walker_idle = stats.cycles - stats.walker.busy - stats.walker.stall;
  std::printf("throughput  %.3f fragments per clock (bound 1), %.1f cycles per triangle\n", fragments / cycles,
              cycles / std::max(n, 1.0));
  // Held: the z-buffer refuses its fragment (a hazard, or the memory's back-pressure).
  std::printf("walker      busy %.1f%%, held by the z-buffer %.1f%%, idle (waiting for setup) %.1f%% of cycles\n",
              100.0 * double(stats.walker.busy) / cycles, 100.0 * double(stats.walker.stall) / cycles,
              100.0 * double(walker_idle) / cycles);
  std::printf("setup       latency %d cycles per drawn triangle, %d per rejected; busy %.1f%% of cycles\n",
              setup.drawn_latency + 1, setup.rejected_latency + 1, 100.0 * double(stats.setup.busy) / cycles);
  std::printf("verified    counters, triangle records and buffers equal a traced render's\n");
  return 0;
}

}  // namespace rastersim
