// Built-in scenes and input dispatch, in process: every scene fits the guard band of any valid
// screen size, is deterministic, and the fan mesh covers every pixel centre exactly once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "bench_command.h"
#include "builtin_scenes.h"
#include "inputs.h"
#include "model/input_error.h"
#include "model/pipeline.h"

namespace rastersim {
namespace {

std::vector<Profile> screen_sizes() {
  std::vector<Profile> profiles;
  const int sizes[][2] = {{1, 1}, {7, 5}, {64, 48}, {640, 480}, {4096, 4096}, {4096, 1}};
  for (const auto& size : sizes) {
    for (int s : {1, 8}) {
      Profile p;
      p.width = size[0];
      p.height = size[1];
      p.subpixel_bits = s;
      profiles.push_back(p);
    }
  }
  return profiles;
}

bool same_triangles(const std::vector<ScreenTriangle>& a, const std::vector<ScreenTriangle>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (std::memcmp(&a[i].v[k].x, &b[i].v[k].x, sizeof(double)) != 0 ||
          std::memcmp(&a[i].v[k].y, &b[i].v[k].y, sizeof(double)) != 0 ||
          std::memcmp(&a[i].v[k].z, &b[i].v[k].z, sizeof(double)) != 0 || !(a[i].v[k].color == b[i].v[k].color))
        return false;
  return true;
}

TEST(BuiltinScenes, RegistryHasTheRequiredScenes) {
  for (const char* name : {"overlap", "fan", "stress"}) {
    const BuiltinScene* scene = find_builtin_scene(name);
    ASSERT_NE(scene, nullptr) << name;
    EXPECT_FALSE(scene->description.empty());
    EXPECT_EQ(scene->description.find('\n'), std::string::npos);
  }
  EXPECT_EQ(find_builtin_scene("no-such-scene"), nullptr);
}

TEST(BuiltinScenes, EveryTriangleFitsTheGuardBandAndIsDeterministic) {
  for (const BuiltinScene& scene : builtin_scenes()) {
    for (const Profile& p : screen_sizes()) {
      const auto tris = scene.generate(p);
      EXPECT_FALSE(tris.empty()) << scene.name;
      for (size_t i = 0; i < tris.size(); ++i)
        ASSERT_EQ(check_screen_triangle(tris[i], p), "") << scene.name << " " << p.width << "x" << p.height << " #" << i;
      EXPECT_TRUE(same_triangles(tris, scene.generate(p))) << scene.name;
    }
  }
}

TEST(BuiltinScenes, DefaultIsTheFrontEndsScene) {
  Profile p;
  EXPECT_EQ(find_builtin_scene("default"), nullptr);
  EXPECT_TRUE(same_triangles(load_input("", "", p), frontend::builtin_scene("default", p, {})));
  const auto list = scene_list();
  ASSERT_FALSE(list.empty());
  EXPECT_EQ(list.front().first, "default");
}

TEST(BuiltinScenes, OverlapHasInterpenetratingTriangles) {
  // Some pixel's depth test fails (triangles overlap) and both of two triangles win somewhere
  // inside their common area: the depth planes cross.
  Profile p;
  p.width = 160;
  p.height = 120;
  struct Winners : FragmentSink {
    std::vector<int64_t> last_pass;  // per pixel: triangle of the last passing fragment
    std::vector<uint8_t> covered_by;  // bit per triangle 0..7
    explicit Winners(size_t n) : last_pass(n, -1), covered_by(n, 0) {}
    int width = 160;
    void on_fragment(const Fragment& f) override {
      const size_t a = size_t(f.y) * size_t(width) + size_t(f.x);
      covered_by[a] |= uint8_t(1u << f.tri);
      if (f.pass) last_pass[a] = f.tri;
    }
  } winners(size_t(p.width * p.height));
  Pipeline pipeline(p);
  pipeline.set_fragment_sink(&winners);
  for (const ScreenTriangle& t : find_builtin_scene("overlap")->generate(p)) pipeline.submit(snap(t, p));
  EXPECT_GT(pipeline.stats().depth_fail, 0);
  // Triangles 0 and 1: in pixels both cover, each is the winner somewhere.
  bool zero_wins = false, one_wins = false;
  for (size_t a = 0; a < winners.last_pass.size(); ++a) {
    if ((winners.covered_by[a] & 3) != 3) continue;
    const uint8_t later = uint8_t(winners.covered_by[a] & ~3u);
    if (later) continue;  // only pixels decided between 0 and 1
    zero_wins |= winners.last_pass[a] == 0;
    one_wins |= winners.last_pass[a] == 1;
  }
  EXPECT_TRUE(zero_wins);
  EXPECT_TRUE(one_wins);
}

TEST(BuiltinScenes, FanCoversEveryPixelCentreOnceWithMixedWinding) {
  for (const Profile& base : screen_sizes()) {
    // Cells of several pixels: snapping cannot fold the mesh.
    if (base.width < 64 || base.height < 48 || base.width * int64_t(base.height) > 1000000) continue;
    for (Traversal traversal : {Traversal::BBox, Traversal::Span}) {
      Profile p = base;
      p.traversal = traversal;
      p.depth_func = DepthFunc::Always;
      struct Count : FragmentSink {
        std::vector<int> hits;
        int width;
        void on_fragment(const Fragment& f) override { ++hits[size_t(f.y) * size_t(width) + size_t(f.x)]; }
      } count;
      count.hits.assign(size_t(p.width) * size_t(p.height), 0);
      count.width = p.width;
      Pipeline pipeline(p);
      pipeline.set_fragment_sink(&count);
      int positive_area = 0, negative_area = 0;
      for (const ScreenTriangle& t : find_builtin_scene("fan")->generate(p)) {
        const double area2 = (t.v[1].x - t.v[0].x) * (t.v[2].y - t.v[0].y) - (t.v[2].x - t.v[0].x) * (t.v[1].y - t.v[0].y);
        (area2 > 0 ? positive_area : negative_area) += 1;
        pipeline.submit(snap(t, p));
      }
      EXPECT_GT(positive_area, 0);
      EXPECT_GT(negative_area, 0);
      for (size_t a = 0; a < count.hits.size(); ++a)
        ASSERT_EQ(count.hits[a], 1) << "pixel " << a % size_t(p.width) << "," << a / size_t(p.width) << " of "
                                    << p.width << "x" << p.height << " S=" << p.subpixel_bits;
    }
  }
}

TEST(BuiltinScenes, RandomTrianglesDependOnTheSeedOnly) {
  Profile p;
  const auto a = random_triangles(100, 2, 24, 42, p);
  EXPECT_TRUE(same_triangles(a, random_triangles(100, 2, 24, 42, p)));
  EXPECT_FALSE(same_triangles(a, random_triangles(100, 2, 24, 43, p)));
  for (const ScreenTriangle& t : a) {
    const double xs[] = {t.v[0].x, t.v[1].x, t.v[2].x}, ys[] = {t.v[0].y, t.v[1].y, t.v[2].y};
    EXPECT_LE(*std::max_element(xs, xs + 3) - *std::min_element(xs, xs + 3), 24.0);
    EXPECT_LE(*std::max_element(ys, ys + 3) - *std::min_element(ys, ys + 3), 24.0);
  }
}

std::string load_error(const std::string& path, const std::string& scene) {
  try {
    load_input(path, scene, Profile{});
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(LoadInput, DispatchesScenesAndRejectsWhatItCannotRead) {
  Profile p;
  EXPECT_TRUE(same_triangles(load_input("", "fan", p), find_builtin_scene("fan")->generate(p)));
  EXPECT_NE(load_error("", "nope").find("unknown scene 'nope'"), std::string::npos);
  EXPECT_NE(load_error("missing-mesh.obj", "").find("missing-mesh.obj"), std::string::npos);
  EXPECT_NE(load_error("missing-scene.json", "").find("missing-scene.json"), std::string::npos);
  EXPECT_NE(load_error("list.xyz", "").find("list.xyz: unknown input type '.xyz'"), std::string::npos);
  EXPECT_NE(load_error("a.tri", "fan").find("not both"), std::string::npos);
}

TEST(BenchSizeRange, ParsesRangesAndRejectsNonsense) {
  double lo = 0, hi = 0;
  parse_size_range("2..24", lo, hi);
  EXPECT_EQ(lo, 2.0);
  EXPECT_EQ(hi, 24.0);
  parse_size_range("8", lo, hi);
  EXPECT_EQ(lo, 8.0);
  EXPECT_EQ(hi, 8.0);
  for (const char* bad : {"", "..", "0..4", "5..2", "a..b", "1..inf", "nan", "2..3x"})
    EXPECT_THROW(parse_size_range(bad, lo, hi), InputError) << bad;
}

}  // namespace
}  // namespace rastersim
