// The SystemC system (testbench/systemc/: the verilated rastersim_core, the command FIFO and the
// z-buffer memory model) against the model, the specification: every fragment (order, position,
// depth, colour, pass, taken cycle), every triangle record and setup record, the final memories
// and every frame counter (rtl::compare), with and without the memory's stall pattern; and the
// same cycle counts from the SystemC run, the plain verilated run (rastersim_top, on-chip memory)
// and the model. All frames run in one process: the system is elaborated once and reset per frame.
#include <gtest/gtest.h>

#include <tuple>

#include "testbench/cosim_cases.h"
#include "testbench/rtl_backend.h"
#include "testbench/systemc/systemc_backend.h"

namespace rastersim {
namespace {

std::string settings(const Profile& p) {
  return std::string(to_string(p.traversal)) + ", " + to_string(p.depth_func) + ", latency " +
         std::to_string(p.memory_latency) + ", stall " + std::to_string(p.memory_stall_percent) + "% seed " +
         std::to_string(p.memory_stall_seed);
}

// Runs the frame through the model and the SystemC system and requires them to agree.
rtl::RtlResult expect_agreement(const Profile& p, const rtl::CosimCase& c) {
  const rtl::RtlResult model = rtl::run_model(p, c.triangles);
  const rtl::RtlResult sc = systemc::run_systemc(p, c.triangles);
  const rtl::Divergence d = rtl::compare(model, sc);
  EXPECT_FALSE(d.found) << c.name << " (" << settings(p) << "): " << d.sentence;
  EXPECT_EQ(sc.stats.cycles, model.stats.cycles) << c.name;
  return model;
}

class SystemcRandom : public ::testing::TestWithParam<std::tuple<Traversal, int>> {};

TEST_P(SystemcRandom, EqualsTheModelWithAndWithoutStalls) {
  Profile p = systemc::built_geometry();
  const auto [traversal, latency] = GetParam();
  p.traversal = traversal;
  p.memory_latency = latency;
  for (uint64_t seed = 1; seed <= 2; ++seed) {
    p.depth_func = seed == 1 ? DepthFunc::Less : DepthFunc::LEqual;
    const rtl::CosimCase c = rtl::random_case(p, seed * 131 + uint64_t(latency), 30);
    p.memory_stall_percent = 0;
    const rtl::RtlResult plain = expect_agreement(p, c);
    p.memory_stall_percent = 30;
    p.memory_stall_seed = int(seed);
    const rtl::RtlResult stalled = expect_agreement(p, c);
    // The pattern must bite: the same frame takes longer and its fragments wait.
    EXPECT_GT(plain.stats.fragments, 100);
    EXPECT_GT(stalled.stats.cycles, plain.stats.cycles);
    EXPECT_GT(stalled.stats.zbuffer.stall, plain.stats.zbuffer.stall);
    EXPECT_EQ(stalled.depth, plain.depth);
    EXPECT_EQ(stalled.color, plain.color);
  }
}

INSTANTIATE_TEST_SUITE_P(TraversalsAndLatencies, SystemcRandom,
                         ::testing::Combine(::testing::Values(Traversal::BBox, Traversal::Span),
                                            ::testing::Values(1, 4, 7)),
                         [](const auto& info) {
                           return std::string(to_string(std::get<0>(info.param))) + "_latency" +
                                  std::to_string(std::get<1>(info.param));
                         });

// Every directed frame (ties, hazards, off-screen, degenerate, long rows, every depth function)
// under a heavy stall pattern: hazards and back-pressure together.
TEST(SystemcDirected, EqualsTheModelUnderAHeavyStallPattern) {
  Profile p = systemc::built_geometry();
  p.memory_latency = 3;
  p.memory_stall_percent = 60;
  p.memory_stall_seed = 12345;
  for (const rtl::CosimCase& c : rtl::directed_cases(p)) expect_agreement(p, c);
}

// The same frames through the SystemC system, the plain verilated RTL and the model: equal cycles
// (and every other field: compare()).
TEST(SystemcThreeWay, CyclesOfSystemcPlainVerilatedAndModelAgree) {
  Profile p = systemc::built_geometry();
  ASSERT_EQ(rtl::configuration_error(p), "") << "the SystemC geometry is one of the plain verilated configurations";
  for (Traversal traversal : {Traversal::BBox, Traversal::Span}) {
    for (int latency : {2, 8}) {
      p.traversal = traversal;
      p.memory_latency = latency;
      const rtl::CosimCase c = rtl::random_case(p, 77 + uint64_t(latency), 25);
      const rtl::RtlResult model = rtl::run_model(p, c.triangles);
      const rtl::RtlResult sc = systemc::run_systemc(p, c.triangles);
      const rtl::RtlResult plain = rtl::run_rtl(p, c.triangles);
      EXPECT_EQ(sc.stats.cycles, model.stats.cycles) << settings(p);
      EXPECT_EQ(plain.stats.cycles, model.stats.cycles) << settings(p);
      const rtl::Divergence d_sc = rtl::compare(model, sc), d_plain = rtl::compare(model, plain);
      EXPECT_FALSE(d_sc.found) << "SystemC: " << d_sc.sentence;
      EXPECT_FALSE(d_plain.found) << "plain verilated: " << d_plain.sentence;
      EXPECT_GT(model.stats.cycles, 1000);
    }
  }
}

TEST(SystemcConfiguration, RefusesAnotherGeometryAndSaysWhatIsBuilt) {
  Profile p = systemc::built_geometry();
  EXPECT_EQ(systemc::configuration_error(p), "");
  p.width += 1;
  const std::string error = systemc::configuration_error(p);
  EXPECT_NE(error.find(systemc::built_configuration()), std::string::npos) << error;
  EXPECT_THROW(systemc::run_systemc(p, {}), std::invalid_argument);
}

}  // namespace
}  // namespace rastersim
