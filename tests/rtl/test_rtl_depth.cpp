// The Z adder's depth output stage in the RTL (configuration small_depth: 64 x 48, setup_interval 64,
// the floating-point depth word with 3 exponent bits, the depth bias) against the model in lockstep:
// random frames draw the bias's constant and slope factor with the runtime settings; every fragment's
// depth word and cycle, every setup record of the 28-bit depth plane, the final memories and the
// counters must be equal.
#include <gtest/gtest.h>

#include <cstdint>

#include "testbench/cosim_cases.h"
#include "testbench/rtl_backend.h"

namespace rastersim::rtl {
namespace {

Profile depth_profile() {
  Profile p;
  p.width = 64, p.height = 48;
  p.setup_interval = 64;
  p.depth_exponent_bits = 3;
  p.depth_bias_slope = 16;  // biased: the configuration with the depth bias
  return p;
}

TEST(RtlDepth, FloatingPointWordAndBiasMatchTheModelEveryCycle) {
  const Profile base = depth_profile();
  ASSERT_EQ(configuration_error(base), "");
  const CosimPlan plan(base, {}, 8, 20261128, 40, false);
  int64_t biased = 0, extreme = 0, float_words = 0, fragments = 0;
  for (int64_t k = 0; k < 16; ++k) {
    const CosimCase c = plan.frame(k);
    RtlOptions options;
    options.seed = uint64_t(k) + 1;
    const CosimReport r = cosim(c.profile, c.triangles, options);
    ASSERT_TRUE(r.passed) << c.name << " (bias " << c.profile.depth_bias_constant << ", slope "
                          << c.profile.depth_bias_slope << "/16): " << r.message();
    biased += c.profile.depth_biased();
    extreme += std::abs(c.profile.depth_bias_constant) > 1000;
    for (const Fragment& f : r.model.fragments) {
      float_words += f.z >= (uint32_t(1) << 21);
      ++fragments;
    }
  }
  // The frames reached what they are meant to: biased and unbiased frames, the constant's extremes,
  // and words with a non-zero exponent.
  EXPECT_GT(biased, 4);
  EXPECT_LT(biased, 16);
  EXPECT_GT(extreme, 0);
  EXPECT_GT(float_words, fragments / 4);
}

TEST(RtlDepth, ConfigurationsWithoutTheStageRefuseItsProfiles) {
  Profile p = depth_profile();
  p.setup_interval = 4;  // small: the fixed-point word, no bias
  EXPECT_NE(configuration_error(p).find("DEPTH_EXPONENT_BITS=3"), std::string::npos) << configuration_error(p);
  p.depth_exponent_bits = 0;
  EXPECT_NE(configuration_error(p).find("DEPTH_BIAS=1"), std::string::npos) << configuration_error(p);
  p.depth_bias_slope = 0;
  EXPECT_EQ(configuration_error(p), "");
  p.depth_exponent_bits = 1;  // the fixed-point word bit for bit
  EXPECT_EQ(configuration_error(p), "");
}

}  // namespace
}  // namespace rastersim::rtl
