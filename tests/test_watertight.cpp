// Watertightness: meshes with shared vertices cover every pixel centre inside their outer boundary
// exactly once and nothing outside it, whatever the diagonals, the winding of each triangle and the
// submission order. The meshes tile an axis-aligned rectangle [X0, X1) x [Y0, Y1) (subpixels), so
// the expected coverage is known without any rasterizer: by the top-left rule a centre on the left
// or top side is inside, one on the right or bottom side is not (and likewise for the other fill
// rules and for samples at pixel corners, docs/arithmetic.md section 7).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <tuple>

#include "model/pipeline.h"
#include "reference.h"
#include "test_util.h"

namespace rastersim {
namespace {

struct Point {
  int64_t x, y;
};

struct Mesh {
  int64_t X0, Y0, X1, Y1;                // the outer boundary, subpixels
  std::vector<SnappedTriangle> triangles;
};

class MeshBuilder {
 public:
  MeshBuilder(const Profile& p, uint64_t seed) : gen_(p, seed), p_(p) {}

  // The boundary: inside the guard band, sometimes on pixel centres, sometimes beyond the screen.
  void pick_rectangle(Mesh& m) {
    const int64_t M = gen_.M(), W = int64_t(p_.width) * M, H = int64_t(p_.height) * M;
    auto side = [&](int64_t lo, int64_t hi) {
      const int64_t v = gen_.uniform(lo, hi);
      return gen_.coin() ? (v >> p_.subpixel_bits) * M + M / 2 : v;  // half the time on a centre
    };
    switch (gen_.uniform(0, 2)) {
      case 0:  // inside the screen
        m.X0 = side(0, W / 3), m.X1 = side(2 * W / 3, W), m.Y0 = side(0, H / 3), m.Y1 = side(2 * H / 3, H);
        break;
      case 1:  // covering the whole screen, into the guard band
        m.X0 = side(gen_.x_lo(), 0), m.X1 = side(W, gen_.x_hi()), m.Y0 = side(gen_.y_lo(), 0), m.Y1 = side(H, gen_.y_hi());
        break;
      default:  // straddling a screen edge
        m.X0 = side(gen_.x_lo() / 2, W / 2), m.X1 = side(W / 2 + M, W + W / 2), m.Y0 = side(-H / 2, H / 3),
        m.Y1 = side(2 * H / 3, 2 * H);
        break;
    }
  }

  // A jittered grid: each cell split along a random diagonal or into a fan of four around an
  // interior vertex. Boundary vertices move only along the boundary.
  Mesh grid() {
    Mesh m;
    pick_rectangle(m);
    // Cells at least 2 subpixels wide and high, so that a fan's centre is strictly inside.
    const int nx = int(std::clamp<int64_t>(gen_.uniform(1, 12), 1, std::max<int64_t>(1, (m.X1 - m.X0) / 2)));
    const int ny = int(std::clamp<int64_t>(gen_.uniform(1, 12), 1, std::max<int64_t>(1, (m.Y1 - m.Y0) / 2)));
    const int64_t cw = (m.X1 - m.X0) / nx, ch = (m.Y1 - m.Y0) / ny;
    std::vector<Point> v(size_t((nx + 1) * (ny + 1)));
    auto at = [&](int a, int b) -> Point& { return v[size_t(b * (nx + 1) + a)]; };
    for (int b = 0; b <= ny; ++b)
      for (int a = 0; a <= nx; ++a) {
        Point& q = at(a, b);
        q.x = a == nx ? m.X1 : m.X0 + a * cw;
        q.y = b == ny ? m.Y1 : m.Y0 + b * ch;
        // Jitter at most a fifth of a cell: every cell stays a strictly convex quad.
        if (a > 0 && a < nx) q.x += gen_.uniform(-cw / 5, cw / 5);
        if (b > 0 && b < ny) q.y += gen_.uniform(-ch / 5, ch / 5);
      }
    for (int b = 0; b < ny; ++b)
      for (int a = 0; a < nx; ++a) {
        // Corners in clockwise order on screen (y down): the triangles below have area2 > 0.
        const Point p00 = at(a, b), p10 = at(a + 1, b), p11 = at(a + 1, b + 1), p01 = at(a, b + 1);
        switch (gen_.uniform(0, 2)) {
          case 0: add(m, p00, p10, p11), add(m, p00, p11, p01); break;
          case 1: add(m, p00, p10, p01), add(m, p10, p11, p01); break;
          default: {
            const Point c{(p00.x + p10.x + p11.x + p01.x) / 4, (p00.y + p10.y + p11.y + p01.y) / 4};
            add(m, c, p00, p10), add(m, c, p10, p11), add(m, c, p11, p01), add(m, c, p01, p00);
          }
        }
      }
    return m;
  }

  // One fan: an interior vertex joined to a chain of points along the rectangle's four sides.
  Mesh fan() {
    Mesh m;
    pick_rectangle(m);
    std::vector<Point> ring;  // clockwise on screen from the top-left corner
    auto side = [&](Point from, Point to) {
      const int cuts = int(gen_.uniform(0, 6));
      std::vector<int64_t> ts;
      for (int k = 0; k < cuts; ++k) ts.push_back(gen_.uniform(1, 999));
      std::sort(ts.begin(), ts.end());
      ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
      ring.push_back(from);
      for (int64_t t : ts) {
        const Point q{from.x + (to.x - from.x) * t / 1000, from.y + (to.y - from.y) * t / 1000};
        const bool repeats = q.x == ring.back().x && q.y == ring.back().y;
        if (!repeats && !(q.x == to.x && q.y == to.y)) ring.push_back(q);
      }
    };
    const Point tl{m.X0, m.Y0}, tr{m.X1, m.Y0}, br{m.X1, m.Y1}, bl{m.X0, m.Y1};
    side(tl, tr), side(tr, br), side(br, bl), side(bl, tl);
    const Point c{gen_.uniform(m.X0 + (m.X1 - m.X0) / 8, m.X1 - (m.X1 - m.X0) / 8),
                  gen_.uniform(m.Y0 + (m.Y1 - m.Y0) / 8, m.Y1 - (m.Y1 - m.Y0) / 8)};
    for (size_t k = 0; k < ring.size(); ++k) add(m, c, ring[k], ring[(k + 1) % ring.size()]);
    return m;
  }

  void shuffle_and_flip(Mesh& m) {
    std::shuffle(m.triangles.begin(), m.triangles.end(), gen_.rng());
    for (SnappedTriangle& t : m.triangles)
      if (gen_.coin()) t = test::reversed(t);
  }

 private:
  void add(Mesh& m, Point a, Point b, Point c) {
    SnappedTriangle t = gen_.triangle(a.x, a.y, b.x, b.y, c.x, c.y);
    // The construction must give a proper mesh: every triangle positively oriented.
    EXPECT_GT(reference::twice_area(t), 0) << test::describe(t);
    m.triangles.push_back(t);
  }
  test::TriangleGen gen_;
  Profile p_;
};

struct PixelCounter : FragmentSink {
  int width;
  std::vector<int> count;
  explicit PixelCounter(const Profile& p) : width(p.width), count(size_t(p.width) * p.height, 0) {}
  void on_fragment(const Fragment& f) override { ++count[size_t(f.y) * width + f.x]; }
};

class Watertight : public ::testing::TestWithParam<std::tuple<int, Traversal, PixelCenter, FillRule>> {};

// Every sample inside the mesh's boundary rectangle is covered once. A sample on the boundary is
// inside when the rule owns that side: top_left the left and top sides, and so on (the rectangle's
// left side is a left edge of the triangles along it, its top side a top edge).
TEST_P(Watertight, MeshesCoverEveryInsideSampleExactlyOnce) {
  const auto [S, traversal, center, rule] = GetParam();
  Profile p = test::make_profile(64, 48, S, traversal);
  p.pixel_center = center;
  p.fill_rule = rule;
  const bool owns_left = rule == FillRule::TopLeft || rule == FillRule::BottomLeft;
  const bool owns_top = rule == FillRule::TopLeft || rule == FillRule::TopRight;
  const int64_t M = int64_t(1) << S;
  for (int mesh_index = 0; mesh_index < 400; ++mesh_index) {
    const uint64_t seed = 77 * uint64_t(S) + uint64_t(mesh_index) + 1000 * uint64_t(center) + 10000 * uint64_t(rule);
    MeshBuilder builder(p, seed);
    Mesh mesh = mesh_index % 2 ? builder.fan() : builder.grid();
    builder.shuffle_and_flip(mesh);
    SCOPED_TRACE(::testing::Message() << test::describe(p) << " mesh " << (mesh_index % 2 ? "fan" : "grid") << " seed "
                                      << seed << " boundary [" << mesh.X0 << ", " << mesh.X1 << ") x [" << mesh.Y0
                                      << ", " << mesh.Y1 << ") subpixels, " << mesh.triangles.size() << " triangles");
    Pipeline pipe(p);  // depth_func always: every covered centre is counted
    PixelCounter counter(p);
    pipe.set_fragment_sink(&counter);
    for (const SnappedTriangle& t : mesh.triangles) pipe.submit(t);
    int inside = 0;
    for (int j = 0; j < p.height; ++j)
      for (int i = 0; i < p.width; ++i) {
        const int64_t cx = i * M + p.sample_offset(), cy = j * M + p.sample_offset();
        const bool in_x = owns_left ? cx >= mesh.X0 && cx < mesh.X1 : cx > mesh.X0 && cx <= mesh.X1;
        const bool in_y = owns_top ? cy >= mesh.Y0 && cy < mesh.Y1 : cy > mesh.Y0 && cy <= mesh.Y1;
        const bool in = in_x && in_y;
        inside += in;
        ASSERT_EQ(counter.count[size_t(j) * p.width + i], in ? 1 : 0) << "pixel (" << i << ", " << j << ")";
      }
    EXPECT_GT(inside, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(SubpixelBitsTraversalsAndConventions, Watertight,
                         ::testing::Combine(::testing::Values(1, 4, 8),
                                            ::testing::Values(Traversal::BBox, Traversal::Span),
                                            ::testing::Values(PixelCenter::Half, PixelCenter::Corner),
                                            ::testing::Values(FillRule::TopLeft, FillRule::TopRight,
                                                              FillRule::BottomLeft, FillRule::BottomRight)),
                         [](const auto& info) {
                           return "S" + std::to_string(std::get<0>(info.param)) + "_" +
                                  to_string(std::get<1>(info.param)) + "_" + to_string(std::get<2>(info.param)) +
                                  "_" + to_string(std::get<3>(info.param));
                         });

}  // namespace
}  // namespace rastersim
