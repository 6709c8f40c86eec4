// The golden model as a scoreboard, in C++ (docs/library.md): a header-only layer over the C API of
// rastersim.h, the stable interface. Every call returns a Status (a code and the message of
// rastersim_last_error()); nothing throws or aborts.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "rastersim.h"

namespace rastersim {

struct Status {
  int code = RASTERSIM_OK;
  std::string message;
  bool ok() const { return code == RASTERSIM_OK; }
  explicit operator bool() const { return ok(); }
};

class Scoreboard {
 public:
  using ScreenTriangle = std::array<rastersim_screen_vertex, 3>;
  using SnappedTriangle = std::array<rastersim_snapped_vertex, 3>;

  // A pipeline at a profile given as JSON text ("" is the default profile), or as fields
  // ({"width", "64"}, ...) as the command line's flags take them.
  Status create(const std::string& profile_json) {
    rastersim_pipeline* p = nullptr;
    const Status s = status(rastersim_create(profile_json.c_str(), &p));
    pipeline_.reset(p);
    return s;
  }
  Status create(const std::map<std::string, std::string>& fields) {
    std::vector<const char*> keys, values;
    for (const auto& [key, value] : fields) keys.push_back(key.c_str()), values.push_back(value.c_str());
    rastersim_pipeline* p = nullptr;
    const Status s = status(rastersim_create_from_fields(keys.data(), values.data(), keys.size(), &p));
    pipeline_.reset(p);
    return s;
  }

  Status reset() { return status(rastersim_reset(pipeline_.get())); }
  Status submit(const ScreenTriangle& vertices, int64_t* triangle = nullptr) {
    return status(rastersim_submit_screen(pipeline_.get(), vertices.data(), triangle));
  }
  Status submit(const SnappedTriangle& vertices, int64_t* triangle = nullptr) {
    return status(rastersim_submit_snapped(pipeline_.get(), vertices.data(), triangle));
  }

  Status triangle_count(int64_t& count) const { return status(rastersim_triangle_count(pipeline_.get(), &count)); }
  Status triangle(int64_t t, rastersim_triangle_record& record) const {
    return status(rastersim_read_triangle(pipeline_.get(), t, &record));
  }
  Status setup_record(int64_t t, rastersim_setup_record& record) const {
    return status(rastersim_read_setup(pipeline_.get(), t, &record));
  }
  // Triangle t's fragments in the walker's order.
  Status fragments(int64_t t, std::vector<rastersim_fragment>& out) const {
    out.clear();
    int64_t count = 0;
    if (Status s = status(rastersim_fragment_count(pipeline_.get(), t, &count)); !s) return s;
    out.resize(size_t(count));
    for (int64_t k = 0; k < count; ++k)
      if (Status s = status(rastersim_read_fragment(pipeline_.get(), t, k, &out[size_t(k)])); !s) return s;
    return {};
  }
  Status frame_cycles(int64_t& cycles) { return status(rastersim_frame_cycles(pipeline_.get(), &cycles)); }
  Status depth(int32_t x, int32_t y, uint32_t& z) const { return status(rastersim_read_depth(pipeline_.get(), x, y, &z)); }
  Status color(int32_t x, int32_t y, uint32_t& rgb) const {
    return status(rastersim_read_color(pipeline_.get(), x, y, &rgb));
  }
  Status size(int32_t& width, int32_t& height) const {
    if (Status s = status(rastersim_width(pipeline_.get(), &width)); !s) return s;
    return status(rastersim_height(pipeline_.get(), &height));
  }

  static std::string version() { return rastersim_version(); }

 private:
  static Status status(int code) { return code == RASTERSIM_OK ? Status{} : Status{code, rastersim_last_error()}; }
  struct Destroy {
    void operator()(rastersim_pipeline* p) const { rastersim_destroy(p); }
  };
  std::unique_ptr<rastersim_pipeline, Destroy> pipeline_;
};

}  // namespace rastersim
