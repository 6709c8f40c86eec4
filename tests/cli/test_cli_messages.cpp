// Bad input found by a hostile run: each case exits 2 with a message that says what is wrong (no
// raw or cut bytes, no misleading reason), and inputs that would block or run unbounded are refused.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "cli_test_support.h"

namespace rastersim::cli_test {
namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const char* const kOneTriangle = "0 0 0.5  30 0 0.5  0 20 0.5  255 0 0\n";

// Bytes that do not print appear as \xNN: an invalid UTF-8 byte and a NUL (which cut the message).
TEST(CliMessages, BytesThatDoNotPrintAreShownAsHex) {
  ScratchDir dir;
  dir.write("bytes.tri", std::string("0 0 0.5  30 0 0.5  0 20 0.\xff" "5  255 0 0\n"));
  RunResult r = run_rastersim(dir, {"render", "bytes.tri", "--width", "32", "--height", "24"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "0.\\xff5")) << r.err;
  EXPECT_FALSE(contains(r.err, "\xff")) << r.err;

  dir.write("nul.json", std::string("{\"traversal\": \"span\\u0000x\"}\n"));
  r = run_rastersim(dir, {"render", "bytes.tri", "--profile", "nul.json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "span\\x00x")) << r.err;
  EXPECT_TRUE(contains(r.err, "must be one of")) << r.err;  // the message goes on past the NUL
}

// A JSON file whose lines end in a lone CR (old Mac files) reports the line of the problem.
TEST(CliMessages, JsonWithCarriageReturnLineEndsReportsTheLine) {
  ScratchDir dir;
  dir.write("one.tri", kOneTriangle);
  dir.write("cr.json", "{\r  \"width\": 32,\r  \"traversal\": \"sideways\"\r}\r");
  const RunResult r = run_rastersim(dir, {"render", "one.tri", "--profile", "cr.json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "cr.json:3:")) << r.err;
}

// An integer too large for its key is out of range, not "not an integer".
TEST(CliMessages, AnIntegerOutOfRangeIsSaidToBe) {
  ScratchDir dir;
  dir.write("one.tri", kOneTriangle);
  for (const std::string value : {"2147483648", "-2147483649"}) {
    dir.write("big.json", "{\"memory_latency\": " + value + "}\n");
    const RunResult r = run_rastersim(dir, {"render", "one.tri", "--profile", "big.json"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(contains(r.err, "memory_latency is '" + value + "'; it must be")) << r.err;
    EXPECT_FALSE(contains(r.err, "takes an integer")) << r.err;
  }
}

#ifdef RASTERSIM_HAVE_RTL  // cosim needs the RTL backend
// A file given where a folder must be is "not a folder", not "does not exist".
TEST(CliMessages, AFileGivenAsAFolderIsNotAFolder) {
  ScratchDir dir;
  dir.write("x.tri", kOneTriangle);
  const RunResult r = run_rastersim(dir, {"cosim", "--replay-dir", "x.tri"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "--replay-dir: 'x.tri' is not a folder")) << r.err;
}
#endif

// An eye far beyond double precision's reach is too large, not "the same point" as the target.
TEST(CliMessages, ACameraTooFarOutIsSaidToBe) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"render", "--scene", "default", "--eye", "1e300,0,0", "--width", "32", "--height", "24"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "is too large")) << r.err;
  EXPECT_FALSE(contains(r.err, "same point")) << r.err;
}

// A texture PNG cut short: one message, from rastersim, naming the file; no "libpng error:" line
// printed by the PNG library before it (OpenImageIO's reader leaves libpng's handler in place).
TEST(CliMessages, ACutPngTextureGivesOneMessageAndNoLibraryLines) {
  ScratchDir dir;
  RunResult r = run_rastersim(dir, {"render", "--scene", "fan", "--width", "16", "--height", "16", "-o", "whole.png"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string whole = read_text(dir.path("whole.png"));
  ASSERT_GT(whole.size(), 100u);
  dir.write("cut.png", whole.substr(0, 100));  // the header and part of the first IDAT chunk
  // OpenImageIO's PNG reader loses a string when libpng's error longjmps through it (a leak in the
  // library, which the sanitizer build's leak check reports): leak detection off for this run alone.
  const char* asan = std::getenv("ASAN_OPTIONS");
  const std::string saved = asan ? asan : "";
  setenv("ASAN_OPTIONS", (saved + (saved.empty() ? "" : ":") + "detect_leaks=0").c_str(), 1);
  r = run_rastersim(dir, {"render", "--scene", "floor", "--texture-unit", "true", "--texture", "cut.png", "--width",
                          "32", "--height", "24", "-o", "x.png"});
  if (asan) setenv("ASAN_OPTIONS", saved.c_str(), 1);
  else unsetenv("ASAN_OPTIONS");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("rastersim: cut.png: ", 0), 0u) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  EXPECT_FALSE(contains(r.err, "libpng")) << r.err;
  EXPECT_FALSE(fs::exists(dir.path("x.png")));
}

// bench's random-list options with an INPUT would be ignored: they are refused.
TEST(CliInputs, BenchRefusesRandomListOptionsWithAnInput) {
  ScratchDir dir;
  dir.write("one.tri", kOneTriangle);
  for (const std::vector<std::string>& extra : std::vector<std::vector<std::string>>{
           {"one.tri", "--triangles", "5"}, {"--scene", "overlap", "--seed", "3"}, {"one.tri", "--size", "2..3"}}) {
    std::vector<std::string> args = {"bench", "--width", "32", "--height", "24"};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = run_rastersim(dir, args);
    EXPECT_EQ(r.exit_code, 2) << extra[1];
    EXPECT_TRUE(contains(r.err, "excludes")) << r.err;
  }
}

// A FIFO as a .tri file or a profile would block the open: refused, as a FIFO mesh or texture is.
TEST(CliInputs, AFifoAsATriOrProfileIsRefused) {
  ScratchDir dir;
  dir.write("one.tri", kOneTriangle);
  ASSERT_EQ(mkfifo(dir.path("f.tri").c_str(), 0600), 0);
  ASSERT_EQ(mkfifo(dir.path("f.json").c_str(), 0600), 0);
  RunResult r = run_rastersim(dir, {"render", "f.tri"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "f.tri: is not a regular file")) << r.err;
  r = run_rastersim(dir, {"render", "one.tri", "--profile", "f.json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "f.json: is not a regular file")) << r.err;
}

// A mesh name with an escaped NUL would load the file named by its first part.
TEST(CliInputs, AMeshNameWithANulIsRefused) {
  ScratchDir dir;
  dir.write("cube.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  dir.write("scene.json", "{\"objects\": [{\"mesh\": \"cube.obj\\u0000.txt\"}]}\n");
  const RunResult r = run_rastersim(dir, {"render", "scene.json", "--width", "32", "--height", "24"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "scene.json:1:")) << r.err;
  EXPECT_TRUE(contains(r.err, "cube.obj\\x00.txt' holds a NUL character")) << r.err;
}

// Every vertex is lit by every light: a scene has at most 64 (600,000 ran for hours).
TEST(CliInputs, TheLightsOfASceneAreBounded) {
  ScratchDir dir;
  std::string lights;
  for (int i = 0; i < 65; ++i) lights += std::string(i ? "," : "") + "{\"direction\": [0, 0, -1]}";
  dir.write("scene.json", "{\"lights\": [" + lights + "], \"objects\": [{\"surface\": \"sphere\"}]}\n");
  const RunResult r = run_rastersim(dir, {"render", "scene.json", "--width", "32", "--height", "24"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "65 lights; a scene has at most 64")) << r.err;
}

}  // namespace
}  // namespace rastersim::cli_test
