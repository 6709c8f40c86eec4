#include "testbench/vectors/suites.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "testbench/cosim_cases.h"

namespace rastersim::vectors {
namespace {

// Builds triangles from pixel coordinates, clamped into the guard band [-W, 2W) x [-H, 2H) so
// that a small screen still gets valid input (corner cases then merely land off screen).
class Builder {
 public:
  explicit Builder(const Profile& p) : p_(p), ulp_(std::ldexp(1.0, -p.subpixel_bits)) {}

  void add(double x0, double y0, double z0, double x1, double y1, double z1, double x2, double y2, double z2,
           Rgb c0, Rgb c1, Rgb c2) {
    ScreenTriangle t;
    const double xs[] = {x0, x1, x2}, ys[] = {y0, y1, y2}, zs[] = {z0, z1, z2};
    const Rgb cs[] = {c0, c1, c2};
    for (int k = 0; k < 3; ++k) {
      t.v[k].x = std::clamp(xs[k], -double(p_.width), 2.0 * p_.width - ulp_);
      t.v[k].y = std::clamp(ys[k], -double(p_.height), 2.0 * p_.height - ulp_);
      t.v[k].z = zs[k];
      t.v[k].color = cs[k];
    }
    const std::string problem = check_screen_triangle(t, p_);
    if (!problem.empty()) throw std::logic_error("vectors suite: " + problem);
    out_.push_back(snap(t, p_));
  }
  // Flat-coloured, constant depth.
  void flat(double x0, double y0, double x1, double y1, double x2, double y2, double z, Rgb c) {
    add(x0, y0, z, x1, y1, z, x2, y2, z, c, c, c);
  }

  std::vector<SnappedTriangle>& triangles() { return out_; }

 private:
  Profile p_;
  double ulp_;
  std::vector<SnappedTriangle> out_;
};

const Rgb kRed{220, 40, 40}, kGreen{40, 200, 60}, kBlue{50, 80, 230}, kYellow{230, 210, 40}, kGrey{128, 128, 128},
    kWhite{255, 255, 255}, kCyan{40, 210, 210}, kMagenta{200, 50, 200};

// Top-left rule, bounding-box and setup-decision corner cases in a 16 x 12 pixel corner of the
// screen, then the co-simulation's directed frames (ties, huge, off-screen, degenerate, long rows,
// hazards, repeated triangles), all in one frame.
std::vector<SnappedTriangle> rules(const Profile& p) {
  Builder b(p);
  const double W = p.width, H = p.height;
  // A horizontal top edge through pixel centres (row 1), the triangle below it: covered.
  b.flat(1, 1.5, 6, 1.5, 3.5, 4, 0.50, kRed);
  // A horizontal bottom edge through pixel centres (row 3), the triangle above it: not covered.
  b.flat(10.5, 0.25, 13, 3.5, 8, 3.5, 0.50, kGreen);
  // A vertical left edge through pixel centres (column 1): covered.
  b.flat(1.5, 5, 5, 8, 1.5, 11, 0.40, kBlue);
  // A vertical right edge through pixel centres (column 9): not covered.
  b.flat(9.5, 5, 9.5, 11, 6, 8, 0.40, kYellow);
  // Two triangles sharing a diagonal through pixel centres, opposite windings: every centre once.
  b.flat(10.5, 5.5, 14.5, 5.5, 14.5, 9.5, 0.30, kCyan);
  b.flat(10.5, 5.5, 10.5, 9.5, 14.5, 9.5, 0.30, kMagenta);
  // The same triangle in both windings (one of them culled under --cull back or front).
  b.flat(2, 9, 5, 11.5, 1, 11.5, 0.20, kWhite);
  b.flat(2, 9, 1, 11.5, 5, 11.5, 0.25, kGrey);
  // A sliver from a vertex on a pixel centre.
  b.flat(6.5, 9.5, 15.5, 10.5, 6.5, 10, 0.10, kRed);
  // A triangle whose bounding box holds no pixel centre: offscreen though on the screen.
  b.flat(3.6, 3.6, 3.9, 3.6, 3.6, 3.9, 0.5, kGreen);
  // A one-pixel triangle around the centre of pixel (12, 2).
  b.flat(12, 2, 13, 2, 12.5, 3, 0.05, kBlue);
  // Degenerate: a repeated vertex, and three collinear vertices.
  b.flat(2, 2, 8, 6, 2, 2, 0.5, kYellow);
  b.flat(1, 1, 5, 3, 9, 5, 0.5, kYellow);
  // Clipped by the top-left corner of the screen, and by the bottom-right corner.
  b.add(-3, -2, 0.9, 5, -2, 0.1, -3, 6, 0.5, kRed, kGreen, kBlue);
  b.add(W - 4, H + 2, 0.2, W + 3, H - 5, 0.8, W - 6, H - 4, 0.4, kCyan, kMagenta, kYellow);
  // Entirely left of and entirely above the screen (inside the guard band): offscreen.
  b.flat(-5, 1, -1, 1, -3, 4, 0.5, kGrey);
  b.flat(1, -5, 4, -1, 7, -5, 0.5, kGrey);
  // Gouraud colours and a depth slope across the corner.
  b.add(0.25, 0.25, 0.0, 15.75, 2.25, 1.0, 4.25, 11.75, 0.5, kRed, kGreen, kBlue);
  std::vector<SnappedTriangle> out = b.triangles();
  // Two of the huge triangles are enough to clip against every border; the random mix is left out.
  for (const rtl::CosimCase& c : rtl::directed_cases(p)) {
    if (c.name == "directed mixed") continue;
    const size_t n = c.name == "directed huge" ? std::min<size_t>(2, c.triangles.size()) : c.triangles.size();
    out.insert(out.end(), c.triangles.begin(), c.triangles.begin() + std::ptrdiff_t(n));
  }
  return out;
}

// Overlapping triangles at equal, nearer, farther, sloped, clear and zero depth: every depth
// function (and depth_write off) passes some fragments and fails others.
std::vector<SnappedTriangle> depth(const Profile& p) {
  Builder b(p);
  const double W = p.width, H = p.height;
  const double x0 = W / 8, x1 = 5 * W / 8, y0 = H / 8, y1 = 5 * H / 8;
  // A quad at depth 0.5, then the same quad again at the same depth in another colour.
  b.flat(x0, y0, x1, y0, x1, y1, 0.5, kRed);
  b.flat(x0, y0, x1, y1, x0, y1, 0.5, kRed);
  b.flat(x0, y0, x1, y0, x1, y1, 0.5, kGreen);
  b.flat(x0, y0, x1, y1, x0, y1, 0.5, kGreen);
  // Nearer and farther triangles over part of it.
  b.flat(3 * W / 8, 3 * H / 8, 7 * W / 8, 3 * H / 8, 3 * W / 8, 7 * H / 8, 0.25, kBlue);
  b.flat(W / 16, H / 4, W / 2, H / 4, W / 16, 3 * H / 4, 0.75, kYellow);
  // A slope from depth 0 to 1 through everything.
  b.add(0, H / 2, 0.0, W, H / 4, 1.0, W, H, 1.0, kCyan, kMagenta, kWhite);
  // At the clear depth (1.0 = 2^N - 1) where nothing was drawn, and at depth 0.
  b.flat(0, 7 * H / 8, W / 4, 7 * H / 8, 0, H, 1.0, kGrey);
  b.flat(3 * W / 4, 0, W, 0, W, H / 4, 0.0, kWhite);
  // Gouraud colours at the quad's depth, twice.
  b.add(x0, y0, 0.5, x1, y0, 0.5, x0, y1, 0.5, kRed, kGreen, kBlue);
  b.add(x0, y0, 0.5, x1, y0, 0.5, x0, y1, 0.5, kBlue, kRed, kGreen);
  return b.triangles();
}

}  // namespace

std::vector<std::pair<std::string, std::string>> suite_list() {
  return {{"rules", "top-left rule, bounding box and setup-decision corner cases, then the co-simulation's directed "
                    "frames (ties, two huge, off-screen, degenerate, long rows, hazards, repeats)"},
          {"depth", "overlapping triangles at equal, nearer, farther, sloped, clear and zero depth: for every depth "
                    "function"}};
}

std::vector<SnappedTriangle> suite_triangles(const std::string& name, const Profile& profile) {
  if (name == "rules") return rules(profile);
  if (name == "depth") return depth(profile);
  std::string names;
  for (const auto& [n, description] : suite_list()) names += (names.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown suite '" + name + "' (" + names + ")");
}

}  // namespace rastersim::vectors
