// The C API (api/rastersim.h): the same results as the model's Pipeline, checked field by field,
// and every misuse an error code with a message, never a crash.
#include "api/rastersim.h"
#include "api/rastersim.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "model/pipeline.h"

namespace rastersim {
namespace {

const char* kProfile = R"({"width": 64, "height": 48, "memory_latency": 3, "setup_interval": 2})";

struct Handle {
  rastersim_pipeline* p = nullptr;
  explicit Handle(const char* profile = kProfile) { EXPECT_EQ(rastersim_create(profile, &p), RASTERSIM_OK); }
  ~Handle() { rastersim_destroy(p); }
};

std::vector<rastersim_screen_vertex> triangle_vertices() {
  return {{3.5, 2.25, 0.25, 255, 0, 0}, {40.0, 10.5, 0.5, 0, 255, 0}, {12.75, 30.0, 0.75, 0, 0, 255}};
}

TEST(Api, ResultsEqualThePipelinesFieldByField) {
  Handle h;
  ASSERT_NE(h.p, nullptr);
  Profile profile;
  load_profile_text(profile, kProfile, "profile");
  Pipeline pipeline(profile);
  std::vector<TriangleRecord> records;
  struct Collect : FragmentSink {
    std::vector<Fragment> all;
    void on_fragment(const Fragment& f) override { all.push_back(f); }
  } collect;
  pipeline.set_triangle_log(&records);
  pipeline.set_fragment_sink(&collect);

  // The same triangle twice (the second fails the depth test), then one turned around and culled
  // nowhere (no cull): three triangles through both.
  std::vector<rastersim_screen_vertex> v = triangle_vertices();
  std::vector<rastersim_screen_vertex> flipped = {v[0], v[2], v[1]};
  for (const auto* tri : {&v, &v, &flipped}) {
    int64_t index = -1;
    ASSERT_EQ(rastersim_submit_screen(h.p, tri->data(), &index), RASTERSIM_OK) << rastersim_last_error();
    ScreenTriangle screen;
    for (int k = 0; k < 3; ++k)
      screen.v[k] = {(*tri)[k].x, (*tri)[k].y, (*tri)[k].z, {(*tri)[k].r, (*tri)[k].g, (*tri)[k].b}};
    pipeline.submit(snap(screen, profile));
    EXPECT_EQ(index, int64_t(records.size()) - 1);

    rastersim_setup_record s;
    ASSERT_EQ(rastersim_read_setup(h.p, index, &s), RASTERSIM_OK) << rastersim_last_error();
    const SetupResult& m = pipeline.last_setup();
    EXPECT_EQ(s.x0, m.x0);
    EXPECT_EQ(s.y1, m.y1);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(s.edge_start[k], int64_t(m.edge[k].start));
      EXPECT_EQ(s.span_step_rem[k], int64_t(m.edge[k].span_step_rem));
      EXPECT_EQ(s.color_step_y[k], int64_t(m.color[k].step_y));
    }
    EXPECT_EQ(s.depth_step_x, int64_t(m.depth.step_x));
    for (int j = 0; j < kLeftEdgeSlots; ++j) {
      EXPECT_EQ(s.left_depth_start[j], int64_t(m.left[j].depth.start));
      EXPECT_EQ(s.left_depth_step[j], int64_t(m.left[j].depth.step));
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(s.left_color_start[j][c], int64_t(m.left[j].color[c].start));
        EXPECT_EQ(s.left_color_step[j][c], int64_t(m.left[j].color[c].step));
      }
    }
  }
  int64_t count = 0;
  ASSERT_EQ(rastersim_triangle_count(h.p, &count), RASTERSIM_OK);
  ASSERT_EQ(count, 3);
  size_t next = 0;
  for (int64_t t = 0; t < count; ++t) {
    rastersim_triangle_record r;
    ASSERT_EQ(rastersim_read_triangle(h.p, t, &r), RASTERSIM_OK);
    EXPECT_EQ(r.setup_accept, records[size_t(t)].setup_accept);
    EXPECT_EQ(r.setup_done, records[size_t(t)].setup_done);
    EXPECT_EQ(r.walker_end, records[size_t(t)].walker_end);
    EXPECT_EQ(r.last_write, records[size_t(t)].last_write);
    int64_t fragments = 0;
    ASSERT_EQ(rastersim_fragment_count(h.p, t, &fragments), RASTERSIM_OK);
    EXPECT_GT(fragments, 100);
    for (int64_t k = 0; k < fragments; ++k, ++next) {
      rastersim_fragment f;
      ASSERT_EQ(rastersim_read_fragment(h.p, t, k, &f), RASTERSIM_OK);
      const Fragment& m = collect.all.at(next);
      EXPECT_EQ(f.triangle, m.tri);
      EXPECT_EQ(f.x, m.x);
      EXPECT_EQ(f.y, m.y);
      EXPECT_EQ(f.z, m.z);
      EXPECT_EQ(f.pass, m.pass);
      EXPECT_EQ(f.cycle, m.cycle);
    }
  }
  EXPECT_EQ(next, collect.all.size());
  int64_t cycles = 0;
  ASSERT_EQ(rastersim_frame_cycles(h.p, &cycles), RASTERSIM_OK);
  EXPECT_EQ(cycles, pipeline.stats().cycles);
  for (int y = 0; y < profile.height; ++y)
    for (int x = 0; x < profile.width; ++x) {
      uint32_t depth = 0, rgb = 0;
      ASSERT_EQ(rastersim_read_depth(h.p, x, y, &depth), RASTERSIM_OK);
      ASSERT_EQ(rastersim_read_color(h.p, x, y, &rgb), RASTERSIM_OK);
      EXPECT_EQ(depth, pipeline.zbuffer().depth()[size_t(y * profile.width + x)]);
      EXPECT_EQ(rgb, pipeline.zbuffer().color()[size_t(y * profile.width + x)]);
    }
}

// The snapped entry point equals snapping the screen triangle; reset starts a frame at cycle 0.
TEST(Api, SnappedSubmitAndResetStartAFreshFrame) {
  Handle h;
  Profile profile;
  load_profile_text(profile, kProfile, "profile");
  std::vector<rastersim_screen_vertex> v = triangle_vertices();
  ScreenTriangle screen;
  for (int k = 0; k < 3; ++k) screen.v[k] = {v[k].x, v[k].y, v[k].z, {v[k].r, v[k].g, v[k].b}};
  const SnappedTriangle snapped = snap(screen, profile);
  rastersim_snapped_vertex s[3];
  for (int k = 0; k < 3; ++k)
    s[k] = {snapped.v[k].x, snapped.v[k].y, snapped.v[k].z, snapped.v[k].color.r, snapped.v[k].color.g,
            snapped.v[k].color.b};
  ASSERT_EQ(rastersim_submit_screen(h.p, v.data(), nullptr), RASTERSIM_OK);
  int64_t screen_cycles = 0, snapped_cycles = 0, count = -1;
  ASSERT_EQ(rastersim_frame_cycles(h.p, &screen_cycles), RASTERSIM_OK);
  ASSERT_EQ(rastersim_reset(h.p), RASTERSIM_OK);
  ASSERT_EQ(rastersim_triangle_count(h.p, &count), RASTERSIM_OK);
  EXPECT_EQ(count, 0);
  uint32_t depth = 0;
  ASSERT_EQ(rastersim_read_depth(h.p, 10, 10, &depth), RASTERSIM_OK);
  EXPECT_EQ(depth, profile.depth_clear_value());
  ASSERT_EQ(rastersim_submit_snapped(h.p, s, nullptr), RASTERSIM_OK);
  ASSERT_EQ(rastersim_frame_cycles(h.p, &snapped_cycles), RASTERSIM_OK);
  EXPECT_EQ(snapped_cycles, screen_cycles);
  EXPECT_GT(screen_cycles, 0);
}

// Every misuse returns a code and a message naming the problem.
TEST(Api, MisuseIsAnErrorWithAMessage) {
  rastersim_pipeline* p = nullptr;
  EXPECT_EQ(rastersim_create(R"({"width": 5000})", &p), RASTERSIM_ERROR_INPUT);
  EXPECT_EQ(p, nullptr);
  EXPECT_NE(std::string(rastersim_last_error()).find("width"), std::string::npos) << rastersim_last_error();
  EXPECT_EQ(rastersim_create(R"({"width": 64,)", &p), RASTERSIM_ERROR_INPUT);
  EXPECT_NE(std::string(rastersim_last_error()).find("line"), std::string::npos) << rastersim_last_error();
  EXPECT_EQ(rastersim_create(R"({"no_such_key": 1})", &p), RASTERSIM_ERROR_INPUT);
  EXPECT_NE(std::string(rastersim_last_error()).find("no_such_key"), std::string::npos) << rastersim_last_error();
  EXPECT_EQ(rastersim_create(nullptr, nullptr), RASTERSIM_ERROR_ARGUMENT);

  Handle h;
  rastersim_fragment f;
  rastersim_triangle_record r;
  rastersim_setup_record s;
  // Reading before submitting.
  EXPECT_EQ(rastersim_read_triangle(h.p, 0, &r), RASTERSIM_ERROR_ARGUMENT);
  EXPECT_NE(std::string(rastersim_last_error()).find("was not submitted"), std::string::npos);
  EXPECT_EQ(rastersim_read_fragment(h.p, 0, 0, &f), RASTERSIM_ERROR_ARGUMENT);
  // A triangle outside the guard band, with a NaN, a depth out of range.
  std::vector<rastersim_screen_vertex> v = triangle_vertices();
  v[1].x = 1000.0;
  EXPECT_EQ(rastersim_submit_screen(h.p, v.data(), nullptr), RASTERSIM_ERROR_INPUT);
  EXPECT_NE(std::string(rastersim_last_error()).find("triangle"), std::string::npos) << rastersim_last_error();
  v = triangle_vertices();
  v[2].z = 1.5;
  EXPECT_EQ(rastersim_submit_screen(h.p, v.data(), nullptr), RASTERSIM_ERROR_INPUT);
  rastersim_snapped_vertex far[3] = {{0, 0, 0, 0, 0, 0}, {64 * 16 * 3, 0, 0, 0, 0, 0}, {0, 16, 0, 0, 0, 0}};
  EXPECT_EQ(rastersim_submit_snapped(h.p, far, nullptr), RASTERSIM_ERROR_INPUT);
  rastersim_snapped_vertex deep[3] = {{0, 0, 1u << 24, 0, 0, 0}, {16, 0, 0, 0, 0, 0}, {0, 16, 0, 0, 0, 0}};
  EXPECT_EQ(rastersim_submit_snapped(h.p, deep, nullptr), RASTERSIM_ERROR_INPUT);
  EXPECT_NE(std::string(rastersim_last_error()).find("depth"), std::string::npos) << rastersim_last_error();
  int64_t count = -1;
  ASSERT_EQ(rastersim_triangle_count(h.p, &count), RASTERSIM_OK);
  EXPECT_EQ(count, 0);  // nothing refused was submitted
  // A degenerate triangle is submitted but has no setup record.
  v = triangle_vertices();
  v[2] = v[1];
  ASSERT_EQ(rastersim_submit_screen(h.p, v.data(), nullptr), RASTERSIM_OK);
  EXPECT_EQ(rastersim_read_setup(h.p, 0, &s), RASTERSIM_ERROR_ARGUMENT);
  EXPECT_NE(std::string(rastersim_last_error()).find("degenerate"), std::string::npos) << rastersim_last_error();
  EXPECT_EQ(rastersim_read_fragment(h.p, 0, 0, &f), RASTERSIM_ERROR_ARGUMENT);
  uint32_t word = 0;
  EXPECT_EQ(rastersim_read_depth(h.p, 64, 0, &word), RASTERSIM_ERROR_ARGUMENT);
  EXPECT_EQ(rastersim_read_color(h.p, 0, -1, &word), RASTERSIM_ERROR_ARGUMENT);
  EXPECT_EQ(rastersim_read_depth(h.p, 0, 0, nullptr), RASTERSIM_ERROR_ARGUMENT);
  EXPECT_EQ(rastersim_submit_screen(nullptr, v.data(), nullptr), RASTERSIM_ERROR_ARGUMENT);
  EXPECT_EQ(std::string(rastersim_last_error()), "pipeline is NULL");
  EXPECT_NE(std::string(rastersim_version()).find("0.1.0"), std::string::npos);
}

// A profile from fields is the profile of the same JSON; a bad field names itself.
TEST(Api, FieldsMakeTheSameProfileAsJson) {
  const char* keys[] = {"width", "height", "memory_latency", "setup_interval"};
  const char* values[] = {"64", "48", "3", "2"};
  rastersim_pipeline* from_fields = nullptr;
  ASSERT_EQ(rastersim_create_from_fields(keys, values, 4, &from_fields), RASTERSIM_OK) << rastersim_last_error();
  Handle from_json;
  const char* a = nullptr;
  const char* b = nullptr;
  ASSERT_EQ(rastersim_profile_json(from_fields, &a), RASTERSIM_OK);
  ASSERT_EQ(rastersim_profile_json(from_json.p, &b), RASTERSIM_OK);
  EXPECT_EQ(std::string(a), std::string(b));
  rastersim_destroy(from_fields);
  const char* bad_keys[] = {"width", "traversal"};
  const char* bad_values[] = {"64", "diagonal"};
  rastersim_pipeline* p = nullptr;
  EXPECT_EQ(rastersim_create_from_fields(bad_keys, bad_values, 2, &p), RASTERSIM_ERROR_INPUT);
  EXPECT_EQ(p, nullptr);
  EXPECT_NE(std::string(rastersim_last_error()).find("profile field traversal"), std::string::npos)
      << rastersim_last_error();
  const char* unknown[] = {"widht"};
  EXPECT_EQ(rastersim_create_from_fields(unknown, values, 1, &p), RASTERSIM_ERROR_INPUT);
  EXPECT_NE(std::string(rastersim_last_error()).find("widht"), std::string::npos) << rastersim_last_error();
}

// The C++ layer (rastersim.hpp): the same results as the C calls, errors as a Status with the message.
TEST(Api, CppLayerGivesTheSameResultsAndStatusMessages) {
  Scoreboard model;
  ASSERT_TRUE(model.create(std::map<std::string, std::string>{{"width", "64"}, {"height", "48"},
                                                              {"memory_latency", "3"}, {"setup_interval", "2"}}));
  Handle h;
  const std::vector<rastersim_screen_vertex> v = triangle_vertices();
  int64_t index = -1;
  ASSERT_TRUE(model.submit(Scoreboard::ScreenTriangle{v[0], v[1], v[2]}, &index));
  ASSERT_EQ(rastersim_submit_screen(h.p, v.data(), nullptr), RASTERSIM_OK);
  std::vector<rastersim_fragment> fragments;
  ASSERT_TRUE(model.fragments(index, fragments));
  ASSERT_GT(fragments.size(), 100u);
  for (size_t k = 0; k < fragments.size(); ++k) {
    rastersim_fragment f;
    ASSERT_EQ(rastersim_read_fragment(h.p, 0, int64_t(k), &f), RASTERSIM_OK);
    EXPECT_EQ(fragments[k].x, f.x);
    EXPECT_EQ(fragments[k].z, f.z);
    EXPECT_EQ(fragments[k].cycle, f.cycle);
  }
  int64_t a = 0, b = 0;
  ASSERT_TRUE(model.frame_cycles(a));
  ASSERT_EQ(rastersim_frame_cycles(h.p, &b), RASTERSIM_OK);
  EXPECT_EQ(a, b);
  rastersim_triangle_record r;
  const Status missing = model.triangle(5, r);
  EXPECT_FALSE(missing);
  EXPECT_EQ(missing.code, RASTERSIM_ERROR_ARGUMENT);
  EXPECT_NE(missing.message.find("was not submitted"), std::string::npos) << missing.message;
  Scoreboard bad;
  const Status refused = bad.create("{\"width\": 0}");
  EXPECT_EQ(refused.code, RASTERSIM_ERROR_INPUT);
  EXPECT_NE(refused.message.find("width"), std::string::npos) << refused.message;
  EXPECT_FALSE(bad.reset());  // no pipeline: an error, not a crash
}

}  // namespace
}  // namespace rastersim
