// Counter-driven scanline walker: x and y counters step over the triangle, edge functions are
// updated by additions only, one candidate pixel per clock. Two traversals (profile.traversal):
//  - bbox: every pixel of the bounding box, row by row, left to right; the edge test decides.
//  - span: per row, the exact first and last covered pixel come from the edges by stepping a
//    quotient and remainder (a DDA, additions only), computed while the row before goes out; one
//    cycle per covered pixel, one for a row with none.
// Both emit the same fragments in the same order; they differ in cycles (docs/cycle-model.md).
#pragma once

#include <algorithm>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "profile.h"
#include "triangle_setup.h"
#include "z_adder.h"

namespace rastersim {

struct WalkerCounters {
  int64_t busy = 0;        // candidate, empty-row and (idle) load cycles
  int64_t stall = 0;       // cycles a fragment waited for the z-buffer
  int64_t candidates = 0;  // pixel candidates visited (bbox: all bbox pixels; span: span pixels)
  int64_t rows = 0;
};

// A sink takes each covered candidate through fragment(x, y, adders, cycle). It may also offer
// run(x, y, n, adders, cycle): take n covered candidates of row y from pixel x, presented in
// consecutive cycles from `cycle`, at once (stepping the adders n times, unless the sink enters
// rows at their offset, below), when none of them can stall; it returns false to have them one at a
// time. The pipeline offers it; observers need not.
template <class Sink, class Adders, class = void>
struct TakesRuns : std::false_type {};
template <class Sink, class Adders>
struct TakesRuns<Sink, Adders,
                 std::void_t<decltype(std::declval<Sink&>().run(0, 0, int64_t(0), std::declval<Adders&>(), int64_t(0)))>>
    : std::true_type {};

// A sink may also declare `static constexpr bool kEntersRowsAtOffset = true`: the span walk then
// enters each row at its offset t with ZAdder::enter_row_at (a multiplier; the same outputs as the
// left-edge slots, which it leaves unstepped) instead of as the hardware does. For the fast walks
// (fast/), whose fragments read only the registers' outputs. Such a sink's run() need not step the
// adders: a row has one run of covered candidates (the triangle is convex), and no output is read
// after it before the next row's entry (enter_row_at, or next_row in the bbox walk).
template <class Sink, class = void>
struct EntersRowsAtOffset : std::false_type {};
template <class Sink>
struct EntersRowsAtOffset<Sink, std::enable_if_t<Sink::kEntersRowsAtOffset>> : std::true_type {};

class ScanlineWalker {
 public:
  ScanlineWalker(const Profile& profile, const Widths& widths)
      : traversal_(profile.traversal), load_cycles_(widths.walker_load_cycles) {}

  // Walks one set-up triangle whose record the walker loads in cycle `load_cycle`: in a cycle of
  // its own when `idle_load` (the walker had nothing else to do), else in the previous triangle's
  // last candidate cycle. For each covered pixel it calls sink.fragment(x, y, adders, cycle), which
  // returns the cycle the z-buffer accepted the fragment (>= cycle; the walker holds meanwhile).
  // Returns walker_end: the cycle in which the triangle's last candidate (or empty row) moved on.
  // `adders` is the Z adder (ZAdder), or anything with its stepping interface whose outputs the
  // sink does not read (the pipeline's timing-only walk steps none).
  template <class Sink, class Adders>
  int64_t walk(const SetupResult& s, Adders& adders, int64_t load_cycle, bool idle_load, Sink& sink,
               WalkerCounters& counters) const {
    adders.load(s);
    if (idle_load) counters.busy += load_cycles_;
    int64_t cycle = load_cycle + load_cycles_;
    if (traversal_ == Traversal::BBox) cycle = walk_bbox(s, adders, cycle, sink, counters);
    else cycle = walk_span(s, adders, cycle, sink, counters);
    return cycle - 1;
  }

 private:
  template <class Sink, class Adders>
  static int64_t emit(int x, int y, Adders& adders, int64_t cycle, Sink& sink, WalkerCounters& counters) {
    const int64_t accepted = sink.fragment(x, y, adders, cycle);
    counters.stall += accepted - cycle;
    return accepted + 1;
  }

  // n covered candidates of row y from pixel x, one per clock (each held while the z-buffer stalls
  // it); the adders step past each. Returns the cycle after the last.
  template <class Sink, class Adders>
  static int64_t emit_run(int x, int y, int64_t n, Adders& adders, int64_t cycle, Sink& sink,
                          WalkerCounters& counters) {
    for (; n > 0; ++x, --n) {
      if constexpr (TakesRuns<Sink, Adders>::value)
        if (sink.run(x, y, n, adders, cycle)) return cycle + n;
      cycle = emit(x, y, adders, cycle, sink, counters);
      adders.step_x();
    }
    return cycle;
  }

  template <class Sink, class Adders>
  int64_t walk_bbox(const SetupResult& s, Adders& adders, int64_t cycle, Sink& sink, WalkerCounters& counters) const {
    int64_t row0 = s.edge[0].start, row1 = s.edge[1].start, row2 = s.edge[2].start;
    const int64_t sx0 = s.edge[0].step_x, sx1 = s.edge[1].step_x, sx2 = s.edge[2].step_x;
    const int64_t width = s.x1 - s.x0 + 1;
    for (int y = s.y0; y <= s.y1; ++y) {
      int64_t e0 = row0, e1 = row1, e2 = row2;
      for (int x = s.x0; x <= s.x1;) {
        if ((e0 | e1 | e2) >= 0) {
          // A run of covered candidates (one per row: the triangle is convex).
          int end = x;
          do {
            ++end;
            e0 += sx0, e1 += sx1, e2 += sx2;
          } while (end <= s.x1 && (e0 | e1 | e2) >= 0);
          cycle = emit_run(x, y, end - x, adders, cycle, sink, counters);
          x = end;
        } else {
          ++cycle;
          e0 += sx0, e1 += sx1, e2 += sx2;
          adders.step_x();
          ++x;
        }
      }
      row0 += s.edge[0].step_y, row1 += s.edge[1].step_y, row2 += s.edge[2].step_y;
      adders.next_row();
    }
    const int64_t pixels = width * (s.y1 - s.y0 + 1);
    counters.candidates += pixels;
    counters.busy += pixels;
    counters.rows += s.y1 - s.y0 + 1;
    return cycle;
  }

  template <class Sink, class Adders>
  int64_t walk_span(const SetupResult& s, Adders& adders, int64_t cycle, Sink& sink, WalkerCounters& counters) const {
    struct EdgeState {
      int64_t row_value, quot, rem, divisor, step_x, step_y, step_quot, step_rem;
      int slot;  // left edges: the left-edge slot (the number of left edges before it), else -1
    } edge[3];
    for (int k = 0, left = 0; k < 3; ++k) {
      const EdgeSetup& e = s.edge[k];
      const int64_t step_x = e.step_x;
      edge[k] = {e.start, e.span_quot, e.span_rem, step_x < 0 ? -step_x : step_x,
                 e.step_x, e.step_y, e.span_step_quot, e.span_step_rem, step_x > 0 ? left++ : -1};
    }
    const int64_t last = s.x1 - s.x0;
    for (int y = s.y0; y <= s.y1; ++y) {
      // The row's span, computed before it starts: offsets t from x0 with E(t) = row_value + t step_x
      // >= 0 on every edge.
      // The span starts at x0 or at the left edge that bounds it (either of two that tie: their
      // planes there are equal).
      int64_t lo = 0, hi = last;
      int lo_slot = -1;
      for (const EdgeState& e : edge) {
        if (e.step_x > 0) {
          if (-e.quot > lo) lo = -e.quot, lo_slot = e.slot;  // t >= ceil(-E / d) = -floor(E / d)
        } else if (e.step_x < 0) {
          hi = std::min(hi, e.quot);  // t <= floor(E / d)
        } else if (e.row_value < 0) {
          hi = -1;  // horizontal edge, row outside
        }
      }
      if (lo <= hi) {
        if constexpr (EntersRowsAtOffset<Sink>::value) adders.enter_row_at(lo);
        else adders.enter_span_row(lo_slot);
        cycle = emit_run(int(s.x0 + lo), y, hi - lo + 1, adders, cycle, sink, counters);
        counters.candidates += hi - lo + 1;
        counters.busy += hi - lo + 1;
      } else {
        ++cycle;  // the empty-row cycle
        ++counters.busy;
      }
      bool carry[kLeftEdgeSlots] = {false, false};
      for (EdgeState& e : edge) {
        e.row_value += e.step_y;
        if (e.step_x == 0) continue;
        e.quot += e.step_quot;
        e.rem += e.step_rem;
        if (e.rem >= e.divisor) {
          e.rem -= e.divisor, ++e.quot;
          if (e.slot >= 0) carry[e.slot] = true;
        }
      }
      if constexpr (!EntersRowsAtOffset<Sink>::value) adders.step_left_edges(carry);
      adders.next_row();
    }
    counters.rows += s.y1 - s.y0 + 1;
    return cycle;
  }

  Traversal traversal_;
  int load_cycles_;
};

}  // namespace rastersim
