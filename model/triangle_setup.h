// Triangle setup unit: snapped vertices in; edge functions with the top-left bias, the
// screen-clipped bounding box, the cull / degenerate decision, and the depth and colour planes
// (start value and per-pixel x / y increments from an exact floor division). docs/arithmetic.md.
#pragma once

#include <cstdint>

#include "fixed.h"
#include "profile.h"
#include "triangle.h"
#include "widths.h"

namespace rastersim {

// The setup record's register types, sized for the largest profile (4096 x 4096, S = 8, N = 32,
// z_guard_bits up to 24); a smaller profile's narrower widths are checked when the values are made.
using AreaValue = Reg<45>;                 // twice the signed area, s.2S
using EdgeValue = Reg<45>;                 // edge function value, s.2S
using EdgeStep = Reg<31>;                  // edge step per pixel, s.2S
using SpanQuotient = Reg<45>;              // floor(E / |edge_step_x|), s.0
using SpanStepQuotient = Reg<31>;          // floor(edge_step_y / |edge_step_x|), s.0
using SpanRemainder = Reg<30, false>;      // in [0, |edge_step_x|), u.2S
using PlaneValue = Reg<64>;                // plane register, s(N+1).F, s9.F or s9.(P+Ft), wrapped
constexpr Widths kLargestWidths = derive_widths(4096, 4096, 8, 32, 24);
static_assert(kLargestWidths.area_bits <= AreaValue::bits);
static_assert(kLargestWidths.edge_bits <= EdgeValue::bits && kLargestWidths.edge_bits <= SpanQuotient::bits);
static_assert(kLargestWidths.edge_step_x_bits <= EdgeStep::bits && kLargestWidths.edge_step_y_bits <= EdgeStep::bits);
static_assert(kLargestWidths.edge_step_y_bits <= SpanStepQuotient::bits);
static_assert(kLargestWidths.span_rem_bits <= SpanRemainder::bits);
static_assert(kLargestWidths.z_reg_bits <= PlaneValue::bits && kLargestWidths.color_reg_bits <= PlaneValue::bits);
static_assert(kLargestWidths.texture_reg_bits <= PlaneValue::bits);

enum class SetupStatus : uint8_t {
  Drawn,       // goes on to the walker
  Degenerate,  // zero signed area
  Culled,      // back or front face removed by the profile's cull
  Offscreen,   // the bounding box's pixel-centre columns or rows all lie beyond the screen
  NoCentre,    // on the screen, but no pixel centre lies in the bounding box (it falls between them)
};
const char* to_string(SetupStatus status);

// One edge function E(P) = dx (Py - Ya) - dy (Px - Xa) - bias, for the edge from vertex a to b
// after the vertices are ordered so that the interior has E >= 0 (twice the area > 0).
struct EdgeSetup {
  EdgeValue start;      // E at the first candidate's centre (bbox x0, y0), s(edge_bits).2S, biased
  EdgeStep step_x;      // E change per pixel in x = -dy * 2^S, s(edge_step_x_bits).2S
  EdgeStep step_y;      // E change per pixel in y =  dx * 2^S, s(edge_step_y_bits).2S
  bool owns_samples;    // bias 0: the samples on the edge are inside (the profile's fill_rule), else 1
  // Span walker (exact row bounds without division per row): with d = |step_x| > 0,
  // start = span_quot * d + span_rem and step_y = span_step_quot * d + span_step_rem, remainders
  // in [0, d). Unused when step_x == 0.
  SpanQuotient span_quot;
  SpanRemainder span_rem;
  SpanStepQuotient span_step_quot;
  SpanRemainder span_step_rem;
};

// Whether an edge from a to b (dx = Xb - Xa, dy = Yb - Ya) of a triangle ordered to area2 > 0
// owns the samples that lie on it under `rule` (docs/arithmetic.md sections 2 and 7).
bool owns_samples_on_edge(FillRule rule, int64_t dx, int64_t dy);

// A plane P(x, y) = start + (x - x0) * step_x + (y - y0) * step_y held in a wrapping register of
// `reg_bits` with F fraction bits: start = floor(2^F P(x0 + 1/2, y0 + 1/2)), step = floor(2^F dP).
struct PlaneSetup {
  PlaneValue start;
  PlaneValue step_x;
  PlaneValue step_y;
};

// A plane along a left edge (edge_step_x > 0), for the walker's span start without a multiplier
// (docs/cycle-model.md): both modulo the plane register's width.
struct EdgePlane {
  PlaneValue start;  // start - span_quot * step_x: the plane at the edge's span start x0 - span_quot, row y0
  PlaneValue step;   // step_y - span_step_quot * step_x: its change per row without the DDA's carry
};

// The planes along the triangle's left edges: slot 0 is the first left edge in edge order, slot 1
// the second (a slot without an edge takes quotients 0: start and step_y).
struct LeftEdgePlanes {
  EdgePlane depth;
  EdgePlane color[3];  // r, g, b (zero, as their planes, without Gouraud shading)
  EdgePlane texture[3];  // S, T, Q (zero, as their planes, for an untextured triangle)
};
constexpr int kLeftEdgeSlots = 2;

struct SetupResult {
  SetupStatus status = SetupStatus::Degenerate;
  bool front_facing = false;
  AreaValue area2 = 0;           // twice the signed area as submitted (s.2S, > 0 = clockwise on screen)
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // candidate pixel range, inclusive, on screen
  EdgeSetup edge[3]{};           // edge k runs from ordered vertex k to vertex k+1
  PlaneSetup depth{};            // s(N+1).F
  PlaneSetup color[3]{};         // r, g, b planes, s9.F (Gouraud)
  Rgb flat_color;                // provoking (first) vertex colour (flat)
  bool textured = false;         // the texture planes below are set (docs/arithmetic.md section 5)
  PlaneSetup texture[3]{};       // S = u/w, T = v/w, Q = 1/w planes, s9.(P+Ft)
  LeftEdgePlanes left[kLeftEdgeSlots]{};
};

// What the front stage hands to the planes: the edge functions' inputs to the plane weights.
struct SetupEdges {
  const SnappedVertex* v[3];      // the input's vertices ordered to area2 > 0 (it must outlive this)
  i128 unbiased[3];               // each edge function at the first candidate without its bias, s.2S
  int64_t step_x[3], step_y[3];   // the edge steps, s.2S
  int64_t area;                   // |area2| > 0, s.2S
};

class TriangleSetup {
 public:
  explicit TriangleSetup(const Profile& profile);
  SetupResult run(const SnappedTriangle& tri) const {
    SetupResult r;
    run(tri, r);
    return r;
  }
  // The same into `r` (the pipeline's output register), without copying the result: front(), then
  // for a drawn triangle planes() and left_edge_planes().
  void run(const SnappedTriangle& tri, SetupResult& r) const;

  // The stages of run(). front: the status, facing, area, box and edges into `r`; true for a drawn
  // triangle, whose planes follow from `edges`. Every field of a drawn triangle's record is written
  // by the three stages (the colour planes only with Gouraud shading, otherwise they keep a fresh
  // record's zeros); a rejected one's record is a fresh one with what was decided.
  bool front(const SnappedTriangle& tri, SetupResult& r, SetupEdges& edges) const;
  // The depth, colour and texture planes (r.depth, r.color, r.texture).
  void planes(const SetupEdges& edges, SetupResult& r) const;
  // The planes along the left edges (r.left), from the planes and the edges' span quotients: what
  // the walker enters rows with. A walk that enters them another way (ZAdder::enter_row_at, the
  // fast walks in fast/) does not need them.
  void left_edge_planes(SetupResult& r) const;

  const Profile& profile() const { return profile_; }
  const Widths& widths() const { return widths_; }

 private:
  // The register format of a plane: fraction bits beyond the vertex values', width, dividend limit.
  struct PlaneFormatBits {
    int guard_bits, reg_bits, divider_bits;
  };
  PlaneSetup plane(const i128 value[3], const i128 edge_at_start[3], const int64_t step_x[3],
                   const int64_t step_y[3], const FloorDivider& by_area2, PlaneFormatBits format,
                   const char* what) const;
  Profile profile_;
  Widths widths_;
};

}  // namespace rastersim
