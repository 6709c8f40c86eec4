// The Python module `rastersim` (docs/library.md): the C API of api/rastersim.h for Python
// testbenches (pytest, cocotb). Fragments and buffers come back as numpy arrays; every error the C
// API returns is raised as rastersim.Error with its message.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <string>
#include <tuple>
#include <vector>

#include "api/rastersim.h"

namespace py = pybind11;

namespace {

PyObject* error_type = nullptr;  // rastersim.Error

void check(int status) {
  if (status != RASTERSIM_OK) {
    PyErr_SetString(error_type, rastersim_last_error());
    throw py::error_already_set();
  }
}

using Vertex = std::tuple<double, double, double, int, int, int>;  // x, y, z, r, g, b

uint8_t channel(int v) {
  if (v < 0 || v > 255) {
    PyErr_SetString(error_type, ("colour value " + std::to_string(v) + " is outside 0..255").c_str());
    throw py::error_already_set();
  }
  return uint8_t(v);
}

class Pipeline {
 public:
  Pipeline(const std::string& profile_json, const py::kwargs& fields) {
    if (fields.empty()) {
      check(rastersim_create(profile_json.c_str(), &p_));
      return;
    }
    if (!profile_json.empty()) {
      PyErr_SetString(error_type, "give a profile as JSON text or as fields, not both");
      throw py::error_already_set();
    }
    // Fields as the command line's flags take them: numbers and booleans as their text.
    std::vector<std::string> keys, values;
    for (const auto& [key, value] : fields) {
      keys.push_back(py::str(key));
      values.push_back(py::isinstance<py::bool_>(value) ? (value.cast<bool>() ? "true" : "false")
                                                         : std::string(py::str(value)));
    }
    std::vector<const char*> key_ptrs, value_ptrs;
    for (size_t i = 0; i < keys.size(); ++i) key_ptrs.push_back(keys[i].c_str()), value_ptrs.push_back(values[i].c_str());
    check(rastersim_create_from_fields(key_ptrs.data(), value_ptrs.data(), keys.size(), &p_));
  }
  ~Pipeline() { rastersim_destroy(p_); }
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  void reset() { check(rastersim_reset(p_)); }

  int64_t submit_screen(const std::array<Vertex, 3>& vertices) {
    rastersim_screen_vertex v[3];
    for (int k = 0; k < 3; ++k) {
      const auto& [x, y, z, r, g, b] = vertices[size_t(k)];
      v[k] = {x, y, z, channel(r), channel(g), channel(b)};
    }
    int64_t index = -1;
    check(rastersim_submit_screen(p_, v, &index));
    return index;
  }

  int64_t submit_snapped(const std::array<std::tuple<int32_t, int32_t, uint32_t, int, int, int>, 3>& vertices) {
    rastersim_snapped_vertex v[3];
    for (int k = 0; k < 3; ++k) {
      const auto& [x, y, z, r, g, b] = vertices[size_t(k)];
      v[k] = {x, y, z, channel(r), channel(g), channel(b)};
    }
    int64_t index = -1;
    check(rastersim_submit_snapped(p_, v, &index));
    return index;
  }

  int64_t triangle_count() const {
    int64_t n = 0;
    check(rastersim_triangle_count(p_, &n));
    return n;
  }

  py::dict triangle(int64_t t) const {
    rastersim_triangle_record r;
    check(rastersim_read_triangle(p_, t, &r));
    static const char* status_names[] = {"drawn", "degenerate", "culled", "offscreen", "no_centre"};
    py::dict d;
    d["triangle"] = r.triangle;
    d["status"] = r.status >= 0 && r.status <= 4 ? status_names[r.status] : "?";
    d["setup_accept"] = r.setup_accept;
    d["setup_done"] = r.setup_done;
    d["walker_load"] = r.walker_load;
    d["walker_end"] = r.walker_end;
    d["fragments"] = r.fragments;
    d["depth_pass"] = r.depth_pass;
    d["last_write"] = r.last_write;
    return d;
  }

  py::dict setup_record(int64_t t) const {
    rastersim_setup_record s;
    check(rastersim_read_setup(p_, t, &s));
    auto three = [](const int64_t v[3]) { return std::vector<int64_t>{v[0], v[1], v[2]}; };
    py::dict d;
    d["x0"] = s.x0, d["y0"] = s.y0, d["x1"] = s.x1, d["y1"] = s.y1;
    d["edge_start"] = three(s.edge_start), d["edge_step_x"] = three(s.edge_step_x);
    d["edge_step_y"] = three(s.edge_step_y), d["span_quot"] = three(s.span_quot);
    d["span_rem"] = three(s.span_rem), d["span_step_quot"] = three(s.span_step_quot);
    d["span_step_rem"] = three(s.span_step_rem);
    d["depth_start"] = s.depth_start, d["depth_step_x"] = s.depth_step_x, d["depth_step_y"] = s.depth_step_y;
    d["color_start"] = three(s.color_start), d["color_step_x"] = three(s.color_step_x);
    d["color_step_y"] = three(s.color_step_y);
    d["flat_rgb"] = std::vector<int>{s.flat_r, s.flat_g, s.flat_b};
    // Left-edge slots j = 0, 1 (docs/library.md).
    auto two = [](const int64_t v[2]) { return std::vector<int64_t>{v[0], v[1]}; };
    d["left_depth_start"] = two(s.left_depth_start), d["left_depth_step"] = two(s.left_depth_step);
    d["left_color_start"] = std::vector<std::vector<int64_t>>{three(s.left_color_start[0]), three(s.left_color_start[1])};
    d["left_color_step"] = std::vector<std::vector<int64_t>>{three(s.left_color_step[0]), three(s.left_color_step[1])};
    return d;
  }

  // Triangle t's fragments (every triangle's with t = None) as an (n, 9) int64 array whose columns
  // are FRAGMENT_COLUMNS.
  py::array_t<int64_t> fragments(py::object which) const {
    int64_t first = 0, last = triangle_count();
    if (!which.is_none()) {
      first = which.cast<int64_t>();
      int64_t unused = 0;
      check(rastersim_fragment_count(p_, first, &unused));  // the index check and its message
      last = first + 1;
    }
    std::vector<int64_t> rows;
    for (int64_t t = first; t < last; ++t) {
      int64_t n = 0;
      check(rastersim_fragment_count(p_, t, &n));
      for (int64_t k = 0; k < n; ++k) {
        rastersim_fragment f;
        check(rastersim_read_fragment(p_, t, k, &f));
        rows.insert(rows.end(), {f.triangle, f.x, f.y, f.z, f.pass, f.r, f.g, f.b, f.cycle});
      }
    }
    py::array_t<int64_t> out({py::ssize_t(rows.size() / 9), py::ssize_t(9)});
    std::copy(rows.begin(), rows.end(), out.mutable_data());
    return out;
  }

  int64_t frame_cycles() {
    int64_t c = 0;
    check(rastersim_frame_cycles(p_, &c));
    return c;
  }

  // The depth (or colour, 0x00RRGGBB) buffer as a (height, width) uint32 array.
  py::array_t<uint32_t> buffer(bool colour) const {
    int32_t w = 0, h = 0;
    check(rastersim_width(p_, &w));
    check(rastersim_height(p_, &h));
    py::array_t<uint32_t> out({py::ssize_t(h), py::ssize_t(w)});
    uint32_t* data = out.mutable_data();
    for (int32_t y = 0; y < h; ++y)
      for (int32_t x = 0; x < w; ++x)
        check(colour ? rastersim_read_color(p_, x, y, &data[size_t(y) * size_t(w) + size_t(x)])
                     : rastersim_read_depth(p_, x, y, &data[size_t(y) * size_t(w) + size_t(x)]));
    return out;
  }

  std::string profile() const {
    const char* json = nullptr;
    check(rastersim_profile_json(p_, &json));
    return json;
  }

 private:
  rastersim_pipeline* p_ = nullptr;
};

}  // namespace

PYBIND11_MODULE(rastersim, m) {
  m.doc() = "The rastersim golden model: a bit- and cycle-exact model of a fixed-point triangle rasterizer";
  error_type = PyErr_NewException("rastersim.Error", PyExc_ValueError, nullptr);
  m.attr("__version__") = RASTERSIM_PYTHON_VERSION;
  m.attr("Error") = py::handle(error_type);
  m.attr("FRAGMENT_COLUMNS") = py::make_tuple("tri", "x", "y", "z", "pass", "r", "g", "b", "cycle");
  m.def("version", &rastersim_version, "the release and the commit the library was built from");
  py::class_<Pipeline>(m, "Pipeline", "one frame through setup, walker, Z adder and z-buffer")
      .def(py::init<const std::string&, const py::kwargs&>(), py::arg("profile_json") = "",
           "a pipeline at a profile given as JSON text or as fields (Pipeline(width=64, traversal='bbox')); "
           "absent keys keep their defaults")
      .def("reset", &Pipeline::reset, "start a new frame: cleared buffers, cycle 0, no triangles")
      .def("submit_screen", &Pipeline::submit_screen, py::arg("vertices"),
           "one triangle of three (x, y, z, r, g, b) vertices in screen space; returns its index")
      .def("submit_snapped", &Pipeline::submit_snapped, py::arg("vertices"),
           "one triangle of three (x, y, z, r, g, b) vertices as the setup unit's words; returns its index")
      .def_property_readonly("triangle_count", &Pipeline::triangle_count)
      .def("triangle", &Pipeline::triangle, py::arg("index"), "the triangle's status and cycle record")
      .def("setup_record", &Pipeline::setup_record, py::arg("index"), "a drawn triangle's setup record")
      .def("fragments", &Pipeline::fragments, py::arg("index") = py::none(),
           "fragments as an (n, 9) int64 array, columns FRAGMENT_COLUMNS; one triangle's or all")
      .def("frame_cycles", &Pipeline::frame_cycles, "the frame's cycles so far")
      .def("depth", [](const Pipeline& p) { return p.buffer(false); }, "depth buffer, (height, width) uint32")
      .def("color", [](const Pipeline& p) { return p.buffer(true); }, "colour buffer 0x00RRGGBB, (height, width) uint32")
      .def_property_readonly("profile", &Pipeline::profile, "the profile, every key resolved, as JSON text");
}
