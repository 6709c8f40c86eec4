// The C API (api/rastersim.h) over the model's Pipeline: every call catches what the model throws
// and turns it into a code and a message.
#include "api/rastersim.h"

#include <cmath>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "model/pipeline.h"
#include "model/profile.h"
#include "model/triangle.h"

struct rastersim_pipeline {
  rastersim::Profile profile;
  std::unique_ptr<rastersim::Pipeline> pipeline;
  std::vector<rastersim::TriangleRecord> records;
  std::vector<rastersim::SetupResult> setups;       // per triangle (rejected ones too: their decision)
  std::vector<rastersim::Fragment> fragments;        // in emission order
  std::vector<int64_t> first_fragment;               // per triangle: index into fragments
  mutable std::string profile_json;  // rastersim_profile_json's text

  struct Sink : rastersim::FragmentSink {
    std::vector<rastersim::Fragment>* out = nullptr;
    void on_fragment(const rastersim::Fragment& f) override { out->push_back(f); }
  } sink;

  void start_frame() {
    pipeline = std::make_unique<rastersim::Pipeline>(profile);
    records.clear();
    setups.clear();
    fragments.clear();
    first_fragment.clear();
    sink.out = &fragments;
    pipeline->set_fragment_sink(&sink);
    pipeline->set_triangle_log(&records);
  }
};

namespace {

thread_local std::string last_error;

int fail(int code, const std::string& message) {
  last_error = message;
  return code;
}

// Runs `body`, turning exceptions into RASTERSIM_ERROR_INPUT with their message.
template <typename Body>
int guarded(Body&& body) {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    return fail(RASTERSIM_ERROR_INPUT, "out of memory");
  } catch (const std::exception& e) {
    return fail(RASTERSIM_ERROR_INPUT, e.what());
  } catch (...) {
    return fail(RASTERSIM_ERROR_INPUT, "unknown error");
  }
}

int null_argument(const char* what) { return fail(RASTERSIM_ERROR_ARGUMENT, std::string(what) + " is NULL"); }

int check_triangle_index(const rastersim_pipeline* p, int64_t triangle) {
  if (triangle < 0 || triangle >= int64_t(p->records.size()))
    return fail(RASTERSIM_ERROR_ARGUMENT, "triangle " + std::to_string(triangle) + " was not submitted (" +
                                              std::to_string(p->records.size()) + " so far)");
  return RASTERSIM_OK;
}

int check_pixel(const rastersim_pipeline* p, int32_t x, int32_t y) {
  if (x < 0 || y < 0 || x >= p->profile.width || y >= p->profile.height)
    return fail(RASTERSIM_ERROR_ARGUMENT, "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                              ") is outside the " + std::to_string(p->profile.width) + " x " +
                                              std::to_string(p->profile.height) + " screen");
  return RASTERSIM_OK;
}

int submit(rastersim_pipeline* p, const rastersim::SnappedTriangle& tri, int64_t* triangle) {
  const int64_t first = int64_t(p->fragments.size());
  p->pipeline->submit(tri);
  // Recorded after the submit, so that a triangle the model refuses (an exception) leaves the
  // per-triangle tables as they were.
  p->first_fragment.push_back(first);
  p->setups.push_back(p->pipeline->last_setup());
  if (triangle) *triangle = int64_t(p->records.size()) - 1;
  return RASTERSIM_OK;
}

}  // namespace

extern "C" {

const char* rastersim_version(void) { return RASTERSIM_VERSION " (" RASTERSIM_GIT_DESCRIBE ")"; }

const char* rastersim_last_error(void) { return last_error.c_str(); }

int rastersim_create(const char* profile_json, rastersim_pipeline** pipeline) {
  if (!pipeline) return null_argument("pipeline");
  *pipeline = nullptr;
  return guarded([&] {
    auto p = std::make_unique<rastersim_pipeline>();
    if (profile_json && *profile_json) rastersim::load_profile_text(p->profile, profile_json, "profile");
    const std::vector<std::string> errors = rastersim::validate(p->profile);
    if (!errors.empty()) return fail(RASTERSIM_ERROR_INPUT, "profile: " + errors.front());
    p->start_frame();
    *pipeline = p.release();
    return int(RASTERSIM_OK);
  });
}

int rastersim_create_from_fields(const char* const keys[], const char* const values[], size_t count,
                                 rastersim_pipeline** pipeline) {
  if (!pipeline) return null_argument("pipeline");
  *pipeline = nullptr;
  if (count > 0 && (!keys || !values)) return null_argument(!keys ? "keys" : "values");
  return guarded([&] {
    auto p = std::make_unique<rastersim_pipeline>();
    for (size_t i = 0; i < count; ++i) {
      if (!keys[i] || !values[i]) return null_argument(("field " + std::to_string(i)).c_str());
      const std::string error = rastersim::set_profile_key(p->profile, keys[i], values[i]);
      if (!error.empty()) return fail(RASTERSIM_ERROR_INPUT, "profile field " + std::string(keys[i]) + ": " + error);
    }
    const std::vector<std::string> errors = rastersim::validate(p->profile);
    if (!errors.empty()) return fail(RASTERSIM_ERROR_INPUT, "profile: " + errors.front());
    p->start_frame();
    *pipeline = p.release();
    return int(RASTERSIM_OK);
  });
}

void rastersim_destroy(rastersim_pipeline* pipeline) { delete pipeline; }

int rastersim_reset(rastersim_pipeline* pipeline) {
  if (!pipeline) return null_argument("pipeline");
  return guarded([&] {
    pipeline->start_frame();
    return int(RASTERSIM_OK);
  });
}

int rastersim_width(const rastersim_pipeline* pipeline, int32_t* width) {
  if (!pipeline) return null_argument("pipeline");
  if (!width) return null_argument("width");
  *width = pipeline->profile.width;
  return RASTERSIM_OK;
}

int rastersim_height(const rastersim_pipeline* pipeline, int32_t* height) {
  if (!pipeline) return null_argument("pipeline");
  if (!height) return null_argument("height");
  *height = pipeline->profile.height;
  return RASTERSIM_OK;
}

int rastersim_profile_json(const rastersim_pipeline* pipeline, const char** json) {
  if (!pipeline) return null_argument("pipeline");
  if (!json) return null_argument("json");
  return guarded([&] {
    pipeline->profile_json = rastersim::profile_to_json(pipeline->profile);
    *json = pipeline->profile_json.c_str();
    return int(RASTERSIM_OK);
  });
}

int rastersim_submit_screen(rastersim_pipeline* pipeline, const rastersim_screen_vertex vertices[3],
                            int64_t* triangle) {
  if (!pipeline) return null_argument("pipeline");
  if (!vertices) return null_argument("vertices");
  return guarded([&] {
    rastersim::ScreenTriangle tri;
    for (int k = 0; k < 3; ++k)
      tri.v[k] = {vertices[k].x, vertices[k].y, vertices[k].z, {vertices[k].r, vertices[k].g, vertices[k].b}};
    const std::string problem = rastersim::check_screen_triangle(tri, pipeline->profile);
    if (!problem.empty()) return fail(RASTERSIM_ERROR_INPUT, "triangle: " + problem);
    return submit(pipeline, rastersim::snap(tri, pipeline->profile), triangle);
  });
}

int rastersim_submit_snapped(rastersim_pipeline* pipeline, const rastersim_snapped_vertex vertices[3],
                             int64_t* triangle) {
  if (!pipeline) return null_argument("pipeline");
  if (!vertices) return null_argument("vertices");
  return guarded([&] {
    const rastersim::Profile& p = pipeline->profile;
    const int64_t m = int64_t(1) << p.subpixel_bits;
    rastersim::SnappedTriangle tri;
    for (int k = 0; k < 3; ++k) {
      const rastersim_snapped_vertex& v = vertices[k];
      // The guard band of check_screen_triangle, in subpixels: x in [-W 2^S, 2W 2^S], y likewise.
      if (v.x < -p.width * m || v.x > 2 * p.width * m || v.y < -p.height * m || v.y > 2 * p.height * m)
        return fail(RASTERSIM_ERROR_INPUT, "triangle: vertex " + std::to_string(k) + " (" + std::to_string(v.x) +
                                               ", " + std::to_string(v.y) + ") subpixels is outside the guard band");
      if (v.z > p.depth_max())
        return fail(RASTERSIM_ERROR_INPUT, "triangle: vertex " + std::to_string(k) + " depth " + std::to_string(v.z) +
                                               " exceeds 2^z_bits - 1 = " + std::to_string(p.depth_max()));
      tri.v[k] = {v.x, v.y, v.z, {v.r, v.g, v.b}};
    }
    return submit(pipeline, tri, triangle);
  });
}

int rastersim_triangle_count(const rastersim_pipeline* pipeline, int64_t* count) {
  if (!pipeline) return null_argument("pipeline");
  if (!count) return null_argument("count");
  *count = int64_t(pipeline->records.size());
  return RASTERSIM_OK;
}

int rastersim_read_triangle(const rastersim_pipeline* pipeline, int64_t triangle,
                              rastersim_triangle_record* record) {
  if (!pipeline) return null_argument("pipeline");
  if (!record) return null_argument("record");
  if (int e = check_triangle_index(pipeline, triangle)) return e;
  const rastersim::TriangleRecord& r = pipeline->records[size_t(triangle)];
  *record = {r.index,       int32_t(r.status), r.setup_accept, r.setup_done, r.walker_load,
             r.walker_end,  r.fragments,       r.depth_pass,   r.last_write};
  return RASTERSIM_OK;
}

int rastersim_read_setup(const rastersim_pipeline* pipeline, int64_t triangle, rastersim_setup_record* record) {
  if (!pipeline) return null_argument("pipeline");
  if (!record) return null_argument("record");
  if (int e = check_triangle_index(pipeline, triangle)) return e;
  const rastersim::SetupResult& s = pipeline->setups[size_t(triangle)];
  if (s.status != rastersim::SetupStatus::Drawn)
    return fail(RASTERSIM_ERROR_ARGUMENT, "triangle " + std::to_string(triangle) + " was not drawn (" +
                                              rastersim::to_string(s.status) + "): it has no setup record");
  rastersim_setup_record& r = *record;
  r = {};
  r.x0 = s.x0, r.y0 = s.y0, r.x1 = s.x1, r.y1 = s.y1;
  for (int k = 0; k < 3; ++k) {
    const rastersim::EdgeSetup& e = s.edge[k];
    r.edge_start[k] = e.start, r.edge_step_x[k] = e.step_x, r.edge_step_y[k] = e.step_y;
    r.span_quot[k] = e.span_quot, r.span_rem[k] = e.span_rem;
    r.span_step_quot[k] = e.span_step_quot, r.span_step_rem[k] = e.span_step_rem;
    r.color_start[k] = s.color[k].start, r.color_step_x[k] = s.color[k].step_x, r.color_step_y[k] = s.color[k].step_y;
  }
  r.depth_start = s.depth.start, r.depth_step_x = s.depth.step_x, r.depth_step_y = s.depth.step_y;
  r.flat_r = s.flat_color.r, r.flat_g = s.flat_color.g, r.flat_b = s.flat_color.b;
  static_assert(rastersim::kLeftEdgeSlots == 2, "rastersim_setup_record holds two left-edge slots");
  for (int j = 0; j < rastersim::kLeftEdgeSlots; ++j) {
    const rastersim::LeftEdgePlanes& left = s.left[j];
    r.left_depth_start[j] = left.depth.start, r.left_depth_step[j] = left.depth.step;
    for (int c = 0; c < 3; ++c) r.left_color_start[j][c] = left.color[c].start, r.left_color_step[j][c] = left.color[c].step;
  }
  return RASTERSIM_OK;
}

int rastersim_fragment_count(const rastersim_pipeline* pipeline, int64_t triangle, int64_t* count) {
  if (!pipeline) return null_argument("pipeline");
  if (!count) return null_argument("count");
  if (int e = check_triangle_index(pipeline, triangle)) return e;
  *count = pipeline->records[size_t(triangle)].fragments;
  return RASTERSIM_OK;
}

int rastersim_read_fragment(const rastersim_pipeline* pipeline, int64_t triangle, int64_t k, rastersim_fragment* fragment) {
  if (!pipeline) return null_argument("pipeline");
  if (!fragment) return null_argument("fragment");
  if (int e = check_triangle_index(pipeline, triangle)) return e;
  const int64_t count = pipeline->records[size_t(triangle)].fragments;
  if (k < 0 || k >= count)
    return fail(RASTERSIM_ERROR_ARGUMENT, "triangle " + std::to_string(triangle) + " has " + std::to_string(count) +
                                              " fragments, not a fragment " + std::to_string(k));
  const rastersim::Fragment& f = pipeline->fragments[size_t(pipeline->first_fragment[size_t(triangle)] + k)];
  *fragment = {f.tri, f.x, f.y, f.z, f.color.r, f.color.g, f.color.b, uint8_t(f.pass), f.cycle};
  return RASTERSIM_OK;
}

int rastersim_frame_cycles(rastersim_pipeline* pipeline, int64_t* cycles) {
  if (!pipeline) return null_argument("pipeline");
  if (!cycles) return null_argument("cycles");
  return guarded([&] {
    *cycles = pipeline->pipeline->stats().cycles;
    return int(RASTERSIM_OK);
  });
}

int rastersim_read_depth(const rastersim_pipeline* pipeline, int32_t x, int32_t y, uint32_t* depth) {
  if (!pipeline) return null_argument("pipeline");
  if (!depth) return null_argument("depth");
  if (int e = check_pixel(pipeline, x, y)) return e;
  *depth = pipeline->pipeline->zbuffer().depth()[size_t(y) * size_t(pipeline->profile.width) + size_t(x)];
  return RASTERSIM_OK;
}

int rastersim_read_color(const rastersim_pipeline* pipeline, int32_t x, int32_t y, uint32_t* rgb) {
  if (!pipeline) return null_argument("pipeline");
  if (!rgb) return null_argument("rgb");
  if (int e = check_pixel(pipeline, x, y)) return e;
  *rgb = pipeline->pipeline->zbuffer().color()[size_t(y) * size_t(pipeline->profile.width) + size_t(x)];
  return RASTERSIM_OK;
}

}  // extern "C"

// ---- DPI-C shims (api/rastersim_dpi.sv) ----
namespace {
rastersim_pipeline* from_chandle(void* p) { return static_cast<rastersim_pipeline*>(p); }
uint32_t packed_rgb(uint8_t r, uint8_t g, uint8_t b) { return uint32_t(r) << 16 | uint32_t(g) << 8 | b; }
}  // namespace

extern "C" {

const char* rastersim_dpi_version(void) { return rastersim_version(); }
const char* rastersim_dpi_last_error(void) { return rastersim_last_error(); }
int rastersim_dpi_create(const char* profile_json, void** pipeline) {
  rastersim_pipeline* created = nullptr;
  const int status = rastersim_create(profile_json, &created);
  if (pipeline) *pipeline = created;
  return status;
}
void rastersim_dpi_destroy(void* pipeline) { rastersim_destroy(from_chandle(pipeline)); }
int rastersim_dpi_reset(void* pipeline) { return rastersim_reset(from_chandle(pipeline)); }
int rastersim_dpi_width(void* pipeline, int* width) { return rastersim_width(from_chandle(pipeline), width); }
int rastersim_dpi_height(void* pipeline, int* height) { return rastersim_height(from_chandle(pipeline), height); }

int rastersim_dpi_submit_screen(void* pipeline, double x0, double y0, double z0, unsigned rgb0, double x1,
                                double y1, double z1, unsigned rgb1, double x2, double y2, double z2,
                                unsigned rgb2, long long* triangle) {
  const double x[3] = {x0, x1, x2}, y[3] = {y0, y1, y2}, z[3] = {z0, z1, z2};
  const unsigned rgb[3] = {rgb0, rgb1, rgb2};
  rastersim_screen_vertex v[3];
  for (int k = 0; k < 3; ++k)
    v[k] = {x[k], y[k], z[k], uint8_t(rgb[k] >> 16), uint8_t(rgb[k] >> 8), uint8_t(rgb[k])};
  int64_t index = -1;
  const int status = rastersim_submit_screen(from_chandle(pipeline), v, &index);
  if (triangle) *triangle = index;
  return status;
}

int rastersim_dpi_submit_snapped(void* pipeline, int x0, int y0, unsigned z0, unsigned rgb0, int x1, int y1,
                                 unsigned z1, unsigned rgb1, int x2, int y2, unsigned z2, unsigned rgb2,
                                 long long* triangle) {
  const int x[3] = {x0, x1, x2}, y[3] = {y0, y1, y2};
  const unsigned z[3] = {z0, z1, z2}, rgb[3] = {rgb0, rgb1, rgb2};
  rastersim_snapped_vertex v[3];
  for (int k = 0; k < 3; ++k)
    v[k] = {x[k], y[k], z[k], uint8_t(rgb[k] >> 16), uint8_t(rgb[k] >> 8), uint8_t(rgb[k])};
  int64_t index = -1;
  const int status = rastersim_submit_snapped(from_chandle(pipeline), v, &index);
  if (triangle) *triangle = index;
  return status;
}

int rastersim_dpi_read_triangle(void* pipeline, long long triangle, int* status, long long* setup_accept,
                                long long* setup_done, long long* walker_load, long long* walker_end,
                                long long* fragments, long long* last_write) {
  rastersim_triangle_record r;
  if (int e = rastersim_read_triangle(from_chandle(pipeline), triangle, &r)) return e;
  if (!status || !setup_accept || !setup_done || !walker_load || !walker_end || !fragments || !last_write)
    return null_argument("an output argument");
  *status = r.status, *setup_accept = r.setup_accept, *setup_done = r.setup_done;
  *walker_load = r.walker_load, *walker_end = r.walker_end, *fragments = r.fragments, *last_write = r.last_write;
  return RASTERSIM_OK;
}

int rastersim_dpi_read_fragment(void* pipeline, long long triangle, long long k, int* x, int* y, unsigned* z,
                                unsigned* rgb, int* pass, long long* cycle) {
  rastersim_fragment f;
  if (int e = rastersim_read_fragment(from_chandle(pipeline), triangle, k, &f)) return e;
  if (!x || !y || !z || !rgb || !pass || !cycle) return null_argument("an output argument");
  *x = f.x, *y = f.y, *z = f.z, *rgb = packed_rgb(f.r, f.g, f.b), *pass = f.pass, *cycle = f.cycle;
  return RASTERSIM_OK;
}

int rastersim_dpi_frame_cycles(void* pipeline, long long* cycles) {
  int64_t c = 0;
  if (int e = rastersim_frame_cycles(from_chandle(pipeline), &c)) return e;
  if (!cycles) return null_argument("cycles");
  *cycles = c;
  return RASTERSIM_OK;
}

int rastersim_dpi_read_buffers(void* pipeline, int x, int y, unsigned* depth, unsigned* rgb) {
  uint32_t d = 0, c = 0;
  if (int e = rastersim_read_depth(from_chandle(pipeline), x, y, &d)) return e;
  if (int e = rastersim_read_color(from_chandle(pipeline), x, y, &c)) return e;
  if (!depth || !rgb) return null_argument("an output argument");
  *depth = d, *rgb = c;
  return RASTERSIM_OK;
}

}  // extern "C"
