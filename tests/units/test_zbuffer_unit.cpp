// Unit test: the verilated zbuffer alone behind a scripted memory port, against the model's ZBuffer
// and its memory. The script is the memory contract of docs/rtl.md: a read taken in c returns its
// word in exactly c + L (the data lines carry noise in every other cycle), writes land at the end
// of their cycle, and the read port refuses requests in the seeded stall pattern's cycles. The
// fragments crowd a few pixels so that read-after-write hazards are frequent; every depth function,
// depth_write, latency 1..MAX_MEMORY_LATENCY and stall rate comes up. Checked: the cycle each fragment
// is taken into the input buffer, the cycle and address of its read, each depth-test result and
// write (cycle, enables, address, data), the busy and stall counts (the walker's stall recomputed
// from the take cycles), and the final memory word by word.
#include <gtest/gtest.h>

#include <deque>
#include <limits>
#include <random>

#include "model/zbuffer.h"
#include "testbench/units/unit_harness.h"
#include "unit_configs.h"

namespace rastersim::units {
namespace {

struct TestFragment {
  int x, y;
  uint32_t z;
  uint32_t rgb;
  int64_t gap;  // cycles the test waits after the previous take before offering it
};

struct ModelFragment {
  int64_t taken, read;
  bool pass;
};

template <class V>
void check_zbuffer_unit(const char* config, const Profile& base, int max_latency, uint64_t seed, int64_t count) {
  std::mt19937_64 rng(seed);
  auto uniform = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
  Unit<V> unit(seed);
  constexpr int kBatch = 2000;
  const uint32_t z_max = uint32_t((uint64_t(1) << base.z_bits) - 1);
  int64_t checked = 0;
  for (uint64_t batch = 0; checked < count; ++batch) {
    Profile p = base;
    p.depth_func = DepthFunc(uniform(0, 7));
    p.depth_write = uniform(0, 3) != 0;
    const int64_t latency_kind = uniform(0, 3);
    p.memory_latency = int(latency_kind == 0 ? 1 : latency_kind == 1 ? max_latency : uniform(1, std::min(max_latency, 12)));
    p.memory_stall_percent = batch % 3 == 0 ? 0 : int(uniform(1, 60));
    p.memory_stall_seed = int(uniform(0, 1000000));
    p.depth_clear = uniform(0, 3) == 0 ? uniform(0, z_max) : -1;
    const uint32_t clear = p.depth_clear_value();
    const int n = int(std::min<int64_t>(kBatch, count - checked));

    // Fragments on a few pixels (hazards), now and then a row run (the walker's usual pattern).
    std::vector<TestFragment> frags;
    const int spread_x = int(uniform(1, std::min(p.width, 8))), spread_y = int(uniform(1, std::min(p.height, 4)));
    const int corner_x = int(uniform(0, p.width - spread_x)), corner_y = int(uniform(0, p.height - spread_y));
    const uint32_t z_lo = uint32_t(uniform(0, z_max)), z_span = uint32_t(uniform(0, 3) == 0 ? 3 : 1000);
    while (int(frags.size()) < n) {
      const int run = uniform(0, 9) == 0 ? int(uniform(2, 20)) : 1;
      const int y = corner_y + int(uniform(0, spread_y - 1));
      int x = run > 1 ? int(uniform(0, p.width - 1)) : corner_x + int(uniform(0, spread_x - 1));
      for (int i = 0; i < run && x < p.width && int(frags.size()) < n; ++i, ++x) {
        const uint32_t z = uint32_t(std::min<uint64_t>(z_max, uint64_t(z_lo) + uint64_t(uniform(0, z_span))));
        frags.push_back({x, y, z, uint32_t(uniform(0, 0xffffff)), uniform(0, 4) == 0 ? uniform(1, 2 * p.memory_latency) : 0});
      }
    }

    // The model: fragment i is offered the cycle after fragment i - 1 was taken, plus its gap.
    ZBuffer model(p);
    std::vector<ModelFragment> want;
    int64_t previous = -1, walker_stall = 0;
    for (const TestFragment& f : frags) {
      const uint32_t address = uint32_t(f.y * p.width + f.x);
      model.begin_triangle(std::numeric_limits<int64_t>::min());  // every fragment is checked for hazards
      const int64_t offered = previous + 1 + f.gap;
      const int64_t taken = model.take(address, offered);
      const Rgb rgb{uint8_t(f.rgb >> 16), uint8_t(f.rgb >> 8), uint8_t(f.rgb)};
      want.push_back({taken, model.last_read(), model.test_and_write(address, f.z, rgb)});
      walker_stall += taken - offered;
      previous = taken;
    }
    const std::string where_batch =
        std::string(config) + ", seed " + std::to_string(seed) + ", batch " + std::to_string(batch) + " (depth_func " +
        to_string(p.depth_func) + ", depth_write " + std::to_string(p.depth_write) + ", latency " +
        std::to_string(p.memory_latency) + ", stall " + std::to_string(p.memory_stall_percent) + "%)";

    // The scripted memory, cleared.
    std::vector<uint32_t> depth(size_t(p.width) * p.height, clear), color(depth.size(), 0u);
    std::deque<std::pair<int64_t, uint32_t>> reads;  // (data cycle, address)
    unit->rst = 1;
    unit->frag_valid = 0;
    unit->mem_clear_done = 0;
    unit->mem_rd_ready = 0;
    unit->cfg_depth_func = uint8_t(p.depth_func);
    unit->cfg_depth_write = p.depth_write;
    unit->cfg_memory_latency = uint8_t(p.memory_latency);
    for (int i = 0; i < 4; ++i) unit.settle(), unit.tick();
    unit->rst = 0;
    unit->mem_clear_done = 1;  // frame cycle 0 is the next one

    size_t next = 0, next_read = 0;
    std::deque<size_t> in_flight;
    int64_t present = frags.empty() ? 0 : frags[0].gap, busy = 0, stall = 0;
    const int64_t end = want.empty() ? 0 : want.back().read + p.memory_latency + 2;
    for (int64_t cycle = 0; cycle <= end; ++cycle) {
      const bool presenting = next < frags.size() && cycle >= present;
      unit->frag_valid = presenting;
      if (presenting) {
        unit->frag_x = uint32_t(frags[next].x);
        unit->frag_y = uint32_t(frags[next].y);
        unit->frag_z = frags[next].z;
        unit->frag_rgb = frags[next].rgb;
      }
      unit->mem_rd_ready = !memory_stalls(uint64_t(p.memory_stall_seed), p.memory_stall_percent, cycle);
      const bool data_due = !reads.empty() && reads.front().first == cycle;
      unit->mem_rd_depth = data_due ? depth[reads.front().second] : uint32_t(rng()) & z_max;
      if (data_due) reads.pop_front();
      unit.settle();
      const std::string at = where_batch + ", cycle " + std::to_string(cycle);
      if (unit->mem_rd_valid && unit->mem_rd_ready) {
        ASSERT_LT(next_read, next) << at << ": a read with no fragment taken";
        const TestFragment& f = frags[next_read];
        ASSERT_EQ(cycle, want[next_read].read) << at << ": fragment " << next_read << " read";
        ASSERT_EQ(uint32_t(unit->mem_rd_addr), uint32_t(f.y * p.width + f.x)) << at << ": read address";
        reads.emplace_back(cycle + p.memory_latency, uint32_t(f.y * p.width + f.x));
        in_flight.push_back(next_read++);
      } else if (next_read < frags.size()) {
        ASSERT_NE(cycle, want[next_read].read) << at << ": fragment " << next_read << " not read";
      }
      if (presenting && unit->frag_ready) {
        ASSERT_EQ(cycle, want[next].taken) << at << ": fragment " << next << " taken";
        ++next;
        present = next < frags.size() ? cycle + 1 + frags[next].gap : 0;
      } else if (next < frags.size()) {
        ASSERT_NE(cycle, want[next].taken) << at << ": fragment " << next << " not taken";
      }
      ASSERT_LE(next - next_read, 2u) << at << ": more than two fragments held";
      if (!in_flight.empty() && want[in_flight.front()].read + p.memory_latency == cycle) {
        const size_t i = in_flight.front();
        in_flight.pop_front();
        const TestFragment& f = frags[i];
        const bool pass = want[i].pass;
        const std::string which = at + ", fragment " + std::to_string(i);
        ASSERT_TRUE(unit->result_valid) << which << ": no result";
        ASSERT_EQ(bool(unit->result_pass), pass) << which << ": depth test";
        ASSERT_EQ(bool(unit->mem_wr_depth_en), pass && p.depth_write) << which << ": depth write enable";
        ASSERT_EQ(bool(unit->mem_wr_color_en), pass) << which << ": colour write enable";
        if (pass) {
          ASSERT_EQ(uint32_t(unit->mem_wr_addr), uint32_t(f.y * p.width + f.x)) << which << ": write address";
          if (p.depth_write) {
            ASSERT_EQ(uint32_t(unit->mem_wr_depth), f.z) << which << ": written depth";
          }
          ASSERT_EQ(uint32_t(unit->mem_wr_rgb), f.rgb) << which << ": written colour";
        }
      } else {
        ASSERT_FALSE(unit->result_valid) << at << ": a result with none due";
        ASSERT_FALSE(unit->mem_wr_depth_en || unit->mem_wr_color_en) << at << ": a write with none due";
      }
      busy += unit->busy;
      stall += unit->stall;
      walker_stall -= presenting && !unit->frag_ready;
      // Writes land at the end of the cycle.
      if (unit->mem_wr_depth_en) depth[unit->mem_wr_addr] = uint32_t(unit->mem_wr_depth);
      if (unit->mem_wr_color_en) color[unit->mem_wr_addr] = uint32_t(unit->mem_wr_rgb);
      unit.tick();
    }
    ASSERT_EQ(next, frags.size()) << where_batch;
    ASSERT_EQ(busy, model.counters().busy) << where_batch << ": busy cycles";
    ASSERT_EQ(stall, model.counters().stall) << where_batch << ": stall cycles";
    ASSERT_EQ(walker_stall, 0) << where_batch << ": cycles a fragment was offered and not taken";
    for (size_t a = 0; a < depth.size(); ++a) {
      ASSERT_EQ(depth[a], model.depth()[a]) << where_batch << ": depth word " << a;
      ASSERT_EQ(color[a], model.color()[a]) << where_batch << ": colour word " << a;
    }
    checked += n;
  }
}

#define RASTERSIM_ZBUFFER_TEST(name, V, width, height, subpixel_bits, z_bits, z_guard_bits, max_latency, count) \
  TEST(ZBufferUnit, name) {                                                                                   \
    check_zbuffer_unit<V>(#name, unit_profile(width, height, subpixel_bits, z_bits, z_guard_bits, 4), max_latency, \
                          20261126, unit_count(count));                                                   \
  }
RASTERSIM_ZBUFFER_UNITS(RASTERSIM_ZBUFFER_TEST)

}  // namespace
}  // namespace rastersim::units
