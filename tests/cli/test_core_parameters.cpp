// One mapping from a profile to rastersim_core's build parameters (model/core_parameters.h) feeds
// every consumer (docs/rtl.md "The profile in the RTL"): a profile with every build parameter at a
// non-default value goes through each, and each gives the list written out by hand below.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "cli/hw_cost.h"
#include "cli_test_support.h"
#include "model/core_parameters.h"
#ifdef RASTERSIM_HAVE_RTL
#include "testbench/modules.h"
#include "testbench/rtl_backend.h"
#endif

namespace rastersim {
namespace {

using cli_test::read_text;
using cli_test::run_rastersim;
using cli_test::ScratchDir;

}  // namespace

// gtest prints a mismatching list as NAME=value.
void PrintTo(const CoreParameter& c, std::ostream* out) { *out << c.name << "=" << c.value; }

namespace {

// Every build parameter away from its default in rtl/rastersim_core.sv and in Profile{}.
Profile unusual_profile() {
  Profile p;
  p.width = 48;
  p.height = 40;
  p.subpixel_bits = 5;
  p.z_bits = 20;
  p.z_guard_bits = 9;
  p.memory_latency = 5;
  p.setup_fifo_depth = 3;
  p.setup_interval = 8;
  p.texture_unit = true;
  p.texture_latency = 7;
  p.depth_exponent_bits = 2;
  p.depth_bias_constant = 3;
  p.pixel_center = PixelCenter::Corner;
  p.fill_rule = FillRule::BottomLeft;
  p.depth_rounding = Rounding::Truncate;
  p.color_rounding = Rounding::Truncate;
  return p;
}

// The same profile as flags.
const std::vector<std::string> kUnusualFlags = {
    "--width", "48", "--height", "40", "--subpixel-bits", "5", "--z-bits", "20", "--z-guard-bits", "9",
    "--memory-latency", "5", "--setup-fifo-depth", "3", "--setup-interval", "8", "--texture-unit", "true",
    "--texture-latency", "7", "--depth-exponent-bits", "2", "--depth-bias-constant", "3",
    "--pixel-center", "corner", "--fill-rule", "bottom_left", "--depth-rounding", "truncate",
    "--color-rounding", "truncate"};

// Written out by hand from rtl/rastersim_core_parameters.vh's list and the rules of docs/rtl.md.
const CoreParameters kExpected = {
    {"WIDTH", 48},           {"HEIGHT", 40},         {"SUBPIXEL_BITS", 5},       {"Z_BITS", 20},
    {"Z_GUARD_BITS", 9},     {"DEPTH_EXPONENT_BITS", 2}, {"DEPTH_BIAS", 1},      {"MAX_MEMORY_LATENCY", 5},
    {"MAX_SETUP_FIFO_DEPTH", 3}, {"SETUP_INTERVAL", 8}, {"TEXTURE", 1},         {"MAX_TEXTURE_LATENCY", 7},
    {"PIXEL_CENTER", 1},     {"FILL_RULE", 2},           {"DEPTH_ROUNDING", 1},      {"COLOR_ROUNDING", 1}};

std::vector<std::string> names_of(const CoreParameters& parameters) {
  std::vector<std::string> names;
  for (const CoreParameter& c : parameters) names.push_back(c.name);
  return names;
}

TEST(CoreParameters, TheMappingGivesEveryParameterInTheCoresOrder) {
  EXPECT_EQ(core_parameters(unusual_profile()), kExpected);
  // The largest bounds change only the run-time bounds.
  CoreParameters largest = kExpected;
  for (CoreParameter& c : largest) {
    if (c.name == "MAX_MEMORY_LATENCY" || c.name == "MAX_TEXTURE_LATENCY") c.value = 64;
    if (c.name == "MAX_SETUP_FIFO_DEPTH") c.value = 16;
  }
  EXPECT_EQ(core_parameters(unusual_profile(), CoreBounds::Largest), largest);
  // One exponent bit is the fixed-point word; a bias of 0 needs no bias stage.
  Profile p = unusual_profile();
  p.depth_exponent_bits = 1;
  p.depth_bias_constant = 0;
  EXPECT_EQ(parameter_value(core_parameters(p), "DEPTH_EXPONENT_BITS"), 0);
  EXPECT_EQ(parameter_value(core_parameters(p), "DEPTH_BIAS"), 0);
  EXPECT_EQ(parse_core_parameters(core_parameters_text(kExpected, ",")), kExpected);
  EXPECT_THROW(parse_core_parameters("WIDTH=64,COLOUR=3"), std::invalid_argument);
  EXPECT_THROW(parse_core_parameters("WIDTH=6x4"), std::invalid_argument);
}

TEST(CoreParameters, ACoreRunsAProfileWhenEveryParameterFits) {
  const Profile p = unusual_profile();
  EXPECT_EQ(core_mismatch(kExpected, p), "");
  EXPECT_EQ(core_mismatch(core_parameters(p, CoreBounds::Largest), p), "") << "larger bounds run it";
  CoreParameters other = kExpected;
  other[9].value = 4;  // SETUP_INTERVAL
  EXPECT_NE(core_mismatch(other, p).find("SETUP_INTERVAL is 4"), std::string::npos) << core_mismatch(other, p);
  other = kExpected;
  other[7].value = 4;  // MAX_MEMORY_LATENCY below the profile's 5
  EXPECT_NE(core_mismatch(other, p).find("MAX_MEMORY_LATENCY"), std::string::npos);
  // Z_GUARD_BITS 0 derives the guard bits: 48 x 40 derives ceil(log2(2 * 87)) = 8, so an explicit 8
  // is the same core and 9 is not.
  Profile derived = p;
  derived.z_guard_bits = 8;
  other = kExpected;
  other[4].value = 0;
  EXPECT_EQ(core_mismatch(other, derived), "");
  EXPECT_NE(core_mismatch(other, p), "");
}

TEST(CoreParameters, EveryConsumerTakesTheSameList) {
  const Profile p = unusual_profile();
  // hw-cost's chparam list.
  EXPECT_EQ(hardware_parameters(p), core_parameters_text(kExpected));
  // rastersim profile --core-parameters, from the same profile as flags.
  ScratchDir dir;
  std::vector<std::string> args = {"profile", "--core-parameters"};
  args.insert(args.end(), kUnusualFlags.begin(), kUnusualFlags.end());
  const cli_test::RunResult printed = run_rastersim(dir, args);
  ASSERT_EQ(printed.exit_code, 0) << printed.err;
  EXPECT_EQ(printed.out, core_parameters_text(kExpected, "\n") + "\n");
  // The FuseSoC core declares them and its lint target passes them, in the same order.
  const std::string core_file = read_text(RASTERSIM_SOURCE_DIR "/rastersim.core");
  std::vector<std::string> declared;
  const std::regex declaration("\n  ([A-Z_]+): \\{datatype: int, paramtype: vlogparam");
  for (std::sregex_iterator it(core_file.begin(), core_file.end(), declaration), end; it != end; ++it)
    declared.push_back((*it)[1]);
  EXPECT_EQ(declared, names_of(kExpected));
  // The RTL's one declaration (rtl/rastersim_core_parameters.vh), which rastersim_core, rastersim_top,
  // scripts/hw_cost.py (tests/hw_cost) and the build's read-back of verilated cores take: the
  // declarations and the pass-through list name them in the same order.
  const std::string vh = read_text(RASTERSIM_SOURCE_DIR "/rtl/rastersim_core_parameters.vh");
  const size_t passed_at = vh.find("`define RASTERSIM_CORE_PARAMETERS_PASSED");
  ASSERT_NE(passed_at, std::string::npos);
  std::vector<std::string> vh_declared, vh_passed;
  const std::regex vh_declaration("parameter integer ([A-Z0-9_]+) = "), pass("\\.([A-Z0-9_]+)\\(([A-Z0-9_]+)\\)");
  const std::string declarations = vh.substr(0, passed_at), passes = vh.substr(passed_at);
  for (std::sregex_iterator it(declarations.begin(), declarations.end(), vh_declaration), end; it != end; ++it)
    vh_declared.push_back((*it)[1]);
  for (std::sregex_iterator it(passes.begin(), passes.end(), pass), end; it != end; ++it) {
    EXPECT_EQ((*it)[1], (*it)[2]);
    vh_passed.push_back((*it)[1]);
  }
  EXPECT_EQ(vh_declared, names_of(kExpected));
  EXPECT_EQ(vh_passed, names_of(kExpected));
#ifdef RASTERSIM_HAVE_RTL
  // A vector package's manifest.
  // (vector packages are built with the RTL backend)
  args = {"vectors", "--random", "2", "--seed", "3", "--out", "package"};
  args.insert(args.end(), kUnusualFlags.begin(), kUnusualFlags.end());
  const cli_test::RunResult vectors = run_rastersim(dir, args);
  ASSERT_EQ(vectors.exit_code, 0) << vectors.err;
  const nlohmann::ordered_json manifest = nlohmann::ordered_json::parse(read_text(dir.path("package/manifest.json")));
  CoreParameters in_manifest;
  for (auto it = manifest["rtl"]["parameters"].begin(); it != manifest["rtl"]["parameters"].end(); ++it)
    in_manifest.push_back({it.key(), it->get<int64_t>()});
  EXPECT_EQ(in_manifest, kExpected);
  // The modules built on demand: the same list with the largest run-time bounds.
  EXPECT_EQ(modules::module_parameters(p), core_parameters(p, CoreBounds::Largest));
  // The cores built in: each read back from its verilated P_* constants, named as the mapping names.
  for (const std::string& built : rtl::built_configurations()) {
    const std::string list = built.substr(built.find(": ") + 2);
    std::vector<std::string> names;
    std::istringstream words(list);
    for (std::string kv; words >> kv;) names.push_back(kv.substr(0, kv.find('=')));
    EXPECT_EQ(names, names_of(kExpected)) << built;
  }
  // The default profile runs on the built default core.
  EXPECT_EQ(rtl::configuration_error(Profile{}), "");
#endif
}

}  // namespace
}  // namespace rastersim
