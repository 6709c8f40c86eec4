// Unit test: the verilated triangle_setup alone against the model's TriangleSetup and SetupTiming,
// on constrained-random triangles (every category: degenerate, culled, off-screen, huge, slivers),
// with the cull and front-face settings varied between batches. Checked per triangle: the accept
// cycle, the decision (its cycle, status, facing, twice the area) and, for a drawn triangle, the
// cycle and every field of its record and of its texture record. The units built with TEXTURE=1
// run with the profile's texture unit on textured and untextured triangles mixed; the others get
// texture coordinates too, which they ignore (as the model does without the texture unit).
#include <gtest/gtest.h>

#include <deque>
#include <random>
#include <sstream>

#include "model/triangle_setup.h"
#include "model/widths.h"
#include "testbench/cosim_cases.h"
#include "testbench/setup_record.h"
#include "testbench/units/unit_harness.h"
#include "unit_configs.h"

namespace rastersim::units {
namespace {


struct Expected {
  int64_t index;
  int64_t cycle;
};

// The texture coordinates of a batch: random_case's (snapped from random u, v, w), a quarter of
// them replaced by raw values over the whole valid range (|S|, |T| <= 2^(P+7), 0 < Q <= 2^P, the
// bounds of docs/widths.md) and the extremes, and a third of the triangles untextured.
void vary_texture(std::vector<SnappedTriangle>& tris, std::mt19937_64& rng) {
  constexpr int P = kTextureFractionBits;
  const int64_t st_max = int64_t(1) << (P + 7), q_max = int64_t(1) << P;
  for (SnappedTriangle& t : tris) {
    if (rng() % 3 == 0) {
      t.textured = false;
      continue;
    }
    if (!t.textured) {  // random_case leaves some untextured: give them coordinates
      t.textured = true;
      for (SnappedVertex& v : t.v) v.q = q_max, v.s = 0, v.t = 0;
    }
    if (rng() % 4 != 0) continue;
    for (SnappedVertex& v : t.v) {
      auto st = [&]() -> int64_t {
        switch (rng() % 8) {
          case 0: return st_max;
          case 1: return -st_max;
          case 2: return 0;
          default: return int64_t(rng() % uint64_t(2 * st_max + 1)) - st_max;
        }
      };
      v.s = st();
      v.t = st();
      const int64_t kind = int64_t(rng() % 8);
      v.q = kind == 0 ? q_max : kind == 1 ? 1 : 1 + int64_t(rng() % uint64_t(q_max));
    }
  }
}

template <class V>
void check_setup_unit(const char* config, const Profile& build, uint64_t seed, int64_t count, bool texture) {
  Profile base = build;
  base.texture_unit = texture;
  const Widths w = derive_widths(base);
  const SetupTiming timing = setup_timing(base);
  const std::vector<rtl::SetupRecordField> fields = rtl::setup_record_fields(w, true);
  const rtl::RecordLayout layout(w, true);
  std::mt19937_64 rng(seed);
  Unit<V> unit(seed);
  constexpr int kBatch = 4096;
  int64_t checked = 0, textured_records = 0;
  for (uint64_t batch = 0; checked < count; ++batch) {
    Profile p = base;
    p.shading = Shading::Gouraud;  // the unit computes the colour planes whatever the shading
    p.cull = CullMode(rng() % 3);
    p.front_face = FrontFace(rng() % 2);
    const TriangleSetup model(p);
    Profile with_texture = p;  // random coordinates for the units without TEXTURE too
    with_texture.texture_unit = true;
    std::vector<SnappedTriangle> tris =
        rtl::random_case(with_texture, seed * 1000003u + batch, int(std::min<int64_t>(kBatch, count - checked))).triangles;
    vary_texture(tris, rng);
    std::vector<SetupResult> want(tris.size());
    for (size_t i = 0; i < tris.size(); ++i) want[i] = model.run(tris[i]);
    const std::string where_batch = std::string(config) + ", seed " + std::to_string(seed) + ", batch " +
                                    std::to_string(batch) + " (cull " + to_string(p.cull) + ", front face " +
                                    to_string(p.front_face) + ")";

    // Reset, then `run` from cycle 0 (the pipelined unit counts its slots from there).
    unit->rst = 1;
    unit->run = 0;
    unit->in_valid = 0;
    unit->cfg_cull = uint8_t(p.cull);
    unit->cfg_front_face = p.front_face == FrontFace::CW;
    for (int i = 0; i < 4; ++i) unit.settle(), unit.tick();
    unit->rst = 0;
    unit->run = 1;

    std::deque<Expected> decisions, records;
    size_t next = 0;
    int64_t present = 0;       // the cycle from which the test presents triangle `next`
    int64_t unit_free = 0;     // the first cycle the unit may accept again (the cycle model's rule)
    const int64_t bound = int64_t(tris.size()) * (timing.textured_drawn_latency + 8) + 1000;
    for (int64_t cycle = 0; next < tris.size() || !decisions.empty() || !records.empty(); ++cycle) {
      ASSERT_LT(cycle, bound) << where_batch << ": the unit stopped";
      // Accept in the first cycle >= max(present, unit_free) that starts a slot (pipelined) or at once.
      int64_t expected_accept = std::max(present, unit_free);
      if (timing.interval > 0) expected_accept = (expected_accept + timing.interval - 1) / timing.interval * timing.interval;
      const bool presenting = next < tris.size() && cycle >= present;
      unit->in_valid = presenting;
      if (presenting) {
        const SnappedTriangle& t = tris[next];
        for (int k = 0; k < 3; ++k) {
          put_bits(unit->in_x, k * w.coord_bits, w.coord_bits, uint64_t(int64_t(t.v[k].x)));
          put_bits(unit->in_y, k * w.coord_bits, w.coord_bits, uint64_t(int64_t(t.v[k].y)));
          put_bits(unit->in_z, k * p.z_bits, p.z_bits, t.v[k].z);
          put_bits(unit->in_rgb, k * 24, 24, rtl::rgb_word(t.v[k].color));
          put_bits(unit->in_texture, (3 * k + 0) * kTextureVertexBits, kTextureVertexBits, uint64_t(t.v[k].s));
          put_bits(unit->in_texture, (3 * k + 1) * kTextureVertexBits, kTextureVertexBits, uint64_t(t.v[k].t));
          put_bits(unit->in_texture, (3 * k + 2) * kTextureVertexBits, kTextureVertexBits, uint64_t(t.v[k].q));
        }
        unit->in_textured = t.textured;
      }
      unit.settle();
      const bool accepted = presenting && unit->in_ready;
      if (presenting && cycle == expected_accept) {
        ASSERT_TRUE(accepted) << where_batch << ": triangle " << next << " not accepted in cycle " << cycle;
      }
      if (accepted) {
        ASSERT_EQ(cycle, expected_accept) << where_batch << ": triangle " << next << " accepted early";
        const SetupResult& r = want[next];
        const bool drawn = r.status == SetupStatus::Drawn;
        const int64_t latency = r.textured ? timing.textured_drawn_latency : timing.drawn_latency;
        decisions.push_back({int64_t(next), cycle + timing.rejected_latency});
        if (drawn) records.push_back({int64_t(next), cycle + latency});
        unit_free = timing.interval > 0 ? cycle + timing.interval
                                        : cycle + (drawn ? latency : timing.rejected_latency) + 1;
        ++next;
        present = cycle + 1 + (rng() % 4 == 0 ? int64_t(rng() % (timing.textured_drawn_latency + 2)) : 0);
      }
      if (!decisions.empty() && decisions.front().cycle == cycle) {
        const SetupResult& r = want[size_t(decisions.front().index)];
        const std::string where = where_batch + ", triangle " + std::to_string(decisions.front().index);
        ASSERT_TRUE(unit->decided) << where << ": no decision in cycle " << cycle;
        ASSERT_EQ(int(unit->decided_status), int(r.status)) << where << ": status";
        ASSERT_EQ(int64_t(field_bits(unit->decided_area2, 0, w.area_bits, true)), int64_t(r.area2)) << where << ": area2";
        ASSERT_EQ(bool(unit->decided_front_facing), r.front_facing) << where << ": front facing";
        decisions.pop_front();
      } else {
        ASSERT_FALSE(unit->decided) << where_batch << ": a decision in cycle " << cycle << " with none due";
      }
      if (!records.empty() && records.front().cycle == cycle) {
        const SetupResult& r = want[size_t(records.front().index)];
        ASSERT_TRUE(unit->out_valid) << where_batch << ", triangle " << records.front().index << ": no record in cycle "
                                     << cycle;
        const SetupResult got = layout.unpack(unit->out_record.data());
        for (const rtl::SetupRecordField& f : fields)
          ASSERT_EQ(f.get(got), f.get(r)) << where_batch << ", triangle " << records.front().index << ": " << f.name;
        // The texture record: all zero without the texture unit or for an untextured triangle.
        const uint32_t* texture_words = unit->out_texture.data();
        textured_records += r.textured;
        ASSERT_EQ(rtl::texture_record_flag(texture_words), r.textured)
            << where_batch << ", triangle " << records.front().index << ": textured";
        static const char* const kGroup[] = {"start", "step_x", "step_y", "left0_start", "left0_step", "left1_start",
                                             "left1_step"};
        for (int g = 0; g < rtl::kTextureRecordGroups; ++g)
          for (int c = 0; c < 3; ++c)
            ASSERT_EQ(rtl::texture_record_register(texture_words, w, g, c), rtl::texture_record_field(r, g, c))
                << where_batch << ", triangle " << records.front().index << ": texture " << "STQ"[c] << " "
                << kGroup[g];
        records.pop_front();
      } else {
        ASSERT_FALSE(unit->out_valid) << where_batch << ": a record in cycle " << cycle << " with none due";
      }
      unit.tick();
    }
    checked += int64_t(tris.size());
  }
  ::testing::Test::RecordProperty("triangles", std::to_string(checked));
  ::testing::Test::RecordProperty("textured_records", std::to_string(textured_records));
}

#define RASTERSIM_SETUP_TEST(name, V, width, height, subpixel_bits, z_bits, z_guard_bits, interval, count) \
  TEST(SetupUnit, name) {                                                                                   \
    const Profile p = unit_profile(width, height, subpixel_bits, z_bits, z_guard_bits, interval);           \
    check_setup_unit<V>(#name, p, 20261126, unit_count(count), false);                                  \
  }
RASTERSIM_SETUP_UNITS(RASTERSIM_SETUP_TEST)

#define RASTERSIM_SETUP_TEXTURE_TEST(name, V, width, height, subpixel_bits, z_bits, z_guard_bits, interval, count) \
  TEST(SetupTextureUnit, name) {                                                                                   \
    const Profile p = unit_profile(width, height, subpixel_bits, z_bits, z_guard_bits, interval);                  \
    check_setup_unit<V>(#name, p, 20261127, unit_count(count), true);                                          \
  }
RASTERSIM_SETUP_TEXTURE_UNITS(RASTERSIM_SETUP_TEXTURE_TEST)

}  // namespace
}  // namespace rastersim::units
