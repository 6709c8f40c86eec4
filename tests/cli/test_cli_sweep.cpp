// `rastersim sweep` (cli/sweep_command.cpp): every combination of the swept values is one CSV row
// whose figures equal what `rastersim render` reports for the same settings; the plots are PNGs;
// the precision figures against the exact planes (tests/reference.h) and an ideal z-buffer; the
// hardware cost is synthesized once per profile and then read from the cache. And `rastersim
// render --backend systemc` against the model, with and without a memory stall pattern.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <tuple>

#include "cli_test_support.h"
#include "reference.h"
#include "sweep_command.h"

namespace rastersim::cli_test {
namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// sweep.csv as rows of named cells.
std::vector<std::map<std::string, std::string>> read_csv(const fs::path& path) {
  std::istringstream in(read_text(path));
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::istringstream names(line);
  for (std::string n; std::getline(names, n, ',');) header.push_back(n);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    std::map<std::string, std::string> row;
    size_t i = 0;
    for (std::string c; std::getline(cells, c, ','); ++i) row[header.at(i)] = c;
    EXPECT_EQ(i, header.size()) << line;
    rows.push_back(row);
  }
  return rows;
}

TEST(CliSweep, EveryCombinationIsARowEqualToRenderAndPlotted) {
  ScratchDir dir;
  const std::vector<std::string> base = {"--scene", "overlap", "--width", "64", "--height", "48"};
  std::vector<std::string> args = {"sweep", "--vary", "memory_latency=1,4", "--vary", "traversal=bbox,span",
                                   "--vary", "z_bits=16,24", "--out", "study"};
  args.insert(args.end(), base.begin(), base.end());
  const RunResult r = run_rastersim(dir, args);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto rows = read_csv(dir.path("study/sweep.csv"));
  ASSERT_EQ(rows.size(), 8u);
  std::set<std::string> combinations;
  for (const auto& row : rows) {
    combinations.insert(row.at("memory_latency") + row.at("traversal") + row.at("z_bits"));
    std::vector<std::string> render = {"render", "--stats", "s.json", "--memory-latency", row.at("memory_latency"),
                                       "--traversal", row.at("traversal"), "--z-bits", row.at("z_bits")};
    render.insert(render.end(), base.begin(), base.end());
    const RunResult rr = run_rastersim(dir, render);
    ASSERT_EQ(rr.exit_code, 0) << rr.err;
    const nlohmann::json s = read_json(dir.path("s.json"));
    const int64_t cycles = s["cycles"], fragments = s["fragments"];
    EXPECT_EQ(std::stoll(row.at("cycles")), cycles);
    EXPECT_EQ(std::stoll(row.at("fragments")), fragments);
    EXPECT_EQ(std::stoll(row.at("depth_fails")), s["depth_fail"].get<int64_t>());
    EXPECT_NEAR(std::stod(row.at("fragments_per_clock")), double(fragments) / double(cycles), 1e-5);
    EXPECT_NEAR(std::stod(row.at("setup_share")), s["units"]["setup"]["busy"].get<double>() / double(cycles), 1e-5);
    EXPECT_NEAR(std::stod(row.at("stall_share")), s["units"]["zbuffer"]["stall"].get<double>() / double(cycles), 1e-5);
    // Derived guard bits keep every fragment within 1 LSB of the exact plane (docs/arithmetic.md section 4).
    EXPECT_LT(std::stod(row.at("max_depth_error")), 1.0);
    EXPECT_GT(fragments, 1000);
  }
  EXPECT_EQ(combinations.size(), 8u);
  for (const std::string name : {"cycles", "fragments_per_clock", "setup_share", "stall_share", "depth_fails",
                                 "wrong_depth_tests", "max_depth_error"}) {
    const Image plot = read_image(dir.path("study/" + name + ".png"));
    EXPECT_EQ(plot.width, 800) << name;
    EXPECT_EQ(plot.height, 500) << name;
  }
  EXPECT_TRUE(fs::exists(dir.path("study/sweep.gp")));
  EXPECT_NE(read_text(dir.path("study/sweep.gp")).find("set yrange [0:*]"), std::string::npos);  // zero baseline
}

// The width of the plot's frame: the longest horizontal run of dark pixels (the frame's top and
// bottom; the key's line samples are short, the grid is grey).
int plot_frame_width(const Image& plot) {
  int longest = 0;
  for (int y = 0; y < plot.height; ++y) {
    int run = 0;
    for (int x = 0; x < plot.width; ++x) {
      const uint8_t* px = &plot.pixels8[(size_t(y) * size_t(plot.width) + size_t(x)) * size_t(plot.channels)];
      run = px[0] < 64 && px[1] < 64 && px[2] < 64 ? run + 1 : 0;
      longest = std::max(longest, run);
    }
  }
  return longest;
}

// Four axes: twelve curves with long names. gnuplot's colours repeat every 8 linetypes ("unless
// explicitly defined"), so no two curves may share colour, point shape and dash; and the key at the
// right must leave the plot about the 300 px the key of docs/studies.md's memory study leaves it.
// --jobs N renders points in parallel: the same CSV and the same lines, in point order.
TEST(CliSweep, JobsGiveTheSameResultsAsOneJob) {
  ScratchDir dir;
  std::map<std::string, RunResult> runs;
  for (const std::string jobs : {"1", "3"}) {
    runs[jobs] = run_rastersim(dir, {"sweep", "--scene", "overlap", "--width", "64", "--height", "48", "--vary",
                                     "memory_latency=1,4", "--vary", "traversal=bbox,span", "--vary", "setup_interval=0,2",
                                     "--out", "s" + jobs, "--no-plots", "--jobs", jobs});
    ASSERT_EQ(runs[jobs].exit_code, 0) << runs[jobs].err;
  }
  EXPECT_EQ(read_text(dir.path("s3/sweep.csv")), read_text(dir.path("s1/sweep.csv")));
  auto points = [](const std::string& out) { return out.substr(0, out.find("wrote")); };
  EXPECT_EQ(points(runs["3"].out), points(runs["1"].out));
  EXPECT_TRUE(contains(runs["3"].out, "[8/8]")) << runs["3"].out;
  EXPECT_EQ(run_rastersim(dir, {"sweep", "--scene", "overlap", "--vary", "memory_latency=1,4", "--out", "x", "--jobs", "0"})
                .exit_code,
            2);
}

// --threads N meters each point's fragments on N - 1 threads beside the render: the same CSV and
// lines, on a frame whose 16-bit depth gets depth tests wrong (so the counts can differ).
TEST(CliSweep, ThreadsGiveTheSameResultsAsOneThread) {
  ScratchDir dir;
  std::map<std::string, RunResult> runs;
  for (const std::string threads : {"1", "3"}) {
    runs[threads] = run_rastersim(dir, {"sweep", "--scene", "default", "--width", "320", "--height", "240", "--vary",
                                        "z_bits=16,24", "--out", "s" + threads, "--no-plots", "--threads", threads});
    ASSERT_EQ(runs[threads].exit_code, 0) << runs[threads].err;
  }
  const std::vector<std::map<std::string, std::string>> rows = read_csv(dir.path("s1/sweep.csv"));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_GT(std::stoll(rows[0].at("wrong_depth_tests")), 0);
  EXPECT_EQ(read_text(dir.path("s3/sweep.csv")), read_text(dir.path("s1/sweep.csv")));
  auto points = [](const std::string& out) { return out.substr(0, out.find("wrote")); };
  EXPECT_EQ(points(runs["3"].out), points(runs["1"].out));
  for (const std::string bad : {"0", "257"})
    EXPECT_EQ(run_rastersim(dir, {"sweep", "--scene", "overlap", "--vary", "z_bits=16", "--out", "x", "--threads", bad})
                  .exit_code,
              2);
}

// The meter's figures at any thread count and chunk size equal one meter's: random overlapping
// triangles, fragments from the model at 16-bit depth.
TEST(DepthErrorMeter, BandsOnMeterThreadsGiveOneMetersFigures) {
  Profile p;
  p.width = 96, p.height = 64, p.z_bits = 16;
  std::mt19937_64 rng(20261129);
  std::uniform_real_distribution<double> x(-10, 106), y(-10, 74), z(0.2, 0.8);
  std::vector<ScreenTriangle> screen(300);
  std::vector<SnappedTriangle> snapped;
  for (ScreenTriangle& t : screen) {
    for (ScreenVertex& v : t.v) v.x = x(rng), v.y = y(rng), v.z = z(rng);
    snapped.push_back(snap(t, p));
  }
  auto figures = [&](int threads, size_t chunk) {
    DepthErrorMeter meter(screen, snapped, p, threads, chunk);
    Pipeline pipeline(p);
    pipeline.set_fragment_sink(&meter);
    for (const SnappedTriangle& t : snapped) pipeline.submit(t);
    meter.finish();
    return std::make_pair(meter.max_depth_error(), meter.wrong_depth_tests());
  };
  const auto one = figures(1, 1);
  EXPECT_GT(one.second, 0);
  EXPECT_GT(one.first, 0.0);
  for (int threads : {2, 3, 5})
    for (size_t chunk : {size_t(251), size_t(4093), size_t(1) << 18}) {
      SCOPED_TRACE("threads " + std::to_string(threads) + ", chunk " + std::to_string(chunk));
      EXPECT_EQ(figures(threads, chunk), one);
    }
}

TEST(CliSweep, ManyLongNamedCurvesStayDistinctAndLeaveRoomForThePlot) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"sweep", "--scene", "overlap", "--width", "16", "--height", "8", "--vary",
                                          "memory_latency=1,2,4", "--vary", "traversal=bbox,span", "--vary",
                                          "subpixel_bits=2,4,8", "--vary", "memory_stall_percent=0,30", "--out", "many"});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  std::istringstream script(read_text(dir.path("many/sweep.gp")));
  size_t plots = 0;
  for (std::string line; std::getline(script, line);) {
    if (line.rfind("plot ", 0) != 0) continue;
    ++plots;
    auto number_after = [](const std::string& element, const std::string& word, int absent) {
      const size_t at = element.find(word + " ");
      return at == std::string::npos ? absent : std::stoi(element.substr(at + word.size() + 1));
    };
    std::set<std::tuple<int, int, int>> styles;
    size_t curves = 0;
    for (size_t at = line.find("$series"); at != std::string::npos; at = line.find("$series", at + 1)) {
      const std::string element = line.substr(at, line.find(" title '", at) - at);
      EXPECT_FALSE(contains(element, "linetype") || contains(element, "linecolor")) << element;
      styles.insert({std::stoi(element.substr(7)) % 8, number_after(element, "pointtype", 1),
                     number_after(element, "dashtype", 1)});
      ++curves;
    }
    EXPECT_EQ(curves, 12u) << line;
    EXPECT_EQ(styles.size(), curves) << line;
  }
  EXPECT_GE(plots, 7u);
  const Image plot = read_image(dir.path("many/cycles.png"));
  EXPECT_GE(plot_frame_width(plot), 280) << plot.width << "x" << plot.height;
}

TEST(CliSweep, FewerGuardBitsThanDerivedShowAsDepthError) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"sweep", "--scene", "overlap", "--width", "160", "--height", "120",
                                          "--vary", "z_guard_bits=1,auto", "--out", "g", "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto rows = read_csv(dir.path("g/sweep.csv"));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_GT(std::stod(rows[0].at("max_depth_error")), 1.0);
  EXPECT_LT(std::stod(rows[1].at("max_depth_error")), 1.0);
  EXPECT_FALSE(fs::exists(dir.path("g/max_depth_error.png")));
}

TEST(CliSweep, BadAxesAreInputErrors) {
  ScratchDir dir;
  for (const auto& [vary, message] : std::vector<std::pair<std::string, std::string>>{
           {"colour=1,2", "unknown key 'colour'"},
           {"z_bits=16,16", "value '16' given twice"},
           {"z_bits=8,16", "z_bits is 8"},
           {"near=close", "'close' is not a number"},
           {"traversal", "expected KEY=V1,V2"}}) {
    const RunResult r = run_rastersim(dir, {"sweep", "--vary", vary, "--out", "x"});
    EXPECT_EQ(r.exit_code, 2) << vary;
    EXPECT_TRUE(contains(r.err, message)) << vary << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir.path("x"))) << vary;
  }
  // More points than the limit are refused before they are held (4096 x 4096 made one 4.4 GB allocation).
  std::string widths = "width=", heights = "height=";
  for (int v = 1; v <= 101; ++v) widths += (v > 1 ? "," : "") + std::to_string(v), heights += (v > 1 ? "," : "") + std::to_string(v);
  const RunResult r = run_rastersim(dir, {"sweep", "--vary", widths, "--vary", heights, "--out", "x"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(contains(r.err, "the sweep has more than 10000 points, the limit")) << r.err;
  EXPECT_FALSE(fs::exists(dir.path("x")));
}

// A profile (or any input) inside --out under an output's name is refused before anything runs,
// and left as it was (sweep once wrote its CSV over it).
TEST(CliSweep, AnOutputThatIsAnInputIsRefused) {
  ScratchDir dir;
  fs::create_directory(dir.path("x"));
  const std::string profile = "{\"width\": 32, \"height\": 24}\n";
  for (const std::string name : {"sweep.csv", "sweep.gp", "cycles.png"}) {
    dir.write("x/" + name, profile);
    const RunResult r = run_rastersim(dir, {"sweep", "--vary", "z_bits=16,24", "--profile", "x/" + name, "--out", "x"});
    EXPECT_EQ(r.exit_code, 2) << name;
    EXPECT_TRUE(contains(r.err, "is an input of this run")) << r.err;
    EXPECT_EQ(read_text(dir.path("x/" + name)), profile);
    fs::remove(dir.path("x/" + name));
    EXPECT_TRUE(fs::is_empty(dir.path("x"))) << name;
  }
}

// A write that fails (here the file size limit, as on a full disk) is an error, and no plot, CSV
// or script is left: gnuplot exited 0 with a 0-byte and a truncated PNG, and the sweep with it.
TEST(CliSweep, AFailedPlotWriteIsAnErrorAndLeavesNothing) {
  ScratchDir dir;
  const RunResult r = run_rastersim(
      dir, {"sweep", "--vary", "z_bits=16,24", "--scene", "overlap", "--width", "64", "--height", "48", "--out", "x"},
      4000);
  EXPECT_NE(r.exit_code, 0) << r.out;
  EXPECT_TRUE(contains(r.err, "write error")) << r.err;
  EXPECT_FALSE(fs::exists(dir.path("x")));  // made by the run, gone with it
}

// The 1/w buffer (docs/arithmetic.md section 6): two parallel squares facing the camera 60 units away,
// 0.1 apart, the far one drawn first, near plane 0.01. A 16-bit z word cannot tell them apart
// (0.02 LSB apart) and neither can a 16-bit fixed-point 1/w word (the same spacing); a 16-bit
// floating-point 1/w word (4 exponent bits: 12 mantissa bits, relative spacing 2^-12, the squares
// 2^-9 apart) orders every pixel. And on the default scene the floating-point 1/w buffer draws the
// same image as the z buffer, with no wrong depth test.
TEST(CliSweep, AFloatingPointInverseWBufferOrdersWhereA16BitZBufferFights) {
  ScratchDir dir;
  dir.write("parallel.json", R"({
  "camera": {"eye": [0, 0, 60], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 20, "near": 0.01, "far": 100},
  "objects": [
    {"surface": "plane", "params": {"width": 12, "depth": 12}, "rotate": [90, 0, 0], "color": [200, 80, 60]},
    {"surface": "plane", "params": {"width": 12, "depth": 12}, "rotate": [90, 0, 0], "translate": [0, 0, 0.1],
     "color": [60, 120, 200]}
  ]
})");
  auto wrong_tests = [&](const std::vector<std::string>& depth) {
    std::vector<std::string> args = {"sweep", "parallel.json", "--width", "160", "--height", "120", "--z-bits", "16",
                                     "--vary", "near=0.01", "--out", "p", "--no-plots"};
    args.insert(args.end(), depth.begin(), depth.end());
    const RunResult r = run_rastersim(dir, args);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    const auto rows = read_csv(dir.path("p/sweep.csv"));
    EXPECT_EQ(rows.size(), 1u);
    fs::remove_all(dir.path("p"));
    return rows.empty() ? -1 : std::stoll(rows[0].at("wrong_depth_tests"));
  };
  const int64_t z = wrong_tests({});
  const int64_t fixed = wrong_tests({"--depth-buffer", "inverse_w", "--depth-func", "greater"});
  const int64_t floating =
      wrong_tests({"--depth-buffer", "inverse_w", "--depth-func", "greater", "--depth-exponent-bits", "4"});
  EXPECT_GT(z, 4000);  // the near square covers 4,624 pixels: every one wrong
  EXPECT_GT(fixed, 4000);
  EXPECT_EQ(floating, 0);

  for (const auto& depth : {std::vector<std::string>{"--out", "z.png"},
                            std::vector<std::string>{"--depth-buffer", "inverse_w", "--depth-func", "greater",
                                                     "--depth-exponent-bits", "3", "--out", "w.png"}}) {
    std::vector<std::string> args = {"render", "--scene", "default", "--width", "160", "--height", "120",
                                     "--stats", "s.json"};
    args.insert(args.end(), depth.begin(), depth.end());
    args[args.size() - 2] = "-o";
    const RunResult r = run_rastersim(dir, args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  EXPECT_EQ(read_text(dir.path("z.png")), read_text(dir.path("w.png")));
  const RunResult sweep = run_rastersim(dir, {"sweep", "--scene", "default", "--width", "160", "--height", "120",
                                              "--vary", "depth_exponent_bits=3", "--depth-buffer", "inverse_w",
                                              "--depth-func", "greater", "--out", "d", "--no-plots"});
  ASSERT_EQ(sweep.exit_code, 0) << sweep.err;
  EXPECT_EQ(read_csv(dir.path("d/sweep.csv")).at(0).at("wrong_depth_tests"), "0");
}

// A 1/w buffer needs a perspective camera and a depth function that keeps the larger value.
TEST(CliSweep, AnInverseWBufferRefusesAnOrthographicCameraAndLess) {
  ScratchDir dir;
  const RunResult less = run_rastersim(dir, {"render", "--scene", "default", "--depth-buffer", "inverse_w", "-o", "a.png"});
  EXPECT_EQ(less.exit_code, 2);
  EXPECT_TRUE(contains(less.err, "greater or gequal")) << less.err;
  const RunResult ortho = run_rastersim(dir, {"render", "--scene", "default", "--ortho", "--depth-buffer", "inverse_w",
                                              "--depth-func", "greater", "-o", "a.png"});
  EXPECT_EQ(ortho.exit_code, 2);
  EXPECT_TRUE(contains(ortho.err, "perspective camera")) << ortho.err;
  EXPECT_FALSE(fs::exists(dir.path("a.png")));
}

// A sweep with the texture unit gains the texture unit's busy and stall shares, equal to what
// render reports; one without it has neither; texture flags without the unit are refused.
TEST(CliSweep, TheTextureUnitsSharesAreColumnsWhenAPointHasIt) {
  ScratchDir dir;
  const std::vector<std::string> base = {"--scene", "floor", "--width", "64", "--height", "48", "--texture-unit",
                                         "true", "--texture-latency", "4"};
  std::vector<std::string> args = {"sweep", "--vary", "texture_stall_percent=0,40", "--out", "t", "--no-plots"};
  args.insert(args.end(), base.begin(), base.end());
  const RunResult r = run_rastersim(dir, args);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto rows = read_csv(dir.path("t/sweep.csv"));
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    std::vector<std::string> render = {"render", "--stats", "s.json", "--texture-stall-percent",
                                       row.at("texture_stall_percent")};
    render.insert(render.end(), base.begin(), base.end());
    const RunResult rr = run_rastersim(dir, render);
    ASSERT_EQ(rr.exit_code, 0) << rr.err;
    const nlohmann::json s = read_json(dir.path("s.json"));
    const double cycles = s["cycles"].get<double>();
    EXPECT_GT(s["units"]["texture"]["busy"].get<int64_t>(), 1000);
    EXPECT_NEAR(std::stod(row.at("texture_share")), s["units"]["texture"]["busy"].get<double>() / cycles, 1e-5);
    EXPECT_NEAR(std::stod(row.at("texture_stall_share")), s["units"]["texture"]["stall"].get<double>() / cycles, 1e-5);
  }
  EXPECT_EQ(std::stod(rows[0].at("texture_stall_share")), 0.0);  // no back-pressure: no read waits
  EXPECT_GT(std::stod(rows[1].at("texture_stall_share")), 0.0);

  const RunResult plain = run_rastersim(dir, {"sweep", "--vary", "memory_latency=1,2", "--out", "p", "--no-plots",
                                              "--width", "64", "--height", "48"});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_FALSE(contains(read_text(dir.path("p/sweep.csv")), "texture")) << read_text(dir.path("p/sweep.csv"));
  const RunResult refused = run_rastersim(dir, {"sweep", "--vary", "memory_latency=1,2", "--out", "q",
                                                "--texture-filter", "nearest"});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_TRUE(contains(refused.err, "need the texture_unit at some point of the sweep")) << refused.err;
  EXPECT_FALSE(fs::exists(dir.path("q")));
}

// The exact plane of the sweep's depth error is the reference's (tests/reference.h).
TEST(CliSweep, DepthErrorAgainstTheReferencePlane) {
  SnappedTriangle t;
  t.v[0] = {3, 5, 1000, {}}, t.v[1] = {700, 40, 90000, {}}, t.v[2] = {100, 600, 5, {}};
  for (int subpixel_bits : {1, 4}) {
    for (int y = 0; y < 8; ++y) {
      for (int x = 0; x < 8; ++x) {
        const uint32_t z[3] = {t.v[0].z, t.v[1].z, t.v[2].z};
        const reference::Rational exact = reference::plane_at_centre(t, z, subpixel_bits, x, y);
        const double value = double(exact.num) / double(exact.den);
        for (uint32_t candidate : {uint32_t(value), uint32_t(value) + 7}) {
          EXPECT_NEAR(depth_error_lsb(t, subpixel_bits, x, y, candidate), std::fabs(double(candidate) - value), 1e-6);
        }
      }
    }
  }
}

#ifdef RASTERSIM_HAVE_SYSTEMC
// The SystemC system (verilated core, command FIFO, memory model) renders exactly what the model
// renders: images, fragment trace (cycles included) and counters, with and without back-pressure.
TEST(CliSystemc, SystemcBackendEqualsModelWithAndWithoutAStallPattern) {
  ScratchDir dir;
  for (const std::string stall : {"0", "40"}) {
    for (const std::string backend : {"model", "systemc"}) {
      const std::string name = backend + stall;
      const RunResult r = run_rastersim(dir, {"render", "--scene", "overlap", "--backend", backend, "--memory-latency",
                                              "3", "--memory-stall-percent", stall, "--memory-stall-seed", "9", "-o",
                                              name + ".png", "--fragments", name + ".csv", "--stats", name + ".json"});
      ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
      if (backend == "systemc") {
        EXPECT_TRUE(contains(r.out, "SystemC")) << r.out;
      }
    }
    for (const std::string ext : {".png", ".csv", ".json"})
      EXPECT_EQ(read_text(dir.path("model" + stall + ext)), read_text(dir.path("systemc" + stall + ext))) << stall << ext;
  }
  const nlohmann::json plain = read_json(dir.path("systemc0.json")), stalled = read_json(dir.path("systemc40.json"));
  EXPECT_GT(plain["fragments"].get<int64_t>(), 1000);
  EXPECT_GT(stalled["cycles"].get<int64_t>(), plain["cycles"].get<int64_t>());
  EXPECT_EQ(read_text(dir.path("systemc0.png")), read_text(dir.path("systemc40.png")));
}

TEST(CliSystemc, SweepThroughSystemc) {
  ScratchDir dir;
  const RunResult r = run_rastersim(dir, {"sweep", "--scene", "overlap", "--backend", "systemc", "--vary",
                                          "memory_stall_percent=0,50", "--out", "s", "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto rows = read_csv(dir.path("s/sweep.csv"));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_GT(std::stoll(rows[1].at("cycles")), std::stoll(rows[0].at("cycles")));
  EXPECT_GT(std::stod(rows[1].at("stall_share")), std::stod(rows[0].at("stall_share")));
  EXPECT_EQ(rows[0].at("fragments"), rows[1].at("fragments"));
  // Every figure of every point equals the model's (the model predicts the stalled cycles too).
  const RunResult m = run_rastersim(dir, {"sweep", "--scene", "overlap", "--backend", "model", "--vary",
                                          "memory_stall_percent=0,50", "--out", "m", "--no-plots"});
  ASSERT_EQ(m.exit_code, 0) << m.out << m.err;
  EXPECT_EQ(read_csv(dir.path("m/sweep.csv")), rows);
}
#endif

// --hw-cost runs yosys once per distinct hardware profile and then reads the cache. yosys itself is
// replaced by a stub on PATH (a real synthesis of the core takes minutes; docs/studies.md runs the
// real one): the stub records each script it is given and writes `stat` reports whose counts encode
// the script's MAX_MEMORY_LATENCY, so the test checks the script, the parsing and the caching.
TEST(CliSweep, HardwareCostRunsYosysOncePerProfileAndCaches) {
  ScratchDir dir;
  const fs::path stub_dir = dir.root() / "bin";
  fs::create_directory(stub_dir);
  {
    std::ofstream stub(stub_dir / "yosys");
    stub << "#!/bin/sh\n"
            "# Called as: yosys -q -l LOG -s SCRIPT\n"
            "script=\"$5\"\n"
            "cat \"$script\" >> " << (dir.root() / "yosys-calls.txt").string() << "\n"
            "echo '=== next call ===' >> " << (dir.root() / "yosys-calls.txt").string() << "\n"
            "latency=$(sed -n 's/.*MAX_MEMORY_LATENCY \\([0-9]*\\).*/\\1/p' \"$script\" | head -1)\n"
            "generic=$(sed -n 's/^tee -q -o \\(.*generic.txt\\) stat$/\\1/p' \"$script\")\n"
            "ice40=$(sed -n 's/^tee -q -o \\(.*ice40.txt\\) stat$/\\1/p' \"$script\")\n"
            "printf '=== rastersim_core ===\\n\\n   Number of cells:  %d\\n     $_AND_  7\\n' $((1000 + latency)) > \"$generic\"\n"
            "printf '=== rastersim_core ===\\n\\n   Number of cells:  9\\n     SB_CARRY  3\\n"
            "     SB_DFF  %d\\n     SB_DFFE  5\\n     SB_LUT4  %d\\n' $((10 * latency)) $((500 + latency)) > \"$ice40\"\n";
  }
  fs::permissions(stub_dir / "yosys", fs::perms::owner_all);
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  setenv("PATH", (stub_dir.string() + ":" + path).c_str(), 1);
  const std::vector<std::string> args = {"sweep", "--scene", "overlap", "--width", "16", "--height", "8",
                                         "--subpixel-bits", "2", "--z-bits", "16", "--vary", "memory_latency=1,8", "--vary", "traversal=bbox,span",
                                         "--hw-cost", "--hw-cost-cache", "cache", "--out", "hw", "--no-plots"};
  const RunResult first = run_rastersim(dir, args);
  const std::string first_csv = read_text(dir.path("hw/sweep.csv"));
  const std::string calls = read_text(dir.root() / "yosys-calls.txt");
  const RunResult second = run_rastersim(dir, args);
  setenv("PATH", path.c_str(), 1);
  ASSERT_EQ(first.exit_code, 0) << first.out << first.err;
  ASSERT_EQ(second.exit_code, 0) << second.out << second.err;
  // Traversal is a runtime setting: two hardware profiles, two yosys runs, none the second time.
  size_t runs = 0;
  for (size_t at = calls.find("=== next call ==="); at != std::string::npos; at = calls.find("=== next call ===", at + 1)) ++runs;
  EXPECT_EQ(runs, 2u) << calls;
  EXPECT_EQ(read_text(dir.root() / "yosys-calls.txt"), calls);
  for (const std::string step : {"chparam -set WIDTH 16 -set HEIGHT 8 -set SUBPIXEL_BITS 2 -set Z_BITS 16 "
                                 "-set Z_GUARD_BITS 0 -set DEPTH_EXPONENT_BITS 0 -set DEPTH_BIAS 0 -set MAX_MEMORY_LATENCY 8 "
                                 "-set MAX_SETUP_FIFO_DEPTH 8 -set SETUP_INTERVAL 4 -set TEXTURE 0 -set MAX_TEXTURE_LATENCY 2 "
                                 "-set PIXEL_CENTER 0 -set FILL_RULE 0 -set DEPTH_ROUNDING 0 -set COLOR_ROUNDING 0 "
                                 "rastersim_core",
                                 "synth -flatten -top rastersim_core", "synth_ice40 -top rastersim_core"})
    EXPECT_TRUE(contains(calls, step)) << step << "\n" << calls;
  EXPECT_EQ(read_text(dir.path("hw/sweep.csv")), first_csv);
  EXPECT_TRUE(contains(second.out, "[1/4] memory_latency=1 traversal=bbox")) << second.out;
  EXPECT_TRUE(contains(second.out.substr(0, second.out.find("[2/4]")), "(cached)")) << second.out;
  const auto rows = read_csv(dir.path("hw/sweep.csv"));
  ASSERT_EQ(rows.size(), 4u);
  for (const auto& row : rows) {
    const int latency = std::stoi(row.at("memory_latency"));
    EXPECT_EQ(std::stoll(row.at("yosys_cells")), 1000 + latency);
    EXPECT_EQ(std::stoll(row.at("ice40_luts")), 500 + latency);
    EXPECT_EQ(std::stoll(row.at("ice40_ffs")), 10 * latency + 5);  // SB_DFF + SB_DFFE
    EXPECT_EQ(std::stoll(row.at("memory_bits")), 16 * 8 * (16 + 24) + 2 * 2 * 64);
  }
}

}  // namespace
}  // namespace rastersim::cli_test
