// Speed of the reference model: one frame of 100k random triangles of mixed sizes on 1920 x 1080
// through Pipeline::submit, per traversal and shading. The triangles are generated, checked and
// snapped once, outside the timed loop; each iteration renders the whole list into a cleared
// frame. Counters: fragments/s and triangles/s (rates), model cycles per frame.
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "fast/fast_walk.h"
#include "model/pipeline.h"
#include "model/triangle.h"

namespace rastersim {
namespace {

constexpr int kWidth = 1920, kHeight = 1080, kTriangles = 100000;

Profile bench_profile(Traversal traversal, Shading shading) {
  Profile p;
  p.width = kWidth;
  p.height = kHeight;
  p.subpixel_bits = 4;
  p.z_bits = 24;
  p.traversal = traversal;
  p.shading = shading;
  p.depth_func = DepthFunc::Less;
  return p;
}

// Mixed sizes: 70% small (up to 8 px across), 25% medium (up to 64 px), 5% large (up to 400 px),
// centred anywhere on screen, random depths and colours. Fixed seed: every run draws the same list.
const std::vector<SnappedTriangle>& triangle_list() {
  static const std::vector<SnappedTriangle> list = [] {
    const Profile p = bench_profile(Traversal::Span, Shading::Gouraud);
    std::mt19937_64 rng(20240601);
    std::uniform_real_distribution<double> x(0.0, kWidth), y(0.0, kHeight), unit(0.0, 1.0);
    std::uniform_int_distribution<int> channel(0, 255), size_class(0, 99);
    std::vector<SnappedTriangle> out;
    out.reserve(kTriangles);
    while (int(out.size()) < kTriangles) {
      const int c = size_class(rng);
      const double radius = c < 70 ? 4.0 : c < 95 ? 32.0 : 200.0;
      std::uniform_real_distribution<double> offset(-radius, radius);
      const double cx = x(rng), cy = y(rng);
      ScreenTriangle t;
      for (ScreenVertex& v : t.v) {
        v.x = cx + offset(rng);
        v.y = cy + offset(rng);
        v.z = unit(rng);
        v.color = Rgb{uint8_t(channel(rng)), uint8_t(channel(rng)), uint8_t(channel(rng))};
      }
      if (check_screen_triangle(t, p).empty()) out.push_back(snap(t, p));
    }
    return out;
  }();
  return list;
}

void BM_Frame(benchmark::State& state) {
  use_fast_walk();  // the untraced path rastersim render takes
  const Traversal traversal = state.range(0) == 0 ? Traversal::BBox : Traversal::Span;
  const Shading shading = state.range(1) == 0 ? Shading::Flat : Shading::Gouraud;
  const std::vector<SnappedTriangle>& triangles = triangle_list();
  Pipeline pipe(bench_profile(traversal, shading));
  int64_t fragments = 0, cycles = 0;
  for (auto _ : state) {
    pipe.reset();
    for (const SnappedTriangle& t : triangles) pipe.submit(t);
    const FrameStats& stats = pipe.stats();
    fragments += stats.fragments;
    cycles = stats.cycles;
    benchmark::DoNotOptimize(pipe.zbuffer().depth().data());
  }
  state.SetLabel(std::string(to_string(traversal)) + ", " + to_string(shading));
  state.counters["fragments_per_s"] = benchmark::Counter(double(fragments), benchmark::Counter::kIsRate);
  state.counters["triangles_per_s"] =
      benchmark::Counter(double(state.iterations()) * double(triangles.size()), benchmark::Counter::kIsRate);
  state.counters["fragments_per_frame"] = double(fragments) / double(state.iterations());
  state.counters["model_cycles_per_frame"] = double(cycles);
}

BENCHMARK(BM_Frame)
    ->ArgNames({"span", "gouraud"})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Args({1, 0})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);

}  // namespace
}  // namespace rastersim

BENCHMARK_MAIN();
