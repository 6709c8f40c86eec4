// Absolute form = incremental form (docs/arithmetic.md, section 3): at every fragment the walker's
// depth and colour REGISTERS (before rounding) equal
//   P(x, y) = start + (x - x0) step_x + (y - y0) step_y
// computed in 128 bits and reduced to the register width, bit for bit, for both traversals; and
// the outputs are the rounded, clamped register values. The walker is driven directly with a sink
// that reads the registers.
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <tuple>

#include "model/scanline_walker.h"
#include "model/triangle_setup.h"
#include "model/z_adder.h"
#include "reference.h"
#include "test_util.h"

namespace rastersim {
namespace {

using i128 = __int128;

// v modulo 2^bits in the two's-complement range [-2^(bits-1), 2^(bits-1)).
int64_t reduce_to_register(i128 v, int bits) {
  using u128 = unsigned __int128;
  const u128 low = u128(v) & ((u128(1) << bits) - 1);
  return low >= (u128(1) << (bits - 1)) ? int64_t(i128(low) - (i128(1) << bits)) : int64_t(low);
}

struct RegisterSink {
  const SetupResult* setup = nullptr;
  Widths widths{};
  int z_bits = 0;
  bool gouraud = true;
  int64_t fragments = 0;
  std::string first_error;

  int64_t fragment(int x, int y, const ZAdder& adders, int64_t cycle) {
    ++fragments;
    if (first_error.empty()) check(x, y, adders);
    return cycle;
  }

  void check(int x, int y, const ZAdder& adders) {
    auto fail = [&](const std::string& what, int64_t model, int64_t expected) {
      first_error = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): " + what + " is " +
                    std::to_string(model) + ", expected " + std::to_string(expected);
    };
    const int64_t depth = reduce_to_register(reference::absolute_plane(setup->depth, *setup, x, y), widths.z_reg_bits);
    if (adders.depth_register().value() != depth) return fail("depth register", adders.depth_register().value(), depth);
    const int64_t depth_out = reference::rounded_plane_output(depth, widths.guard_bits, (int64_t(1) << z_bits) - 1);
    if (adders.depth() != depth_out) return fail("depth output", adders.depth(), depth_out);
    if (!gouraud) return;
    const Rgb color = adders.color();
    const uint8_t outputs[3] = {color.r, color.g, color.b};
    for (int c = 0; c < 3; ++c) {
      const int64_t value = reduce_to_register(reference::absolute_plane(setup->color[c], *setup, x, y), widths.color_reg_bits);
      if (adders.color_register(c).value() != value)
        return fail("colour register " + std::to_string(c), adders.color_register(c).value(), value);
      const int64_t out = reference::rounded_plane_output(value, widths.guard_bits, 255);
      if (outputs[c] != out) return fail("colour output " + std::to_string(c), outputs[c], out);
    }
  }
};

struct Case {
  int width, height, subpixel_bits, z_bits, z_guard_bits;
};
void PrintTo(const Case& c, std::ostream* out) {
  *out << c.width << "x" << c.height << " S=" << c.subpixel_bits << " N=" << c.z_bits << " z_guard_bits=" << c.z_guard_bits;
}

class AbsoluteForm : public ::testing::TestWithParam<std::tuple<Case, Traversal>> {};

TEST_P(AbsoluteForm, RegistersEqualTheAbsoluteFormBitForBit) {
  const auto [c, traversal] = GetParam();
  Profile p = test::make_profile(c.width, c.height, c.subpixel_bits, traversal, c.z_bits);
  p.z_guard_bits = c.z_guard_bits;
  const uint64_t seed = uint64_t(c.width) * 7 + uint64_t(c.z_guard_bits) + uint64_t(traversal);
  SCOPED_TRACE(::testing::Message() << test::describe(p) << " z_guard_bits " << p.z_guard_bits << " seed " << seed);
  const TriangleSetup setup(p);
  const ScanlineWalker walker(p, setup.widths());
  ZAdder adders(setup.widths(), p);  // make_profile: Gouraud
  RegisterSink sink;
  sink.widths = setup.widths();
  sink.z_bits = p.z_bits;
  test::TriangleGen gen(p, seed);
  const int64_t M = gen.M(), W = int64_t(p.width) * M, H = int64_t(p.height) * M;
  int64_t fragments = 0;
  int drawn = 0;
  auto run = [&](const SnappedTriangle& t) {
    const SetupResult s = setup.run(t);
    if (s.status != SetupStatus::Drawn) return;
    ++drawn;
    sink.setup = &s;
    sink.fragments = 0;
    sink.first_error.clear();
    WalkerCounters counters;
    walker.walk(s, adders, 0, true, sink, counters);
    ASSERT_EQ(sink.first_error, "") << test::describe(t);
    fragments += sink.fragments;
  };
  for (int n = 0; n < 300; ++n) run(gen.near_screen(std::max(4, c.width / 16)));
  for (int n = 0; n < 300; ++n) run(gen.tiny());
  for (int n = 0; n < 100; ++n) run(gen.sliver(std::max<int>(c.width, c.height)));
  // Far bounding-box starts: anti-diagonal slivers across the whole screen.
  for (int n = 0; n < 3; ++n)
    run(gen.triangle(W - gen.uniform(0, M), gen.uniform(0, M), gen.uniform(0, M), H - gen.uniform(0, M),
                     W / 2 + gen.uniform(1, 3 * M), H / 2 + gen.uniform(1, 3 * M)));
  for (int n = 0; n < 2; ++n) run(gen.guard_band());
  EXPECT_GT(drawn, 300);
  EXPECT_GT(fragments, 1000);
}

INSTANTIATE_TEST_SUITE_P(
    Profiles, AbsoluteForm,
    ::testing::Combine(::testing::Values(Case{4096, 4096, 8, 32, 0}, Case{4096, 4096, 8, 32, 24}, Case{64, 48, 4, 16, 0},
                                         Case{640, 480, 4, 24, 0}, Case{1000, 700, 1, 20, 3}),
                       ::testing::Values(Traversal::BBox, Traversal::Span)),
    [](const auto& info) {
      const Case& c = std::get<0>(info.param);
      return std::to_string(c.width) + "x" + std::to_string(c.height) + "_S" + std::to_string(c.subpixel_bits) + "_N" +
             std::to_string(c.z_bits) + "_F" + std::to_string(c.z_guard_bits) + "_" +
             to_string(std::get<1>(info.param));
    });

}  // namespace
}  // namespace rastersim
