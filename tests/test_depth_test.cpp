// The depth test (docs/arithmetic.md section 5): for every compare function, depth
// write on and off and several clear values, the pass flag of every fragment and the final depth
// and colour buffers equal a brute-force z-buffer computed here from the reference coverage, the
// fragments' z values and the provoking vertex's flat colour.
#include <gtest/gtest.h>

#include <map>
#include <tuple>

#include "model/pipeline.h"
#include "reference.h"
#include "test_util.h"

namespace rastersim {
namespace {

using test::describe;

// The compare functions as docs/formats.md names them: the fragment's z against the stored z.
bool passes(DepthFunc f, uint32_t z, uint32_t stored) {
  switch (f) {
    case DepthFunc::Never: return false;
    case DepthFunc::Less: return z < stored;
    case DepthFunc::Equal: return z == stored;
    case DepthFunc::LEqual: return z <= stored;
    case DepthFunc::Greater: return z > stored;
    case DepthFunc::NotEqual: return z != stored;
    case DepthFunc::GEqual: return z >= stored;
    case DepthFunc::Always: return true;
  }
  ADD_FAILURE() << "unknown depth function";
  return false;
}

uint32_t packed(Rgb c) { return (uint32_t(c.r) << 16) | (uint32_t(c.g) << 8) | c.b; }

class DepthTest : public ::testing::TestWithParam<std::tuple<DepthFunc, bool>> {};

TEST_P(DepthTest, BuffersEqualABruteForceZBuffer) {
  const auto [func, write] = GetParam();
  for (int64_t clear : {int64_t(-1), int64_t(0), int64_t(1) << 15}) {
    Profile p = test::make_profile(40, 32, 4, Traversal::Span, 16);
    p.depth_func = func;
    p.depth_write = write;
    p.depth_clear = clear;
    p.shading = Shading::Flat;
    const uint64_t seed = 11 * uint64_t(func) + 3 * uint64_t(write) + uint64_t(clear & 7);
    SCOPED_TRACE(::testing::Message() << describe(p) << " depth_write " << write << " depth_clear " << clear << " seed "
                                      << seed);
    test::TriangleGen gen(p, seed);
    // Constant-depth triangles from a few levels (their z is known exactly, and equal depths meet),
    // and sloped ones.
    const uint32_t levels[] = {0, 1000, 20000, 20000, 32768, 40000, p.depth_max()};
    std::vector<SnappedTriangle> scene;
    std::vector<int64_t> constant_z;  // -1 for sloped triangles
    for (int n = 0; n < 60; ++n) {
      SnappedTriangle t = n % 5 == 0 ? gen.guard_band() : n % 5 == 1 ? gen.tiny() : gen.near_screen(16);
      if (n % 2) t = test::reversed(t);  // the flat colour stays the first vertex's
      int64_t z = -1;
      if (n % 3 != 0) {
        z = levels[gen.uniform(0, 6)];
        for (SnappedVertex& v : t.v) v.z = uint32_t(z);
      }
      scene.push_back(t);
      constant_z.push_back(z);
    }
    Pipeline pipe(p);
    test::FragmentLog log;
    pipe.set_fragment_sink(&log);
    for (const SnappedTriangle& t : scene) pipe.submit(t);

    // Brute force over the reference coverage, taking each fragment's z from the trace.
    const size_t pixels = size_t(p.width) * p.height;
    std::vector<uint32_t> depth(pixels, clear < 0 ? p.depth_max() : uint32_t(clear)), color(pixels, 0);
    size_t next = 0;
    int64_t passed = 0, failed = 0;
    for (size_t n = 0; n < scene.size(); ++n) {
      for (const reference::Pixel& px : reference::covered_pixels(scene[n], p)) {
        ASSERT_LT(next, log.fragments.size()) << "triangle " << n;
        const Fragment& f = log.fragments[next++];
        ASSERT_TRUE(f.tri == int64_t(n) && f.x == px.x && f.y == px.y)
            << "fragment " << next - 1 << " is (tri " << f.tri << ", " << f.x << ", " << f.y << "), expected (tri "
            << n << ", " << px.x << ", " << px.y << ")";
        if (constant_z[n] >= 0) {
          ASSERT_EQ(f.z, uint32_t(constant_z[n])) << "a constant plane is exact";
        }
        ASSERT_EQ(f.color, scene[n].v[0].color) << "flat colour is the provoking vertex's";
        const size_t a = size_t(px.y) * p.width + px.x;
        const bool pass = passes(func, f.z, depth[a]);
        ASSERT_EQ(f.pass, pass) << "fragment " << next - 1 << " at (" << px.x << ", " << px.y << ") z " << f.z
                                << " stored " << depth[a];
        if (pass) {
          color[a] = packed(scene[n].v[0].color);
          if (write) depth[a] = f.z;
        }
        passed += pass;
        failed += !pass;
      }
    }
    ASSERT_EQ(next, log.fragments.size());
    EXPECT_TRUE(pipe.zbuffer().depth() == depth) << "final depth buffer differs";
    EXPECT_TRUE(pipe.zbuffer().color() == color) << "final colour buffer differs";
    const FrameStats& stats = pipe.stats();
    EXPECT_EQ(stats.depth_pass, passed);
    EXPECT_EQ(stats.depth_fail, failed);
    // Each function must see both outcomes where they are possible: nothing is greater than a
    // clear of 2^N - 1 or less than a clear of 0, and without depth writes nothing fails
    // gequal against 0 or lequal against 2^N - 1.
    const bool cannot_pass = func == DepthFunc::Never || (func == DepthFunc::Greater && clear < 0) ||
                             (func == DepthFunc::Less && clear == 0);
    const bool cannot_fail = func == DepthFunc::Always || (!write && func == DepthFunc::GEqual && clear == 0) ||
                             (!write && func == DepthFunc::LEqual && clear < 0);
    EXPECT_EQ(passed == 0, cannot_pass);
    EXPECT_EQ(failed == 0, cannot_fail);
  }
}

INSTANTIATE_TEST_SUITE_P(
    FunctionsAndWrite, DepthTest,
    ::testing::Combine(::testing::Values(DepthFunc::Never, DepthFunc::Less, DepthFunc::Equal, DepthFunc::LEqual,
                                         DepthFunc::Greater, DepthFunc::NotEqual, DepthFunc::GEqual, DepthFunc::Always),
                       ::testing::Bool()),
    [](const auto& info) {
      return std::string(to_string(std::get<0>(info.param))) + (std::get<1>(info.param) ? "_write" : "_nowrite");
    });

// The default clear value is 2^N - 1 for every depth width, and a fresh buffer's colour is 0.
TEST(DepthClear, DefaultIsAllOnesAndColourZero) {
  for (int z_bits : {16, 20, 24, 31, 32}) {
    Profile p = test::make_profile(8, 4, 4, Traversal::Span, z_bits);
    Pipeline pipe(p);
    for (uint32_t d : pipe.zbuffer().depth()) ASSERT_EQ(uint64_t(d), (uint64_t(1) << z_bits) - 1) << z_bits;
    for (uint32_t c : pipe.zbuffer().color()) ASSERT_EQ(c, 0u);
  }
}

}  // namespace
}  // namespace rastersim
