// Coverage is the exact top-left rule of docs/arithmetic.md, pixel for pixel and in walker order (row by
// row, left to right), checked against the independent brute-force reference (tests/reference.h)
// on random and directed triangle families, for both traversals and several subpixel precisions.
#include <gtest/gtest.h>

#include <functional>
#include <sstream>
#include <tuple>

#include "model/pipeline.h"
#include "reference.h"
#include "test_util.h"

namespace rastersim {
namespace {

using test::describe;
using test::FragmentLog;
using test::TriangleGen;

// The first difference between the model's fragment positions and the reference's, as a sentence;
// empty when they are equal.
std::string coverage_difference(const std::vector<Fragment>& model, const std::vector<reference::Pixel>& ref) {
  const size_t n = std::min(model.size(), ref.size());
  for (size_t i = 0; i < n; ++i)
    if (model[i].x != ref[i].x || model[i].y != ref[i].y) {
      std::ostringstream out;
      out << "fragment " << i << " is pixel (" << model[i].x << ", " << model[i].y << ") but the reference's is ("
          << ref[i].x << ", " << ref[i].y << ")";
      return out.str();
    }
  if (model.size() != ref.size()) {
    std::ostringstream out;
    out << "the model emits " << model.size() << " fragments, the reference covers " << ref.size();
    if (model.size() > n) out << "; first extra model pixel (" << model[n].x << ", " << model[n].y << ")";
    else out << "; first missing pixel (" << ref[n].x << ", " << ref[n].y << ")";
    return out.str();
  }
  return "";
}

// The status the setup must report, decided from the rules (cull none): zero area is degenerate;
// no pixel centre of the screen inside the vertices' extent is offscreen when the extent lies
// beyond the outermost centres, no_centre otherwise.
SetupStatus expected_status(const SnappedTriangle& t, const Profile& p) {
  if (reference::twice_area(t) == 0) return SetupStatus::Degenerate;
  if (reference::bounding_box(t, p).empty())
    return reference::beyond_outer_centres(t, p) ? SetupStatus::Offscreen : SetupStatus::NoCentre;
  return SetupStatus::Drawn;
}

struct Family {
  const char* name;
  std::function<SnappedTriangle(TriangleGen&)> make;
};

std::vector<Family> families() {
  return {
      {"guard_band", [](TriangleGen& g) { return g.guard_band(); }},
      {"medium", [](TriangleGen& g) { return g.near_screen(12); }},
      {"tiny", [](TriangleGen& g) { return g.tiny(); }},
      {"on_centres", [](TriangleGen& g) { return g.on_centres(6); }},
      {"axis_edges_through_centres", [](TriangleGen& g) { return g.axis_edges_through_centres(8); }},
      {"edge_through_centres", [](TriangleGen& g) { return g.edge_through_centres(6); }},
      {"half_pixel_lattice", [](TriangleGen& g) { return g.half_pixel_lattice(5); }},
      {"sliver", [](TriangleGen& g) { return g.sliver(30); }},
      {"degenerate", [](TriangleGen& g) { return g.degenerate(); }},
      {"offscreen", [](TriangleGen& g) { return g.offscreen(); }},
  };
}

// A pixel_center and a fill_rule (docs/arithmetic.md section 7).
using Convention = std::pair<PixelCenter, FillRule>;
class Coverage : public ::testing::TestWithParam<std::tuple<int, Traversal, Convention>> {};

TEST_P(Coverage, RandomAndDirectedFamiliesMatchTheFillRule) {
  const auto [S, traversal, convention] = GetParam();
  Profile p = test::make_profile(48, 40, S, traversal);
  p.pixel_center = convention.first;
  p.fill_rule = convention.second;
  Pipeline pipe(p);  // depth_func always: coverage does not depend on the buffer contents
  FragmentLog log;
  pipe.set_fragment_sink(&log);
  int family_index = 0;
  for (const Family& family : families()) {
    const uint64_t seed = 1000 * uint64_t(S) + 17 * uint64_t(family_index++) + 3 + 100000 * uint64_t(convention.first) +
                          10000 * uint64_t(convention.second);
    SCOPED_TRACE(::testing::Message() << describe(p) << " family " << family.name << " seed " << seed);
    TriangleGen gen(p, seed);
    int drawn = 0, offscreen = 0, no_centre = 0, degenerate = 0;
    for (int n = 0; n < 400; ++n) {
      const SnappedTriangle t = family.make(gen);
      const std::vector<reference::Pixel> ref = reference::covered_pixels(t, p);
      const SetupStatus status = expected_status(t, p);
      for (const SnappedTriangle& winding : {t, test::reversed(t)}) {
        log.fragments.clear();
        pipe.submit(winding);
        ASSERT_EQ(to_string(pipe.last_setup().status), std::string(to_string(status))) << "n=" << n << " " << describe(winding);
        const std::string diff = coverage_difference(log.fragments, ref);
        ASSERT_EQ(diff, "") << "n=" << n << " " << describe(winding);
      }
      drawn += status == SetupStatus::Drawn;
      offscreen += status == SetupStatus::Offscreen;
      no_centre += status == SetupStatus::NoCentre;
      degenerate += status == SetupStatus::Degenerate;
    }
    // The directed families must really be what their names say.
    if (std::string(family.name) == "degenerate") EXPECT_EQ(degenerate, 400);
    else if (std::string(family.name) == "offscreen") {
      // Beside the screen (4 in 5) or in a strip between two centres: at S = 1 the strip is one
      // subpixel column, so those come out degenerate.
      EXPECT_EQ(offscreen + no_centre + degenerate, 400);
      EXPECT_GT(offscreen, 250);
      if (p.subpixel_bits >= 2) EXPECT_GT(no_centre, 30);
      else EXPECT_EQ(no_centre, 0);
    }
    else EXPECT_GT(drawn, 100);
  }
}

std::vector<Convention> every_convention() {
  std::vector<Convention> out;
  for (PixelCenter c : {PixelCenter::Half, PixelCenter::Corner})
    for (FillRule r : {FillRule::TopLeft, FillRule::TopRight, FillRule::BottomLeft, FillRule::BottomRight})
      out.push_back({c, r});
  return out;
}

INSTANTIATE_TEST_SUITE_P(SubpixelBitsTraversalsAndConventions, Coverage,
                         ::testing::Combine(::testing::Values(8, 4, 1),
                                            ::testing::Values(Traversal::BBox, Traversal::Span),
                                            ::testing::ValuesIn(every_convention())),
                         [](const auto& info) {
                           const Convention c = std::get<2>(info.param);
                           return "S" + std::to_string(std::get<0>(info.param)) + "_" +
                                  to_string(std::get<1>(info.param)) + "_" + to_string(c.first) + "_" + to_string(c.second);
                         });

// Directed cases whose coverage is known by hand, so that the reference itself is checked too.
TEST(CoverageDirected, TopLeftRuleByHand) {
  for (Traversal traversal : {Traversal::BBox, Traversal::Span}) {
    const Profile p = test::make_profile(8, 8, 4, traversal);
    Pipeline pipe(p);
    FragmentLog log;
    pipe.set_fragment_sink(&log);
    auto pixels_of = [&](const SnappedTriangle& t) {
      log.fragments.clear();
      pipe.submit(t);
      std::vector<std::pair<int, int>> out;
      for (const Fragment& f : log.fragments) out.emplace_back(f.x, f.y);
      return out;
    };
    auto tri = [](int x0, int y0, int x1, int y1, int x2, int y2) {
      SnappedTriangle t;
      t.v[0].x = x0, t.v[0].y = y0, t.v[1].x = x1, t.v[1].y = y1, t.v[2].x = x2, t.v[2].y = y2;
      return t;
    };
    using Pixels = std::vector<std::pair<int, int>>;
    // A 2x2-pixel square between pixel centres (8, 8) and (40, 40) subpixels, split along its
    // diagonal: centres on the top and left sides belong to it, those on the right and bottom do
    // not; the diagonal's centres (1,1) go to the triangle that has it as a left edge.
    // Upper-right half (top edge y=8, right edge x=40, diagonal): top-edge centres (0,0), (1,0)
    // and the diagonal centre (1,1) (a left edge of this half); the corner (2,0) is on its
    // right edge.
    EXPECT_EQ(pixels_of(tri(8, 8, 40, 8, 40, 40)), (Pixels{{0, 0}, {1, 0}, {1, 1}})) << to_string(traversal);
    // Lower-left half (left edge x=8, bottom edge y=40, diagonal as a right edge): (0,1) only.
    EXPECT_EQ(pixels_of(tri(8, 8, 40, 40, 8, 40)), (Pixels{{0, 1}})) << to_string(traversal);
    // A vertex exactly on a centre with both its edges top and left: the centre is covered.
    EXPECT_EQ(pixels_of(tri(24, 24, 40, 24, 24, 40)), (Pixels{{1, 1}})) << to_string(traversal);
    // The same corner as a bottom-right corner: not covered.
    EXPECT_EQ(pixels_of(tri(24, 24, 24, 8, 8, 24)), (Pixels{})) << to_string(traversal);
  }
}

// docs/arithmetic.md: front faces are counter-clockwise as the viewer sees the screen (y down), unless
// front_face says cw; cull removes back or front faces, which then produce nothing.
TEST(CoverageDirected, CullingFollowsTheScreenWinding) {
  SnappedTriangle clockwise;  // (1, 1) -> (9, 1) -> (1, 9) in pixels: clockwise on a y-down screen
  clockwise.v[0].x = 16, clockwise.v[0].y = 16, clockwise.v[1].x = 144, clockwise.v[1].y = 16;
  clockwise.v[2].x = 16, clockwise.v[2].y = 144;
  const SnappedTriangle counter_clockwise = test::reversed(clockwise);
  for (FrontFace front : {FrontFace::CCW, FrontFace::CW})
    for (CullMode cull : {CullMode::None, CullMode::Back, CullMode::Front}) {
      Profile p = test::make_profile(16, 16, 4, Traversal::Span);
      p.front_face = front;
      p.cull = cull;
      Pipeline pipe(p);
      FragmentLog log;
      pipe.set_fragment_sink(&log);
      for (const bool is_clockwise : {true, false}) {
        const SnappedTriangle& t = is_clockwise ? clockwise : counter_clockwise;
        const bool is_front = is_clockwise == (front == FrontFace::CW);
        const bool culled = (cull == CullMode::Back && !is_front) || (cull == CullMode::Front && is_front);
        log.fragments.clear();
        pipe.submit(t);
        SCOPED_TRACE(::testing::Message() << "front_face " << to_string(front) << " cull " << to_string(cull)
                                          << (is_clockwise ? " clockwise" : " counter-clockwise"));
        EXPECT_EQ(pipe.last_setup().front_facing, is_front);
        EXPECT_EQ(to_string(pipe.last_setup().status), std::string(culled ? "culled" : "drawn"));
        EXPECT_EQ(log.fragments.size(), culled ? 0u : reference::covered_pixels(t, p).size());
      }
      EXPECT_EQ(pipe.stats().triangles_culled, cull == CullMode::None ? 0 : 1);
    }
}

// A fragment recorder for big screens: checks the walker order of every fragment and keeps only
// the fragments of selected rows.
struct SampledRowsLog : FragmentSink {
  std::vector<char> keep_row;
  bool keep_all = false;
  std::vector<Fragment> kept;
  int64_t count = 0;
  bool in_walker_order = true;
  int last_x = -1, last_y = -1;
  void restart(int height) {
    keep_row.assign(size_t(height), 0);
    kept.clear();
    count = 0;
    in_walker_order = true;
    last_x = last_y = -1;
  }
  void on_fragment(const Fragment& f) override {
    ++count;
    if (f.y < last_y || (f.y == last_y && f.x <= last_x)) in_walker_order = false;
    last_x = f.x, last_y = f.y;
    if (keep_all || keep_row[size_t(f.y)]) kept.push_back(f);
  }
};

// Compares the triangle completely when its candidate box is small, else on the box's first and
// last rows, the vertices' rows and random rows. Returns the number of rows compared.
void compare_on_big_screen(Pipeline& pipe, SampledRowsLog& log, const SnappedTriangle& t, const Profile& p,
                           std::mt19937_64& rng) {
  const reference::PixelRect box = reference::bounding_box(t, p);
  log.restart(p.height);
  log.keep_all = box.area() <= 100000;
  std::vector<int> rows;
  if (!log.keep_all && !box.empty()) {
    rows = {box.y0, box.y1};
    for (const SnappedVertex& v : t.v) {
      const int64_t row = (int64_t(v.y) >> p.subpixel_bits);
      if (row >= box.y0 && row <= box.y1) rows.push_back(int(row));
    }
    std::uniform_int_distribution<int> pick(box.y0, box.y1);
    for (int k = 0; k < 10; ++k) rows.push_back(pick(rng));
    for (int row : rows) log.keep_row[size_t(row)] = 1;
  }
  pipe.submit(t);
  ASSERT_EQ(to_string(pipe.last_setup().status), std::string(to_string(expected_status(t, p)))) << describe(t);
  ASSERT_TRUE(log.in_walker_order) << describe(t);
  if (log.keep_all) {
    ASSERT_EQ(coverage_difference(log.kept, reference::covered_pixels(t, p)), "") << describe(t);
    return;
  }
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  for (int row : rows) {
    std::vector<int> model_row;
    for (const Fragment& f : log.kept)
      if (f.y == row) model_row.push_back(f.x);
    ASSERT_EQ(model_row, reference::covered_in_row(t, p, row)) << "row " << row << " " << describe(t);
  }
}

class BigScreenCoverage : public ::testing::TestWithParam<Traversal> {};

TEST_P(BigScreenCoverage, GuardBandLimitsAt4096S8) {
  const Profile p = test::make_profile(4096, 4096, 8, GetParam());
  const uint64_t seed = 4096;
  SCOPED_TRACE(::testing::Message() << describe(p) << " seed " << seed);
  Pipeline pipe(p);
  SampledRowsLog log;
  pipe.set_fragment_sink(&log);
  TriangleGen gen(p, seed);
  // Triangles between the guard band's corners, the screen's corners and the midpoints.
  const int64_t M = gen.M(), W = int64_t(p.width) * M, H = int64_t(p.height) * M;
  const int64_t xs[] = {-W, 0, W / 2, W, 2 * W}, ys[] = {-H, 0, H / 2, H, 2 * H};
  for (int n = 0; n < 10; ++n) {
    const SnappedTriangle t = gen.triangle(xs[gen.uniform(0, 4)], ys[gen.uniform(0, 4)], xs[gen.uniform(0, 4)],
                                           ys[gen.uniform(0, 4)], xs[gen.uniform(0, 4)], ys[gen.uniform(0, 4)]);
    compare_on_big_screen(pipe, log, n % 2 ? t : test::reversed(t), p, gen.rng());
  }
  // The largest triangle: two guard-band corners and the opposite edge's midpoint.
  compare_on_big_screen(pipe, log, gen.triangle(-W, -H, 2 * W, -H, W / 2, 2 * H), p, gen.rng());
  for (int n = 0; n < 6; ++n) compare_on_big_screen(pipe, log, gen.guard_band(), p, gen.rng());
  for (int n = 0; n < 6; ++n) compare_on_big_screen(pipe, log, gen.sliver(3000), p, gen.rng());
  // Medium and small triangles anywhere, compared completely.
  for (int n = 0; n < 300; ++n) compare_on_big_screen(pipe, log, gen.near_screen(24), p, gen.rng());
  for (int n = 0; n < 300; ++n) compare_on_big_screen(pipe, log, gen.on_centres(4), p, gen.rng());
  for (int n = 0; n < 300; ++n) compare_on_big_screen(pipe, log, gen.tiny(), p, gen.rng());
  for (int n = 0; n < 100; ++n) compare_on_big_screen(pipe, log, gen.offscreen(), p, gen.rng());
}

INSTANTIATE_TEST_SUITE_P(Traversals, BigScreenCoverage, ::testing::Values(Traversal::BBox, Traversal::Span),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace rastersim
