// The two traversals and the cycle model (docs/cycle-model.md).
// - bbox and span emit identical fragment traces (tri, x, y, z, colour, pass) and final buffers.
// - Their cycles follow the written rules, with every expected number computed here from the
//   reference coverage (bounding-box rows and area, covered pixels) and the documented constants:
//   walker = load + bbox pixels (bbox) or load + rows + span pixels (span), each fragment's cycle,
//   the setup/walker hand-off chain, z-buffer busy intervals, frame cycles.
// - The z-buffer's two-entry input buffer, simulated here cycle by cycle: a fragment is taken while
//   fewer than two are held and read from the buffer's head a cycle later at the earliest; its
//   read-after-write hazard: a fragment to an address read in cycle r waits until r + L + 1;
//   fragments to other addresses never stall.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <limits>
#include <map>
#include <tuple>

#include "model/pipeline.h"
#include "reference.h"
#include "test_util.h"

namespace rastersim {
namespace {

using test::describe;
using test::FragmentLog;
using test::TriangleGen;

SnappedTriangle random_scene_triangle(TriangleGen& g, int n) {
  switch (n % 6) {
    case 0: return g.guard_band();
    case 1: return g.tiny();
    case 2: return g.sliver(40);
    case 3: return g.on_centres(5);
    case 4: return g.degenerate();
    default: return g.near_screen(20);
  }
}

class TraversalEquivalence : public ::testing::TestWithParam<Shading> {};

TEST_P(TraversalEquivalence, SameFragmentsAndBuffersDifferentCycles) {
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    Profile p = test::make_profile(96, 72, 4, Traversal::BBox, 24);
    p.shading = GetParam();
    p.depth_func = seed % 2 ? DepthFunc::Less : DepthFunc::GEqual;
    p.depth_clear = seed % 2 ? -1 : 0;
    p.memory_latency = int(1 + seed * 3);
    SCOPED_TRACE(::testing::Message() << describe(p) << " seed " << seed);
    TriangleGen gen(p, seed);
    std::vector<SnappedTriangle> scene;
    for (int n = 0; n < 150; ++n) scene.push_back(random_scene_triangle(gen, n));
    // Some triangles at one constant depth, so that equal depths meet the depth test too.
    for (int n = 0; n < 150; n += 7)
      for (SnappedVertex& v : scene[size_t(n)].v) v.z = 1u << 20;

    FragmentLog logs[2];
    std::vector<TriangleRecord> records[2];
    std::vector<uint32_t> depth[2], color[2];
    FrameStats stats[2];
    for (int k = 0; k < 2; ++k) {
      Profile q = p;
      q.traversal = k == 0 ? Traversal::BBox : Traversal::Span;
      Pipeline pipe(q);
      pipe.set_fragment_sink(&logs[k]);
      pipe.set_triangle_log(&records[k]);
      for (const SnappedTriangle& t : scene) pipe.submit(t);
      depth[k] = pipe.zbuffer().depth();
      color[k] = pipe.zbuffer().color();
      stats[k] = pipe.stats();
    }
    ASSERT_EQ(logs[0].fragments.size(), logs[1].fragments.size());
    ASSERT_GT(logs[0].fragments.size(), 1000u);
    for (size_t i = 0; i < logs[0].fragments.size(); ++i) {
      const Fragment& a = logs[0].fragments[i];
      const Fragment& b = logs[1].fragments[i];
      ASSERT_TRUE(a.tri == b.tri && a.x == b.x && a.y == b.y && a.z == b.z && a.color == b.color && a.pass == b.pass)
          << "fragment " << i << ": bbox (tri " << a.tri << ", " << a.x << ", " << a.y << ", z " << a.z << ", pass "
          << a.pass << ") span (tri " << b.tri << ", " << b.x << ", " << b.y << ", z " << b.z << ", pass " << b.pass << ")";
    }
    EXPECT_TRUE(depth[0] == depth[1]) << "final depth buffers differ";
    EXPECT_TRUE(color[0] == color[1]) << "final colour buffers differ";
    EXPECT_EQ(stats[0].fragments, stats[1].fragments);
    EXPECT_EQ(stats[0].depth_pass, stats[1].depth_pass);
    EXPECT_EQ(stats[0].depth_fail, stats[1].depth_fail);
    EXPECT_GT(stats[0].depth_pass, 0);
    EXPECT_GT(stats[0].depth_fail, 0);
    for (size_t n = 0; n < scene.size(); ++n) {
      EXPECT_EQ(records[0][n].status, records[1][n].status) << "triangle " << n;
      EXPECT_EQ(records[0][n].fragments, records[1][n].fragments) << "triangle " << n;
      EXPECT_EQ(records[0][n].depth_pass, records[1][n].depth_pass) << "triangle " << n;
    }
    // The traversals cost different cycles: bbox visits every candidate, span only covered pixels.
    EXPECT_NE(stats[0].cycles, stats[1].cycles);
    EXPECT_GT(stats[0].candidates, stats[1].candidates);
    EXPECT_EQ(stats[1].candidates, stats[1].fragments);
  }
}

INSTANTIATE_TEST_SUITE_P(Shadings, TraversalEquivalence, ::testing::Values(Shading::Gouraud, Shading::Flat),
                         [](const auto& info) { return std::string(to_string(info.param)); });

// The walker's cycles on one triangle without stalls and without its load, from the reference
// coverage: bbox, the box's area; span, per row its covered pixels or 1 for a row with none.
int64_t expected_walk_cycles(const SnappedTriangle& t, const Profile& p) {
  const reference::PixelRect box = reference::bounding_box(t, p);
  if (p.traversal == Traversal::BBox) return box.area();
  std::map<int, int64_t> per_row;
  for (const reference::Pixel& px : reference::covered_pixels(t, p)) ++per_row[px.y];
  int64_t cycles = 0;
  for (int row = box.y0; row <= box.y1; ++row) cycles += std::max<int64_t>(1, per_row[row]);
  return cycles;
}

// Each covered pixel's acceptance cycle when nothing stalls: bbox, one cycle per candidate from the
// box's first pixel; span, one cycle per covered pixel and one for each row with none.
std::vector<int64_t> expected_fragment_cycles(const SnappedTriangle& t, const Profile& p, const Widths& w,
                                              int64_t walker_load) {
  const reference::PixelRect box = reference::bounding_box(t, p);
  const std::vector<reference::Pixel> covered = reference::covered_pixels(t, p);
  std::vector<int64_t> cycles;
  const int64_t first = walker_load + w.walker_load_cycles;
  if (p.traversal == Traversal::BBox) {
    for (const reference::Pixel& px : covered)
      cycles.push_back(first + int64_t(px.y - box.y0) * (box.x1 - box.x0 + 1) + (px.x - box.x0));
    return cycles;
  }
  int64_t cycle = first;
  size_t next = 0;
  for (int row = box.y0; row <= box.y1; ++row) {
    const size_t row_first = next;
    for (; next < covered.size() && covered[next].y == row; ++next) cycles.push_back(cycle++);
    if (next == row_first) ++cycle;  // the empty-row cycle
  }
  return cycles;
}

// Cycles in the union of the intervals [c, c + L].
int64_t busy_union(std::vector<int64_t> accepted, int latency) {
  std::sort(accepted.begin(), accepted.end());
  int64_t total = 0, covered_until = std::numeric_limits<int64_t>::min();
  for (int64_t c : accepted) {
    const int64_t begin = std::max(c, covered_until + 1), end = c + latency;
    if (end >= begin) total += end - begin + 1;
    covered_until = std::max(covered_until, end);
  }
  return total;
}

// The z-buffer's input buffer cycle by cycle (docs/cycle-model.md, "Z-buffer"), not the model's
// recurrence: fragment i is offered in unstalled[i] shifted by the walker's stall cycles before it,
// taken in a cycle in which fewer than two fragments are held at the cycle's start, and read from
// the head in the first cycle after its take in which can_read(cycle, i) holds.
struct InputBuffer {
  std::vector<int64_t> taken, read;
  int64_t walker_stall = 0, head_waits = 0;
};
template <class CanRead>
InputBuffer simulate_input_buffer(const std::vector<int64_t>& unstalled, CanRead can_read) {
  InputBuffer b;
  const size_t n = unstalled.size();
  b.taken.assign(n, -1), b.read.assign(n, -1);
  std::vector<size_t> held;  // oldest first
  size_t next = 0;
  for (int64_t cycle = n ? unstalled[0] : 0; next < n || !held.empty(); ++cycle) {
    const size_t held_at_start = held.size();
    if (!held.empty()) {
      if (can_read(cycle, held.front(), b.read)) {
        b.read[held.front()] = cycle;
        held.erase(held.begin());
      } else {
        ++b.head_waits;
      }
    }
    if (next < n && unstalled[next] + b.walker_stall <= cycle) {
      if (held_at_start < 2) {
        b.taken[next] = cycle;
        held.push_back(next++);
      } else {
        ++b.walker_stall;
      }
    }
  }
  return b;
}

class CycleModel : public ::testing::TestWithParam<Traversal> {};

TEST_P(CycleModel, OneTriangleCostsWhatTheRulesSay) {
  Profile p = test::make_profile(80, 60, 4, GetParam(), 20);
  p.setup_interval = 0;  // the serial setup's timing (the pipelined one: HandOffChainPipelinedSetup)
  // The serial unit's latencies: docs/cycle-model.md's program, checked by its worked example and
  // by the RTL; what this test checks is that every other event follows from them.
  const SetupTiming timing = setup_timing(p);
  const uint64_t seed = 99 + uint64_t(GetParam());
  SCOPED_TRACE(::testing::Message() << describe(p) << " seed " << seed);
  TriangleGen gen(p, seed);
  int drawn = 0;
  for (int n = 0; n < 600; ++n) {
    p.memory_latency = int(gen.uniform(1, 20));
    const SnappedTriangle t = random_scene_triangle(gen, n);
    Pipeline pipe(p);
    const Widths& w = pipe.widths();
    FragmentLog log;
    std::vector<TriangleRecord> records;
    pipe.set_fragment_sink(&log);
    pipe.set_triangle_log(&records);
    pipe.submit(t);
    const FrameStats& stats = pipe.stats();
    ASSERT_EQ(records.size(), 1u);
    const TriangleRecord& r = records[0];
    SCOPED_TRACE(::testing::Message() << "n=" << n << " L=" << p.memory_latency << " " << describe(t));
    ASSERT_EQ(r.setup_accept, 0);
    if (reference::twice_area(t) == 0 || reference::bounding_box(t, p).empty()) {
      // Rejected in the DECIDE cycle; the walker never sees it.
      EXPECT_EQ(r.setup_done, timing.rejected_latency);
      EXPECT_EQ(r.walker_load, -1);
      EXPECT_EQ(stats.setup.busy, timing.rejected_latency + 1);
      EXPECT_EQ(stats.walker.busy, 0);
      EXPECT_EQ(stats.cycles, timing.rejected_latency + 1);
      continue;
    }
    ++drawn;
    ASSERT_EQ(r.status, SetupStatus::Drawn);
    const int64_t setup_cycles = timing.drawn_latency + 1;  // accept .. output register
    EXPECT_EQ(r.setup_done, setup_cycles - 1);
    EXPECT_EQ(r.walker_load, r.setup_done + 1);  // at the record FIFO's head
    // The walker was idle: its load is a cycle of its own.
    const int64_t walk = expected_walk_cycles(t, p);
    EXPECT_EQ(r.walker_end - r.walker_load, walk);
    EXPECT_EQ(stats.walker.busy, w.walker_load_cycles + walk);
    EXPECT_EQ(stats.walker.stall, 0);
    EXPECT_EQ(stats.z_adder.busy, w.walker_load_cycles + walk);
    EXPECT_EQ(stats.zbuffer.stall, 0);
    EXPECT_EQ(stats.setup.busy, setup_cycles);
    EXPECT_EQ(stats.setup.stall, 0);
    const reference::PixelRect box = reference::bounding_box(t, p);
    const std::vector<int64_t> cycles = expected_fragment_cycles(t, p, w, r.walker_load);
    EXPECT_EQ(stats.candidates, p.traversal == Traversal::BBox ? box.area() : int64_t(cycles.size()));
    ASSERT_EQ(log.fragments.size(), cycles.size());
    for (size_t i = 0; i < cycles.size(); ++i)
      ASSERT_EQ(log.fragments[i].cycle, cycles[i]) << "fragment " << i << " at (" << log.fragments[i].x << ", "
                                                   << log.fragments[i].y << ")";
    EXPECT_EQ(r.fragments, int64_t(cycles.size()));
    // Each fragment read in the cycle after it is taken: busy from its take through its write.
    EXPECT_EQ(stats.zbuffer.busy, busy_union(cycles, p.memory_latency + 1));
    const int64_t last_write = cycles.empty() ? -1 : cycles.back() + 1 + p.memory_latency;
    EXPECT_EQ(r.last_write, last_write);
    EXPECT_EQ(stats.cycles, std::max(r.walker_end, last_write) + 1);
  }
  EXPECT_GT(drawn, 250);
}

// `count` random scene triangles through one pipeline: the triangles, their records and the stats.
struct SceneRun {
  Widths widths;
  std::vector<SnappedTriangle> scene;
  std::vector<TriangleRecord> records;
  FrameStats stats;
};
SceneRun run_random_scene(const Profile& p, uint64_t seed, int count) {
  TriangleGen gen(p, seed);
  Pipeline pipe(p);
  SceneRun run{pipe.widths(), {}, {}, {}};
  pipe.set_triangle_log(&run.records);
  for (int n = 0; n < count; ++n) run.scene.push_back(random_scene_triangle(gen, n));
  for (const SnappedTriangle& t : run.scene) pipe.submit(t);
  run.stats = pipe.stats();
  EXPECT_EQ(run.records.size(), run.scene.size());
  return run;
}

// The pipelined setup unit (setup_interval I >= 2, docs/cycle-model.md): accepts only in the first
// cycle of a slot of I cycles, at most one per slot, with a free credit (found by brute force as
// above); a drawn record in the output register I (1 + edge + numerator + divide + product slots) cycles after
// its accept, the slot counts re-derived here from the page's formulas; busy counted cycle by cycle.
TEST_P(CycleModel, HandOffChainPipelinedSetup) {
  for (int interval : {2, 3, 4, 16, 64}) {
    for (int depth : {1, 4, 16}) {
      Profile p = test::make_profile(80, 60, 4, GetParam(), 24);
      p.memory_latency = 1;
      p.setup_fifo_depth = depth;
      p.setup_interval = interval;
      const uint64_t seed = 11 + uint64_t(GetParam());
      SCOPED_TRACE(::testing::Message() << describe(p) << " seed " << seed << " setup_fifo_depth " << depth
                                        << " setup_interval " << interval);
      const SceneRun run = run_random_scene(p, seed, 200);
      const Widths& w = run.widths;
      const std::vector<TriangleRecord>& records = run.records;
      const std::vector<SnappedTriangle>& scene = run.scene;
      const FrameStats& stats = run.stats;
      auto up = [](int a, int b) { return (a + b - 1) / b; };
      const int edge_slots = up(w.coord_bits + 1, 4 * interval);
      const int numer_slots = up(p.z_bits, 4 * interval);
      const int divide_slots = up(w.divider_bits, 4 * interval);
      // The planes along the left edges: PB = min(z_reg_bits, edge_bits) multiply steps.
      const int product_slots = up(std::min(w.z_reg_bits, w.edge_bits), 4 * interval);
      const int64_t latency = int64_t(interval) * (1 + edge_slots + numer_slots + divide_slots + product_slots);
      std::vector<std::pair<int64_t, int64_t>> credits;
      std::set<int64_t> busy_cycles;
      int64_t setup_free = 0, walker_end_prev = -1, last_busy = -1, setup_stall = 0;
      for (size_t n = 0; n < scene.size(); ++n) {
        const TriangleRecord& r = records[n];
        const SnappedTriangle& t = scene[n];
        SCOPED_TRACE(::testing::Message() << "triangle " << n << " " << describe(t));
        auto held = [&](int64_t c) {
          return std::count_if(credits.begin(), credits.end(), [c](auto h) { return h.first <= c && c <= h.second; });
        };
        int64_t accept = setup_free;
        while (accept % interval != 0 || held(accept) >= depth) ++accept;
        ASSERT_EQ(r.setup_accept, accept);
        setup_stall += accept - setup_free;
        setup_free = accept + interval;
        const bool drawn = reference::twice_area(t) != 0 && !reference::bounding_box(t, p).empty();
        ASSERT_EQ(r.status == SetupStatus::Drawn, drawn);
        const int64_t done = drawn ? accept + latency : accept + 1;
        ASSERT_EQ(r.setup_done, done);
        for (int64_t c = accept; c <= done; ++c) busy_cycles.insert(c);
        last_busy = std::max(last_busy, done);
        if (!drawn) {
          credits.push_back({accept + 1, accept + 1});
          continue;
        }
        const int64_t load = std::max(done + 1, walker_end_prev);  // at the FIFO's head after done
        ASSERT_EQ(r.walker_load, load);
        ASSERT_EQ(r.walker_end, load + expected_walk_cycles(t, p));
        walker_end_prev = r.walker_end;
        last_busy = std::max({last_busy, r.walker_end, r.last_write});
        credits.push_back({accept + 1, load});
      }
      EXPECT_EQ(stats.setup.busy, int64_t(busy_cycles.size()));
      EXPECT_EQ(stats.setup.stall, setup_stall);
      EXPECT_EQ(stats.cycles, last_busy + 1);
    }
  }
}

// Many triangles with L = 1, where a hazard needs a triangle's first fragment on its predecessor's
// last one in the next cycle (none in these scenes: the walker's stall 0 is asserted): every record follows the documented hand-off chain, for record FIFOs of
// 1 to 4 credits. The accept cycle is found by brute force: the first cycle at or after the one the
// unit is free in which fewer than setup_fifo_depth earlier triangles hold a credit (from the cycle
// after their accept to their decision if rejected, to their walker load if drawn).
// With a depth bias a record is ready for the walker from setup_done + 7 (the bias unit's stages),
// else from setup_done + 1.
TEST_P(CycleModel, HandOffChainOverAScene) {
  for (int run_index = 0; run_index < 6; ++run_index) {
    const int depth = run_index < 4 ? run_index + 1 : run_index - 3;
    const bool biased = run_index >= 4;
    Profile p = test::make_profile(80, 60, 4, GetParam(), 24);
    p.memory_latency = 1;
    p.setup_fifo_depth = depth;
    p.setup_interval = 0;  // the serial setup's timing
    if (biased) {
      p.depth_bias_constant = -3;
      p.depth_bias_slope = 24;  // 1.5
    }
    const int64_t ready_after = biased ? 7 : 1;
    const uint64_t seed = 7 + uint64_t(GetParam());
    SCOPED_TRACE(::testing::Message() << describe(p) << " seed " << seed << " setup_fifo_depth " << depth
                                      << (biased ? " depth bias" : ""));
    const SceneRun run = run_random_scene(p, seed, 300);
    const Widths& w = run.widths;
    const std::vector<TriangleRecord>& records = run.records;
    const std::vector<SnappedTriangle>& scene = run.scene;
    const FrameStats& stats = run.stats;
    const SetupTiming timing = setup_timing(p);
    const int64_t setup_cycles = timing.drawn_latency + 1;
    std::vector<std::pair<int64_t, int64_t>> credits;  // [first, last] cycle each triangle holds one
    int64_t setup_free = 0, walker_end_prev = -1, last_busy = -1, setup_busy = 0, setup_stall = 0, walker_busy = 0;
    for (size_t n = 0; n < scene.size(); ++n) {
      const TriangleRecord& r = records[n];
      const SnappedTriangle& t = scene[n];
      SCOPED_TRACE(::testing::Message() << "triangle " << n << " " << describe(t));
      int64_t accept = setup_free;
      auto held = [&](int64_t c) {
        return std::count_if(credits.begin(), credits.end(), [c](auto h) { return h.first <= c && c <= h.second; });
      };
      while (held(accept) >= depth) ++accept;
      ASSERT_EQ(r.index, int64_t(n));
      ASSERT_EQ(r.setup_accept, accept);
      setup_stall += accept - setup_free;
      const bool drawn = reference::twice_area(t) != 0 && !reference::bounding_box(t, p).empty();
      ASSERT_EQ(r.status == SetupStatus::Drawn, drawn);
      if (!drawn) {
        ASSERT_EQ(r.setup_done, accept + timing.rejected_latency);
        setup_busy += timing.rejected_latency + 1;
        last_busy = std::max(last_busy, r.setup_done);
        credits.push_back({accept + 1, r.setup_done});
        setup_free = r.setup_done + 1;
        continue;
      }
      ASSERT_EQ(r.setup_done, accept + setup_cycles - 1);
      const int64_t load = std::max(r.setup_done + ready_after, walker_end_prev);  // ready after setup_done
      ASSERT_EQ(r.walker_load, load);
      const int64_t walk = expected_walk_cycles(t, p);
      ASSERT_EQ(r.walker_end, load + walk);
      setup_busy += setup_cycles;
      walker_busy += walk + (load > walker_end_prev ? w.walker_load_cycles : 0);  // an idle load counts
      walker_end_prev = r.walker_end;
      last_busy = std::max({last_busy, r.walker_end, r.last_write});
      credits.push_back({accept + 1, load});
      setup_free = r.setup_done + 1;
    }
    EXPECT_EQ(stats.setup.busy, setup_busy);
    EXPECT_EQ(stats.setup.stall, setup_stall);
    if (depth == 1) {
      EXPECT_GT(setup_stall, 0);
    }
    EXPECT_EQ(stats.walker.busy, walker_busy);
    EXPECT_EQ(stats.walker.stall, 0);
    EXPECT_EQ(stats.zbuffer.stall, 0);
    EXPECT_EQ(stats.cycles, last_busy + 1);
  }
}

// The memory's stall pattern (zbuffer_memory.h): one triangle has no hazards, so each covered pixel
// is read in the first cycle after its take in which the memory is ready; the walker waits when the
// input buffer is full, and every later event of the walker shifts by its waits.
TEST_P(CycleModel, OneTriangleUnderAStallPatternShiftsByEachWait) {
  Profile p = test::make_profile(80, 60, 4, GetParam(), 20);
  const uint64_t seed = 7 + uint64_t(GetParam());
  SCOPED_TRACE(::testing::Message() << describe(p) << " seed " << seed);
  TriangleGen gen(p, seed);
  int64_t total_wait = 0;
  for (int n = 0; n < 200; ++n) {
    p.memory_latency = int(gen.uniform(1, 20));
    p.memory_stall_percent = int(gen.uniform(1, 90));
    p.memory_stall_seed = int(gen.uniform(0, 1000));
    const SnappedTriangle t = random_scene_triangle(gen, n);
    if (reference::twice_area(t) == 0 || reference::bounding_box(t, p).empty()) continue;
    Pipeline pipe(p);
    FragmentLog log;
    std::vector<TriangleRecord> records;
    pipe.set_fragment_sink(&log);
    pipe.set_triangle_log(&records);
    pipe.submit(t);
    const FrameStats& stats = pipe.stats();
    SCOPED_TRACE(::testing::Message() << "n=" << n << " L=" << p.memory_latency << " stall "
                                      << p.memory_stall_percent << "% seed " << p.memory_stall_seed);
    const TriangleRecord& r = records.at(0);
    const std::vector<int64_t> unstalled = expected_fragment_cycles(t, p, pipe.widths(), r.walker_load);
    ASSERT_EQ(log.fragments.size(), unstalled.size());
    const InputBuffer b = simulate_input_buffer(unstalled, [&](int64_t cycle, size_t, const std::vector<int64_t>&) {
      return !memory_stalls(uint64_t(p.memory_stall_seed), p.memory_stall_percent, cycle);
    });
    for (size_t i = 0; i < unstalled.size(); ++i) ASSERT_EQ(log.fragments[i].cycle, b.taken[i]) << "fragment " << i;
    const int64_t wait = b.walker_stall;
    EXPECT_EQ(stats.walker.stall, wait);
    EXPECT_EQ(stats.zbuffer.stall, b.head_waits);
    EXPECT_EQ(r.walker_end - r.walker_load, expected_walk_cycles(t, p) + wait);
    EXPECT_EQ(stats.walker.busy, pipe.widths().walker_load_cycles + expected_walk_cycles(t, p));
    const int64_t last_write = unstalled.empty() ? -1 : b.read.back() + p.memory_latency;
    EXPECT_EQ(r.last_write, last_write);
    EXPECT_EQ(stats.cycles, std::max(r.walker_end, last_write) + 1);
    total_wait += wait;
  }
  EXPECT_GT(total_wait, 1000);
}

INSTANTIATE_TEST_SUITE_P(Traversals, CycleModel, ::testing::Values(Traversal::BBox, Traversal::Span),
                         [](const auto& info) { return std::string(to_string(info.param)); });

// A triangle inside pixel (i, j)'s square around its centre: its bounding box is that one pixel.
SnappedTriangle inside_pixel(int i, int j, int S) {
  const int32_t M = 1 << S, cx = i * M + M / 2, cy = j * M + M / 2, d = M / 4;
  SnappedTriangle t;
  t.v[0].x = cx - d, t.v[0].y = cy - d;
  t.v[1].x = cx + d, t.v[1].y = cy - d / 2;
  t.v[2].x = cx - d / 2, t.v[2].y = cy + d;
  for (SnappedVertex& v : t.v) v.z = 100;
  return t;
}

// A triangle pointing right whose bounding box is exactly pixels (i, j) and (i + 1, j), both covered.
SnappedTriangle two_pixels(int i, int j, int S) {
  const int32_t M = 1 << S, x = i * M, cy = j * M + M / 2;
  SnappedTriangle t;
  t.v[0].x = x + M / 4, t.v[0].y = cy - 5 * M / 16;
  t.v[1].x = x + 2 * M - M / 8, t.v[1].y = cy;
  t.v[2].x = x + M / 4, t.v[2].y = cy + 5 * M / 16;
  for (SnappedVertex& v : t.v) v.z = 100;
  return t;
}

class ZBufferHazard : public ::testing::TestWithParam<Traversal> {};

TEST_P(ZBufferHazard, SameAddressWaitsLPlusOneOthersNever) {
  Profile p = test::make_profile(16, 16, 4, GetParam(), 16);
  p.setup_interval = 2;  // the fastest setup, so that back-to-back triangles can meet in the z-buffer
  const int S = p.subpixel_bits;
  const Widths w = derive_widths(p);
  const int64_t setup_cycles = setup_timing(p).drawn_latency + 1;
  // Back-to-back triangles meet in the z-buffer only when the setup is faster than the memory.
  ASSERT_LT(setup_cycles, 60) << "the profile must let a hazard happen";
  struct Case {
    const char* name;
    SnappedTriangle first, second;
    bool overlap;
  };
  const Case cases[] = {
      {"same pixel", inside_pixel(5, 5, S), inside_pixel(5, 5, S), true},
      {"right neighbour", inside_pixel(5, 5, S), inside_pixel(6, 5, S), false},
      {"pixel below", inside_pixel(5, 5, S), inside_pixel(5, 6, S), false},
      {"second fragment collides", inside_pixel(7, 5, S), two_pixels(6, 5, S), true},
      {"first of two collides with an earlier one", two_pixels(5, 5, S), inside_pixel(5, 5, S), true},
      {"both collide", two_pixels(5, 5, S), two_pixels(5, 5, S), true},
      {"disjoint pairs", two_pixels(5, 5, S), two_pixels(7, 5, S), false},
  };
  for (const Case& c : cases) {
    const std::vector<reference::Pixel> first_pixels = reference::covered_pixels(c.first, p);
    const std::vector<reference::Pixel> second_pixels = reference::covered_pixels(c.second, p);
    ASSERT_EQ(int64_t(first_pixels.size()), reference::bounding_box(c.first, p).area()) << c.name;
    ASSERT_EQ(int64_t(second_pixels.size()), reference::bounding_box(c.second, p).area()) << c.name;
    int stalls_seen = 0;
    for (int latency : {1, 2, 3, 8, 16, 32, int(setup_cycles) - 2, int(setup_cycles), int(setup_cycles) + 1, 63, 64}) {
      p.memory_latency = latency;
      SCOPED_TRACE(::testing::Message() << describe(p) << " case " << c.name);
      Pipeline pipe(p);
      FragmentLog log;
      std::vector<TriangleRecord> records;
      pipe.set_fragment_sink(&log);
      pipe.set_triangle_log(&records);
      pipe.submit(c.first);
      pipe.submit(c.second);
      ASSERT_EQ(log.fragments.size(), first_pixels.size() + second_pixels.size());
      // Each triangle's fragments are consecutive candidates on one row, offered right after its
      // load; each read waits for any earlier fragment to its address read L or fewer cycles before.
      std::vector<int64_t> unstalled;
      std::vector<reference::Pixel> pixels = first_pixels;
      pixels.insert(pixels.end(), second_pixels.begin(), second_pixels.end());
      for (size_t k = 0; k < first_pixels.size(); ++k)
        unstalled.push_back(records[0].walker_load + w.walker_load_cycles + int64_t(k));
      for (size_t k = 0; k < second_pixels.size(); ++k)
        unstalled.push_back(records[1].walker_load + w.walker_load_cycles + int64_t(k));
      const InputBuffer b = simulate_input_buffer(unstalled, [&](int64_t cycle, size_t i, const std::vector<int64_t>& read) {
        for (size_t m = 0; m < i; ++m)
          if (pixels[m].x == pixels[i].x && pixels[m].y == pixels[i].y && cycle <= read[m] + latency) return false;
        return true;
      });
      for (size_t k = 0; k < pixels.size(); ++k)
        EXPECT_EQ(log.fragments[k].cycle, b.taken[k]) << "fragment " << k << " of the two triangles";
      const FrameStats& stats = pipe.stats();
      EXPECT_EQ(stats.zbuffer.stall, b.head_waits);
      EXPECT_EQ(stats.walker.stall, b.walker_stall);
      EXPECT_EQ(records[0].walker_end, b.taken[first_pixels.size() - 1]);
      EXPECT_EQ(records[1].walker_end, b.taken.back());
      EXPECT_EQ(records[1].last_write, b.read.back() + latency);
      EXPECT_EQ(stats.cycles, b.read.back() + latency + 1);
      stalls_seen += b.head_waits > 0;
    }
    if (c.overlap) {
      EXPECT_GE(stalls_seen, 3) << c.name << ": the latencies above must include stalling ones";
    } else {
      EXPECT_EQ(stalls_seen, 0) << c.name;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Traversals, ZBufferHazard, ::testing::Values(Traversal::BBox, Traversal::Span),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace rastersim
