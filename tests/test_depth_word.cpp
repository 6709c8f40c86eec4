// The depth output stage (docs/arithmetic.md section 6): the floating-point depth word against an
// independent reading of its values, the worked example, and every fragment's word against the exact
// plane; the depth bias: a constant moves every output by exactly its LSBs, a slope bias keeps the
// output within 1 LSB of the exact plane plus the bias computed from the rules.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "model/pipeline.h"
#include "reference.h"
#include "test_util.h"

namespace rastersim {
namespace {

using test::describe;
using test::TriangleGen;

// The value of a word, read from the format's definition: exponent 0 is the mantissa itself,
// exponent e >= 1 is (1.mantissa) x 2^(e - 1 + Nm) in plane LSBs.
uint64_t word_value(uint32_t word, int z_bits, int exponent_bits) {
  const int mantissa_bits = z_bits - exponent_bits;
  const uint64_t e = word >> mantissa_bits, mantissa = word % (uint64_t(1) << mantissa_bits);
  if (e == 0) return mantissa;
  return (uint64_t(1) << (mantissa_bits + e - 1)) + (mantissa << (e - 1));
}

int plane_bits(int z_bits, int exponent_bits) {
  Profile p;
  p.z_bits = z_bits, p.depth_exponent_bits = exponent_bits;
  return p.depth_plane_bits();
}

TEST(DepthWord, EncodesEveryValueToTheLargestWordNotAboveIt) {
  for (int z_bits : {16, 17, 20, 24, 28, 32})
    for (int exponent_bits = 1; exponent_bits <= 4; ++exponent_bits) {
      const int np = plane_bits(z_bits, exponent_bits);
      if (np > 32) continue;
      SCOPED_TRACE(::testing::Message() << "z_bits " << z_bits << " Ne " << exponent_bits << " Np " << np);
      const DepthWord word(z_bits, exponent_bits);
      const uint64_t words = uint64_t(1) << z_bits;
      // Every word (or 2^16 spread over the range): values strictly increase, so integer order is
      // value order, and each word's values [value(w), value(w + 1)) encode to w.
      const uint64_t stride = std::max<uint64_t>(1, words >> 16);
      for (uint64_t w = 0; w + 1 < words; w += stride) {
        const uint64_t v = word_value(uint32_t(w), z_bits, exponent_bits);
        const uint64_t next = word_value(uint32_t(w + 1), z_bits, exponent_bits);
        ASSERT_LT(v, next) << "word " << w;
        ASSERT_EQ(word.decode(uint32_t(w)), v) << "word " << w;
        ASSERT_EQ(word.encode(v), w) << "value " << v;
        ASSERT_EQ(word.encode(next - 1), w) << "value " << next - 1;
      }
      // The top word holds the plane's largest value, 2^Np - 1.
      const uint64_t top = (uint64_t(1) << np) - 1;
      EXPECT_EQ(word.encode(top), words - 1);
      EXPECT_LE(word_value(uint32_t(words - 1), z_bits, exponent_bits), top);
      std::mt19937_64 random(uint64_t(z_bits) * 5 + uint64_t(exponent_bits));
      for (int n = 0; n < 20000; ++n) {
        const uint64_t x = random() >> (64 - np);
        const uint32_t w = word.encode(x);
        ASSERT_LE(word_value(w, z_bits, exponent_bits), x);
        if (w + 1 < words) {
          ASSERT_GT(word_value(w + 1, z_bits, exponent_bits), x);
        }
      }
    }
}

TEST(DepthWord, OneExponentBitIsTheFixedPointWord) {
  const DepthWord word(16, 1);
  for (uint64_t x = 0; x < (uint64_t(1) << 16); ++x) ASSERT_EQ(word.encode(x), x);
  EXPECT_EQ(plane_bits(16, 1), 16);
}

// docs/arithmetic.md section 6, the example.
TEST(DepthWord, TheDocumentedExample) {
  EXPECT_EQ(plane_bits(16, 4), 27);
  const DepthWord word(16, 4);
  EXPECT_EQ(word.encode(4095), 4095u);
  EXPECT_EQ(word.encode(4096), 4096u);
  EXPECT_EQ(word.encode(100000), 22634u);
  EXPECT_EQ(word.decode(22634), 100000u);
  EXPECT_EQ(word.encode((uint64_t(1) << 27) - 1), 65535u);
}

// Runs random triangles through the pipeline; `check` sees each triangle's fragments.
struct Collector : FragmentSink {
  std::vector<Fragment> fragments;
  void on_fragment(const Fragment& f) override { fragments.push_back(f); }
};

std::vector<SnappedTriangle> random_triangles(const Profile& p, uint64_t seed, int count) {
  TriangleGen gen(p, seed);
  std::vector<SnappedTriangle> out;
  for (int n = 0; n < count; ++n) out.push_back(n % 4 == 3 ? gen.sliver(p.width / 2) : gen.near_screen(40));
  return out;
}

// Every fragment's word holds the plane output X within 1 of the exact plane: value(word) <= X <
// value(word + 1), so value(word) - 1 < exact < value(word + 1) + 1.
TEST(DepthWord, EveryFragmentsWordHoldsTheExactPlane) {
  for (const auto& [z_bits, exponent_bits] : {std::pair{16, 4}, std::pair{24, 3}, std::pair{20, 2}}) {
    Profile p = test::make_profile(320, 240, 4, Traversal::Span, z_bits);
    p.depth_exponent_bits = exponent_bits;
    p.depth_func = DepthFunc::Always;
    SCOPED_TRACE(describe(p) + " Ne " + std::to_string(exponent_bits));
    Pipeline pipe(p);
    Collector sink;
    pipe.set_fragment_sink(&sink);
    int64_t checked = 0;
    for (const SnappedTriangle& t : random_triangles(p, uint64_t(z_bits), 400)) {
      sink.fragments.clear();
      pipe.submit(t);
      const uint32_t z[3] = {t.v[0].z, t.v[1].z, t.v[2].z};
      for (const Fragment& f : sink.fragments) {
        const reference::Rational exact = reference::plane_at_centre(t, z, p.subpixel_bits, f.x, f.y);
        const __int128 low = __int128(word_value(f.z, z_bits, exponent_bits)) - 1;
        const __int128 high = f.z + 1 < (uint64_t(1) << z_bits)
                                  ? __int128(word_value(f.z + 1, z_bits, exponent_bits)) + 1
                                  : (__int128(1) << p.depth_plane_bits()) + 1;
        ASSERT_TRUE(low * exact.den < exact.num && exact.num < high * exact.den)
            << describe(t) << " pixel (" << f.x << ", " << f.y << ") word " << f.z;
        ++checked;
      }
    }
    EXPECT_GT(checked, 50000);
  }
}

TEST(DepthBias, AConstantMovesEveryOutputByExactlyItsLsbs) {
  Profile p = test::make_profile(320, 240, 4, Traversal::Span, 16);
  p.depth_func = DepthFunc::Always;
  const std::vector<SnappedTriangle> triangles = random_triangles(p, 3, 300);
  auto depths = [&](int64_t constant) {
    Profile biased = p;
    biased.depth_bias_constant = constant;
    Pipeline pipe(biased);
    Collector sink;
    pipe.set_fragment_sink(&sink);
    for (const SnappedTriangle& t : triangles) pipe.submit(t);
    return sink.fragments;
  };
  const std::vector<Fragment> plain = depths(0);
  ASSERT_GT(plain.size(), 20000u);
  for (int64_t constant : {int64_t(37), int64_t(-37), int64_t(70000), int64_t(-65535)}) {
    const std::vector<Fragment> biased = depths(constant);
    ASSERT_EQ(biased.size(), plain.size());
    int64_t clamped = 0;
    for (size_t i = 0; i < plain.size(); ++i) {
      const int64_t expected = std::clamp<int64_t>(int64_t(plain[i].z) + constant, 0, p.depth_max());
      clamped += expected != int64_t(plain[i].z) + constant;
      ASSERT_EQ(biased[i].z, uint32_t(expected)) << "fragment " << i << " constant " << constant;
    }
    if (std::abs(constant) > 65535 / 2) {
      EXPECT_GT(clamped, 0);
    }
  }
}

// The bias from the rules: B = c 2^F + floor(f max(|step_x|, |step_y|) / 16) with the steps read in
// s(N+1).F, clamped to +-2^(N+F); the output lies within 1 of exact + B / 2^F, clamped.
TEST(DepthBias, ASlopeBiasKeepsTheOutputWithinOneLsbOfTheBiasedPlane) {
  for (const auto& [constant, slope] : {std::pair{0, 24}, std::pair{-5, -128}, std::pair{300, 127}, std::pair{2, 1}}) {
    Profile p = test::make_profile(320, 240, 4, Traversal::Span, 16);
    p.depth_func = DepthFunc::Always;
    p.depth_bias_constant = constant, p.depth_bias_slope = slope;
    SCOPED_TRACE(::testing::Message() << "c " << constant << " f " << slope);
    const TriangleSetup setup(p);
    const Widths w = setup.widths();
    Pipeline pipe(p);
    Collector sink;
    pipe.set_fragment_sink(&sink);
    int64_t checked = 0, moved = 0;
    for (const SnappedTriangle& t : random_triangles(p, 11, 300)) {
      sink.fragments.clear();
      pipe.submit(t);
      if (sink.fragments.empty()) continue;
      const SetupResult s = setup.run(t);
      auto held = [&](int64_t v) {  // the register's reading of a step: two's complement of z_reg_bits
        const int64_t m = int64_t(uint64_t(v) << (64 - w.z_reg_bits)) >> (64 - w.z_reg_bits);
        return m < 0 ? -__int128(m) : __int128(m);
      };
      const __int128 limit = __int128(1) << (16 + w.guard_bits);
      const __int128 steepest = std::max(held(s.depth.step_x), held(s.depth.step_y));
      __int128 bias = __int128(constant) * (__int128(1) << w.guard_bits);
      // floor(f steepest / 16) for either sign
      const __int128 product = __int128(slope) * steepest;
      bias += product >= 0 ? product / 16 : -((-product + 15) / 16);
      bias = std::clamp(bias, -limit, limit);
      const uint32_t z[3] = {t.v[0].z, t.v[1].z, t.v[2].z};
      for (const Fragment& f : sink.fragments) {
        reference::Rational exact = reference::plane_at_centre(t, z, p.subpixel_bits, f.x, f.y);
        // exact + bias / 2^F as one fraction
        exact.num = exact.num * (__int128(1) << w.guard_bits) + bias * exact.den;
        exact.den <<= w.guard_bits;
        const __int128 max = p.depth_max();
        if (exact.num <= 0) ASSERT_LE(f.z, 1u);
        else if (exact.num >= max * exact.den) ASSERT_GE(f.z, max - 1);
        else ASSERT_TRUE(reference::within_one_lsb(f.z, exact)) << describe(t) << " pixel (" << f.x << ", " << f.y << ")";
        ++checked;
      }
      moved += bias != __int128(constant) * (__int128(1) << w.guard_bits);
    }
    EXPECT_GT(checked, 20000);
    EXPECT_GT(moved, 100);  // the slope term acted on most triangles
  }
}

TEST(DepthBias, ProfileKeysReadAndRefuse) {
  Profile p;
  EXPECT_EQ(set_profile_key(p, "depth_bias_slope", "1.5"), "");
  EXPECT_EQ(p.depth_bias_slope, 24);
  EXPECT_EQ(set_profile_key(p, "depth_bias_slope", "-8"), "");
  EXPECT_EQ(p.depth_bias_slope, -128);
  EXPECT_NE(set_profile_key(p, "depth_bias_slope", "0.03"), "");
  EXPECT_NE(set_profile_key(p, "depth_bias_slope", "x"), "");
  p.depth_bias_slope = 128;
  EXPECT_FALSE(validate(p).empty());
  p = Profile{};
  p.z_bits = 24, p.depth_exponent_bits = 4;  // a 35-bit plane
  EXPECT_FALSE(validate(p).empty());
  p.depth_exponent_bits = 3;
  EXPECT_TRUE(validate(p).empty());
  EXPECT_EQ(p.depth_plane_bits(), 28);
  p.depth_bias_constant = (int64_t(1) << 28);
  EXPECT_FALSE(validate(p).empty());
  p = Profile{};
  p.depth_buffer = DepthBuffer::InverseW;
  EXPECT_FALSE(validate(p).empty());  // depth_func less
  p.depth_func = DepthFunc::Greater;
  EXPECT_TRUE(validate(p).empty());
  EXPECT_EQ(p.depth_clear_value(), 0u);
}

}  // namespace
}  // namespace rastersim
