// `rastersim vectors` end to end: a package from each kind of source, and exit 2 with a message
// naming the problem and nothing written for every kind of bad usage.
#include <sys/wait.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <utility>

#include "cli_test_support.h"

namespace rastersim::cli_test {
namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(CliVectors, HelpNamesEverySource) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"vectors", "--help"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  for (const char* flag : {"Usage", "--out", "--random", "--seed", "--suite", "--scene", "--rtl-path", "--force",
                           "--memory-latency"})
    EXPECT_TRUE(contains(r.out, flag)) << flag << "\n" << r.out;
  EXPECT_TRUE(dir.listing().empty());
}

// The folders are named as written in the package's run scripts: a shell command in one would run
// when anyone runs the package. Refused before anything is written (also without the RTL library).
TEST(CliVectors, ARelativePathWithShellCharactersIsRefused) {
  ScratchDir dir;
  for (const std::string option : {"--rtl-path", "--testbench-path"})
    for (const std::string path : {"$(touch X)rtl", "`touch X`", "rtl; touch X", "a b", "rtl\ntouch X"}) {
      const RunResult r = run_rastersim(dir, {"vectors", "--random", "1", "--width", "32", "--height", "24", "--out",
                                              "pkg", option, path});
      EXPECT_EQ(r.exit_code, 2) << option << " " << path << ": " << r.err;
      EXPECT_TRUE(contains(r.err, option + " '") && contains(r.err, "only letters, digits and / . _ - + may name"))
          << r.err;
      EXPECT_TRUE(dir.listing().empty()) << option << " " << path;
    }
}

#ifdef RASTERSIM_HAVE_RTL

TEST(CliVectors, WritesAPackageFromEachSource) {
  ScratchDir dir;
  dir.write("two.tri", "0 0 0.5 10 0 0.5 0 10 0.5\n2 2 0.25 14 3 0.75 4 11 0.5 0 255 0\n");
  const std::vector<std::vector<std::string>> sources = {
      {"two.tri"}, {"--scene", "fan"}, {"--random", "5", "--seed", "3"}, {"--suite", "rules"}, {"--suite", "depth"}};
  int n = 0;
  for (const std::vector<std::string>& source : sources) {
    const std::string out = "pkg" + std::to_string(n++);
    std::vector<std::string> args = {"vectors", "--width", "32", "--height", "24", "--out", out};
    args.insert(args.end(), source.begin(), source.end());
    const RunResult r = run_rastersim(dir, args);
    ASSERT_EQ(r.exit_code, 0) << source[0] << ": " << r.err;
    EXPECT_TRUE(contains(r.out, "wrote " + out + ": ")) << r.out;
    const nlohmann::json manifest = nlohmann::json::parse(read_text(dir.path(out) / "manifest.json"));
    EXPECT_EQ(manifest["format"], "rastersim-vectors");
    EXPECT_EQ(manifest["profile"]["width"], 32);
    for (const char* file : {"commands.hex", "triangles.hex", "setup.hex", "fragments.hex", "depth.hex", "color.hex",
                             "frame.hex", "rastersim_vectors_tb.v", "rastersim_vectors_params.vh", "run_icarus.sh", "run_verilator.sh",
                             "README.md", "lint_waivers.vlt", "lint_verilator.sh", "rtl/rastersim_top.sv",
                             "rtl/lint_waivers.vlt"})
      EXPECT_TRUE(fs::exists(dir.path(out) / file)) << out << "/" << file;
    EXPECT_TRUE((fs::status(dir.path(out) / "run_icarus.sh").permissions() & fs::perms::owner_exec) != fs::perms::none);
  }
  const nlohmann::json random = nlohmann::json::parse(read_text(dir.path("pkg2") / "manifest.json"));
  EXPECT_EQ(random["source"]["count"], 5);
  EXPECT_EQ(random["source"]["seed"], 3);
  EXPECT_EQ(random["cycles"]["per_triangle"].size(), 5u);
}

// The package's checker reports a damaged manifest (no files list, a path outside the package)
// with exit 2 and a message, not a Python traceback, and does not read outside the package.
TEST(CliVectors, TheCheckerRefusesADamagedManifest) {
  ScratchDir dir;
  const RunResult made = run_rastersim(dir, {"vectors", "--width", "32", "--height", "24", "--out", "pk", "--scene", "fan"});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  dir.write("secret.txt", "not part of the package\n");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{\"format\": \"rastersim-vectors\"}", "no \"files\" list"},
      {"{\"files\": [{\"path\": \"../secret.txt\", \"bytes\": 24, \"crc32\": \"0x00000000\"}]}",
       "'../secret.txt' is not a path inside the package"},
      {"{\"files\": [{\"path\": \"commands.hex\"}]}", "is not {path, bytes, crc32}"}};
  for (const auto& [manifest, message] : cases) {
    dir.write("pk/manifest.json", manifest);
    const std::string command = "cd '" + dir.work().string() + "' && python3 pk/check_manifest.py > out.txt 2> err.txt";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2) << manifest;
    const std::string err = read_text(dir.path("err.txt"));
    EXPECT_TRUE(contains(err, message)) << err;
    EXPECT_FALSE(contains(err, "Traceback")) << err;
  }
}

// Camera flags on a 3D input (once refused): the package holds the frame `render` draws with the
// same flags, and its manifest records them in the source and the regenerate command.
// A stall pattern makes a package of rastersim_core with the memory model on its memory port.
TEST(CliVectors, AStallPatternMakesAPackageOfTheCoreWithAMemoryModel) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"vectors", "--suite", "depth", "--width", "16", "--height", "12",
                                          "--memory-stall-percent", "30", "--out", "core"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json manifest = nlohmann::json::parse(read_text(dir.path("core") / "manifest.json"));
  EXPECT_EQ(manifest["rtl"]["top"], "rastersim_core");
  EXPECT_EQ(manifest["profile"]["memory_stall_percent"], 30);
  EXPECT_TRUE(contains(manifest["regenerate"].get<std::string>(), " --top rastersim_core")) << manifest["regenerate"];
  EXPECT_TRUE(fs::exists(dir.path("core") / "rastersim_memory_model.v"));
  EXPECT_TRUE(contains(read_text(dir.path("core") / "rastersim_vectors_params.vh"), "`define RS_EXTERNAL_MEMORY"));
  EXPECT_TRUE(contains(read_text(dir.path("core") / "README.md"), "## Putting a port in place of rastersim_core"));
}

TEST(CliVectors, CameraFlagsApplyToA3DInput) {
  ScratchDir dir;
  dir.write("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n");
  const std::vector<std::string> camera = {"--eye", "0.5,0.25,3", "--fov", "40"};
  std::vector<std::string> args = {"vectors", "quad.obj", "--width", "32", "--height", "24", "--out", "pkg"};
  args.insert(args.end(), camera.begin(), camera.end());
  RunResult r = run_rastersim(dir, args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json manifest = nlohmann::json::parse(read_text(dir.path("pkg") / "manifest.json"));
  EXPECT_EQ(manifest["source"]["camera"], "--eye 0.5,0.25,3 --fov 40");
  EXPECT_TRUE(contains(manifest["regenerate"].get<std::string>(), "quad.obj --eye 0.5,0.25,3 --fov 40 "));
  std::vector<std::string> render = {"render", "quad.obj", "--width", "32", "--height", "24", "--stats", "s.json"};
  render.insert(render.end(), camera.begin(), camera.end());
  r = run_rastersim(dir, render);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(manifest["stats"]["fragments"], read_json(dir.path("s.json"))["fragments"]);
  EXPECT_GT(manifest["stats"]["fragments"].get<int64_t>(), 0);
  args = {"vectors", "--random", "3", "--eye", "1,2,3", "--width", "32", "--height", "24", "--out", "pkg2"};
  r = run_rastersim(dir, args);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "camera flags apply to 3D inputs")) << r.err;
}

TEST(CliVectors, TheSameCommandGivesTheSameBytesAndForceReplaces) {
  ScratchDir dir;
  const std::vector<std::string> args = {"vectors", "--random", "4", "--seed", "9", "--width", "16", "--height", "12"};
  std::vector<std::string> a = args, b = args;
  a.insert(a.end(), {"--out", "a"});
  b.insert(b.end(), {"--out", "b"});
  ASSERT_EQ(run_rastersim(dir, a).exit_code, 0);
  ASSERT_EQ(run_rastersim(dir, b).exit_code, 0);
  for (const auto& entry : fs::recursive_directory_iterator(dir.path("a"))) {
    if (!entry.is_regular_file()) continue;
    const fs::path relative = fs::relative(entry.path(), dir.path("a"));
    EXPECT_TRUE(read_text(entry.path()) == read_text(dir.path("b") / relative)) << relative;
  }
  const RunResult again = run_rastersim(dir, a);
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_TRUE(contains(again.err, "--out: folder 'a' is not empty (--force replaces an existing package)")) << again.err;
  a.push_back("--force");
  EXPECT_EQ(run_rastersim(dir, a).exit_code, 0);
  EXPECT_EQ(dir.listing(), (std::set<std::string>{"a", "b"}));
}

// --force replaces a package and nothing else: a file the package does not list (a user's notes),
// also in a subfolder, keeps the folder from being replaced (it was deleted with the package).
TEST(CliVectors, ForceKeepsAFolderWithFilesThatAreNotThePackages) {
  ScratchDir dir;
  const std::vector<std::string> args = {"vectors", "--random", "2", "--width", "16", "--height", "12", "--out", "pk",
                                         "--force"};
  ASSERT_EQ(run_rastersim(dir, args).exit_code, 0);
  for (const std::string notes : {"pk/notes.txt", "pk/sub/notes.txt"}) {
    fs::create_directories(dir.path(notes).parent_path());
    dir.write(notes, "mine");
    const RunResult r = run_rastersim(dir, args);
    EXPECT_EQ(r.exit_code, 2) << notes;
    EXPECT_TRUE(contains(r.err, "holds something other than a rastersim-vectors package")) << r.err;
    EXPECT_EQ(read_text(dir.path(notes)), "mine");
    EXPECT_TRUE(fs::exists(dir.path("pk/manifest.json")));
    fs::remove_all(dir.path("pk/sub"));
    fs::remove(dir.path("pk/notes.txt"));
  }
  EXPECT_EQ(run_rastersim(dir, args).exit_code, 0) << "the package alone is replaced";
  EXPECT_EQ(dir.listing(), std::set<std::string>{"pk"});
}

// --force replaces the package folder as a whole: an input inside it (a scene's mesh named like a
// package file, the .tri itself, the profile) is refused and left as it was.
TEST(CliVectors, AnInputInsideTheOutFolderIsRefused) {
  ScratchDir dir;
  ASSERT_EQ(run_rastersim(dir, {"vectors", "--scene", "fan", "--width", "16", "--height", "12", "--out", "pk"}).exit_code, 0);
  const std::string mesh = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  dir.write("pk/README.md", mesh);  // a package file's name, holding the scene's mesh
  dir.write("scene.json", "{\"objects\": [{\"mesh\": \"pk/README.md\"}]}\n");
  dir.write("pk/frame.tri", "0 0 0.5 10 0 0.5 0 10 0.5\n");
  dir.write("pk/profile.json", "{}\n");
  const std::vector<std::vector<std::string>> runs = {
      {"scene.json"}, {"pk/frame.tri"}, {"--random", "2", "--profile", "pk/profile.json"}};
  for (const std::vector<std::string>& source : runs) {
    std::vector<std::string> args = {"vectors", "--width", "16", "--height", "12", "--out", "pk", "--force"};
    args.insert(args.end(), source.begin(), source.end());
    const RunResult r = run_rastersim(dir, args);
    EXPECT_EQ(r.exit_code, 2) << source[0] << ": " << r.err;
    EXPECT_TRUE(contains(r.err, "pk: cannot write the package there: it holds an input of this run")) << r.err;
  }
  EXPECT_EQ(read_text(dir.path("pk/README.md")), mesh);
  EXPECT_TRUE(fs::exists(dir.path("pk/frame.tri")));
  EXPECT_TRUE(fs::exists(dir.path("pk/manifest.json")));
}

struct BadVectors {
  const char* name;
  std::vector<std::string> args;
  const char* message;
};

class CliVectorsBadInput : public ::testing::TestWithParam<BadVectors> {};

// Nothing is written: the scratch folder holds what the test put there, and the existing folder
// `full` keeps its one file.
TEST_P(CliVectorsBadInput, ExitsTwoWithMessageAndWritesNothing) {
  const BadVectors& bad = GetParam();
  ScratchDir dir;
  dir.write("bad.tri", "0 0 0.5 10 0 0.5 0 10 0.5\n1 1 0.5 9 1 0.5 1 nine 0.5\n");
  fs::create_directory(dir.path("full"));
  dir.write("full/notes.txt", "keep");
  std::vector<std::string> args = {"vectors", "--width", "16", "--height", "12"};
  args.insert(args.end(), bad.args.begin(), bad.args.end());
  if (std::find(bad.args.begin(), bad.args.end(), "--out") == bad.args.end()) args.insert(args.end(), {"--out", "pkg"});
  const RunResult r = run_rastersim(dir, args);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, bad.message)) << "stderr: " << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(dir.listing(), (std::set<std::string>{"bad.tri", "full"}));
  EXPECT_EQ(read_text(dir.path("full/notes.txt")), "keep");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path("full")), fs::directory_iterator()), 1);
}

// `vectors --random 5000` at 640 x 480 once grew to gigabytes and died in bad_alloc: a frame beyond
// the package's fragment limit is refused before anything is held, saying which limit and why.
TEST(CliVectors, AFrameBeyondTheFragmentLimitIsRefusedUpFront) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"vectors", "--random", "20000", "--out", "pkg"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "the package would hold more than 8000000 fragments, the limit")) << r.err;
  EXPECT_TRUE(contains(r.err, "of 20000;")) << r.err;
  EXPECT_TRUE(dir.listing().empty());
}

INSTANTIATE_TEST_SUITE_P(
    AllKinds, CliVectorsBadInput,
    ::testing::Values(
        BadVectors{"OutNotEmpty", {"--suite", "depth", "--out", "full"}, "--out: folder 'full' is not empty"},
        BadVectors{"ForceOnAFolderThatIsNoPackage", {"--suite", "depth", "--out", "full", "--force"},
                   "holds something other than a rastersim-vectors package"},
        BadVectors{"OutParentMissing", {"--suite", "depth", "--out", "no/such/pkg"}, "folder 'no/such' does not exist"},
        BadVectors{"OutIsAFile", {"--suite", "depth", "--out", "bad.tri"}, "'bad.tri' exists and is not a folder"},
        BadVectors{"OutMissing", {"--suite", "depth", "--out"}, "--out"},
        BadVectors{"UnknownSuite", {"--suite", "corners"}, "--suite: unknown suite 'corners' (rules, depth)"},
        BadVectors{"TwoSources", {"--suite", "depth", "--random", "3"}, "give one of INPUT, --scene, --random and --suite"},
        BadVectors{"SeedWithoutRandom", {"--suite", "depth", "--seed", "4"}, "--seed goes with --random"},
        BadVectors{"RandomZero", {"--random", "0"}, "--random must be in 1..1000000"},
        BadVectors{"RandomNotANumber", {"--random", "many"}, "--random"},
        BadVectors{"AbsoluteRtlPath", {"--suite", "depth", "--rtl-path", "/work/rtl"}, "--rtl-path must be relative"},
        BadVectors{"AbsoluteTestbenchPath", {"--suite", "depth", "--testbench-path", "/work/tb"},
                   "--testbench-path must be relative"},
        BadVectors{"BadTriLine", {"bad.tri"}, "bad.tri:2: y2 'nine' is not a number"},
        BadVectors{"MissingInput", {"missing.tri"}, "missing.tri: cannot open"},
        BadVectors{"UnknownScene", {"--scene", "teapot"}, "unknown scene 'teapot'"},
        BadVectors{"BadProfile", {"--suite", "depth", "--z-bits", "8"}, "z_bits is 8"},
        BadVectors{"BadDepthFunc", {"--suite", "depth", "--depth-func", "sometimes"}, "depth_func is 'sometimes'"},
        BadVectors{"StallPatternOnTheTop", {"--suite", "depth", "--memory-stall-percent", "10", "--top", "rastersim_top"},
                   "no back-pressure"},
        BadVectors{"UnknownTop", {"--suite", "depth", "--top", "rastersim_walker"},
                   "--top must be rastersim_top or rastersim_core, not 'rastersim_walker'"},
        BadVectors{"TextureFlagsWithoutTheUnit", {"--scene", "floor", "--texture-filter", "nearest"},
                   "the texture flags (--texture-filter nearest) need the profile's texture_unit"},
        BadVectors{"TextureFlagsWithRandom", {"--random", "3", "--texture-unit", "true", "--texture-wrap", "clamp"},
                   "the texture flags apply to INPUT and --scene"},
        BadVectors{"MissingTexture", {"--scene", "floor", "--texture-unit", "true", "--texture", "none.png"},
                   "none.png"}),
    [](const ::testing::TestParamInfo<BadVectors>& info) { return info.param.name; });

#endif

}  // namespace
}  // namespace rastersim::cli_test
