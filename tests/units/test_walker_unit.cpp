// Unit test: the verilated scanline_walker and z_adder (testbench/units/walker_unit.sv) against the
// model's ScanlineWalker and ZAdder, both traversals, flat and Gouraud shading. Records come from
// the model's setup of constrained-random triangles, presented back to back or after random gaps;
// the z-buffer's ready is a seeded stall pattern. Checked: every load cycle, every fragment (pixel,
// depth, colour and the cycle it was taken), every walker_end, and the busy and candidate counts.
#include <gtest/gtest.h>

#include <random>
#include <type_traits>

#include "model/scanline_walker.h"
#include "model/triangle_setup.h"
#include "model/widths.h"
#include "model/zbuffer_memory.h"
#include "testbench/cosim_cases.h"
#include "testbench/setup_record.h"
#include "testbench/units/unit_harness.h"
#include "unit_configs.h"

namespace rastersim::units {
namespace {

struct ExpectedFragment {
  int x, y;
  uint32_t z;
  Rgb color;
  int64_t cycle;  // taken (frag_valid and frag_ready)
};

struct ExpectedTriangle {
  int64_t available;  // the record is presented from this cycle
  int64_t load, end;  // walker_load, walker_end
};

// The model's walk of the records in order, the walker taking record i in
// max(available_i, walker_end_(i-1)) (in a cycle of its own when the walker is idle by then).
struct ModelWalk {
  std::vector<ExpectedTriangle> triangles;
  std::vector<ExpectedFragment> fragments;
  WalkerCounters counters;
};

// The z-buffer's ready: low in `stall_percent` of the cycles, a pure function of the cycle.
struct ReadyScript {
  uint64_t seed;
  int stall_percent;
  bool ready(int64_t cycle) const { return !memory_stalls(seed, stall_percent, cycle); }
};

struct CollectingSink {
  std::vector<ExpectedFragment>& out;
  const ReadyScript& script;
  int64_t fragment(int x, int y, ZAdder& adders, int64_t cycle) {
    while (!script.ready(cycle)) ++cycle;
    out.push_back({x, y, adders.depth(), adders.color(), cycle});
    return cycle;
  }
};

ModelWalk model_walk(const Profile& p, const std::vector<SetupResult>& records, const std::vector<int64_t>& gaps,
                     const ReadyScript& script) {
  const Widths w = derive_widths(p);
  const ScanlineWalker walker(p, w);
  ZAdder adders(w, p);
  ModelWalk m;
  CollectingSink sink{m.fragments, script};
  int64_t previous_end = -1, previous_load = -1;
  for (size_t i = 0; i < records.size(); ++i) {
    ExpectedTriangle t;
    t.available = previous_load + 1 + gaps[i];
    t.load = std::max(t.available, previous_end);
    t.end = walker.walk(records[i], adders, t.load, t.available > previous_end, sink, m.counters);
    m.triangles.push_back(t);
    previous_end = t.end;
    previous_load = t.load;
  }
  return m;
}

template <class V>
void check_walker_unit(const char* config, const Profile& base, uint64_t seed, int64_t count) {
  const Widths w = derive_widths(base);
  using Module = std::remove_pointer_t<decltype(std::declval<V&>().walker_unit)>;  // its public localparams
  const rtl::RecordLayout layout(w, true);
  ASSERT_EQ(layout.bits(), int(Module::RECORD_BITS)) << "the test packs the record as the RTL lays it out";
  std::mt19937_64 rng(seed);
  Unit<V> unit(seed);
  constexpr int kBatch = 512;
  int64_t checked = 0;
  for (uint64_t batch = 0; checked < count; ++batch) {
    Profile p = base;
    p.traversal = Traversal(batch % 2);
    p.shading = Shading(rng() % 2);
    const ReadyScript script{rng(), batch % 3 == 0 ? 0 : int(rng() % 60)};
    const TriangleSetup setup(p);
    std::vector<SetupResult> records;
    for (const SnappedTriangle& t :
         rtl::random_case(p, seed * 1000003u + batch, int(std::min<int64_t>(kBatch, count - checked))).triangles) {
      SetupResult r = setup.run(t);
      if (r.status == SetupStatus::Drawn) records.push_back(r);
    }
    checked += kBatch;
    std::vector<int64_t> gaps;
    for (size_t i = 0; i < records.size(); ++i) gaps.push_back(rng() % 3 == 0 ? int64_t(rng() % 40) : 0);
    const ModelWalk m = model_walk(p, records, gaps, script);
    std::vector<std::vector<uint32_t>> packed;
    for (const SetupResult& r : records) packed.push_back(layout.pack(r));
    const std::string where_batch = std::string(config) + ", seed " + std::to_string(seed) + ", batch " +
                                    std::to_string(batch) + " (" + to_string(p.traversal) + ", " +
                                    to_string(p.shading) + ", ready low " + std::to_string(script.stall_percent) +
                                    "%)";

    unit->rst = 1;
    unit->in_valid = 0;
    unit->frag_ready = 0;
    unit->cfg_traversal = p.traversal == Traversal::Span;
    unit->cfg_shading = p.shading == Shading::Gouraud;
    for (int i = 0; i < 4; ++i) unit.settle(), unit.tick();
    unit->rst = 0;

    size_t next = 0, fragment = 0;
    int64_t walking = -1;  // the triangle in the walker
    int64_t busy = 0, candidates = 0;
    const int64_t last_cycle = records.empty() ? 0 : m.triangles.back().end;
    for (int64_t cycle = 0; cycle <= last_cycle + 2; ++cycle) {
      const bool presenting = next < records.size() && cycle >= m.triangles[next].available;
      unit->in_valid = presenting;
      if (presenting) {
        for (size_t k = 0; k < packed[next].size(); ++k) unit->in_record[k] = packed[next][k];
      }
      unit->frag_ready = script.ready(cycle);
      unit.settle();
      if (unit->frag_valid && unit->frag_ready) {
        const std::string where = where_batch + ", triangle " + std::to_string(walking) + ", fragment " +
                                  std::to_string(fragment) + ", cycle " + std::to_string(cycle);
        ASSERT_LT(fragment, m.fragments.size()) << where << ": a fragment the model does not have";
        const ExpectedFragment& e = m.fragments[fragment];
        ASSERT_EQ(cycle, e.cycle) << where << ": taken in another cycle";
        ASSERT_EQ(int(unit->frag_x), e.x) << where << ": x";
        ASSERT_EQ(int(unit->frag_y), e.y) << where << ": y";
        ASSERT_EQ(uint32_t(unit->frag_z), e.z) << where << ": z";
        ASSERT_EQ(uint32_t(unit->frag_rgb), rtl::rgb_word(e.color)) << where << ": rgb";
        ++fragment;
      } else if (fragment < m.fragments.size()) {
        ASSERT_NE(cycle, m.fragments[fragment].cycle) << where_batch << ": fragment " << fragment << " not taken";
      }
      if (unit->last) {
        ASSERT_GE(walking, 0) << where_batch << ": walker_end in cycle " << cycle << " with no triangle";
        ASSERT_EQ(cycle, m.triangles[size_t(walking)].end) << where_batch << ", triangle " << walking << ": walker_end";
        walking = -1;
      }
      if (unit->load) {
        ASSERT_TRUE(presenting) << where_batch << ": a load in cycle " << cycle << " with no record";
        ASSERT_EQ(cycle, m.triangles[next].load) << where_batch << ", triangle " << next << ": walker_load";
        walking = int64_t(next++);
      } else if (next < records.size()) {
        ASSERT_NE(cycle, m.triangles[next].load) << where_batch << ", triangle " << next << ": not loaded";
      }
      busy += unit->busy;
      candidates += unit->candidate;
      unit.tick();
    }
    ASSERT_EQ(next, records.size()) << where_batch;
    ASSERT_EQ(fragment, m.fragments.size()) << where_batch;
    ASSERT_EQ(busy, m.counters.busy) << where_batch << ": busy cycles";
    ASSERT_EQ(candidates, m.counters.candidates) << where_batch << ": candidates";
  }
}

#define RASTERSIM_WALKER_TEST(name, V, width, height, subpixel_bits, z_bits, z_guard_bits, unused, count)         \
  TEST(WalkerUnit, name) {                                                                              \
    check_walker_unit<V>(#name, unit_profile(width, height, subpixel_bits, z_bits, z_guard_bits, 4), 20261126, \
                         unit_count(count));                                                        \
  }
RASTERSIM_WALKER_UNITS(RASTERSIM_WALKER_TEST)

}  // namespace
}  // namespace rastersim::units
