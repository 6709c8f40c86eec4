// The rastersim binary end to end, run in a scratch folder: outputs on good input, their mutual
// consistency (image = the trace's last passing fragments), and exit 2 with file:line and no output
// file at all for every kind of bad input.
#include <fcntl.h>
#include <sys/wait.h>
#include <csignal>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <thread>
#include <cmath>
#include <array>
#include <fstream>
#include <cstring>
#include <map>
#include <set>
#include <sstream>

#include "cli_test_support.h"
#include "tri_reader.h"

namespace rastersim::cli_test {
namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// 32x24 screen. Triangle 0 is a flat red triangle over the top-left corner at depth 0.5; triangle 1
// a Gouraud triangle whose depth crosses 0.5; triangle 2 lies behind triangle 0; triangle 3 has zero
// area.
const char* const kSmallTri =
    "# test scene\n"
    "0 0 0.5  32 0 0.5  0 24 0.5  255 0 0\n"
    "4 4 0.25  30 6 0.75  8 22 0.1  0 255 0  0 0 255  255 255 255  # crosses triangle 0\n"
    "\n"
    "2 2 0.9  12 2 0.9  2 12 0.9\n"
    "1 1 0.5  5 5 0.5  9 9 0.5\n";

const std::vector<std::string> kSmallProfile = {"--width", "32", "--height", "24"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(CliRender, SmallTriWritesConsistentOutputs) {
  ScratchDir dir;
  dir.write("small.tri", kSmallTri);
  const RunResult r = run_rastersim(dir, with({"render", "small.tri", "-o", "color.png", "--depth-out", "depth.exr",
                                               "--fragments", "frags.csv", "--stats", "stats.json"},
                                              kSmallProfile));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(dir.listing(), (std::set<std::string>{"small.tri", "color.png", "depth.exr", "frags.csv", "stats.json"}));

  // The human summary.
  EXPECT_TRUE(contains(r.out, "triangles  4")) << r.out;
  EXPECT_TRUE(contains(r.out, "fragments per clock")) << r.out;
  for (const char* unit : {"setup", "walker", "z_adder", "zbuffer"}) EXPECT_TRUE(contains(r.out, unit)) << r.out;

  const Image color = read_image(dir.path("color.png"));
  EXPECT_EQ(color.width, 32);
  EXPECT_EQ(color.height, 24);
  EXPECT_EQ(color.channels, 3);
  EXPECT_EQ(color.format, "uint8");
  // Pixel (1, 0): centre (1.5, 0.5) is inside triangle 0 only (the others start at x, y >= 1 and
  // triangle 3 has no area): flat red.
  const size_t red_pixel = (0 * 32 + 1) * 3;
  EXPECT_EQ(color.pixels8[red_pixel + 0], 255);
  EXPECT_EQ(color.pixels8[red_pixel + 1], 0);
  EXPECT_EQ(color.pixels8[red_pixel + 2], 0);
  // Pixel (31, 23): centre (31.5, 23.5) is outside every triangle: the clear colour, black.
  const size_t empty_pixel = (23 * 32 + 31) * 3;
  EXPECT_EQ(color.pixels8[empty_pixel] + color.pixels8[empty_pixel + 1] + color.pixels8[empty_pixel + 2], 0);

  const Csv csv = read_fragments_csv(dir.path("frags.csv"));
  EXPECT_EQ(csv.header, "tri,x,y,z,pass,r,g,b,cycle");
  const nlohmann::json stats = read_json(dir.path("stats.json"));
  EXPECT_EQ(int64_t(csv.rows.size()), stats.at("fragments").get<int64_t>());
  int64_t passes = 0;
  for (const CsvRow& row : csv.rows) passes += row.pass;
  EXPECT_EQ(passes, stats.at("depth_pass").get<int64_t>());
  EXPECT_EQ(stats.at("depth_pass").get<int64_t>() + stats.at("depth_fail").get<int64_t>(),
            stats.at("fragments").get<int64_t>());
  EXPECT_EQ(stats.at("triangles").get<int64_t>(), 4);
  EXPECT_EQ(stats.at("triangles_degenerate").get<int64_t>(), 1);
  EXPECT_EQ(stats.at("triangles_drawn").get<int64_t>() + stats.at("triangles_culled").get<int64_t>() +
                stats.at("triangles_degenerate").get<int64_t>() + stats.at("triangles_offscreen").get<int64_t>() +
                stats.at("triangles_no_centre").get<int64_t>(),
            4);
  EXPECT_GE(stats.at("candidates").get<int64_t>(), stats.at("fragments").get<int64_t>());
  EXPECT_GT(stats.at("cycles").get<int64_t>(), 0);
  for (const char* unit : {"setup", "walker", "z_adder", "zbuffer"}) {
    EXPECT_TRUE(stats.at("units").at(unit).at("busy").is_number_integer()) << unit;
    EXPECT_TRUE(stats.at("units").at(unit).at("stall").is_number_integer()) << unit;
  }
  EXPECT_EQ(stats.at("profile").at("width").get<int>(), 32);
  EXPECT_EQ(stats.at("profile").at("height").get<int>(), 24);
  EXPECT_EQ(stats.at("profile").at("depth_func").get<std::string>(), "less");

  // Independent replay of the trace with the depth test `less` and depth writes from the cleared
  // buffer (2^24 - 1, black): every pass bit agrees, and the images hold the last passing fragment's
  // colour and depth. Triangle indices are the line order and fragments of a triangle come
  // together, in triangle order.
  const uint32_t depth_max = (1u << 24) - 1;
  std::vector<uint32_t> depth(32 * 24, depth_max);
  std::vector<std::array<int64_t, 3>> rgb(32 * 24, {0, 0, 0});
  int64_t previous_tri = 0;
  for (const CsvRow& row : csv.rows) {
    ASSERT_TRUE(row.x >= 0 && row.x < 32 && row.y >= 0 && row.y < 24);
    ASSERT_GE(row.tri, previous_tri);
    ASSERT_LE(row.tri, 3);
    previous_tri = row.tri;
    const size_t a = size_t(row.y * 32 + row.x);
    const bool pass = uint32_t(row.z) < depth[a];
    ASSERT_EQ(row.pass, pass ? 1 : 0) << "fragment of triangle " << row.tri << " at " << row.x << "," << row.y;
    if (pass) {
      depth[a] = uint32_t(row.z);
      rgb[a] = {row.r, row.g, row.b};
    }
    if (row.tri == 0) {  // flat red at z = 0.5: Z = floor(0.5 * (2^24 - 1) + 1/2) = 2^23, within 1 LSB
      EXPECT_EQ((std::array<int64_t, 3>{row.r, row.g, row.b}), (std::array<int64_t, 3>{255, 0, 0}));
      EXPECT_LE(std::abs(row.z - (int64_t(1) << 23)), 1);
    }
  }
  const Image depth_image = read_image(dir.path("depth.exr"));
  EXPECT_EQ(depth_image.width, 32);
  EXPECT_EQ(depth_image.height, 24);
  EXPECT_EQ(depth_image.channels, 1);
  EXPECT_EQ(depth_image.format, "float");
  for (size_t a = 0; a < depth.size(); ++a) {
    ASSERT_EQ(color.pixels8[3 * a + 0], rgb[a][0]) << "pixel " << a % 32 << "," << a / 32;
    ASSERT_EQ(color.pixels8[3 * a + 1], rgb[a][1]) << "pixel " << a % 32 << "," << a / 32;
    ASSERT_EQ(color.pixels8[3 * a + 2], rgb[a][2]) << "pixel " << a % 32 << "," << a / 32;
    ASSERT_EQ(depth_image.pixels[a], float(double(depth[a]) / depth_max)) << "pixel " << a % 32 << "," << a / 32;
  }
}

// ---- outputs that are not plain files (each was replaced by a regular file, or overwritten) ----

// A symlink is followed: its target gets the output and the link stays a link.
TEST(CliOutputs, ASymlinkIsFollowed) {
  ScratchDir dir;
  dir.write("small.tri", kSmallTri);
  dir.write("target.json", "old");
  fs::create_symlink("target.json", dir.path("link.json"));
  const RunResult r = run_rastersim(dir, with({"render", "small.tri", "--stats", "link.json"}, kSmallProfile));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir.path("link.json"))));
  EXPECT_EQ(read_json(dir.path("target.json"))["fragments"], read_json(dir.path("link.json"))["fragments"]);
  EXPECT_EQ(dir.listing(), (std::set<std::string>{"small.tri", "target.json", "link.json"}));
}

// An empty INPUT or --scene name is bad input (issue 44 L: it rendered the default scene).
TEST(CliInputs, AnEmptyNameIsRefused) {
  ScratchDir dir;
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"render", "", "-o", "x.png"}, {"render", "--scene", "", "-o", "x.png"},
        {"vectors", "--out", "pkg", ""}, {"vectors", "--out", "pkg", "--scene", ""},
        {"sweep", "--out", "study", "--vary", "width=8,16", "--scene", ""}}) {
    const RunResult r = run_rastersim(dir, args);
    EXPECT_EQ(r.exit_code, 2) << args[0];
    EXPECT_TRUE(contains(r.err, "an empty name names no file and no scene")) << r.err;
  }
  EXPECT_TRUE(dir.listing().empty());
}

// Seeds and frame numbers out of range are bad input (issue 44 N: -1 and 2^64 became 2^64-1, 010
// was octal, --frame -1 ran every frame).
TEST(CliInputs, SeedsAndFramesOutOfRangeAreRefused) {
  ScratchDir dir;
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"cosim", "--count", "1", "--seed", "-1"},
        {"cosim", "--count", "1", "--seed", "18446744073709551616"},
        {"cosim", "--count", "1", "--seed", "010"}, {"vectors", "--out", "pkg", "--random", "2", "--seed", "-5"},
        {"render", "--seed", "x", "-o", "x.png"}, {"bench", "--seed", "-2"}}) {
    const RunResult r = run_rastersim(dir, args);
    EXPECT_EQ(r.exit_code, 2) << args[0] << " " << args[args.size() - 1];
    EXPECT_TRUE(contains(r.err, "is not a decimal number in 0..18446744073709551615")) << r.err;
  }
  const RunResult frame = run_rastersim(dir, {"cosim", "--count", "1", "--frame", "-1"});
  EXPECT_EQ(frame.exit_code, 2);
  EXPECT_TRUE(contains(frame.err, "'-1' is not a frame number")) << frame.err;
  EXPECT_TRUE(dir.listing().empty());
}

// A dangling symlink is followed too: its target is made and the link stays (issue 44 J: the link
// was replaced by a regular file).
TEST(CliOutputs, ADanglingSymlinkGetsItsTargetMade) {
  ScratchDir dir;
  dir.write("small.tri", kSmallTri);
  fs::create_directory(dir.path("sub"));
  fs::create_symlink("sub/made.json", dir.path("link.json"));
  const RunResult r = run_rastersim(dir, with({"render", "small.tri", "--stats", "link.json"}, kSmallProfile));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir.path("link.json"))));
  ASSERT_TRUE(fs::is_regular_file(dir.path("sub/made.json")));
  EXPECT_GT(read_json(dir.path("sub/made.json"))["fragments"].get<int64_t>(), 0);
  EXPECT_EQ(dir.listing(), (std::set<std::string>{"small.tri", "sub", "link.json"}));
}

// A FIFO is written into, not replaced: a reader on the other end gets the stats.
TEST(CliOutputs, AFifoIsWrittenDirectly) {
  ScratchDir dir;
  dir.write("small.tri", kSmallTri);
  const fs::path fifo = dir.path("stats.fifo");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  // Held open at both ends here, so the writer never waits and the stats (1 kB) fit the pipe's buffer.
  const int fd = open(fifo.c_str(), O_RDWR | O_NONBLOCK);
  ASSERT_GE(fd, 0);
  const RunResult r = run_rastersim(dir, with({"render", "small.tri", "--stats", "stats.fifo"}, kSmallProfile));
  std::string received;
  char buffer[4096];
  for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) > 0;) received.append(buffer, size_t(n));
  close(fd);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_TRUE(contains(received, "\"fragments\"")) << received;
}

// `-` is standard output; the summary then goes to standard error.
TEST(CliOutputs, DashIsStandardOutput) {
  ScratchDir dir;
  dir.write("small.tri", kSmallTri);
  const RunResult r = run_rastersim(dir, with({"render", "small.tri", "--stats", "-"}, kSmallProfile));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["triangles"], 4) << r.out;
  EXPECT_TRUE(contains(r.err, "wrote standard output")) << r.err;
  EXPECT_EQ(dir.listing(), (std::set<std::string>{"small.tri"}));
}

// A name near the file system's limit (255 bytes) is written: its temporary's name stays inside it.
TEST(CliOutputs, ANameNearTheLengthLimitIsWritten) {
  ScratchDir dir;
  dir.write("small.tri", kSmallTri);
  const std::string stats = std::string(245, 's') + ".json";
  std::vector<std::string> args{"render", "small.tri", "--stats", stats, "--width", "64", "--height", "48"};  // a built-in RTL profile
#ifdef RASTERSIM_HAVE_RTL  // the waveform's writer opens its own temporary, and a VCD a scratch FST beside it
  const std::string wave = std::string(246, 'w') + ".vcd";  // its save file: 255 bytes
  for (const std::string arg : {"--backend", "rtl", "--wave", wave.c_str()}) args.push_back(arg);
#endif
  const RunResult r = run_rastersim(dir, args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(read_json(dir.path(stats))["fragments"].get<int64_t>(), 0);
  std::set<std::string> expected{"small.tri", stats};
#ifdef RASTERSIM_HAVE_RTL
  EXPECT_TRUE(contains(read_text(dir.path(wave)), "$enddefinitions"));
  expected.insert({wave, wave + ".gtkw"});
#endif
  EXPECT_EQ(dir.listing(), expected);
}

// A file with another hard link stays one file: both names show the output.
TEST(CliOutputs, AHardLinkStaysLinked) {
  ScratchDir dir;
  dir.write("small.tri", kSmallTri);
  dir.write("stats.json", "old");
  fs::create_hard_link(dir.path("stats.json"), dir.path("other-name.json"));
  const RunResult r = run_rastersim(dir, with({"render", "small.tri", "--stats", "stats.json"}, kSmallProfile));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::equivalent(dir.path("stats.json"), dir.path("other-name.json")));
  EXPECT_EQ(read_text(dir.path("other-name.json")), read_text(dir.path("stats.json")));
  EXPECT_EQ(read_json(dir.path("other-name.json"))["triangles"], 4);
}

// An output that is the input (or the profile) is refused and the input is left as it was.
TEST(CliOutputs, AnOutputThatIsAnInputIsRefused) {
  ScratchDir dir;
  dir.write("small.tri", kSmallTri);
  dir.write("p.json", "{\"width\": 32, \"height\": 24}\n");
  fs::create_symlink("small.tri", dir.path("alias.tri"));
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"render", "small.tri", "--fragments", "small.tri", "--profile", "p.json"},
        std::vector<std::string>{"render", "small.tri", "--fragments", "./alias.tri", "--profile", "p.json"},
        std::vector<std::string>{"render", "small.tri", "--stats", "p.json", "--profile", "p.json"}}) {
    const RunResult r = run_rastersim(dir, args);
    EXPECT_EQ(r.exit_code, 2) << args[3];
    EXPECT_TRUE(contains(r.err, "is an input of this run")) << r.err;
  }
  EXPECT_EQ(read_text(dir.path("small.tri")), kSmallTri);
  EXPECT_EQ(dir.listing(), (std::set<std::string>{"small.tri", "p.json", "alias.tri"}));
}

// A scene's mesh is an input of the run like the scene itself (`render scene.json --stats m.obj`
// wrote the stats over the mesh).
TEST(CliOutputs, AnOutputThatIsASceneMeshIsRefused) {
  ScratchDir dir;
  const std::string mesh = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  fs::create_directory(dir.path("meshes"));
  dir.write("meshes/m.obj", mesh);
  dir.write("scene.json", "{\"objects\": [{\"mesh\": \"meshes/m.obj\"}]}\n");
  for (const std::string output : {"meshes/m.obj", "./meshes/../meshes/m.obj"}) {
    const RunResult r = run_rastersim(dir, with({"render", "scene.json", "--stats", output}, kSmallProfile));
    EXPECT_EQ(r.exit_code, 2) << output;
    EXPECT_TRUE(contains(r.err, "is an input of this run")) << r.err;
  }
  EXPECT_EQ(read_text(dir.path("meshes/m.obj")), mesh);
  EXPECT_EQ(dir.listing(), (std::set<std::string>{"meshes", "scene.json"}));
}

// bench's --triangles stops at a frame's triangle limit (10,000,000 was in range and ended in bad_alloc).
TEST(CliBench, TrianglesBeyondTheFrameLimitAreRefused) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"bench", "--triangles", "4000001"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "--triangles")) << r.err;
  EXPECT_TRUE(contains(r.err, "4000000")) << r.err;
}

// Runs rastersim with `args` in `dir`, sends SIGTERM as soon as a name starting with
// `temporary_prefix` appears there (polling every millisecond, up to a minute), and returns the
// process's wait status; `seen` says whether the temporary appeared.
int terminate_when_temporary_appears(const ScratchDir& dir, std::vector<std::string> args,
                                     const std::string& temporary_prefix, bool& seen, int signal_number = SIGTERM) {
  std::string exe = RASTERSIM_EXE;
  args.insert(args.begin(), exe);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    if (chdir(dir.work().c_str()) != 0) _exit(126);
    const rlimit no_core{0, 0};  // SIGQUIT would dump one into the folder under test
    setrlimit(RLIMIT_CORE, &no_core);
    const int null = open("/dev/null", O_RDWR);
    dup2(null, 0), dup2(null, 1), dup2(null, 2);
    execv(exe.c_str(), argv.data());
    _exit(127);
  }
  seen = false;
  if (pid <= 0) return -1;
  int status = 0;
  for (int i = 0; i < 60000 && !seen; ++i) {
    for (const std::string& name : dir.listing()) seen |= name.rfind(temporary_prefix, 0) == 0;
    if (seen) break;
    if (waitpid(pid, &status, WNOHANG) == pid) return status;  // ended before writing anything
    usleep(1000);
  }
  kill(pid, signal_number);
  waitpid(pid, &status, 0);
  return status;
}

// SIGTERM while the fragment trace is being written: the hidden temporary goes with the process
// (an interrupted render left a 614 MB one).
TEST(CliOutputs, ATerminatedRenderLeavesNoTemporary) {
  ScratchDir dir;
  bool seen = false;
  // Large enough to run for seconds: the default scene at 4096 x 4096 through the traced model.
  const int status = terminate_when_temporary_appears(
      dir, {"render", "--scene", "default", "--width", "4096", "--height", "4096", "--fragments", "frags.csv"},
      ".frags.tmp", seen);
  ASSERT_TRUE(seen) << "the temporary never appeared";
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  EXPECT_TRUE(dir.listing().empty()) << *dir.listing().begin();
}

// A sweep killed while it runs leaves no --out folder it made (one stayed behind, empty).
TEST(CliOutputs, AKilledSweepLeavesNoFolderItMade) {
  ScratchDir dir;
  bool seen = false;
  const int status = terminate_when_temporary_appears(
      dir, {"sweep", "--vary", "z_bits=16,20,24,28", "--scene", "default", "--no-plots", "--out", "out"}, "out", seen);
  ASSERT_TRUE(seen) << "the folder never appeared";
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  EXPECT_TRUE(dir.listing().empty()) << *dir.listing().begin();
}

// Every signal that ends the process by default removes the temporaries too (SIGQUIT, SIGUSR1,
// SIGALRM and SIGXFSZ once left a 750 MB hidden CSV behind).
TEST(CliOutputs, EveryTerminatingSignalRemovesTheTemporaries) {
  for (const int signal_number : {SIGQUIT, SIGUSR1, SIGALRM, SIGXFSZ}) {
    ScratchDir dir;
    bool seen = false;
    const int status = terminate_when_temporary_appears(
        dir, {"render", "--scene", "default", "--width", "4096", "--height", "4096", "--fragments", "frags.csv"},
        ".frags.tmp", seen, signal_number);
    ASSERT_TRUE(seen) << "the temporary never appeared";
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number) << strsignal(signal_number);
    EXPECT_TRUE(dir.listing().empty()) << strsignal(signal_number) << ": " << *dir.listing().begin();
  }
}

#ifdef RASTERSIM_HAVE_RTL  // `vectors` needs the RTL library
// SIGTERM while a vector package is being written: its hidden folder goes with the process (an
// interrupted `vectors` left folders of 57 and 109 MB).
TEST(CliOutputs, ATerminatedVectorsRunLeavesNoTemporaryFolder) {
  ScratchDir dir;
  bool seen = false;
  // About 55 MB of expected words: the write takes long enough to be caught in it.
  const int status = terminate_when_temporary_appears(
      dir, {"vectors", "--scene", "default", "--width", "1024", "--height", "1024", "--out", "pkg"}, ".pkg.tmp-",
      seen);
  ASSERT_TRUE(seen) << "the hidden folder never appeared";
  if (WIFSIGNALED(status)) {  // caught while writing
    EXPECT_EQ(WTERMSIG(status), SIGTERM);
    EXPECT_TRUE(dir.listing().empty()) << *dir.listing().begin();
  } else {  // the write finished first: the package, whole, and nothing else
    EXPECT_EQ(dir.listing(), std::set<std::string>{"pkg"});
  }
}
#endif

TEST(CliRender, DepthPngIsSixteenBitScaled) {
  ScratchDir dir;
  dir.write("small.tri", kSmallTri);
  const RunResult r = run_rastersim(
      dir, with({"render", "small.tri", "--depth-out", "depth.png", "--fragments", "f.csv", "--z-bits", "16"},
                kSmallProfile));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image depth = read_image(dir.path("depth.png"));
  EXPECT_EQ(depth.channels, 1);
  EXPECT_EQ(depth.format, "uint16");
  // With 16 depth bits the scale is exactly 1: the image holds the z of the last passing fragment.
  std::vector<int64_t> expected(32 * 24, 65535);
  for (const CsvRow& row : read_fragments_csv(dir.path("f.csv")).rows)
    if (row.pass) expected[size_t(row.y * 32 + row.x)] = row.z;
  for (size_t a = 0; a < expected.size(); ++a) ASSERT_EQ(depth.pixels16[a], expected[a]) << a;
}

TEST(CliRender, NoOutputsRequestedWritesNothingButPrintsTheSummary) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"render", "--width", "64", "--height", "48"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(dir.listing().empty());
  EXPECT_TRUE(contains(r.out, "scene default")) << r.out;
  EXPECT_TRUE(contains(r.out, "cycles")) << r.out;
  EXPECT_EQ(r.err, "");  // no progress line: stderr is not a terminal
}

TEST(CliRender, FanSceneCoversEveryPixelOnce) {
  ScratchDir dir;
  const RunResult r =
      run_rastersim(dir, {"render", "--scene", "fan", "--width", "80", "--height", "60", "--fragments", "f.csv",
                          "--stats", "s.json", "--traversal", "bbox"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<int> hits(80 * 60, 0);
  for (const CsvRow& row : read_fragments_csv(dir.path("f.csv")).rows) ++hits[size_t(row.y * 80 + row.x)];
  for (size_t a = 0; a < hits.size(); ++a) ASSERT_EQ(hits[a], 1) << "pixel " << a % 80 << "," << a / 80;
  EXPECT_EQ(read_json(dir.path("s.json")).at("profile").at("traversal").get<std::string>(), "bbox");
}

TEST(CliRender, ProfileFileThenFlags) {
  ScratchDir dir;
  dir.write("p.json", "{\n  \"width\": 40,\n  \"height\": 30,\n  \"cull\": \"back\"\n}\n");
  const RunResult r = run_rastersim(dir, {"render", "--profile", "p.json", "--width", "20", "-o", "c.tif",
                                          "--stats", "s.json", "--scene", "stress"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image color = read_image(dir.path("c.tif"));
  EXPECT_EQ(color.width, 20);   // the flag wins
  EXPECT_EQ(color.height, 30);  // from the file
  const nlohmann::json stats = read_json(dir.path("s.json"));
  EXPECT_EQ(stats.at("profile").at("cull").get<std::string>(), "back");
  EXPECT_GT(stats.at("triangles_culled").get<int64_t>(), 0);
}

// --conventions sets its keys before the flags; a flag naming one of them wins; an unknown name is
// bad input naming the presets.
TEST(CliRender, ConventionPresetsThenFlags) {
  ScratchDir dir;
  RunResult r = run_rastersim(dir, {"render", "--conventions", "d3d10", "--stats", "s.json", "--scene", "stress",
                                    "--width", "32", "--height", "24"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  nlohmann::json stats = read_json(dir.path("s.json"));
  EXPECT_EQ(stats.at("profile").at("subpixel_bits").get<int>(), 8);
  EXPECT_EQ(stats.at("profile").at("pixel_center").get<std::string>(), "half");
  r = run_rastersim(dir, {"render", "--conventions", "d3d9", "--fill-rule", "bottom_right", "--stats", "s.json",
                          "--scene", "stress", "--width", "32", "--height", "24"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  stats = read_json(dir.path("s.json"));
  EXPECT_EQ(stats.at("profile").at("pixel_center").get<std::string>(), "corner");
  EXPECT_EQ(stats.at("profile").at("fill_rule").get<std::string>(), "bottom_right");
  r = run_rastersim(dir, {"render", "--conventions", "opengl", "--scene", "stress"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "'opengl' is not a preset; the presets are rastersim, d3d9, d3d10")) << r.err;
}

TEST(CliRender, EmptyTriListRendersAClearFrame) {
  ScratchDir dir;
  dir.write("empty.tri", "# nothing here\n\n");
  const RunResult r = run_rastersim(dir, with({"render", "empty.tri", "--fragments", "f.csv", "--stats", "s.json"},
                                              kSmallProfile));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_text(dir.path("f.csv")), "tri,x,y,z,pass,r,g,b,cycle\n");
  EXPECT_EQ(read_json(dir.path("s.json")).at("triangles").get<int>(), 0);
}

// 240 half-screen triangles on 1024x1024: a run of many updates' length (the terminal harness
// removes the one-second wait before the first progress line).
std::string long_tri() {
  std::string text;
  for (int i = 0; i < 240; ++i) text += "0 0 0.5 1024 0 0.5 0 1024 0.5 " + std::to_string(i) + " 0 0\n";
  return text;
}

TEST(CliProgress, ShownOnATerminalForALongRun) {
  ScratchDir dir;
  dir.write("long.tri", long_tri());
  const RunResult r = run_rastersim_with_terminal_stderr(dir, {"render", "long.tri", "--width", "1024", "--height", "1024"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "rendering: ")) << r.err;
  EXPECT_TRUE(contains(r.err, " / 240 triangles")) << r.err;
  // At most ten updates a second: far fewer updates than triangles.
  size_t updates = 0;
  for (size_t at = r.err.find("rendering: "); at != std::string::npos; at = r.err.find("rendering: ", at + 1)) ++updates;
  EXPECT_LT(updates, 100u) << r.err;
}

TEST(CliProgress, NeverShownWhenStderrIsNotATerminal) {
  ScratchDir dir;
  dir.write("long.tri", long_tri());
  const RunResult r = run_rastersim(dir, {"render", "long.tri", "--width", "1024", "--height", "1024"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
}

// The front end and the pipeline can be checked separately: the triangles --dump-tri writes for a
// 3D input re-render through the .tri path to the same fragments, buffers and cycles.
TEST(CliRender, DumpedTrianglesOfA3dInputRenderIdentically) {
  ScratchDir dir;
  dir.write("cube.obj",
            "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
            "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  const std::vector<std::string> common = {"--width", "96", "--height", "64", "--cull", "back"};
  std::vector<std::string> first = {"render", "cube.obj", "--eye", "3,2,4", "--fov", "50", "--dump-tri", "cube.tri",
                                    "--stats", "a.json", "--fragments", "a.csv"};
  first.insert(first.end(), common.begin(), common.end());
  const RunResult a = run_rastersim(dir, first);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  std::vector<std::string> second = {"render", "cube.tri", "--stats", "b.json", "--fragments", "b.csv"};
  second.insert(second.end(), common.begin(), common.end());
  const RunResult b = run_rastersim(dir, second);
  ASSERT_EQ(b.exit_code, 0) << b.err;
  nlohmann::json sa = read_json(dir.path("a.json")), sb = read_json(dir.path("b.json"));
  EXPECT_GT(sa["fragments"].get<int64_t>(), 0);
  EXPECT_EQ(sa, sb);
  EXPECT_EQ(read_text(dir.path("a.csv")), read_text(dir.path("b.csv")));
}

// An OBJ's texture coordinates reach the screen triangles: --dump-tri writes each triangle's u, v
// and clip-space w (the .tri uvw section), a cube's corners at 0 or 1, w its distance along the
// view direction (between the nearest and farthest corner from the eye).
TEST(CliRender, DumpedTrianglesCarryAnObjsTextureCoordinates) {
  ScratchDir dir;
  dir.write("cube.obj",
            "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
            "f 1/1 4/2 3/3 2/4\nf 5/1 6/2 7/3 8/4\nf 1/1 2/2 6/3 5/4\nf 2/1 3/2 7/3 6/4\nf 3/1 4/2 8/3 7/4\nf 4/1 1/2 5/3 8/4\n");
  const RunResult r = run_rastersim(dir, {"render", "cube.obj", "--eye", "3,2,4", "--fov", "50", "--dump-tri", "cube.tri",
                                          "--width", "96", "--height", "64"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Profile profile;
  profile.width = 96;
  profile.height = 64;
  const std::vector<ScreenTriangle> triangles = read_tri_file(dir.path("cube.tri"), profile);
  ASSERT_EQ(triangles.size(), 12u);  // nothing clipped
  const double eye_distance = std::sqrt(9.0 + 4.0 + 16.0);
  for (const ScreenTriangle& t : triangles) {
    EXPECT_TRUE(t.textured);
    std::set<std::pair<double, double>> corners;
    for (const ScreenVertex& v : t.v) {
      EXPECT_TRUE(v.u == 0 || v.u == 1) << v.u;
      EXPECT_TRUE(v.v == 0 || v.v == 1) << v.v;
      corners.insert({v.u, v.v});
      EXPECT_GT(v.w, eye_distance - std::sqrt(3.0) - 1e-9);
      EXPECT_LT(v.w, eye_distance + std::sqrt(3.0) + 1e-9);
    }
    EXPECT_EQ(corners.size(), 3u);  // three different corners of the face's texture square
  }
}

// A texture file is what the texture unit samples: with a one-texel texture of colour c every
// textured fragment is round(c g / 255) of the colour g it has without a texture; without the
// profile's texture unit --texture is refused, and a missing file is named, with nothing written.
TEST(CliRender, TextureFileIsModulatedIntoTheFragments) {
  ScratchDir dir;
  dir.write("cube.obj",
            "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
            "f 1/1 4/2 3/3 2/4\nf 5/1 6/2 7/3 8/4\nf 1/1 2/2 6/3 5/4\nf 2/1 3/2 7/3 6/4\nf 3/1 4/2 8/3 7/4\nf 4/1 1/2 5/3 8/4\n");
  dir.write("texel.ppm", std::string("P6\n1 1\n255\n") + char(0x80) + char(0xFF) + char(0x10));
  const std::vector<std::string> common = {"render", "cube.obj", "--eye", "3,2,4", "--fov", "50", "--width", "96",
                                           "--height", "64", "--texture-unit", "true"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = common;
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  RunResult r = run_rastersim(dir, with({"--fragments", "plain.csv"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_rastersim(dir, with({"--fragments", "textured.csv", "--texture", "texel.ppm", "--stats", "s.json"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(contains(read_text(dir.path("s.json")), "\"texture\"")) << "stats name the texture unit";
  const Csv plain = read_fragments_csv(dir.path("plain.csv")), textured = read_fragments_csv(dir.path("textured.csv"));
  ASSERT_EQ(plain.rows.size(), textured.rows.size());
  ASSERT_GT(plain.rows.size(), 500u);
  auto rounded = [](int64_t c, int64_t g) { return (2 * c * g + 255) / 510; };
  for (size_t i = 0; i < plain.rows.size(); ++i) {
    ASSERT_EQ(textured.rows[i].r, rounded(0x80, plain.rows[i].r)) << i;
    ASSERT_EQ(textured.rows[i].g, rounded(0xFF, plain.rows[i].g)) << i;
    ASSERT_EQ(textured.rows[i].b, rounded(0x10, plain.rows[i].b)) << i;
    ASSERT_EQ(textured.rows[i].cycle, plain.rows[i].cycle) << i;
  }
  const std::set<std::string> before = dir.listing();
  r = run_rastersim(dir, {"render", "cube.obj", "--texture", "texel.ppm", "-o", "x.png"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "--texture needs the profile's texture unit")) << r.err;
  r = run_rastersim(dir, with({"--texture", "missing.png", "-o", "x.png"}));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "missing.png")) << r.err;
  EXPECT_EQ(dir.listing(), before);
}

// A textured mesh whose clipped triangles span more than the texture divide's w ratio (a strip of
// ground seen from a millimetre above it, from the near plane at 0.01 to 1000 away) is bad input with the texture unit, naming the
// object and triangle and what to do; without the unit its coordinates are ignored and it draws.
TEST(CliRender, TexturedMeshBeyondTheWRatioIsBadInput) {
  ScratchDir dir;
  // Two millimetres wide, so that no side of the guard band cuts it before the near plane does.
  dir.write("ground.obj", "v -0.001 0 1\nv 0.001 0 1\nv 0.001 0 -1000\nv -0.001 0 -1000\n"
                          "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n");
  const std::vector<std::string> args = {"render", "ground.obj", "--eye", "0,0.001,0", "--target", "0,0.001,-10", "--near",
                                         "0.01", "--far", "2000", "--width", "64", "--height", "48", "-o", "g.png"};
  std::vector<std::string> with_unit = args;
  with_unit.insert(with_unit.end(), {"--texture-unit", "true"});
  RunResult r = run_rastersim(dir, with_unit);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "object 1, triangle 1: textured, and the largest w")) << r.err;
  EXPECT_TRUE(contains(r.err, "move the near plane out")) << r.err;
  EXPECT_FALSE(fs::exists(dir.path("g.png")));
  r = run_rastersim(dir, args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// The floor scene: perspective-correct and affine images differ (the affine one bends the checks).
TEST(CliRender, FloorSceneDiffersWithoutPerspective) {
  ScratchDir dir;
  for (const std::string perspective : {"true", "false"}) {
    const RunResult r = run_rastersim(dir, {"render", "--scene", "floor", "--texture-unit", "true", "--perspective",
                                            perspective, "--width", "160", "--height", "120", "--fragments",
                                            perspective + ".csv"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const Csv a = read_fragments_csv(dir.path("true.csv")), b = read_fragments_csv(dir.path("false.csv"));
  ASSERT_EQ(a.rows.size(), b.rows.size());
  size_t differ = 0;
  for (size_t i = 0; i < a.rows.size(); ++i)
    differ += a.rows[i].r != b.rows[i].r || a.rows[i].g != b.rows[i].g || a.rows[i].b != b.rows[i].b;
  EXPECT_GT(differ, a.rows.size() / 10) << "of " << a.rows.size();
}

#ifdef RASTERSIM_HAVE_RTL
// The RTL has the texture unit (configuration small_texture): the textured floor scene renders
// through the RTL and the co-simulation byte for byte as through the model; a vector package of it
// carries the scene's texture (256 x 256 texels) and the texture flags given (tests/vectors
// replays textured packages in Icarus).
TEST(CliRtl, TexturedSceneThroughTheRtlEqualsTheModel) {
  ScratchDir dir;
  for (const std::string backend : {"model", "rtl", "cosim"}) {
    const RunResult r = run_rastersim(dir, {"render", "--backend", backend, "--scene", "floor", "--width", "64",
                                            "--height", "48", "--texture-unit", "true", "-o", backend + ".png",
                                            "--fragments", backend + ".csv"});
    ASSERT_EQ(r.exit_code, 0) << backend << ": " << r.err;
  }
  EXPECT_EQ(read_text(dir.path("rtl.png")), read_text(dir.path("model.png")));
  EXPECT_EQ(read_text(dir.path("rtl.csv")), read_text(dir.path("model.csv")));
  EXPECT_EQ(read_text(dir.path("cosim.csv")), read_text(dir.path("model.csv")));
  const RunResult v = run_rastersim(dir, {"vectors", "--scene", "floor", "--width", "16", "--height", "12",
                                          "--texture-unit", "true", "--texture-filter", "nearest", "--out", "package"});
  ASSERT_EQ(v.exit_code, 0) << v.err;
  const std::string texels = read_text(dir.path("package/texture.hex"));
  EXPECT_EQ(std::count(texels.begin(), texels.end(), '\n'), 256 * 256);
  const std::string params = read_text(dir.path("package/rastersim_vectors_params.vh"));
  EXPECT_TRUE(contains(params, "localparam [0:0] CFG_TEXTURE_BILINEAR = 1'd0;")) << params;
  EXPECT_TRUE(contains(params, "localparam [3:0] CFG_TEXTURE_LOG2_WIDTH = 4'd8;")) << params;
  EXPECT_TRUE(contains(read_text(dir.path("package/manifest.json")), "--scene floor --texture-filter nearest"));
}
#endif

#ifdef RASTERSIM_HAVE_RTL
// The RTL has the floating-point depth word and the depth bias (configuration small_depth): a scene
// in a biased floating-point 1/w buffer renders through the RTL and the co-simulation byte for byte
// as through the model, cosim says what its random frames draw, and a vector package carries it
// (tests/vectors replays such a package in Icarus).
TEST(CliRtl, BiasedFloatingPointDepthThroughTheRtlEqualsTheModel) {
  ScratchDir dir;
  const std::vector<std::string> depth = {"--width", "64", "--height", "48", "--setup-interval", "64",
                                          "--depth-buffer", "inverse_w", "--depth-func", "greater",
                                          "--depth-exponent-bits", "3", "--depth-bias-constant", "-20",
                                          "--depth-bias-slope", "1.5"};
  for (const std::string backend : {"model", "rtl", "cosim"}) {
    std::vector<std::string> args = {"render", "--backend", backend, "--scene", "default", "-o", backend + ".png",
                                     "--fragments", backend + ".csv"};
    args.insert(args.end(), depth.begin(), depth.end());
    const RunResult r = run_rastersim(dir, args);
    ASSERT_EQ(r.exit_code, 0) << backend << ": " << r.err;
  }
  EXPECT_EQ(read_text(dir.path("rtl.png")), read_text(dir.path("model.png")));
  EXPECT_EQ(read_text(dir.path("rtl.csv")), read_text(dir.path("model.csv")));
  EXPECT_EQ(read_text(dir.path("cosim.csv")), read_text(dir.path("model.csv")));
  std::vector<std::string> cosim = {"cosim", "--count", "5"};
  cosim.insert(cosim.end(), depth.begin(), depth.begin() + 6);
  cosim.insert(cosim.end(), {"--depth-exponent-bits", "3", "--depth-bias-slope", "1"});
  const RunResult c = run_rastersim(dir, cosim);
  ASSERT_EQ(c.exit_code, 0) << c.out << c.err;
  EXPECT_TRUE(contains(c.out + c.err, "Ne=3")) << c.out << c.err;
  EXPECT_TRUE(contains(c.out + c.err, "random frames draw its constant and slope factor, each of either sign"))
      << c.out << c.err;
  std::vector<std::string> vectors = {"vectors", "--suite", "depth", "--out", "package"};
  vectors.insert(vectors.end(), depth.begin(), depth.end());
  const RunResult v = run_rastersim(dir, vectors);
  ASSERT_EQ(v.exit_code, 0) << v.err;
  const std::string params = read_text(dir.path("package/rastersim_vectors_params.vh"));
  EXPECT_TRUE(contains(params, "localparam integer DEPTH_EXPONENT_BITS = 3;")) << params;
  EXPECT_TRUE(contains(params, "CFG_DEPTH_BIAS_SLOPE = 8'd24;")) << params;
}
#endif

#ifdef RASTERSIM_HAVE_RTL
// The RTL backend gives byte-identical images, fragment trace and counters to the model (the
// comparison is the product's claim; the co-simulation suite checks it transaction by transaction).
TEST(CliRtl, RtlBackendEqualsModelByteForByte) {
  ScratchDir dir;
  const std::vector<std::string> common = {"--scene", "fan", "--width", "64", "--height", "48", "--traversal", "bbox"};
  for (const std::string backend : {"model", "rtl", "cosim"}) {
    std::vector<std::string> args = {"render", "--backend", backend, "-o", backend + ".png", "--depth-out",
                                     backend + ".exr", "--fragments", backend + ".csv", "--stats", backend + ".json"};
    args.insert(args.end(), common.begin(), common.end());
    const RunResult r = run_rastersim(dir, args);
    ASSERT_EQ(r.exit_code, 0) << backend << ": " << r.err;
  }
  for (const std::string backend : {"rtl", "cosim"}) {
    for (const std::string ext : {".png", ".csv", ".json"})
      EXPECT_EQ(read_text(dir.path("model" + ext)), read_text(dir.path(backend + ext))) << backend << ext;
    // EXR headers carry a capture date: compare the depth pixels.
    EXPECT_EQ(read_image(dir.path("model.exr")).pixels, read_image(dir.path(backend + ".exr")).pixels) << backend;
  }
  EXPECT_GT(read_json(dir.path("rtl.json"))["fragments"].get<int64_t>(), 0);
}

TEST(CliRtl, CosimEndsWithPassedLine) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"cosim", "--count", "3", "--width", "64", "--height", "48", "--seed", "7"});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::string last = r.out.substr(r.out.rfind('\n', r.out.size() - 2) + 1);
  EXPECT_TRUE(contains(last, " passed, 0 failed")) << r.out;
  EXPECT_NE(last.rfind("0 passed", 0), 0u) << r.out;  // frames ran (the count may end in 0)
}

// The testcase names of a JUnit file, in order.
std::vector<std::string> junit_testcases(const fs::path& path) {
  const std::string xml = read_text(path);
  std::vector<std::string> names;
  const std::string tag = "<testcase classname=\"rastersim.cosim\" name=\"";
  for (size_t at = xml.find(tag); at != std::string::npos; at = xml.find(tag, at + 1)) {
    const size_t begin = at + tag.size();
    names.push_back(xml.substr(begin, xml.find('"', begin) - begin));
  }
  return names;
}

// Shards split the frames of a run without overlap or loss, each frame keeping its seed, so the
// shards' JUnit files together hold exactly the unsharded run's testcases.
TEST(CliRtl, CosimShardsPartitionTheRunAndWriteJunit) {
  ScratchDir dir;
  const std::vector<std::string> common = {"cosim", "--count", "7", "--width", "64", "--height", "48", "--seed", "11"};
  auto run = [&](const std::string& shard, const std::string& junit) {
    std::vector<std::string> args = common;
    args.insert(args.end(), {"--shard", shard, "--junit", junit});
    const RunResult r = run_rastersim(dir, args);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    return r;
  };
  run("1/1", "all.xml");
  const std::vector<std::string> all = junit_testcases(dir.path("all.xml"));
  ASSERT_GT(all.size(), 7u);  // the directed frames and the random ones
  EXPECT_TRUE(contains(read_text(dir.path("all.xml")), "tests=\"" + std::to_string(all.size()) + "\" failures=\"0\""));
  std::multiset<std::string> merged;
  int64_t passed = 0;
  for (int k = 1; k <= 3; ++k) {
    const std::string file = "shard" + std::to_string(k) + ".xml";
    const RunResult r = run(std::to_string(k) + "/3", file);
    const std::vector<std::string> names = junit_testcases(dir.path(file));
    EXPECT_TRUE(contains(r.out, std::to_string(names.size()) + " passed, 0 failed")) << r.out;
    passed += int64_t(names.size());
    merged.insert(names.begin(), names.end());
  }
  EXPECT_EQ(passed, int64_t(all.size()));
  EXPECT_EQ(merged, std::multiset<std::string>(all.begin(), all.end()));
}

// Random frames draw the runtime settings a flag does not pin, from the frame's seed.
TEST(CliRtl, CosimRandomFramesVaryTheSettingsThatAreNotPinned) {
  ScratchDir dir;
  const std::vector<std::string> common = {"cosim", "--count", "12", "--no-directed", "--no-coverage-gate",
                                           "--width", "64", "--height", "48", "--junit", "j.xml"};
  ASSERT_EQ(run_rastersim(dir, common).exit_code, 0);
  std::set<std::string> functions;
  for (const std::string& name : junit_testcases(dir.path("j.xml")))
    for (const char* f : {"never", "less,", "equal", "lequal", "greater", "notequal", "gequal", "always"})
      if (contains(name, std::string("depth ") + f)) functions.insert(f);
  EXPECT_GE(functions.size(), 3u);

  std::vector<std::string> pinned = common;
  pinned.insert(pinned.end(), {"--depth-func", "lequal", "--traversal", "bbox"});
  const RunResult r = run_rastersim(dir, pinned);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const std::string& name : junit_testcases(dir.path("j.xml"))) {
    EXPECT_TRUE(contains(name, "bbox,") && contains(name, "depth lequal")) << name;
  }
  EXPECT_FALSE(contains(r.out, "draw depth_func")) << r.out;
}

// `cosim --count 100` at 64x48 reaches every reachable coverage bin: the table says so, the JSON
// lists each bin with its hits, and the run exits 0.
TEST(CliRtl, CosimCoverageTableShowsEveryReachableBinHit) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"cosim", "--count", "100", "--width", "64", "--height", "48",
                                          "--coverage", "coverage.json"});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "functional coverage (hits, frames):")) << r.out;
  EXPECT_FALSE(contains(r.out, "NOT HIT")) << r.out;
  // docs/rtl.md shows an excerpt of this run's table.
  std::ifstream doc(RASTERSIM_SOURCE_DIR "/docs/rtl.md");
  std::string line;
  int shown = 0;
  for (bool inside = false; std::getline(doc, line);) {
    if (line == "```text cosim-coverage") inside = true;
    else if (inside && line == "```") break;
    else if (inside) {
      EXPECT_TRUE(contains(r.out, line + "\n")) << "docs/rtl.md: " << line;
      ++shown;
    }
  }
  EXPECT_GE(shown, 4);
  const auto j = read_json(dir.path("coverage.json"));
  EXPECT_TRUE(j["gated"].get<bool>());
  EXPECT_TRUE(j["holes"].empty());
  int reachable = 0, unreachable = 0;
  for (const auto& bin : j["bins"]) {
    const std::string name = bin["name"].get<std::string>();
    if (bin["reachable"].get<bool>()) {
      ++reachable;
      EXPECT_GT(bin["hits"].get<int64_t>(), 0) << name;
      EXPECT_GT(bin["frames"].get<int64_t>(), 0) << name;
      EXPECT_TRUE(contains(r.out, name)) << name;
    } else {
      ++unreachable;
      EXPECT_FALSE(bin["unreachable"].get<std::string>().empty()) << name;
    }
  }
  EXPECT_GE(reachable, 40);
  // Never passing, always failing, memory back-pressure on chip; the depth bias's four and the
  // texture unit's eight, which this build lacks.
  EXPECT_EQ(unreachable, 15);
  // Per frame: the frames of the run, each with the bins it hit; the totals are their sums.
  std::map<std::string, int64_t> summed;
  for (const auto& frame : j["frames"])
    for (const auto& [name, hits] : frame["hits"].items()) summed[name] += hits.get<int64_t>();
  for (const auto& bin : j["bins"])
    EXPECT_EQ(summed[bin["name"].get<std::string>()], bin["hits"].get<int64_t>()) << bin["name"];
}

// A whole run whose frames leave a reachable bin at zero exits 1 and names the bin; the gate can be
// switched off, and a shard (a part of a run) is not held to it.
TEST(CliRtl, CosimExitsOneWhenAReachableBinStaysAtZero) {
  ScratchDir dir;
  const std::vector<std::string> one = {"cosim", "--count", "1", "--no-directed", "--width", "64", "--height", "48"};
  RunResult r = run_rastersim(dir, one);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "1 passed, 0 failed")) << r.out;
  EXPECT_TRUE(contains(r.out, "NOT HIT")) << r.out;
  EXPECT_TRUE(contains(r.out, "reachable bins not hit:")) << r.out;
  std::vector<std::string> args = one;
  args.push_back("--no-coverage-gate");
  r = run_rastersim(dir, args);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "(--no-coverage-gate)")) << r.out;
  args = one;
  args.insert(args.end(), {"--shard", "1/2"});
  r = run_rastersim(dir, args);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "(a shard: not gated)")) << r.out;
}

// junit-merge: the shards' files as one, holding exactly the unsharded run's frames; overlapping
// inputs and foreign files are refused; a merged failure gives exit 1.
TEST(CliRtl, JunitMergeOfShardsIsTheWholeRun) {
  ScratchDir dir;
  const std::vector<std::string> run = {"cosim", "--count", "6", "--width", "64", "--height", "48", "--seed", "3"};
  std::vector<std::string> args = run;
  args.insert(args.end(), {"--junit", "all.xml"});
  ASSERT_EQ(run_rastersim(dir, args).exit_code, 0);
  for (const char* k : {"1", "2"}) {
    args = run;
    args.insert(args.end(), {"--shard", std::string(k) + "/2", "--junit", std::string("s") + k + ".xml"});
    ASSERT_EQ(run_rastersim(dir, args).exit_code, 0);
  }
  RunResult r = run_rastersim(dir, {"junit-merge", "-o", "merged.xml", "s1.xml", "s2.xml"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> merged = junit_testcases(dir.path("merged.xml")), all = junit_testcases(dir.path("all.xml"));
  std::sort(merged.begin(), merged.end());
  std::sort(all.begin(), all.end());
  EXPECT_EQ(merged, all);
  EXPECT_TRUE(contains(read_text(dir.path("merged.xml")), "<testsuites tests=\"" + std::to_string(all.size()) +
                                                              "\" failures=\"0\""));
  EXPECT_TRUE(contains(r.out, "merged 2 files: " + std::to_string(all.size()) + " frames, 0 failed")) << r.out;
  r = run_rastersim(dir, {"junit-merge", "-o", "twice.xml", "s1.xml", "s1.xml"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "is in another input too")) << r.err;
  dir.write("other.xml", "<testsuites><testsuite name=\"other\" tests=\"1\"></testsuite></testsuites>\n");
  EXPECT_EQ(run_rastersim(dir, {"junit-merge", "-o", "x.xml", "other.xml"}).exit_code, 2);
  // A shard whose frame failed (its file edited as a failing run writes it).
  std::string failing = read_text(dir.path("s2.xml"));
  failing.replace(failing.find("failures=\"0\""), 14, "failures=\"1\"");
  failing.replace(failing.find("failures=\"0\"", failing.find("<testsuite ")), 14, "failures=\"1\"");
  dir.write("failing.xml", failing);
  r = run_rastersim(dir, {"junit-merge", "-o", "m2.xml", "s1.xml", "failing.xml"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(contains(r.out, "1 failed")) << r.out;
  // An output naming an input, and a number that is not one, are refused with the file named.
  const std::string shard1 = read_text(dir.path("s1.xml"));
  EXPECT_EQ(run_rastersim(dir, {"junit-merge", "-o", "s1.xml", "s1.xml", "s2.xml"}).exit_code, 2);
  EXPECT_EQ(read_text(dir.path("s1.xml")), shard1);
  std::string garbled = shard1;
  garbled.replace(garbled.find("tests=\"", garbled.find("<testsuite ")), 7, "tests=\"x");
  dir.write("garbled.xml", garbled);
  r = run_rastersim(dir, {"junit-merge", "-o", "g.xml", "garbled.xml"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "garbled.xml")) << r.err;
  // An incomplete set of shards, and shards of two runs, are not a whole run.
  r = run_rastersim(dir, {"junit-merge", "-o", "part.xml", "s1.xml"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "not a whole run: shard 2/2 missing")) << r.err;
  args = run;
  args[args.size() - 1] = "4";  // --seed 4: another run
  args.insert(args.end(), {"--shard", "2/2", "--junit", "other_seed.xml"});
  ASSERT_EQ(run_rastersim(dir, args).exit_code, 0);
  r = run_rastersim(dir, {"junit-merge", "-o", "mixed.xml", "s1.xml", "other_seed.xml"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "other_seed.xml: a shard of another run")) << r.err;
  EXPECT_FALSE(fs::exists(dir.path("twice.xml")));
  EXPECT_FALSE(fs::exists(dir.path("x.xml")));
  EXPECT_FALSE(fs::exists(dir.path("part.xml")));
  EXPECT_FALSE(fs::exists(dir.path("mixed.xml")));
}

TEST(CliRtl, CosimRejectsABadShardAndWritesNothing) {
  ScratchDir dir;
  for (const char* shard : {"0/2", "3/2", "1/0", "a/b", "1/2/3"}) {
    const RunResult r =
        run_rastersim(dir, {"cosim", "--count", "1", "--width", "64", "--height", "48", "--shard", shard, "--junit", "j.xml"});
    EXPECT_EQ(r.exit_code, 2) << shard;
    EXPECT_TRUE(contains(r.err, "--shard")) << r.err;
  }
  EXPECT_TRUE(dir.listing().empty());
}

// `--junit -`: the XML alone on standard output, the report on standard error.
TEST(CliRtl, CosimJunitOnStandardOutput) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"cosim", "--count", "1", "--no-directed", "--no-coverage-gate", "--width",
                                          "64", "--height", "48", "--junit", "-"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("<?xml", 0), 0u) << r.out;
  EXPECT_FALSE(contains(r.out, "passed,")) << r.out;
  EXPECT_TRUE(contains(r.err, "1 passed, 0 failed")) << r.err;
  EXPECT_TRUE(dir.listing().empty());
}

// Start-up: a command loads OpenImageIO (about 250 libraries) only to write an image, and SystemC
// only to run it; `rastersim scenes` once took 0.6 s loading 264 libraries.
TEST(Cli, HeavyLibrariesAreLoadedOnlyByTheCommandsThatUseThem) {
  ScratchDir dir;
  auto loaded = [&](const std::vector<std::string>& args) {
    setenv("LD_DEBUG", "files", 1);  // the dynamic loader names every library it opens on stderr
    const RunResult r = run_rastersim(dir, args);
    unsetenv("LD_DEBUG");
    EXPECT_EQ(r.exit_code, 0) << r.err.substr(r.err.size() > 2000 ? r.err.size() - 2000 : 0);
    return std::pair<bool, bool>{contains(r.err, "libOpenImageIO"), contains(r.err, "libsystemc")};
  };
  EXPECT_EQ(loaded({"scenes"}), std::make_pair(false, false));
  EXPECT_EQ(loaded({"render", "--scene", "fan", "--stats", "s.json"}), std::make_pair(false, false));
  EXPECT_EQ(loaded({"render", "--scene", "fan", "-o", "fan.png"}), std::make_pair(false, false));  // PNG: libpng
  EXPECT_EQ(loaded({"render", "--scene", "fan", "--depth-out", "fan.exr"}), std::make_pair(true, false));
#ifdef RASTERSIM_HAVE_SYSTEMC
  EXPECT_EQ(loaded({"render", "--scene", "overlap", "--backend", "systemc", "--stats", "t.json"}),
            std::make_pair(false, true));
#endif
  EXPECT_GT(read_text(dir.path("fan.png")).size(), 100u);
}

TEST(Cli, VersionNamesTheReleaseAndTheCommit) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"--version"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("rastersim 0.1.0 (", 0), 0u) << r.out;
  EXPECT_FALSE(contains(r.out, "subcommand")) << r.out;
}

// Camera flags on a screen-space input were ignored without a word.
TEST(Cli, CameraFlagsOnAScreenSpaceInputAreRefused) {
  ScratchDir dir;
  dir.write("one.tri", "2 1.5 0.25 13.25 4 0.5 5.5 10 0.75 255 128 0\n");
  for (const std::vector<std::string>& input : {std::vector<std::string>{"one.tri"},
                                                std::vector<std::string>{"--scene", "fan"}}) {
    std::vector<std::string> args = {"render"};
    args.insert(args.end(), input.begin(), input.end());
    args.insert(args.end(), {"-o", "x.png", "--eye", "1,2,3"});
    const RunResult r = run_rastersim(dir, args);
    EXPECT_EQ(r.exit_code, 2) << input.back();
    EXPECT_TRUE(contains(r.err, "already in screen space")) << r.err;
  }
  EXPECT_EQ(dir.listing(), std::set<std::string>{"one.tri"});
}

// An input linked to /dev/zero, or a line of millions of tokens, once read for a minute into
// gigabytes and ended in bad_alloc with no file or line: each input kind has a bound.
TEST(Cli, EndlessOrHugeInputsEndWithAnErrorNamingTheFile) {
  ScratchDir dir;
  for (const char* name : {"zero.tri", "zero.json", "zero.obj"})
    ASSERT_EQ(symlink("/dev/zero", dir.path(name).c_str()), 0);
  std::string line;
  for (int i = 0; i < 600000; ++i) line += "1 ";  // 1.2 MB on one line
  dir.write("long.tri", line + "\n");
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  for (const Case& c : std::vector<Case>{
           // A device is refused before it is opened; a regular file past the bound when read.
           {{"render", "zero.tri"}, "zero.tri: is not a regular file (a device, FIFO or socket)"},
           {{"render", "long.tri"}, "long.tri:1: the line is longer than 1 MiB"},
           {{"render", "--scene", "fan", "--profile", "zero.json"}, "zero.json: is not a regular file"},
           {{"render", "zero.json"}, "zero.json: is not a regular file"},
           {{"render", "zero.obj"}, "zero.obj: is not a regular file"}}) {
    std::vector<std::string> args = c.args;
    args.insert(args.end(), {"--stats", "s.json"});
    const RunResult r = run_rastersim(dir, args);
    EXPECT_EQ(r.exit_code, 2) << c.args.back();
    EXPECT_TRUE(contains(r.err, c.message)) << r.err;
  }
  EXPECT_EQ(dir.listing(), (std::set<std::string>{"zero.tri", "zero.json", "zero.obj", "long.tri"}));
}

// cosim's help once hid its defaults and showed the flag as `--no-directed{false}`.
TEST(CliRtl, CosimHelpShowsDefaultsAndPlainFlags) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"cosim", "--help"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_TRUE(contains(r.out, "after the directed ones (default 100)")) << r.out;
  EXPECT_TRUE(contains(r.out, "per random frame (default 16)")) << r.out;
  EXPECT_TRUE(contains(r.out, "--no-directed ")) << r.out;
  EXPECT_FALSE(contains(r.out, "{false}")) << r.out;
}

// --replay-dir was once accepted silently with any backend and any folder, existing or not.
TEST(Cli, ReplayFolderWrongUsesAreErrors) {
  ScratchDir dir;
  dir.write("one.tri", "2 1.5 0.25 13.25 4 0.5 5.5 10 0.75 255 128 0\n");
  const RunResult model = run_rastersim(dir, {"render", "one.tri", "--stats", "s.json", "--replay-dir", "."});
  EXPECT_EQ(model.exit_code, 2);
  EXPECT_TRUE(contains(model.err, "--replay-dir needs --backend cosim")) << model.err;
  const RunResult missing = run_rastersim(
      dir, {"render", "one.tri", "--stats", "s.json", "--backend", "cosim", "--replay-dir", "no/such/folder"});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_TRUE(contains(missing.err, "folder 'no/such/folder' does not exist")) << missing.err;
  EXPECT_EQ(dir.listing(), std::set<std::string>{"one.tri"});  // nothing written
}

// --fst once wrote nothing and exited 0 with the model backend, into a missing folder or a folder.
TEST(CliRtl, WaveformWrongUsesAreErrorsAndAWaveformIsWrittenWhole) {
  ScratchDir dir;
  const std::vector<std::string> render = {"render", "--scene", "fan", "--width", "64", "--height", "48"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = render;
    args.insert(args.end(), extra.begin(), extra.end());
    return run_rastersim(dir, args);
  };
  struct Case {
    std::vector<std::string> args;
    const char* message;
  };
  const Case wrong[] = {
      {{"--fst", "w.fst"}, "--wave needs --backend rtl or cosim"},
      {{"--backend", "rtl", "--wave", "w.txt"}, "must end in .fst or .vcd"},
      {{"--backend", "rtl", "--wave-from", "5"}, "--wave-from needs --wave FILE"},
      {{"--backend", "rtl", "--wave", "w.vcd", "--wave-from", "10", "--wave-to", "5"}, "is after --wave-to 5"},
      {{"--backend", "rtl", "--wave", "w.vcd", "--wave-from", "-3"}, "0 or more"},
      {{"--backend", "rtl", "--wave", "w.vcd", "--wave-from", "100000000"}, "is past the frame's last cycle"},
      {{"--backend", "rtl", "--wave", "w.fst", "--stats", "w.fst.gtkw"}, "named by two outputs"},
      {{"--backend", "rtl", "--fst", dir.path("missing/w.fst")}, "does not exist"},
      {{"--backend", "rtl", "--fst", dir.path("")}, "it is a folder"},
      {{"--backend", "rtl", "--fst", "-"}, "cannot go to standard output"},
      {{"--backend", "cosim", "--fst", "w.fst", "--stats", "w.fst"}, "named by two outputs"},
  };
  for (const Case& c : wrong) {
    const RunResult r = with(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.message;
    EXPECT_TRUE(contains(r.err, c.message)) << r.err;
    EXPECT_TRUE(dir.listing().empty()) << c.message;
  }
  for (const std::string backend : {"rtl", "cosim"}) {
    const RunResult r = with({"--backend", backend, "--fst", backend + ".fst"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_text(dir.path(backend + ".fst")).substr(0, 1), std::string(1, '\0')) << "an FST header";
    EXPECT_GT(read_text(dir.path(backend + ".fst")).size(), 1000u);
  }
  EXPECT_EQ(dir.listing(), (std::set<std::string>{"rtl.fst", "rtl.fst.gtkw", "cosim.fst", "cosim.fst.gtkw"}))
      << "no temporaries left";
  const RunResult cosim = run_rastersim(dir, {"cosim", "--count", "1", "--no-directed", "--no-coverage-gate", "--width",
                                              "64", "--height", "48", "--fst", "frames.fst"});
  ASSERT_EQ(cosim.exit_code, 0) << cosim.err;
  EXPECT_GT(read_text(dir.path("frames.fst")).size(), 1000u);
  EXPECT_EQ(run_rastersim(dir, {"cosim", "--count", "1", "--width", "64", "--height", "48", "--fst", "-"}).exit_code, 2);
}

// cosim's outputs must not be its profile file: --junit, --coverage and --export's replays wrote
// over it.
TEST(CliRtl, CosimOutputsThatAreTheProfileAreRefused) {
  ScratchDir dir;
  const std::string profile = "{\"width\": 64, \"height\": 48}\n";
  fs::create_directory(dir.path("replays"));
  for (const std::vector<std::string>& outputs :
       {std::vector<std::string>{"--junit", "p.json"}, std::vector<std::string>{"--coverage", "p.json"},
        std::vector<std::string>{"--export", "replays", "--frame", "0"}}) {
    const std::string profile_name = outputs[0] == "--export" ? "replays/frame-0.json" : "p.json";
    dir.write(profile_name, profile);
    std::vector<std::string> args = {"cosim", "--count", "1", "--no-directed", "--no-coverage-gate", "--profile",
                                     profile_name};
    args.insert(args.end(), outputs.begin(), outputs.end());
    const RunResult r = run_rastersim(dir, args);
    EXPECT_EQ(r.exit_code, 2) << outputs[0] << ": " << r.err;
    EXPECT_TRUE(contains(r.err, "is an input of this run")) << r.err;
    EXPECT_EQ(read_text(dir.path(profile_name)), profile) << outputs[0];
    EXPECT_FALSE(fs::exists(dir.path("replays/frame-0.tri"))) << outputs[0];
  }
}

// A design's file list and sources are inputs too: an output naming one is refused before anything
// is built, and the file is left as it was.
TEST(CliRtl, CosimOutputsThatAreTheDesignsFilesAreRefused) {
  ScratchDir dir;
  fs::create_directory(dir.path("design"));
  const std::string source = "module my_design(input wire clk);\nendmodule\n";
  dir.write("design/my_design.sv", source);
  dir.write("design.f", "design/my_design.sv\n");
  for (const std::string& dut : {std::string("design.f"), std::string("design")}) {
    for (const std::vector<std::string>& outputs :
         {std::vector<std::string>{"--junit", "design/my_design.sv"}, std::vector<std::string>{"--coverage", "design.f"},
          std::vector<std::string>{"--coverage", "design/my_design.sv"}}) {
      if (dut == "design" && outputs[1] == "design.f") continue;  // a folder has no file list
      std::vector<std::string> args = {"cosim", "--count", "1", "--dut", dut, "--top", "my_design"};
      args.insert(args.end(), outputs.begin(), outputs.end());
      const RunResult r = run_rastersim(dir, args);
      EXPECT_EQ(r.exit_code, 2) << dut << " " << outputs[0] << ": " << r.err;
      EXPECT_TRUE(contains(r.err, "is an input of this run")) << r.err;
      EXPECT_EQ(read_text(dir.path("design/my_design.sv")), source);
      EXPECT_EQ(read_text(dir.path("design.f")), "design/my_design.sv\n");
    }
  }
}

// An FST waveform into a FIFO (or a link to one) is streamed into it: the FST writer, which
// seeks, writes a temporary that is copied in. The FIFO was replaced by a regular file.
TEST(CliRtl, AnFstWaveformIntoAFifoIsStreamedNotReplaced) {
  ScratchDir dir;
  const fs::path fifo = dir.path("w.fifo");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  fs::create_symlink("w.fifo", dir.path("link.fst"));
  ASSERT_EQ(mkfifo(dir.path("w.fst").c_str(), 0600), 0);
  for (const std::string name : {"w.fst", "link.fst"}) {
    const fs::path read_end = name == "w.fst" ? dir.path("w.fst") : fifo;
    // Read while the run writes: the waveform is larger than a pipe's buffer.
    const int fd = open(read_end.c_str(), O_RDWR | O_NONBLOCK);
    ASSERT_GE(fd, 0);
    std::atomic<bool> finished{false};
    std::string received;
    std::thread reader([&] {
      char buffer[65536];
      for (;;) {
        const ssize_t n = read(fd, buffer, sizeof buffer);
        if (n > 0) received.append(buffer, size_t(n));
        else if (finished) break;
        else usleep(1000);
      }
    });
    const RunResult r = run_rastersim(dir, {"cosim", "--count", "1", "--no-directed", "--no-coverage-gate", "--width",
                                            "64", "--height", "48", "--wave", name});
    finished = true;
    reader.join();
    close(fd);
    EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
    EXPECT_TRUE(fs::is_fifo(fs::symlink_status(read_end))) << name << " was replaced";
    EXPECT_GT(received.size(), 1000u) << name;
    EXPECT_EQ(received.substr(0, 1), std::string(1, '\0')) << "an FST header";
  }
  EXPECT_TRUE(fs::is_symlink(dir.path("link.fst")));
  EXPECT_EQ(dir.listing(), (std::set<std::string>{"w.fifo", "w.fst", "link.fst", "w.fst.gtkw", "link.fst.gtkw"}));
}

// A VCD waveform's signals by full name ("scope.scope.name[9:0]" as GTKWave spells them) and the
// values each took, for the frame-cycle counter.
struct Vcd {
  std::set<std::string> names;
  std::vector<int64_t> frame_cycles;
  std::map<int64_t, int64_t> frame_cycle_time;  // value -> time of its first appearance
  std::string without_date;  // the file without its $date block (two runs' dumps compare equal)
};
Vcd read_vcd(const fs::path& path) {
  Vcd vcd;
  std::ifstream in(path);
  std::vector<std::string> scope;
  std::set<std::string> frame_cycle_ids;
  bool in_date = false;
  int64_t time = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("$date", 0) == 0) in_date = true;
    if (!in_date) vcd.without_date += line + "\n";
    if (in_date && line.find("$end") != std::string::npos) in_date = false;
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;) w.push_back(word);
    if (w.empty()) continue;
    if (w[0] == "$scope" && w.size() > 2) scope.push_back(w[2]);
    else if (w[0] == "$upscope" && !scope.empty()) scope.pop_back();
    else if (w[0] == "$var" && w.size() > 5) {
      std::string name;
      for (const std::string& s : scope) name += s + ".";
      name += w[4] + (w[5] != "$end" ? w[5] : "");
      vcd.names.insert(name);
      if (!scope.empty() && scope.back() == "debug" && w[4] == "frame_cycle") frame_cycle_ids.insert(w[3]);
    } else if (w[0][0] == '#') {
      time = std::stoll(w[0].substr(1));
    } else if (w[0][0] == 'b' && w.size() == 2 && frame_cycle_ids.count(w[1])) {
      vcd.frame_cycles.push_back(std::stoll(w[0].substr(1), nullptr, 2));
      vcd.frame_cycle_time.emplace(vcd.frame_cycles.back(), time);
    }
  }
  return vcd;
}

// --wave FILE.vcd with a window: the dump holds exactly frame cycles 100..120 (the debug monitor's
// frame_cycle goes from 100 to 121 at the last rising edge), and the GTKWave save file beside it
// opens it and names only signals the dump has, grouped per unit.
TEST(CliRtl, WaveWindowAsVcdWithAGtkwaveSaveFile) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"render", "--scene", "fan", "--width", "64", "--height", "48", "--backend", "rtl",
                                          "--wave", "w.vcd", "--wave-from", "100", "--wave-to", "120"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(dir.listing(), (std::set<std::string>{"w.vcd", "w.vcd.gtkw"})) << "no FST scratch file left";
  const Vcd vcd = read_vcd(dir.path("w.vcd"));
  ASSERT_FALSE(vcd.frame_cycles.empty());
  EXPECT_EQ(*std::min_element(vcd.frame_cycles.begin(), vcd.frame_cycles.end()), 100);
  EXPECT_EQ(*std::max_element(vcd.frame_cycles.begin(), vcd.frame_cycles.end()), 121);
  // docs/debugging.md: frame cycle c's rising edge is at time 2 (4 + ceil(W H / 64) + c) + 1 and
  // shows frame_cycle c + 1 (4 reset cycles, 48 clear cycles at 64 x 48).
  EXPECT_EQ(vcd.frame_cycle_time.at(101), 2 * (4 + 48 + 100) + 1);
  const std::string save = read_text(dir.path("w.vcd.gtkw"));
  EXPECT_TRUE(contains(save, "[dumpfile] \"" + fs::absolute(dir.path("w.vcd")).string() + "\"")) << save;
  int signals = 0;
  std::set<std::string> groups;
  std::istringstream lines(save);
  std::string previous;
  for (std::string line; std::getline(lines, line); previous = line) {
    if (previous == "@800200") groups.insert(line.substr(1));
    if (line.empty() || line[0] == '@' || line[0] == '[' || line[0] == '-' || line[0] == '*') continue;
    ++signals;
    EXPECT_TRUE(vcd.names.count(line)) << "the save file names " << line << ", which the dump lacks";
  }
  EXPECT_GT(signals, 50);
  EXPECT_EQ(groups, (std::set<std::string>{"frame", "triangle_setup", "setup_fifo", "scanline_walker", "z_adder",
                                           "zbuffer", "zbuffer_memory"}));
  EXPECT_TRUE(contains(save, ".debug.frame_cycle[31:0]")) << save;
  // It opens on the window: from cycle 100's low phase (time 2 (4 + 48 + 100) = 304) to cycle 120's
  // edge (345), named markers A and B on them, zoomed to fit 42 time units into about 1000 pixels
  // (2^4 pixels per unit).
  EXPECT_TRUE(contains(save, "\n[timestart] 304\n")) << save;
  EXPECT_TRUE(contains(save, "\n*4.000000 -1 304 345 -1 ")) << save;
  EXPECT_TRUE(contains(save, "\n[markername] Awindow_start\n[markername] Bwindow_end\n")) << save;

  // An FST named like the VCD gets a save file of its own; the VCD's still opens the VCD.
  const RunResult fst = run_rastersim(dir, {"render", "--scene", "fan", "--width", "64", "--height", "48", "--backend",
                                            "rtl", "--wave", "w.fst"});
  ASSERT_EQ(fst.exit_code, 0) << fst.err;
  EXPECT_EQ(dir.listing(), (std::set<std::string>{"w.vcd", "w.vcd.gtkw", "w.fst", "w.fst.gtkw"}));
  EXPECT_EQ(read_text(dir.path("w.vcd.gtkw")), save);
  EXPECT_TRUE(contains(read_text(dir.path("w.fst.gtkw")), "[dumpfile] \"" + fs::absolute(dir.path("w.fst")).string() + "\""));
}

// cosim --export writes any frame as replay files; the printed command (power-on seed included)
// runs the very same frame: its waveform equals the one `cosim --frame K` dumps.
TEST(CliRtl, CosimExportedFrameReplaysExactly) {
  ScratchDir dir;
  const std::vector<std::string> run = {"cosim", "--count", "5", "--width", "64", "--height", "48", "--seed", "40"};
  std::vector<std::string> args = run;
  fs::create_directory(dir.path("frames"));
  args.insert(args.end(), {"--frame", "38", "--export", "frames"});
  RunResult r = run_rastersim(dir, args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "--seed 78")) << r.out;  // frame k's power-on seed is seed + k
  EXPECT_EQ(read_text(dir.path("frames/frame-38.txt")).rfind("frame 38: random seed 78", 0), 0u);
  args = run;
  args.insert(args.end(), {"--frame", "38", "--wave", "cosim.vcd"});
  r = run_rastersim(dir, args);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "1 passed, 0 failed")) << r.out;
  EXPECT_TRUE(contains(r.out, "(one frame: not gated)")) << r.out;
  r = run_rastersim(dir, {"render", "frames/frame-38.tri", "--profile", "frames/frame-38.json", "--backend", "rtl",
                          "--seed", "78", "--wave", "replay.vcd"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Vcd original = read_vcd(dir.path("cosim.vcd")), replayed = read_vcd(dir.path("replay.vcd"));
  EXPECT_GT(original.frame_cycles.size(), 10u);
  EXPECT_TRUE(original.without_date == replayed.without_date) << "the replay's waveform differs";
  // Wrong uses.
  for (const std::vector<std::string>& extra : {std::vector<std::string>{"--frame", "99"},
                                                std::vector<std::string>{"--export", "no/such/folder"},
                                                std::vector<std::string>{"--frame", "1", "--shard", "1/2"}}) {
    args = run;
    args.insert(args.end(), extra.begin(), extra.end());
    EXPECT_EQ(run_rastersim(dir, args).exit_code, 2) << extra[0];
  }
}

// The JUnit XML without its times (the only part that differs between runs).
std::string without_times(std::string xml) {
  for (size_t at = xml.find(" time=\""); at != std::string::npos; at = xml.find(" time=\"", at)) {
    const size_t end = xml.find('"', at + 7);
    xml.erase(at, end + 1 - at);
  }
  return xml;
}

// --jobs N runs frames in parallel and --threads 2 each frame's model beside its RTL; both report
// exactly what one job on one thread reports (run 4: two jobs of two threads).
TEST(CliRtl, CosimJobsAndThreadsGiveTheSameReportAsOneJob) {
  ScratchDir dir;
  std::map<int, RunResult> runs;
  for (const int jobs : {1, 2, 3, 4}) {
    const std::string j = std::to_string(jobs);
    runs[jobs] = run_rastersim(dir, {"cosim", "--count", "12", "--width", "64", "--height", "48", "--setup-interval", "2",
                                     "--jobs", jobs == 4 ? "2" : j, "--threads", jobs == 4 ? "2" : "1", "--junit",
                                     "j" + j + ".xml", "--coverage", "c" + j + ".json"});
    ASSERT_EQ(runs[jobs].exit_code, 0) << runs[jobs].err;
  }
  for (const int jobs : {2, 3, 4}) {
    const std::string j = std::to_string(jobs);
    EXPECT_EQ(runs[jobs].out, runs[1].out) << jobs;
    EXPECT_EQ(without_times(read_text(dir.path("j" + j + ".xml"))), without_times(read_text(dir.path("j1.xml")))) << jobs;
    EXPECT_EQ(read_text(dir.path("c" + j + ".json")), read_text(dir.path("c1.json"))) << jobs;
  }
  EXPECT_EQ(run_rastersim(dir, {"cosim", "--count", "1", "--width", "64", "--height", "48", "--jobs", "0"}).exit_code, 2);
  const RunResult three = run_rastersim(dir, {"cosim", "--count", "1", "--width", "64", "--height", "48", "--threads", "3"});
  EXPECT_EQ(three.exit_code, 2);
  EXPECT_NE(three.err.find("--threads 3 is outside 1..2"), std::string::npos) << three.err;
}

// A count whose frame indices overflow once ran no frame and reported "0 passed, 0 failed", exit 0.
TEST(CliRtl, CosimRefusesACountItCannotRun) {
  ScratchDir dir;
  for (const char* count : {"9223372036854775807", "1000000001", "-1"}) {
    const RunResult r = run_rastersim(dir, {"cosim", "--count", count, "--width", "64", "--height", "48"});
    EXPECT_EQ(r.exit_code, 2) << count;
    EXPECT_TRUE(contains(r.err, "--count")) << r.err;
    EXPECT_FALSE(contains(r.out, "passed")) << r.out;
  }
}

// A profile no configuration is built for is verilated on demand into the cache
// (scripts/check-modules-on-demand.sh builds one); a cache that cannot be made is an error naming it.
TEST(CliRtl, AProfileNotBuiltInNeedsAUsableModuleCache) {
  for (const std::vector<std::string>& command :
       {std::vector<std::string>{"cosim", "--count", "1", "--width", "100"},
        std::vector<std::string>{"render", "--backend", "rtl", "--width", "100", "-o", "out.png"}
#ifdef RASTERSIM_HAVE_SYSTEMC
        ,
        std::vector<std::string>{"render", "--backend", "systemc", "--width", "100", "-o", "out.png"}
#endif
       }) {
    ScratchDir dir;
    std::ofstream(dir.root() / "cache") << "a file where the cache folder would be\n";
    const RunResult r = run_rastersim(dir, command);
    EXPECT_EQ(r.exit_code, 2) << command[0];
    EXPECT_TRUE(contains(r.err, "cannot create the module cache")) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.work() / "out.png"));
  }
}
#endif

TEST(CliRender, ScenesAreListed) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"scenes"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* name : {"default", "overlap", "fan", "stress"}) EXPECT_TRUE(contains(r.out, name)) << r.out;
}

TEST(CliHelp, EverySubcommandHasHelp) {
  ScratchDir dir;
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"--help"}, {"render", "--help"}, {"bench", "--help"}, {"scenes", "--help"}}) {
    const RunResult r = run_rastersim(dir, args);
    EXPECT_EQ(r.exit_code, 0) << args[0];
    EXPECT_TRUE(contains(r.out, "Usage")) << r.out;
  }
  const RunResult render_help = run_rastersim(dir, {"render", "--help"});
  for (const char* flag : {"--subpixel-bits", "--z-bits", "--depth-func", "--memory-latency", "--profile", "--scene"})
    EXPECT_TRUE(contains(render_help.out, flag)) << flag;
  EXPECT_TRUE(dir.listing().empty());
}

TEST(CliBench, PrintsThroughput) {
  ScratchDir dir;
  const RunResult r = run_rastersim(
      dir, {"bench", "--triangles", "3000", "--size", "2..12", "--seed", "5", "--repeat", "2", "--width", "64", "--height", "48"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* part : {"triangles", "fragments", "per second", "candidates", "cycles"})
    EXPECT_TRUE(contains(r.out, part)) << r.out;
  EXPECT_TRUE(dir.listing().empty());
}

// --threads: the same image and stats at any thread count, on a built-in scene and textured.
TEST(CliThreads, RenderGivesTheSameFrameAtAnyThreadCount) {
  ScratchDir dir;
  for (const std::vector<std::string>& scene : {std::vector<std::string>{"--scene", "default", "--traversal", "bbox"},
                                                std::vector<std::string>{"--scene", "floor", "--texture-unit", "true",
                                                                         "--memory-stall-percent", "20"}}) {
    std::string image[2], stats[2];
    for (int k = 0; k < 2; ++k) {
      std::vector<std::string> args = {"render", "-o", "c.png", "--stats", "s.json", "--threads", k ? "3" : "1"};
      args.insert(args.end(), scene.begin(), scene.end());
      const RunResult r = run_rastersim(dir, args);
      ASSERT_EQ(r.exit_code, 0) << r.err;
      image[k] = read_text(dir.path("c.png"));
      stats[k] = read_text(dir.path("s.json"));
    }
    EXPECT_FALSE(image[0].empty());
    EXPECT_EQ(image[0], image[1]) << scene[1];
    EXPECT_EQ(stats[0], stats[1]) << scene[1];
  }
}

TEST(CliThreads, BenchChecksTheThreadedRender) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"bench", "--scene", "shapes", "--threads", "2", "--repeat", "1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "2 threads")) << r.out;
  EXPECT_TRUE(contains(r.out, "verified")) << r.out;
  const RunResult bad = run_rastersim(dir, {"bench", "--threads", "0"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_TRUE(dir.listing().empty());
}

// Bad input: exit 2, the message names what is wrong (file:line where there is one), and the run
// leaves no file behind, neither outputs nor temporaries.
struct BadRun {
  const char* name;
  const char* tri_line;  // written as line 3 of bad.tri (after a comment and a good line); null: no file
  std::vector<std::string> args;  // after "render", before the outputs
  const char* message;            // must appear on stderr
};

class CliBadInput : public ::testing::TestWithParam<BadRun> {};

TEST_P(CliBadInput, ExitsTwoWithMessageAndWritesNothing) {
  const BadRun& bad = GetParam();
  ScratchDir dir;
  std::set<std::string> before;
  if (bad.tri_line) {
    dir.write("bad.tri", std::string("# header\n0 0 0.5 10 0 0.5 0 10 0.5\n") + bad.tri_line + "\n1 1 0.5 9 1 0.5 1 9 0.5\n");
    before.insert("bad.tri");
  }
  if (std::string(bad.name) == "BadProfileFile") {
    dir.write("p.json", "{\n  \"width\": 32,\n  \"subpixel_bits\": \"four\"\n}\n");
    before.insert("p.json");
  }
  std::vector<std::string> args = {"render"};
  args.insert(args.end(), bad.args.begin(), bad.args.end());
  for (const char* out : {"-o", "--depth-out", "--fragments", "--stats"}) {
    if (std::find(bad.args.begin(), bad.args.end(), out) != bad.args.end()) continue;  // the case names it
    args.push_back(out);
    const std::string o = out;
    args.push_back(o == "-o" ? "color.png" : o == "--depth-out" ? "depth.exr" : o == "--fragments" ? "f.csv" : "s.json");
  }
  const RunResult r = run_rastersim(dir, args);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, bad.message)) << "stderr: " << r.err;
  EXPECT_EQ(dir.listing(), before);
  EXPECT_EQ(r.out, "");
}

INSTANTIATE_TEST_SUITE_P(
    AllKinds, CliBadInput,
    ::testing::Values(
        BadRun{"MalformedLine", "0 0 0.5 10 0 0.5 0 ten 0.5", {"bad.tri", "--width", "32", "--height", "24"},
               "bad.tri:3: y2 'ten' is not a number"},
        BadRun{"TruncatedLine", "0 0 0.5 10 0 0.5 0", {"bad.tri", "--width", "32", "--height", "24"},
               "bad.tri:3: expected 9 numbers"},
        BadRun{"NaN", "0 0 0.5 10 0 nan 0 10 0.5", {"bad.tri", "--width", "32", "--height", "24"},
               "bad.tri:3: z1 'nan' is not a finite number"},
        BadRun{"Inf", "0 0 0.5 10 0 0.5 -inf 10 0.5", {"bad.tri", "--width", "32", "--height", "24"},
               "bad.tri:3: x2 '-inf' is not a finite number"},
        BadRun{"DepthOutsideUnitRange", "0 0 0.5 10 0 0.5 0 10 1.5", {"bad.tri", "--width", "32", "--height", "24"},
               "bad.tri:3: z2 1.5 is outside the depth range [0, 1]"},
        BadRun{"OutsideGuardBand", "0 0 0.5 10 0 0.5 0 49 0.5", {"bad.tri", "--width", "32", "--height", "24"},
               "bad.tri:3: third vertex y 49"},
        BadRun{"BadColour", "0 0 0.5 10 0 0.5 0 10 0.5 1 2 300", {"bad.tri", "--width", "32", "--height", "24"},
               "bad.tri:3: b 300 is outside the colour range 0..255"},
        BadRun{"UnknownFlag", nullptr, {"--frobnicate", "3"}, "--frobnicate"},
        BadRun{"SubpixelBitsNine", nullptr, {"--subpixel-bits", "9"}, "subpixel_bits is 9; it must be in 1..8"},
        BadRun{"WidthZero", nullptr, {"--width", "0"}, "width is 0; it must be in 1..4096"},
        BadRun{"BothProfileErrors", nullptr, {"--width", "0", "--z-bits", "8"}, "z_bits is 8"},
        BadRun{"FlagNotANumber", nullptr, {"--height", "tall"}, "--height: height takes an integer, not 'tall'"},
        BadRun{"BadEnum", nullptr, {"--depth-func", "sometimes"}, "depth_func is 'sometimes'"},
        BadRun{"BadProfileFile", nullptr, {"--profile", "p.json"}, "p.json:3: "},
        BadRun{"MissingProfileFile", nullptr, {"--profile", "nope.json"}, "nope.json: cannot open"},
        BadRun{"MissingInputFile", nullptr, {"missing.tri"}, "missing.tri: cannot open"},
        BadRun{"UnknownInputType", nullptr, {"input.xyz"}, "input.xyz: unknown input type '.xyz'"},
        BadRun{"MissingObj", nullptr, {"mesh.obj"}, "mesh.obj"},
        BadRun{"NearZero", nullptr, {"--near", "0"}, "near"},
        BadRun{"NearBeyondFar", nullptr, {"--near", "5", "--far", "2"}, "near"},
        BadRun{"UpAlongView", nullptr, {"--eye", "0,5,0", "--target", "0,0,0", "--up", "0,1,0"}, "up"},
        BadRun{"EyeNeedsThreeValues", nullptr, {"--eye", "1,2"}, "--eye"},
        BadRun{"UnknownScene", nullptr, {"--scene", "teapot"}, "unknown scene 'teapot'"},
        BadRun{"InputAndScene", nullptr, {"a.tri", "--scene", "fan"}, "not both"},
#ifndef RASTERSIM_HAVE_RTL
        BadRun{"RtlBackendNotBuilt", nullptr, {"--backend", "rtl"}, "backend rtl is not built in this binary"},
#else
        BadRun{"RtlHasNoStallPattern", nullptr, {"--backend", "rtl", "--memory-stall-percent", "20"}, "no back-pressure"},
#endif
#ifndef RASTERSIM_HAVE_SYSTEMC
        BadRun{"SystemcBackendNotBuilt", nullptr, {"--backend", "systemc"}, "backend systemc is not built in this binary"},
#endif
        BadRun{"UnknownBackend", nullptr, {"--backend", "gpu"}, "--backend"},
        BadRun{"OutputFolderMissing", nullptr, {"--stats", "no/such/folder/s2.json"}, "folder 'no/such/folder' does not exist"},
        BadRun{"ImageFormatUnknown", nullptr, {"-o", "picture.nosuchformat"}, "no image format"}),
    [](const ::testing::TestParamInfo<BadRun>& info) { return info.param.name; });

// A write that fails part-way (as on a full disk) is an error, exit 2, and no file is left: neither
// the output that failed nor the ones already complete.
TEST(CliWriteFailure, FragmentTraceTooLargeLeavesNothing) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"render", "-o", "c.png", "--fragments", "f.csv", "--stats", "s.json"}, 200000);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "f.csv")) << r.err;
  EXPECT_TRUE(dir.listing().empty());
}

TEST(CliWriteFailure, ImageTooLargeLeavesNothing) {
  ScratchDir dir;
  // The fan image as TIFF is about 100 kB; the stats JSON (under 1 kB) fits. OpenImageIO's own file
  // writers would report success on the cut-short file.
  const RunResult r = run_rastersim(
      dir, {"render", "--scene", "fan", "--width", "640", "--height", "480", "--stats", "s.json", "-o", "c.tif"}, 20000);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "c.tif")) << r.err;
  EXPECT_TRUE(dir.listing().empty());
}

TEST(CliBadUsage, UnknownOrMissingSubcommand) {
  ScratchDir dir;
  const RunResult unknown = run_rastersim(dir, {"paint", "x.tri"});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_TRUE(contains(unknown.err, "unknown subcommand 'paint'")) << unknown.err;
  const RunResult none = run_rastersim(dir, {});
  EXPECT_EQ(none.exit_code, 2);
  const RunResult bad_size = run_rastersim(dir, {"bench", "--size", "9..3"});
  EXPECT_EQ(bad_size.exit_code, 2);
  EXPECT_TRUE(contains(bad_size.err, "--size '9..3'")) << bad_size.err;
  EXPECT_TRUE(dir.listing().empty());
}

TEST(CliBadInput, LaterBadLineStillWritesNothingAfterManyGoodOnes) {
  // The whole input is read before anything is rendered or written.
  ScratchDir dir;
  std::string text;
  for (int i = 0; i < 2000; ++i) text += "0 0 0.5 30 0 0.5 0 20 0.5 10 20 30\n";
  text += "0 0 0.5 30 0 0.5 0 20\n";
  dir.write("long.tri", text);
  const RunResult r = run_rastersim(dir, with({"render", "long.tri", "-o", "c.png", "--fragments", "f.csv"}, kSmallProfile));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "long.tri:2001: ")) << r.err;
  EXPECT_EQ(dir.listing(), std::set<std::string>{"long.tri"});
}

}  // namespace
}  // namespace rastersim::cli_test
