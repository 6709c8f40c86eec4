// The threaded render (fast/threaded_render.h) against the single-threaded model: at 1 to 4
// threads and with every run kernel, every counter, cycle, triangle record and buffer word equal to the traced
// specification's frame, over both traversals, the serial and pipelined setup, the texture unit,
// memory back-pressure, several latencies and depth functions.
#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "fast/run_kernels.h"
#include "fast/threaded_render.h"
#include "test_util.h"

namespace rastersim::test {
namespace {

// threads 0: the traced specification (a fragment sink, one fragment at a time).
Frame render(const Profile& profile, const std::vector<SnappedTriangle>& triangles, const TextureBinding& texture,
             int threads) {
  Pipeline pipeline(profile);
  FragmentLog log;
  Frame frame;
  pipeline.set_texture(texture);
  pipeline.set_triangle_log(&frame.records);
  if (threads == 0) {
    pipeline.set_fragment_sink(&log);
    for (const SnappedTriangle& t : triangles) pipeline.submit(t);
  } else {
    render_threaded(pipeline, triangles, threads);
  }
  frame.stats = pipeline.stats();
  frame.depth = pipeline.zbuffer().depth();
  frame.color = pipeline.zbuffer().color();
  return frame;
}

// A textured triangle over the screen: u, v in [-3, 3], w in [1, 4].
SnappedTriangle textured_triangle(TriangleGen& gen, const Profile& profile) {
  for (;;) {
    ScreenTriangle tri;
    tri.textured = true;
    for (ScreenVertex& v : tri.v) {
      v.x = double(gen.uniform(-200, 100 * profile.width + 200)) / 100.0;
      v.y = double(gen.uniform(-200, 100 * profile.height + 200)) / 100.0;
      v.z = double(gen.uniform(0, 1000)) / 1000.0;
      v.color = Rgb{uint8_t(gen.uniform(0, 255)), uint8_t(gen.uniform(0, 255)), uint8_t(gen.uniform(0, 255))};
      v.u = double(gen.uniform(-300, 300)) / 100.0;
      v.v = double(gen.uniform(-300, 300)) / 100.0;
      v.w = double(gen.uniform(100, 400)) / 100.0;
    }
    if (check_screen_triangle(tri, profile).empty()) return snap(tri, profile);
  }
}

TextureBinding checker_texture() {
  std::vector<uint32_t> texels(16 * 16);
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) texels[size_t(j * 16 + i)] = ((i ^ j) & 1) ? 0xff8040u : uint32_t(i * 16 + j * 4096);
  return TextureBinding{std::make_shared<const Texture>(4, 4, std::move(texels)), TextureFilter::Bilinear,
                        TextureWrap::Repeat};
}

using Param = std::tuple<Traversal, int /*setup_interval*/, int /*memory_latency*/, int /*memory_stall_percent*/,
                         bool /*texture_unit*/>;

class Threads : public ::testing::TestWithParam<Param> {};

TEST_P(Threads, ThreadedFrameEqualsSingleThreadedFrame) {
  const auto [traversal, interval, latency, stall_percent, texture_unit] = GetParam();
  const TextureBinding texture = checker_texture();
  int64_t fails = 0;
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    Profile profile = make_profile(96, 72, seed % 2 ? 4 : 8, traversal, seed == 3 ? 16 : 24);
    profile.setup_interval = interval;
    profile.setup_fifo_depth = seed == 2 ? 1 : 8;
    profile.memory_latency = latency;
    profile.memory_stall_percent = stall_percent;
    profile.memory_stall_seed = int(seed);
    profile.depth_func = seed == 4 ? DepthFunc::GEqual : DepthFunc::Less;
    profile.depth_write = seed != 2;
    profile.shading = seed % 3 ? Shading::Gouraud : Shading::Flat;
    profile.texture_unit = texture_unit;
    profile.texture_latency = int(seed) * 3;
    profile.texture_stall_percent = texture_unit && stall_percent > 0 ? 20 : 0;
    TriangleGen gen(profile, seed * 104729 + uint64_t(latency));
    // Large overlapping triangles (depth tests both ways, rows of every band), tiny ones (hazard
    // stalls), slivers, off-screen ones and, with the texture unit, textured ones.
    std::vector<SnappedTriangle> triangles;
    for (int i = 0; i < 70; ++i) {
      switch (gen.uniform(0, 4)) {
        case 0: triangles.push_back(gen.near_screen(60)); break;
        case 1: triangles.push_back(gen.tiny()); break;
        case 2: triangles.push_back(gen.sliver(40)); break;
        case 3: triangles.push_back(texture_unit ? textured_triangle(gen, profile) : gen.on_centres(6)); break;
        default: triangles.push_back(gen.guard_band()); break;
      }
    }
    const Frame spec = render(profile, triangles, texture, 0);
    ASSERT_GT(spec.stats.fragments, 0);
    fails += spec.stats.depth_fail;
    if (texture_unit) {
      EXPECT_GT(spec.stats.texture.busy, 0);
    }
    if (stall_percent > 0) {
      EXPECT_GT(spec.stats.zbuffer.stall, 0);
    }
    {
      SCOPED_TRACE(describe(profile) + " seed " + std::to_string(seed) + ", 1 thread");
      expect_same_frame(spec, render(profile, triangles, texture, 1));
    }
    // Every run kernel the workers may call (the compiled ones are what ThreadSanitizer sees into).
    for (const std::string& kernel : run_kernel_versions()) {
      select_run_kernel(kernel);
      for (int threads = 2; threads <= 4; ++threads) {
        SCOPED_TRACE(describe(profile) + " seed " + std::to_string(seed) + ", " + std::to_string(threads) +
                     " threads, run kernel " + kernel);
        expect_same_frame(spec, render(profile, triangles, texture, threads));
      }
    }
    select_run_kernel(run_kernel_versions().front());
  }
  EXPECT_GT(fails, 0) << "some fragments must fail their depth test";
}

INSTANTIATE_TEST_SUITE_P(Settings, Threads,
                         ::testing::Combine(::testing::Values(Traversal::BBox, Traversal::Span),
                                            ::testing::Values(0, 4), ::testing::Values(1, 2, 9),
                                            ::testing::Values(0, 30), ::testing::Bool()));

// A pipeline renders again after a threaded frame: its walk runner and mode are restored.
TEST(Threads, PipelineIsPlainAfterAThreadedFrame) {
  const Profile profile = make_profile(64, 48, 4, Traversal::Span);
  TriangleGen gen(profile, 7);
  std::vector<SnappedTriangle> triangles;
  for (int i = 0; i < 40; ++i) triangles.push_back(gen.near_screen(40));
  const Frame spec = render(profile, triangles, {}, 0);
  Pipeline pipeline(profile);
  render_threaded(pipeline, triangles, 3);
  pipeline.reset();
  Frame again;
  pipeline.set_triangle_log(&again.records);
  for (const SnappedTriangle& t : triangles) pipeline.submit(t);
  again.stats = pipeline.stats();
  again.depth = pipeline.zbuffer().depth();
  again.color = pipeline.zbuffer().color();
  expect_same_frame(spec, again);
}

// The default thread count: one for small triangles or a small frame, the machine's cores for
// triangles of kThreadedPixels and more covering kThreadedFramePixels. A right triangle with legs
// of a pixels has a^2 / 2 pixels.
TEST(Threads, DefaultThreadsFollowTriangleAreaAndFrameSize) {
  const Profile profile = make_profile(1024, 1024, 4, Traversal::Span);
  auto right_triangles = [&](int legs, int count) {
    std::vector<SnappedTriangle> triangles(static_cast<size_t>(count));
    for (SnappedTriangle& t : triangles) {
      t.v[0].x = 16, t.v[0].y = 16;
      t.v[1].x = 16 + legs * 16, t.v[1].y = 16;
      t.v[2].x = 16, t.v[2].y = 16 + legs * 16;
    }
    return triangles;
  };
  EXPECT_EQ(default_threads({}, profile), 1);
  EXPECT_EQ(default_threads(right_triangles(15, 100000), profile), 1);   // 112 pixels, under the bound
  EXPECT_EQ(default_threads(right_triangles(17, 1000), profile), 1);     // 144 pixels, but a small frame
  EXPECT_EQ(default_threads(right_triangles(17, 100000), profile), machine_threads());
  EXPECT_EQ(default_threads(right_triangles(1000, 2), profile), machine_threads());
  // Off the screen: the box on the screen bounds the area.
  std::vector<SnappedTriangle> off = right_triangles(1000, 100);
  for (SnappedTriangle& t : off)
    for (SnappedVertex& v : t.v) v.x -= 2000 * 16;
  EXPECT_EQ(default_threads(off, profile), 1);
}

}  // namespace
}  // namespace rastersim::test
