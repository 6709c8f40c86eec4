// Helpers shared by the verification tests: a fragment recorder, seeded triangle generators in
// snapped (subpixel) coordinates, and readable descriptions for failure messages.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "model/pipeline.h"
#include "reference.h"

namespace rastersim {
// Readable test parameters in gtest and ctest output (found by argument-dependent lookup).
inline void PrintTo(Traversal v, std::ostream* out) { *out << to_string(v); }
inline void PrintTo(Shading v, std::ostream* out) { *out << to_string(v); }
inline void PrintTo(DepthFunc v, std::ostream* out) { *out << to_string(v); }
}  // namespace rastersim

namespace rastersim::test {

// Records every fragment the pipeline emits.
struct FragmentLog : FragmentSink {
  std::vector<Fragment> fragments;
  void on_fragment(const Fragment& f) override { fragments.push_back(f); }
};

// A whole frame's results: every counter, triangle record and buffer word.
struct Frame {
  FrameStats stats;
  std::vector<TriangleRecord> records;
  std::vector<uint32_t> depth, color;
};

inline void expect_same_counters(const UnitCounters& a, const UnitCounters& b, const char* unit) {
  EXPECT_EQ(a.busy, b.busy) << unit << " busy";
  EXPECT_EQ(a.stall, b.stall) << unit << " stall";
}

// `other` (an untraced, fast or threaded render) is `spec`'s frame in every counter, cycle, record
// field and buffer word.
inline void expect_same_frame(const Frame& spec, const Frame& other) {
  const FrameStats &a = spec.stats, &b = other.stats;
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.triangles_culled, b.triangles_culled);
  EXPECT_EQ(a.triangles_degenerate, b.triangles_degenerate);
  EXPECT_EQ(a.triangles_offscreen, b.triangles_offscreen);
  EXPECT_EQ(a.triangles_no_centre, b.triangles_no_centre);
  EXPECT_EQ(a.triangles_drawn, b.triangles_drawn);
  EXPECT_EQ(a.candidates, b.candidates);
  EXPECT_EQ(a.fragments, b.fragments);
  EXPECT_EQ(a.depth_pass, b.depth_pass);
  EXPECT_EQ(a.depth_fail, b.depth_fail);
  EXPECT_EQ(a.cycles, b.cycles);
  expect_same_counters(a.setup, b.setup, "setup");
  expect_same_counters(a.walker, b.walker, "walker");
  expect_same_counters(a.z_adder, b.z_adder, "z_adder");
  expect_same_counters(a.zbuffer, b.zbuffer, "zbuffer");
  expect_same_counters(a.texture, b.texture, "texture");
  ASSERT_EQ(spec.records.size(), other.records.size());
  for (size_t i = 0; i < spec.records.size(); ++i) {
    const TriangleRecord &r = spec.records[i], &t = other.records[i];
    EXPECT_EQ(r.index, t.index) << "triangle " << i;
    EXPECT_EQ(r.status, t.status) << "triangle " << i;
    EXPECT_EQ(r.setup_accept, t.setup_accept) << "triangle " << i;
    EXPECT_EQ(r.setup_decided, t.setup_decided) << "triangle " << i;
    EXPECT_EQ(r.setup_done, t.setup_done) << "triangle " << i;
    EXPECT_EQ(r.walker_load, t.walker_load) << "triangle " << i;
    EXPECT_EQ(r.walker_end, t.walker_end) << "triangle " << i;
    EXPECT_EQ(r.fragments, t.fragments) << "triangle " << i;
    EXPECT_EQ(r.depth_pass, t.depth_pass) << "triangle " << i;
    EXPECT_EQ(r.last_write, t.last_write) << "triangle " << i;
  }
  EXPECT_TRUE(spec.depth == other.depth) << "depth buffers differ";
  EXPECT_TRUE(spec.color == other.color) << "colour buffers differ";
}

inline std::string describe(const SnappedTriangle& t) {
  std::ostringstream out;
  out << "triangle (subpixels, depth, rgb)";
  for (const SnappedVertex& v : t.v)
    out << " (" << v.x << ", " << v.y << ", " << v.z << ", " << int(v.color.r) << "/" << int(v.color.g) << "/"
        << int(v.color.b) << ")";
  return out.str();
}

inline std::string describe(const Profile& p) {
  std::ostringstream out;
  out << "profile " << p.width << "x" << p.height << " S=" << p.subpixel_bits << " N=" << p.z_bits
      << " traversal=" << to_string(p.traversal) << " shading=" << to_string(p.shading)
      << " depth_func=" << to_string(p.depth_func) << " L=" << p.memory_latency;
  return out.str();
}

inline Profile make_profile(int width, int height, int subpixel_bits, Traversal traversal, int z_bits = 24) {
  Profile p;
  p.width = width;
  p.height = height;
  p.subpixel_bits = subpixel_bits;
  p.z_bits = z_bits;
  p.traversal = traversal;
  p.depth_func = DepthFunc::Always;
  p.shading = Shading::Gouraud;
  return p;
}

inline SnappedTriangle reversed(const SnappedTriangle& t) {
  SnappedTriangle r = t;
  std::swap(r.v[1], r.v[2]);
  return r;
}

// Seeded random triangles for one profile, all inside the guard band (every family documented at
// its function). Coordinates are subpixels; M = 2^S subpixels per pixel.
class TriangleGen {
 public:
  TriangleGen(const Profile& profile, uint64_t seed)
      : p_(profile), M_(int64_t(1) << profile.subpixel_bits), rng_(seed) {}

  int64_t uniform(int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng_); }
  bool coin() { return uniform(0, 1) == 1; }
  std::mt19937_64& rng() { return rng_; }
  int64_t M() const { return M_; }

  int64_t x_lo() const { return -int64_t(p_.width) * M_; }
  int64_t x_hi() const { return 2 * int64_t(p_.width) * M_; }
  int64_t y_lo() const { return -int64_t(p_.height) * M_; }
  int64_t y_hi() const { return 2 * int64_t(p_.height) * M_; }
  int64_t clamp_x(int64_t x) const { return std::clamp(x, x_lo(), x_hi()); }
  int64_t clamp_y(int64_t y) const { return std::clamp(y, y_lo(), y_hi()); }
  // Sample point of pixel i in subpixels: its centre, or its corner with pixel_center corner.
  int64_t centre(int64_t i) const { return i * M_ + p_.sample_offset(); }

  SnappedVertex vertex(int64_t x, int64_t y) {
    SnappedVertex v;
    v.x = int32_t(clamp_x(x));
    v.y = int32_t(clamp_y(y));
    v.z = uint32_t(uniform(0, (int64_t(1) << p_.depth_plane_bits()) - 1));
    v.color = Rgb{uint8_t(uniform(0, 255)), uint8_t(uniform(0, 255)), uint8_t(uniform(0, 255))};
    return v;
  }
  SnappedTriangle triangle(int64_t x0, int64_t y0, int64_t x1, int64_t y1, int64_t x2, int64_t y2) {
    return SnappedTriangle{{vertex(x0, y0), vertex(x1, y1), vertex(x2, y2)}};
  }

  // Vertices anywhere in the guard band.
  SnappedTriangle guard_band() {
    return triangle(uniform(x_lo(), x_hi()), uniform(y_lo(), y_hi()), uniform(x_lo(), x_hi()),
                    uniform(y_lo(), y_hi()), uniform(x_lo(), x_hi()), uniform(y_lo(), y_hi()));
  }
  // Vertices within `radius_px` pixels of a random point near the screen (a quarter screen around it).
  SnappedTriangle near_screen(int64_t radius_px) {
    const int64_t cx = uniform(-int64_t(p_.width) * M_ / 4, int64_t(p_.width) * M_ * 5 / 4);
    const int64_t cy = uniform(-int64_t(p_.height) * M_ / 4, int64_t(p_.height) * M_ * 5 / 4);
    const int64_t r = radius_px * M_;
    return triangle(cx + uniform(-r, r), cy + uniform(-r, r), cx + uniform(-r, r), cy + uniform(-r, r),
                    cx + uniform(-r, r), cy + uniform(-r, r));
  }
  // Sub-pixel triangles: every vertex within 3/4 pixel of a random point on screen.
  SnappedTriangle tiny() {
    const int64_t cx = uniform(0, int64_t(p_.width) * M_), cy = uniform(0, int64_t(p_.height) * M_);
    const int64_t r = std::max<int64_t>(1, M_ * 3 / 4);
    return triangle(cx + uniform(-r, r), cy + uniform(-r, r), cx + uniform(-r, r), cy + uniform(-r, r),
                    cx + uniform(-r, r), cy + uniform(-r, r));
  }
  // Every vertex exactly on a pixel centre, a few pixels apart: edges pass through many centres.
  SnappedTriangle on_centres(int64_t radius_px) {
    const int64_t i = uniform(-2, p_.width + 1), j = uniform(-2, p_.height + 1);
    auto px = [&] { return centre(i + uniform(-radius_px, radius_px)); };
    auto py = [&] { return centre(j + uniform(-radius_px, radius_px)); };
    const int64_t x0 = px(), y0 = py(), x1 = px(), y1 = py(), x2 = px(), y2 = py();
    return triangle(x0, y0, x1, y1, x2, y2);
  }
  // A horizontal and a vertical edge, each through a row / column of pixel centres; the third
  // vertex anywhere nearby (so the hypotenuse may pass through centres too).
  SnappedTriangle axis_edges_through_centres(int64_t radius_px) {
    const int64_t cx = centre(uniform(-1, p_.width)), cy = centre(uniform(-1, p_.height));
    const int64_t r = radius_px * M_;
    int64_t a = uniform(-r, r), b = uniform(-r, r);
    if (coin()) a = a / M_ * M_;  // often a whole number of pixels: the far corner on a centre too
    if (coin()) b = b / M_ * M_;
    switch (uniform(0, 2)) {
      case 0: return triangle(cx, cy, cx + a, cy, cx, cy + b);                         // right angle at a centre
      case 1: return triangle(cx, cy, cx + a, cy, cx + uniform(-r, r), cy + b);       // horizontal only
      default: return triangle(cx, cy, cx + uniform(-r, r), cy + b, cx, cy + b / 2);  // vertical only
    }
  }
  // One edge along a lattice direction (p, q) pixels from a centre, so it passes through the
  // centres A + k (p, q); the third vertex random nearby.
  SnappedTriangle edge_through_centres(int64_t radius_px) {
    const int64_t ax = centre(uniform(0, p_.width - 1)), ay = centre(uniform(0, p_.height - 1));
    const int64_t p = uniform(-4, 4), q = uniform(-4, 4), k = uniform(1, 4);
    const int64_t r = radius_px * M_;
    return triangle(ax, ay, ax + k * p * M_, ay + k * q * M_, ax + uniform(-r, r), ay + uniform(-r, r));
  }
  // Vertices on the half-pixel lattice (pixel corners, centres and edge midpoints): many ties.
  SnappedTriangle half_pixel_lattice(int64_t radius_px) {
    const int64_t half = std::max<int64_t>(1, M_ / 2);
    const int64_t cx = uniform(-2, 2 * p_.width + 2), cy = uniform(-2, 2 * p_.height + 2);
    const int64_t r = 2 * radius_px;
    return triangle((cx + uniform(-r, r)) * half, (cy + uniform(-r, r)) * half, (cx + uniform(-r, r)) * half,
                    (cy + uniform(-r, r)) * half, (cx + uniform(-r, r)) * half, (cy + uniform(-r, r)) * half);
  }
  // Thin slivers: the third vertex one subpixel off a point of the first edge.
  SnappedTriangle sliver(int64_t length_px) {
    const SnappedTriangle base = near_screen(length_px);
    const int64_t x0 = base.v[0].x, y0 = base.v[0].y, x1 = base.v[1].x, y1 = base.v[1].y;
    const int64_t num = uniform(0, 16);
    return triangle(x0, y0, x1, y1, x0 + (x1 - x0) * num / 16 + uniform(-1, 1), y0 + (y1 - y0) * num / 16 + uniform(-1, 1));
  }
  // Zero area: coincident vertices, or the third vertex on the line through the first two.
  SnappedTriangle degenerate() {
    const SnappedTriangle base = near_screen(8);
    const int64_t x0 = base.v[0].x, y0 = base.v[0].y;
    const int64_t dx = uniform(-3, 3) * M_ / 2 + uniform(-2, 2), dy = uniform(-3, 3) * M_ / 2 + uniform(-2, 2);
    switch (uniform(0, 3)) {
      case 0: return triangle(x0, y0, x0, y0, x0, y0);
      case 1: return triangle(x0, y0, x0, y0, x0 + dx, y0 + dy);
      case 2: return triangle(x0, y0, x0 + dx, y0 + dy, x0 + 2 * dx, y0 + 2 * dy);
      default: return triangle(x0 + 3 * dx, y0 + 3 * dy, x0 - dx, y0 - dy, x0 + dx, y0 + dy);
    }
  }
  // Entirely off screen (inside the guard band), or between two rows / columns of pixel centres.
  SnappedTriangle offscreen() {
    const int64_t edge = centre(0) - 1;  // last subpixel before the first sample point
    // (the right and bottom cases start one subpixel after the last sample point)
    const int64_t right = centre(p_.width - 1) + 1, bottom = centre(p_.height - 1) + 1;
    switch (uniform(0, 4)) {
      case 0: return triangle(uniform(x_lo(), edge), uniform(y_lo(), y_hi()), uniform(x_lo(), edge),
                              uniform(y_lo(), y_hi()), uniform(x_lo(), edge), uniform(y_lo(), y_hi()));
      case 1: return triangle(uniform(right, x_hi()), uniform(y_lo(), y_hi()), uniform(right, x_hi()),
                              uniform(y_lo(), y_hi()), uniform(right, x_hi()), uniform(y_lo(), y_hi()));
      case 2: return triangle(uniform(x_lo(), x_hi()), uniform(y_lo(), edge), uniform(x_lo(), x_hi()),
                              uniform(y_lo(), edge), uniform(x_lo(), x_hi()), uniform(y_lo(), edge));
      case 3: return triangle(uniform(x_lo(), x_hi()), uniform(bottom, y_hi()), uniform(x_lo(), x_hi()),
                              uniform(bottom, y_hi()), uniform(x_lo(), x_hi()), uniform(bottom, y_hi()));
      default: {
        // A thin vertical strip strictly between the centres of columns i and i + 1 (S >= 2 leaves
        // room; at S = 1 the strip is a single subpixel column at the pixel boundary).
        const int64_t i = uniform(0, p_.width - 2);
        const int64_t lo = centre(i) + 1, hi = std::max(lo, centre(i + 1) - 1);
        return triangle(uniform(lo, hi), uniform(y_lo(), y_hi()), uniform(lo, hi), uniform(y_lo(), y_hi()),
                        uniform(lo, hi), uniform(y_lo(), y_hi()));
      }
    }
  }

 private:
  Profile p_;
  int64_t M_;
  std::mt19937_64 rng_;
};

}  // namespace rastersim::test
