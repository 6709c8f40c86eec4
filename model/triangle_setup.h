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

enum class SetupStatus : uint8_t {
  Drawn,       // goes on to the walker
  Degenerate,  // zero signed area
  Culled,      // back or front face removed by the profile's cull
  Offscreen,   // no pixel centre of the screen lies in the bounding box
};
const char* to_string(SetupStatus status);

// One edge function E(P) = dx (Py - Ya) - dy (Px - Xa) - bias, for the edge from vertex a to b
// after the vertices are ordered so that the interior has E >= 0 (twice the area > 0).
struct EdgeSetup {
  int64_t start;        // E at the first candidate's centre (bbox x0, y0), s(edge_bits).2S, biased
  int64_t step_x;       // E change per pixel in x = -dy * 2^S, s.2S
  int64_t step_y;       // E change per pixel in y =  dx * 2^S, s.2S
  bool top_left;        // bias 0 (top or left edge) or 1
  // Span walker (exact row bounds without division per row): with d = |step_x| > 0,
  // start = span_quot * d + span_rem and step_y = span_step_quot * d + span_step_rem, remainders
  // in [0, d). Unused when step_x == 0.
  int64_t span_quot;
  int64_t span_rem;
  int64_t span_step_quot;
  int64_t span_step_rem;
};

// A plane P(x, y) = start + (x - x0) * step_x + (y - y0) * step_y held in a wrapping register of
// `reg_bits` with F fraction bits: start = floor(2^F P(x0 + 1/2, y0 + 1/2)), step = floor(2^F dP).
struct PlaneSetup {
  int64_t start;
  int64_t step_x;
  int64_t step_y;
};

struct SetupResult {
  SetupStatus status = SetupStatus::Degenerate;
  bool front_facing = false;
  int64_t area2 = 0;             // twice the signed area as submitted (s.2S, > 0 = clockwise on screen)
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // candidate pixel range, inclusive, on screen
  EdgeSetup edge[3]{};           // edge k runs from ordered vertex k to vertex k+1
  PlaneSetup depth{};            // s(N+1).F
  PlaneSetup color[3]{};         // r, g, b planes, s9.F (Gouraud)
  Rgb flat_color;                // provoking (first) vertex colour (flat)
};

class TriangleSetup {
 public:
  explicit TriangleSetup(const Profile& profile);
  SetupResult run(const SnappedTriangle& tri) const;
  // Cycles from accept to the output register being valid (drawn) or to done (rejected).
  int cycles(SetupStatus status) const {
    return status == SetupStatus::Drawn ? widths_.setup_cycles : widths_.setup_front_cycles;
  }
  const Widths& widths() const { return widths_; }

 private:
  PlaneSetup plane(const i128 value[3], const i128 edge_at_start[3], const int64_t step_x[3],
                   const int64_t step_y[3], i128 area2, int reg_bits, const char* what) const;
  Profile profile_;
  Widths widths_;
};

}  // namespace rastersim
