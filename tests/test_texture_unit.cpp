// The texture unit's cycles (docs/cycle-model.md, "Texture unit") and colours, checked against
// figures derived by hand from the rules: its fixed latency on an unstalled stream, the setup
// units' texture planes, the back-pressure of its memory, and the modulation of the fragments.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "model/pipeline.h"

namespace rastersim {
namespace {

struct Collect : FragmentSink {
  std::vector<Fragment> fragments;
  void on_fragment(const Fragment& f) override { fragments.push_back(f); }
};

// One large textured triangle (the walker never waits for the z-buffer: one fragment per clock).
ScreenTriangle large_triangle(bool textured) {
  ScreenTriangle tri;
  tri.textured = textured;
  tri.v[0] = {4.25, 3.5, 0.25, {200, 40, 40}, -1.5, 0.25, 1.0};
  tri.v[1] = {60.5, 9.75, 0.5, {40, 200, 40}, 2.0, -0.5, 30.0};
  tri.v[2] = {20.75, 44.25, 0.75, {40, 40, 200}, 0.5, 3.0, 4.0};
  return tri;
}

struct Frame {
  FrameStats stats;
  std::vector<Fragment> fragments;
  std::vector<TriangleRecord> log;
};

Frame render(const Profile& profile, const std::vector<ScreenTriangle>& triangles, TextureBinding texture = {}) {
  Pipeline pipeline(profile);
  Collect sink;
  Frame frame;
  pipeline.set_fragment_sink(&sink);
  pipeline.set_triangle_log(&frame.log);
  pipeline.set_texture(std::move(texture));
  for (const ScreenTriangle& t : triangles) pipeline.submit(snap(t, profile));
  frame.stats = pipeline.stats();
  frame.fragments = sink.fragments;
  return frame;
}

Profile small_profile() {
  Profile p;
  p.width = 64, p.height = 48;
  return p;
}

// Without back-pressure every fragment reaches the z-buffer Lt + 39 cycles after the walker offered
// it, one per clock: the frame is longer by that and by the setup's texture planes, nothing else.
TEST(TextureUnit, UnstalledStreamIsDelayedByItsLatencyOnly) {
  for (int interval : {0, 4}) {
    for (int latency : {1, 2, 7, 64}) {
      SCOPED_TRACE("setup_interval " + std::to_string(interval) + ", texture_latency " + std::to_string(latency));
      Profile plain = small_profile();
      plain.setup_interval = interval;
      Profile textured = plain;
      textured.texture_unit = true, textured.texture_latency = latency;
      const Frame a = render(plain, {large_triangle(true)});
      const Frame b = render(textured, {large_triangle(true)});
      // The setup's texture planes: the serial unit's 2,652 more cycles for a textured triangle at
      // this profile's widths (docs/cycle-model.md), the pipelined unit's wider slots (I = 4: 60
      // cycles instead of 48 at the default profile; here the widths of 64 x 48).
      const int64_t setup_delta = b.log[0].setup_done - a.log[0].setup_done;
      const SetupTiming t0 = setup_timing(plain), t1 = setup_timing(textured);
      EXPECT_EQ(setup_delta, t1.textured_drawn_latency - t0.drawn_latency);
      if (interval == 0) {
        EXPECT_EQ(setup_delta, serial_setup_texture_cycles(derive_widths(textured), textured.subpixel_bits));
      }
      ASSERT_EQ(a.fragments.size(), b.fragments.size());
      ASSERT_GT(a.fragments.size(), 800u);
      for (size_t i = 0; i < a.fragments.size(); ++i) {
        ASSERT_EQ(b.fragments[i].x, a.fragments[i].x);
        ASSERT_EQ(b.fragments[i].z, a.fragments[i].z);
        ASSERT_EQ(b.fragments[i].cycle, a.fragments[i].cycle + setup_delta + latency + 39) << "fragment " << i;
      }
      EXPECT_EQ(b.stats.cycles, a.stats.cycles + setup_delta + latency + 39);
      EXPECT_EQ(b.stats.walker.stall, 0);
      EXPECT_EQ(b.stats.texture.stall, 0);
      // Busy from the first take to the last z-buffer take, without a gap.
      EXPECT_EQ(b.stats.texture.busy, b.fragments.back().cycle - (a.fragments.front().cycle + setup_delta) + 1);
    }
  }
}

// Untextured fragments pass with the same latency, and keep their colours.
TEST(TextureUnit, UntexturedFragmentsTakeTheSamePath) {
  Profile plain = small_profile(), textured = small_profile();
  textured.texture_unit = true;
  const Frame a = render(plain, {large_triangle(false)});
  const Frame b = render(textured, {large_triangle(false)});
  ASSERT_EQ(a.fragments.size(), b.fragments.size());
  for (size_t i = 0; i < a.fragments.size(); ++i) {
    EXPECT_FALSE(b.fragments[i].textured);
    ASSERT_EQ(b.fragments[i].color, a.fragments[i].color);
    const int64_t setup_delta = setup_timing(textured).drawn_latency - setup_timing(plain).drawn_latency;
    ASSERT_EQ(b.fragments[i].cycle, a.fragments[i].cycle + setup_delta + textured.texture_latency + 39);
  }
}

// Without a texture every texel is white: modulation keeps the Gouraud colour exactly. With the
// texture unit off the texture coordinates are dropped at the snap.
TEST(TextureUnit, WhiteTexelKeepsTheGouraudColour) {
  Profile plain = small_profile(), textured = small_profile();
  textured.texture_unit = true;
  const Frame a = render(plain, {large_triangle(true)});
  const Frame b = render(textured, {large_triangle(true)});
  ASSERT_EQ(a.fragments.size(), b.fragments.size());
  for (size_t i = 0; i < a.fragments.size(); ++i) {
    EXPECT_FALSE(a.fragments[i].textured);
    EXPECT_TRUE(b.fragments[i].textured);
    ASSERT_EQ(b.fragments[i].color, a.fragments[i].color) << "fragment " << i;
  }
  EXPECT_FALSE(snap(large_triangle(true), plain).textured);
  EXPECT_TRUE(snap(large_triangle(true), textured).textured);
  // A snapped triangle marked textured by hand: without the texture unit the setup ignores it.
  SnappedTriangle marked = snap(large_triangle(true), textured);
  EXPECT_FALSE(TriangleSetup(plain).run(marked).textured);
  EXPECT_TRUE(TriangleSetup(textured).run(marked).textured);
}

// A one-texel texture of colour c: every textured fragment is round(c g / 255) of its Gouraud colour g.
TEST(TextureUnit, TexelIsModulatedByTheGouraudColour) {
  Profile plain = small_profile(), textured = small_profile();
  textured.texture_unit = true;
  const Frame a = render(plain, {large_triangle(true)});
  TextureBinding binding;
  binding.texture = std::make_shared<const Texture>(0, 0, std::vector<uint32_t>{0x80FF10});
  const Frame b = render(textured, {large_triangle(true)}, binding);
  ASSERT_EQ(a.fragments.size(), b.fragments.size());
  auto rounded = [](int c, int g) { return (2 * c * g + 255) / 510; };  // round(c g / 255), half up
  for (size_t i = 0; i < a.fragments.size(); ++i) {
    const Rgb g = a.fragments[i].color, got = b.fragments[i].color;
    ASSERT_EQ(got.r, rounded(0x80, g.r));
    ASSERT_EQ(got.g, rounded(0xFF, g.g));
    ASSERT_EQ(got.b, rounded(0x10, g.b));
  }
}

// Texture memory back-pressure: the same fragments, later; each refused cycle is counted, and the
// stall pattern is the z-buffer memory's function with the texture's seed.
TEST(TextureUnit, MemoryBackPressureDelaysButDoesNotChangeFragments) {
  Profile free = small_profile();
  free.texture_unit = true;
  Profile stalled = free;
  stalled.texture_stall_percent = 40, stalled.texture_stall_seed = 9;
  const std::vector<ScreenTriangle> tris = {large_triangle(true), large_triangle(false), large_triangle(true)};
  const Frame a = render(free, tris), b = render(stalled, tris);
  ASSERT_EQ(a.fragments.size(), b.fragments.size());
  for (size_t i = 0; i < a.fragments.size(); ++i) {
    ASSERT_EQ(b.fragments[i].color, a.fragments[i].color);
    ASSERT_EQ(b.fragments[i].pass, a.fragments[i].pass);
    ASSERT_GE(b.fragments[i].cycle, a.fragments[i].cycle);
  }
  EXPECT_GT(b.stats.texture.stall, 0);
  EXPECT_GT(b.stats.cycles, a.stats.cycles);
  // Reads of one fragment per cycle at best, each refused about 40 % of the time: the stall count is
  // the number of refused cycles the textured reads met, between 20 % and 60 % of them here.
  int64_t textured = 0;
  for (const Fragment& f : b.fragments) textured += f.textured;
  EXPECT_GT(b.stats.texture.stall, textured / 5);
  EXPECT_LT(b.stats.texture.stall, textured * 3 / 2);
}

}  // namespace
}  // namespace rastersim
