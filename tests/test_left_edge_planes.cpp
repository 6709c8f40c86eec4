// The setup record's planes along the left edges (docs/cycle-model.md, "Planes along the left
// edges"), checked row by row against an independent computation: for every row y of a drawn
// triangle's box, a left edge's span start is x0 - floor(E(y) / d) with E(y) = start + (y - y0)
// step_y and d = edge_step_x (a floor division per row, no DDA), and the plane there is
// start + (y - y0) step_y - floor(E(y) / d) step_x modulo the register width. Stepping the slot's
// `start` by `step` per row, and by step_x less when the quotient moved one more than
// span_step_quot, must land on it in every row; the quotient never moves by anything else.
#include <gtest/gtest.h>

#include <random>

#include "model/triangle_setup.h"
#include "model/widths.h"

namespace rastersim {
namespace {

i128 floor_quotient(i128 n, i128 d) {  // d > 0
  const i128 q = n / d;
  return (n % d != 0 && n < 0) ? q - 1 : q;
}

int64_t wrap(i128 v, int bits) { return wrap_signed(v, bits); }

struct Counts {
  int64_t slots = 0, rows = 0, two_left_edges = 0;
};

void check_profile(const Profile& p, uint64_t seed, int triangles, Counts& counts) {
  const Widths w = derive_widths(p);
  const TriangleSetup setup(p);
  std::mt19937_64 rng(seed);
  const int64_t span_x = int64_t(p.width) << p.subpixel_bits, span_y = int64_t(p.height) << p.subpixel_bits;
  for (int n = 0; n < triangles; ++n) {
    SnappedTriangle t;
    for (SnappedVertex& v : t.v) {
      // Within the guard band [-W, 2W) x [-H, 2H), mostly on screen.
      v.x = int32_t(int64_t(rng() % uint64_t(2 * span_x)) - span_x / 2);
      v.y = int32_t(int64_t(rng() % uint64_t(2 * span_y)) - span_y / 2);
      v.z = uint32_t(rng() & ((uint64_t(1) << p.z_bits) - 1));
      v.color = Rgb{uint8_t(rng()), uint8_t(rng()), uint8_t(rng())};
    }
    const SetupResult s = setup.run(t);
    if (s.status != SetupStatus::Drawn) continue;
    int slot = 0;
    for (int k = 0; k < 3; ++k) {
      const EdgeSetup& e = s.edge[k];
      if (e.step_x <= 0) continue;
      ASSERT_LT(slot, kLeftEdgeSlots) << "a triangle has at most two left edges";
      const LeftEdgePlanes& left = s.left[slot++];
      ++counts.slots;
      const PlaneSetup* planes[4] = {&s.depth, &s.color[0], &s.color[1], &s.color[2]};
      const EdgePlane* along[4] = {&left.depth, &left.color[0], &left.color[1], &left.color[2]};
      const int bits[4] = {w.z_reg_bits, w.color_reg_bits, w.color_reg_bits, w.color_reg_bits};
      i128 value[4];
      for (int q = 0; q < 4; ++q) value[q] = along[q]->start;
      i128 quot = floor_quotient(i128(e.start), i128(e.step_x));
      ASSERT_EQ(quot, i128(e.span_quot)) << "triangle " << n << " edge " << k;
      for (int y = s.y0; y <= s.y1 && y < s.y0 + 64; ++y) {
        ++counts.rows;
        for (int q = 0; q < 4; ++q) {
          const i128 at_span_start = i128(planes[q]->start) + i128(y - s.y0) * planes[q]->step_y - quot * planes[q]->step_x;
          ASSERT_EQ(wrap(value[q], bits[q]), wrap(at_span_start, bits[q]))
              << "triangle " << n << ", edge " << k << ", plane " << q << ", row " << y;
        }
        const i128 next = floor_quotient(i128(e.start) + i128(y + 1 - s.y0) * e.step_y, i128(e.step_x));
        const i128 carry = next - quot - i128(e.span_step_quot);
        ASSERT_TRUE(carry == 0 || carry == 1) << "the DDA's quotient moves by span_step_quot or one more";
        for (int q = 0; q < 4; ++q) value[q] += i128(along[q]->step) - carry * planes[q]->step_x;
        quot = next;
      }
    }
    if (slot == 2) ++counts.two_left_edges;
    for (int j = slot; j < kLeftEdgeSlots; ++j) {  // a slot without an edge: quotients 0
      EXPECT_EQ(int64_t(s.left[j].depth.start), int64_t(s.depth.start));
      EXPECT_EQ(int64_t(s.left[j].depth.step), int64_t(s.depth.step_y));
    }
  }
}

TEST(LeftEdgePlanes, FollowTheSpanStartRowByRow) {
  struct Case {
    int width, height, subpixel_bits, z_bits;
  };
  for (const Case c : {Case{640, 480, 4, 24}, Case{16, 12, 4, 16}, Case{32, 24, 2, 16}, Case{4096, 4096, 8, 32}}) {
    Profile p;
    p.width = c.width, p.height = c.height, p.subpixel_bits = c.subpixel_bits, p.z_bits = c.z_bits;
    p.shading = Shading::Gouraud;
    p.cull = CullMode::None;
    Counts counts;
    check_profile(p, 1234u + uint64_t(c.width), 3000, counts);
    // The check must have had something to check: left edges in both slots, many rows.
    EXPECT_GT(counts.slots, 3000) << c.width << "x" << c.height;
    EXPECT_GT(counts.two_left_edges, 300) << c.width << "x" << c.height;
    EXPECT_GT(counts.rows, 30000) << c.width << "x" << c.height;
  }
}

TEST(LeftEdgePlanes, FlatShadingLeavesTheColourPlanesZero) {
  Profile p;
  p.shading = Shading::Flat;
  const TriangleSetup setup(p);
  SnappedTriangle t;
  t.v[0] = {0, 0, 100, Rgb{10, 20, 30}};
  t.v[1] = {int32_t(200) << p.subpixel_bits, int32_t(40) << p.subpixel_bits, 5000, Rgb{200, 100, 50}};
  t.v[2] = {int32_t(60) << p.subpixel_bits, int32_t(150) << p.subpixel_bits, 90000, Rgb{1, 2, 3}};
  const SetupResult s = setup.run(t);
  ASSERT_EQ(s.status, SetupStatus::Drawn);
  for (const LeftEdgePlanes& left : s.left)
    for (const EdgePlane& c : left.color) {
      EXPECT_EQ(int64_t(c.start), 0);
      EXPECT_EQ(int64_t(c.step), 0);
    }
}

}  // namespace
}  // namespace rastersim
