// Model against RTL in lockstep: every fragment (order, x, y, z, colour, pass, taken cycle), every
// triangle record, the final memories and the frame counters must be equal (compare()).
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <tuple>

#include "testbench/cosim_cases.h"
#include "testbench/rtl_backend.h"

namespace rastersim::rtl {
namespace {

Profile small_profile() {
  Profile p;
  p.width = 64, p.height = 48;
  return p;
}

Profile hires_profile() {
  Profile p;
  p.subpixel_bits = 8, p.z_bits = 32;
  return p;
}

// This program's scratch folder: its own under the temporary folder, removed when the program ends
// unless a test failed (its replay files are then there to run).
const std::filesystem::path& scratch_folder() {
  struct Folder {
    std::filesystem::path path;
    Folder() {
      std::string name = (std::filesystem::temp_directory_path() / "rastersim_rtl_tests_XXXXXX").string();
      if (!mkdtemp(name.data())) throw std::runtime_error("cannot make a scratch folder in " + name);
      path = name;
    }
    ~Folder() {
      std::error_code ec;
      if (!::testing::UnitTest::GetInstance()->Failed()) std::filesystem::remove_all(path, ec);
    }
  };
  static const Folder folder;
  return folder.path;
}

std::string replay_prefix(const std::string& name) {
  std::string clean;
  for (char c : name) clean += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return (scratch_folder() / ("rastersim_replay_" + clean)).string();
}

// Runs one frame through both, fails with the first divergence and the replay command.
CosimReport check_frame(const Profile& p, const CosimCase& c, uint64_t seed) {
  RtlOptions options;
  options.seed = seed;
  CosimReport report = cosim(p, c.triangles, options, replay_prefix(c.name));
  EXPECT_TRUE(report.passed) << c.name << " (power-on seed " << seed << ", traversal " << to_string(p.traversal)
                             << ", depth_func " << to_string(p.depth_func) << ", latency " << p.memory_latency
                             << "): " << report.message();
  return report;
}

// ---- the small configuration: every depth function, both traversals, several latencies ----

class SmallRandom : public ::testing::TestWithParam<std::tuple<Traversal, DepthFunc>> {};

TEST_P(SmallRandom, MatchesModel) {
  Profile p = small_profile();
  std::tie(p.traversal, p.depth_func) = GetParam();
  int64_t fragments = 0, passes = 0, fails = 0;
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    p.memory_latency = int(1 + seed % 8);
    p.shading = seed % 3 == 0 ? Shading::Flat : Shading::Gouraud;
    p.depth_write = seed % 4 != 0;
    p.cull = CullMode(seed % 3);
    p.front_face = seed % 2 ? FrontFace::CCW : FrontFace::CW;
    // A cleared buffer at 0 or mid-range lets greater / gequal pass too.
    p.depth_clear = seed % 3 == 1 ? -1 : seed % 3 == 2 ? 0 : int64_t(p.depth_max() / 2);
    const CosimReport r = check_frame(p, random_case(p, seed * 7919 + int(p.depth_func), 60), seed);
    if (!r.passed) return;
    fragments += r.model.stats.fragments;
    passes += r.model.stats.depth_pass;
    fails += r.model.stats.depth_fail;
  }
  // The frames must exercise the datapath, not just agree on nothing.
  EXPECT_GT(fragments, 1000);
  if (p.depth_func != DepthFunc::Never) {
    EXPECT_GT(passes, 0);
  }
  if (p.depth_func != DepthFunc::Always) {
    EXPECT_GT(fails, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(
    EveryDepthFunction, SmallRandom,
    ::testing::Combine(::testing::Values(Traversal::BBox, Traversal::Span),
                       ::testing::Values(DepthFunc::Never, DepthFunc::Less, DepthFunc::Equal, DepthFunc::LEqual,
                                         DepthFunc::Greater, DepthFunc::NotEqual, DepthFunc::GEqual,
                                         DepthFunc::Always)),
    [](const auto& info) {
      return std::string(to_string(std::get<0>(info.param))) + "_" + to_string(std::get<1>(info.param));
    });

class SmallDirected : public ::testing::TestWithParam<std::tuple<Traversal, int>> {};

TEST_P(SmallDirected, MatchesModel) {
  Profile p = small_profile();
  std::tie(p.traversal, p.memory_latency) = GetParam();
  int64_t hazard_stalls = 0;
  for (const CosimCase& c : directed_cases(p)) {
    const CosimReport r = check_frame(p, c, 99);
    if (!r.passed) return;
    if (c.name == "directed hazards") hazard_stalls = r.model.stats.zbuffer.stall;
  }
  // A load in the last candidate's cycle puts two triangles' fragments in consecutive cycles: the
  // hazard case stalls at every latency.
  EXPECT_GT(hazard_stalls, 0) << "the hazard case must make the z-buffer stall";
}

INSTANTIATE_TEST_SUITE_P(BothTraversals, SmallDirected,
                         ::testing::Combine(::testing::Values(Traversal::BBox, Traversal::Span),
                                            ::testing::Values(1, 2, 8)),
                         [](const auto& info) {
                           return std::string(to_string(std::get<0>(info.param))) + "_latency" +
                                  std::to_string(std::get<1>(info.param));
                         });

// ---- the pipelined setup unit (configuration small_i2: setup_interval 2) ----

class PipelinedSetup : public ::testing::TestWithParam<std::tuple<Traversal, int>> {};

TEST_P(PipelinedSetup, MatchesModelEveryCycle) {
  Profile p = small_profile();
  p.setup_interval = 2;
  std::tie(p.traversal, p.setup_fifo_depth) = GetParam();
  ASSERT_EQ(configuration_error(p), "");
  int64_t closest = INT64_MAX, stall = 0;
  auto check = [&](const CosimCase& c, uint64_t seed) {
    const CosimReport r = check_frame(p, c, seed);
    const std::vector<TriangleRecord>& t = r.rtl.triangles;
    for (size_t i = 1; i < t.size(); ++i) closest = std::min(closest, t[i].setup_accept - t[i - 1].setup_accept);
    stall += r.rtl.stats.setup.stall;
    return r.passed;
  };
  for (const CosimCase& c : directed_cases(p))
    if (!check(c, 7)) return;
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    p.memory_latency = int(1 + seed % 8);
    p.shading = seed % 3 == 0 ? Shading::Flat : Shading::Gouraud;
    p.cull = CullMode(seed % 3);
    if (!check(random_case(p, seed * 104729, 60), seed)) return;
  }
  // Triangles do enter every interval, and the credits do hold some back.
  EXPECT_EQ(closest, 2);
  EXPECT_GT(stall, 0);
}

INSTANTIATE_TEST_SUITE_P(TraversalsAndFifoDepths, PipelinedSetup,
                         ::testing::Combine(::testing::Values(Traversal::BBox, Traversal::Span),
                                            ::testing::Values(1, 4, 16)),
                         [](const auto& info) {
                           return std::string(to_string(std::get<0>(info.param))) + "_fifo" +
                                  std::to_string(std::get<1>(info.param));
                         });

// ---- the two built product profiles ----

class BuiltProfiles : public ::testing::TestWithParam<std::tuple<int, Traversal>> {};

TEST_P(BuiltProfiles, DirectedAndRandomMatchModel) {
  Profile p = std::get<0>(GetParam()) == 0 ? Profile{} : hires_profile();
  p.traversal = std::get<1>(GetParam());
  ASSERT_EQ(configuration_error(p), "");
  for (const CosimCase& c : directed_cases(p))
    if (!check_frame(p, c, 5).passed) return;
  for (uint64_t seed = 1; seed <= 3; ++seed)
    if (!check_frame(p, random_case(p, seed, 40), seed).passed) return;
  p.memory_latency = 64;  // the deepest memory port the build supports
  check_frame(p, random_case(p, 3, 10), 3);
}

INSTANTIATE_TEST_SUITE_P(DefaultAndHires, BuiltProfiles,
                         ::testing::Combine(::testing::Values(0, 1),
                                            ::testing::Values(Traversal::BBox, Traversal::Span)),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param) == 0 ? "default_" : "hires_") +
                                  to_string(std::get<1>(info.param));
                         });

// The worked example of docs/cycle-model.md, whose numbers were computed by hand.
// The worked examples' tiny triangle (docs/cycle-model.md): it covers pixel (5, 9) only (S = 4).
SnappedTriangle one_pixel_triangle() {
  SnappedTriangle tiny;
  for (int k = 0; k < 3; ++k) tiny.v[k].z = 100;
  tiny.v[0].x = 5 * 16 + 2, tiny.v[0].y = 9 * 16 + 2;
  tiny.v[1].x = 5 * 16 + 14, tiny.v[1].y = 9 * 16 + 8;
  tiny.v[2].x = 5 * 16 + 4, tiny.v[2].y = 9 * 16 + 14;
  return tiny;
}

TEST(RtlCycles, WorkedExampleOfTheCycleModel) {
  Profile p = small_profile();
  p.memory_latency = 4;
  p.setup_interval = 0;  // the serial unit, one record at a time (configuration small_serial)
  p.setup_fifo_depth = 1;
  // Not the 16 x 12 profile of the page (no RTL is built for it): the same rules on the small
  // screen give the same event cycles apart from the widths, checked against the model here.
  const SnappedTriangle tiny = one_pixel_triangle();
  const std::vector<SnappedTriangle> tris = {tiny, tiny};
  const CosimReport r = cosim(p, tris);
  ASSERT_TRUE(r.passed) << r.message();
  // Independent of the model's sum over the program: the closed form of docs/cycle-model.md.
  const Widths w = derive_widths(p);
  const int product_bits = std::min(w.z_reg_bits, w.edge_bits);  // PB
  const int setup_cycles = 1 + 369 + 2 * w.delta_bits + 6 * w.coord_bits + 18 * (w.edge_bits + 3) + 12 * p.z_bits +
                           12 * w.guard_bits + 11 * p.subpixel_bits + 16 * product_bits;
  ASSERT_EQ(r.rtl.fragments.size(), 2u);
  EXPECT_EQ(r.rtl.triangles[0].setup_done, setup_cycles - 1);
  EXPECT_EQ(r.rtl.triangles[0].walker_load, setup_cycles);  // at the record FIFO's head
  EXPECT_EQ(r.rtl.fragments[0].cycle, setup_cycles + 1);  // load, pixel (no row cycle)
  // The one credit is held through the load and free in the next cycle.
  EXPECT_EQ(r.rtl.triangles[1].setup_accept, setup_cycles + 1);
  EXPECT_EQ(r.rtl.triangles[1].setup_done, 2 * setup_cycles);
  EXPECT_EQ(r.rtl.triangles[1].walker_load, 2 * setup_cycles + 1);
  EXPECT_EQ(r.rtl.fragments[1].cycle, 2 * setup_cycles + 2);  // no hazard: long after the write
  // Taken, read in the next cycle, written L cycles later.
  EXPECT_EQ(r.rtl.stats.cycles, r.rtl.fragments[1].cycle + 1 + p.memory_latency + 1);
}

// The pipelined unit's worked example (docs/cycle-model.md) on the small screen, setup_interval 4:
// the second copy enters one slot after the first and its fragment meets the first one's write.
TEST(RtlCycles, PipelinedSetupWorkedExample) {
  Profile p = small_profile();
  p.memory_latency = 4;
  p.setup_interval = 4;
  p.setup_fifo_depth = 2;
  const SnappedTriangle tiny = one_pixel_triangle();
  const CosimReport r = cosim(p, {tiny, tiny});
  ASSERT_TRUE(r.passed) << r.message();
  // Slots: 1 FRONT, ceil((coord_bits + 1) / 16) edge, ceil(24 / 16) = 2 numerator,
  // ceil(divider_bits / 16) divide, ceil(min(z_reg_bits, edge_bits) / 16) product.
  const Widths w = derive_widths(p);
  const int64_t latency = 4 * (1 + (w.coord_bits + 1 + 15) / 16 + 2 + (w.divider_bits + 15) / 16 +
                               (std::min(w.z_reg_bits, w.edge_bits) + 15) / 16);
  ASSERT_EQ(r.rtl.fragments.size(), 2u);
  EXPECT_EQ(r.rtl.triangles[0].setup_done, latency);
  EXPECT_EQ(r.rtl.triangles[0].walker_load, latency + 1);  // at the record FIFO's head
  EXPECT_EQ(r.rtl.fragments[0].cycle, latency + 2);  // load, pixel (no row cycle)
  EXPECT_EQ(r.rtl.triangles[1].setup_accept, 4);
  EXPECT_EQ(r.rtl.triangles[1].setup_done, 4 + latency);
  // The walker is idle after latency + 2; the record comes one slot after the first one's.
  EXPECT_EQ(r.rtl.triangles[1].walker_load, 5 + latency);
  // Offered in latency + 6 and taken at once (the first fragment was read in latency + 3); its
  // read held by the hazard until L + 1 cycles after the first's, then written L cycles later.
  EXPECT_EQ(r.rtl.fragments[1].cycle, latency + 6);
  const int64_t second_read = latency + 3 + p.memory_latency + 1;
  EXPECT_EQ(r.rtl.stats.zbuffer.stall, second_read - (latency + 7));
  EXPECT_EQ(r.rtl.stats.walker.stall, 0);
  EXPECT_EQ(r.rtl.stats.cycles, second_read + p.memory_latency + 1);
}

// ---- the harness itself can fail ----

TEST(RtlCompare, ReportsTheFirstDivergenceAsASentence) {
  Profile p = small_profile();
  const CosimCase c = random_case(p, 3, 20);
  const CosimReport r = cosim(p, c.triangles);
  ASSERT_TRUE(r.passed) << r.message();
  ASSERT_GT(r.rtl.fragments.size(), 10u);
  RtlResult bad = r.rtl;
  Fragment& f = bad.fragments[5];
  f.z ^= 1;
  const Divergence d = compare(r.model, bad);
  ASSERT_TRUE(d.found);
  EXPECT_EQ(d.triangle, f.tri);
  EXPECT_EQ(d.unit, "z_adder");
  EXPECT_EQ(d.cycle, f.cycle);
  EXPECT_EQ(d.expected, std::to_string(r.model.fragments[5].z));
  EXPECT_EQ(d.actual, std::to_string(f.z));
  EXPECT_NE(d.sentence.find("triangle " + std::to_string(f.tri)), std::string::npos) << d.sentence;

  // A setup field: reported by the setup unit in the cycle its record was in the output register.
  size_t drawn = 0;
  while (drawn < r.rtl.triangles.size() && r.rtl.triangles[drawn].status != SetupStatus::Drawn) ++drawn;
  ASSERT_LT(drawn, r.rtl.triangles.size());
  RtlResult setup = r.rtl;
  setup.setups[drawn].depth.step_x = int64_t(setup.setups[drawn].depth.step_x) + 1;
  const Divergence s = compare(r.model, setup);
  EXPECT_EQ(s.unit, "triangle_setup");
  EXPECT_EQ(s.field, "record depth_step_x");
  EXPECT_EQ(s.triangle, int64_t(drawn));
  EXPECT_EQ(s.cycle, r.model.triangles[drawn].setup_done);

  RtlResult late = r.rtl;
  late.stats.cycles += 1;
  EXPECT_EQ(compare(r.model, late).field, "frame cycles");
  RtlResult memory = r.rtl;
  memory.depth[7] ^= 4;
  EXPECT_EQ(compare(r.model, memory).field, "final depth memory word 7");
}

TEST(RtlWaveform, WritesAnFstFile) {
  Profile p = small_profile();
  RtlOptions options;
  options.wave_path = replay_prefix("waveform") + ".fst";
  std::filesystem::remove(options.wave_path);
  const CosimCase c = random_case(p, 4, 3);
  const RtlResult traced = run_rtl(p, c.triangles, options);
  EXPECT_GT(std::filesystem::file_size(options.wave_path), 1000u);
  // Tracing does not change what the RTL does.
  EXPECT_FALSE(compare(run_model(p, c.triangles), traced).found);
}

TEST(RtlReadback, PortAndDirectReadGiveTheSameMemories) {
  Profile p = small_profile();
  p.depth_clear = 12345;
  p.depth_func = DepthFunc::Always;
  const CosimCase c = random_case(p, 6, 30);
  RtlOptions port;
  port.readback_through_port = true;
  const RtlResult direct = run_rtl(p, c.triangles), through_port = run_rtl(p, c.triangles, port);
  EXPECT_EQ(direct.depth, through_port.depth);
  EXPECT_EQ(direct.color, through_port.color);
  EXPECT_FALSE(compare(run_model(p, c.triangles), through_port).found);
  // Some words written, some still cleared.
  EXPECT_GT(std::count(direct.depth.begin(), direct.depth.end(), 12345u), 0);
  EXPECT_LT(std::count(direct.depth.begin(), direct.depth.end(), 12345u), long(direct.depth.size()));
}

TEST(RtlReplay, WritesATriAndAProfileThatSnapBack) {
  Profile p = hires_profile();
  const CosimCase c = random_case(p, 8, 25);
  const std::string prefix = replay_prefix("replay_test");
  const std::string command = write_replay(prefix, p, c.triangles, 1);
  EXPECT_NE(command.find(prefix + ".tri"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(prefix + ".tri"));
  EXPECT_TRUE(std::filesystem::exists(prefix + ".json"));
  Profile loaded;
  load_profile_file(loaded, prefix + ".json");
  EXPECT_EQ(loaded.subpixel_bits, 8);
  EXPECT_EQ(loaded.z_bits, 32);
}

TEST(RtlConfigurations, RefusesAnUnbuiltProfileWithAHowTo) {
  Profile p;
  p.width = 100;
  const std::string error = configuration_error(p);
  EXPECT_NE(error.find("RASTERSIM_RTL_CONFIGS"), std::string::npos) << error;
  EXPECT_THROW(run_rtl(p, {}), std::invalid_argument);
  p = Profile{};
  p.memory_latency = 64;
  EXPECT_EQ(configuration_error(p), "");
}

}  // namespace
}  // namespace rastersim::rtl
