// The worked examples in docs/ are checked against the model: the numbers on the page were
// computed independently (exact rationals from the written rules); the model must reproduce them.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "model/pipeline.h"

namespace rastersim {
namespace {

const std::string kDocs = RASTERSIM_SOURCE_DIR "/docs/";

// The `key = value` lines of the fenced block with the given info string, in order.
std::vector<std::pair<std::string, std::string>> doc_block(const std::string& file, const std::string& info) {
  std::ifstream in(kDocs + file);
  EXPECT_TRUE(in) << "cannot open docs/" << file;
  std::vector<std::pair<std::string, std::string>> lines;
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (!inside && line == "```" + info) inside = true;
    else if (inside && line == "```") break;
    else if (inside) {
      const size_t eq = line.find(" = ");
      if (eq != std::string::npos) lines.emplace_back(line.substr(0, eq), line.substr(eq + 3));
    }
  }
  EXPECT_FALSE(lines.empty()) << "no ```" << info << " block in docs/" << file;
  return lines;
}

// The worked .tri: 9 coordinates and a flat colour per line (a deliberately small reader; the
// CLI's reader is tested on its own).
std::vector<SnappedTriangle> worked_triangles(const Profile& p) {
  std::ifstream in(kDocs + "examples/worked.tri");
  std::vector<SnappedTriangle> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    ScreenTriangle t;
    int r, g, b;
    for (ScreenVertex& v : t.v) fields >> v.x >> v.y >> v.z;
    fields >> r >> g >> b;
    for (ScreenVertex& v : t.v) v.color = Rgb{uint8_t(r), uint8_t(g), uint8_t(b)};
    EXPECT_EQ(check_screen_triangle(t, p), "");
    out.push_back(snap(t, p));
  }
  return out;
}

Profile worked_profile() {
  Profile p;
  load_profile_file(p, kDocs + "examples/worked.json");
  EXPECT_TRUE(validate(p).empty());
  return p;
}

struct Collect : FragmentSink {
  std::vector<Fragment> fragments;
  void on_fragment(const Fragment& f) override { fragments.push_back(f); }
};

std::string setup_line(const EdgeSetup& e) {
  return "start " + std::to_string(e.start) + " step_x " + std::to_string(e.step_x) + " step_y " +
         std::to_string(e.step_y) + " owns " + std::to_string(int(e.owns_samples));
}

TEST(Docs, ArithmeticWorkedExample) {
  const Profile p = worked_profile();
  const SnappedTriangle t = worked_triangles(p).at(0);
  Pipeline pipe(p);
  Collect collect;
  pipe.set_fragment_sink(&collect);
  pipe.submit(t);
  const SetupResult& s = pipe.last_setup();
  size_t next_fragment = 0;
  for (const auto& [key, value] : doc_block("arithmetic.md", "example-setup")) {
    SCOPED_TRACE(key + " = " + value);
    if (key == "guard_bits") EXPECT_EQ(std::to_string(pipe.widths().guard_bits), value);
    else if (key[0] == 'v' && key.size() == 2) {
      const SnappedVertex& v = t.v[key[1] - '0'];
      EXPECT_EQ(std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z), value);
    } else if (key == "area2") EXPECT_EQ(std::to_string(s.area2), value);
    else if (key == "bbox")
      EXPECT_EQ(std::to_string(s.x0) + " " + std::to_string(s.y0) + " " + std::to_string(s.x1) + " " + std::to_string(s.y1), value);
    else if (key.rfind("edge", 0) == 0) EXPECT_EQ(setup_line(s.edge[key[4] - '0']), value);
    else if (key == "depth_plane")
      EXPECT_EQ("start " + std::to_string(s.depth.start) + " step_x " + std::to_string(s.depth.step_x) + " step_y " +
                    std::to_string(s.depth.step_y), value);
    else if (key == "fragments") EXPECT_EQ(std::to_string(collect.fragments.size()), value);
    else if (key == "fragment") {
      ASSERT_LT(next_fragment, collect.fragments.size());
      const Fragment& f = collect.fragments[next_fragment++];
      EXPECT_EQ(std::to_string(f.x) + " " + std::to_string(f.y) + " " + std::to_string(f.z), value);
    } else ADD_FAILURE() << "unknown key";
  }
}

// Runs the keys of one example-timeline block: a profile key sets it, `traversal` (re)runs the frame.
void check_timeline(const std::string& block) {
  Profile p = worked_profile();
  std::vector<TriangleRecord> records;
  FrameStats stats;
  auto run = [&]() {
    Pipeline pipe(p);
    records.clear();
    pipe.set_triangle_log(&records);
    for (const SnappedTriangle& t : worked_triangles(p)) pipe.submit(t);
    stats = pipe.stats();
  };
  for (const auto& [key, value] : doc_block("cycle-model.md", block)) {
    SCOPED_TRACE(key + " = " + value);
    if (key == "traversal") {
      p.traversal = *parse_traversal(value);
      run();
    } else if (key == "setup_interval" || key == "setup_fifo_depth" || key == "texture_unit" ||
               key == "texture_latency") {
      EXPECT_EQ(set_profile_key(p, key, value), "");
    } else if (key == "divider_bits") EXPECT_EQ(std::to_string(derive_widths(p).divider_bits), value);
    else if (key == "setup_rejected_latency") EXPECT_EQ(std::to_string(setup_timing(p).rejected_latency), value);
    else if (key == "setup_latency") EXPECT_EQ(std::to_string(setup_timing(p).drawn_latency), value);
    else if (key.rfind("tri", 0) == 0) {
      const TriangleRecord& r = records.at(size_t(key[3] - '0'));
      EXPECT_EQ("setup_accept " + std::to_string(r.setup_accept) + " setup_done " + std::to_string(r.setup_done) +
                    " walker_load " + std::to_string(r.walker_load) + " walker_end " + std::to_string(r.walker_end) +
                    " fragments " + std::to_string(r.fragments) + " last_write " + std::to_string(r.last_write),
                value);
    } else if (key == "cycles") EXPECT_EQ(std::to_string(stats.cycles), value);
    else if (key == "setup_stall") EXPECT_EQ(std::to_string(stats.setup.stall), value);
    else if (key == "zbuffer_stall") EXPECT_EQ(std::to_string(stats.zbuffer.stall), value);
    else if (key == "texture_busy") EXPECT_EQ(std::to_string(stats.texture.busy), value);
    else ADD_FAILURE() << "unknown key";
  }
}

// The floating-point depth word's example (arithmetic.md, "The depth word").
TEST(Docs, DepthWordExampleMatchesTheModel) {
  Profile p;
  int checked = 0;
  for (const auto& [key, value] : doc_block("arithmetic.md", "example-depth-word")) {
    SCOPED_TRACE(key + " = " + value);
    if (key == "z_bits") p.z_bits = std::stoi(value);
    else if (key == "depth_exponent_bits") p.depth_exponent_bits = std::stoi(value);
    else if (key == "plane_bits") EXPECT_EQ(std::to_string(p.depth_plane_bits()), value);
    else {
      EXPECT_EQ(std::to_string(DepthWord(p).encode(std::stoull(key))), value);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 6);
}

// The two reasons an empty box is rejected (arithmetic.md, "Bounding box"), at 64 x 48, S = 4.
TEST(Docs, ArithmeticEmptyBoxExample) {
  Profile p;
  p.width = 64, p.height = 48, p.subpixel_bits = 4;
  const TriangleSetup setup(p);
  SnappedTriangle t;
  int checked = 0;
  for (const auto& [key, value] : doc_block("arithmetic.md", "example-empty-box")) {
    if (key == "triangle") {
      std::istringstream in(value);
      char comma;
      for (SnappedVertex& v : t.v) in >> v.x >> comma >> v.y;
      ASSERT_TRUE(in) << value;
    } else if (key == "status") {
      EXPECT_EQ(to_string(setup.run(t).status), value) << "triangle before line 'status = " << value << "'";
      ++checked;
    }
  }
  EXPECT_EQ(checked, 3);
}

// docs/arithmetic.md section 7: each convention's pixels of the example triangle, vertex snaps and
// rounded register values, against the model.
TEST(Docs, ConventionsExample) {
  SnappedTriangle t;
  int checked = 0;
  for (const auto& [key, value] : doc_block("arithmetic.md", "example-conventions")) {
    SCOPED_TRACE(key + " = " + value);
    std::istringstream words(key);
    std::string what;
    words >> what;
    Profile p;
    p.width = p.height = 16;
    p.subpixel_bits = 4;
    p.z_bits = 16;
    if (what == "triangle") {
      std::istringstream in(value);
      char comma;
      for (SnappedVertex& v : t.v) in >> v.x >> comma >> v.y, v.z = 0, v.color = {};
      ASSERT_TRUE(in);
      continue;
    }
    if (what == "snap") {
      double x = 0;
      words >> x;
      std::string made;
      for (const char* rule : {"nearest", "nearest_even", "floor", "toward_zero"}) {
        ASSERT_EQ(set_profile_key(p, "vertex_snap", rule), "");
        made += std::string(made.empty() ? "" : " ") + rule + " " + std::to_string(snap_coordinate(x, 4, p.vertex_snap));
      }
      EXPECT_EQ(made, value);
    } else if (what == "output") {
      int guard = 0;
      int64_t value_register = 0;
      words >> guard >> value_register;
      std::string made;
      for (Rounding r : {Rounding::Nearest, Rounding::Truncate})
        made += std::string(made.empty() ? "" : " ") + to_string(r) + " " +
                std::to_string(PlaneFormat(guard + 25, guard, 65535, r).output(uint64_t(value_register)));
      EXPECT_EQ(made, value);
    } else {
      std::string rule;
      words >> rule;
      ASSERT_EQ(set_profile_key(p, "pixel_center", what), "");
      ASSERT_EQ(set_profile_key(p, "fill_rule", rule), "");
      Pipeline pipe(p);
      Collect collect;
      pipe.set_fragment_sink(&collect);
      pipe.submit(t);
      std::string made;
      for (const Fragment& f : collect.fragments) made += (made.empty() ? "" : " ") + std::to_string(f.x) + "," + std::to_string(f.y);
      EXPECT_EQ(made, value);
    }
    ++checked;
  }
  EXPECT_EQ(checked, 14);
}

TEST(Docs, CycleModelWorkedExample) { check_timeline("example-timeline"); }
TEST(Docs, CycleModelPipelinedSetupWorkedExample) { check_timeline("example-timeline-pipelined"); }
TEST(Docs, CycleModelTextureUnitWorkedExample) { check_timeline("example-timeline-texture"); }

TEST(Docs, WidthsTable) {
  for (const auto& [key, value] : doc_block("widths.md", "example-widths")) {
    SCOPED_TRACE(key + " = " + value);
    std::istringstream profile(key);
    int width, height, subpixel_bits, z_bits;
    profile >> width >> height >> subpixel_bits >> z_bits;
    const Widths w = derive_widths(width, height, subpixel_bits, z_bits, 0);
    std::ostringstream derived;
    derived << "guard " << w.guard_bits << " coord " << w.coord_bits << " delta " << w.delta_bits << " area "
            << w.area_bits << " edge " << w.edge_bits << " divider " << w.divider_bits << " z_reg " << w.z_reg_bits
            << " color_reg " << w.color_reg_bits << " serial_setup "
            << serial_setup_drawn_latency(w, subpixel_bits, z_bits) << " texture_reg " << w.texture_reg_bits
            << " texture_divider " << w.texture_divider_bits;
    EXPECT_EQ(derived.str(), value);
  }
}

// docs/formats.md's key table is the profile table (model/profile.cpp), row for row.
TEST(Docs, ProfileKeyTableIsTheProfileTable) {
  std::ifstream in(kDocs + "formats.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string table = profile_table_markdown();
  EXPECT_NE(text.str().find("\n" + table + "\n"), std::string::npos)
      << "docs/formats.md's key table differs from the profile table; `rastersim profile --keys-markdown` prints it:\n"
      << table;
  // Every key has a row, in table order.
  size_t at = 0;
  for (const std::string& key : profile_keys()) {
    at = table.find("| `" + key + "` |", at);
    EXPECT_NE(at, std::string::npos) << key;
  }
}

}  // namespace
}  // namespace rastersim
