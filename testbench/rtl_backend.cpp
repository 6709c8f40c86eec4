#include "testbench/rtl_backend.h"

#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <fstream>
#include <future>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "testbench/modules.h"
#include "testbench/rtl_configs.h"
#include "testbench/setup_record.h"
#include "testbench/waveform.h"

namespace rastersim::rtl {

namespace {

// Configurations loaded from modules built on demand (load_module), searched after the built ones.
// A deque: the addresses find_configuration returns stay valid as modules are added.
std::mutex loaded_mutex;
std::deque<BuiltConfiguration>& loaded_table() {
  static std::deque<BuiltConfiguration> table;
  return table;
}

std::vector<const BuiltConfiguration*> all_configurations() {
  std::vector<const BuiltConfiguration*> all;
  for (const BuiltConfiguration& c : built_configuration_table()) all.push_back(&c);
  const std::lock_guard<std::mutex> lock(loaded_mutex);
  for (const BuiltConfiguration& c : loaded_table()) all.push_back(&c);
  return all;
}

// A configuration that runs the profile (core_mismatch); failing that, one that would but for its
// largest memory latency (configuration_error names it).
const BuiltConfiguration* find_configuration(const Profile& p) {
  const BuiltConfiguration* found = nullptr;
  Profile shortest = p;
  shortest.memory_latency = 1;
  for (const BuiltConfiguration* c : all_configurations()) {
    if (core_mismatch(c->parameters, p).empty()) return c;
    if (!found && core_mismatch(c->parameters, shortest).empty()) found = c;
  }
  return found;
}

}  // namespace

std::vector<std::string> built_configurations() {
  std::vector<std::string> out;
  for (const BuiltConfiguration* c : all_configurations())
    out.push_back(c->name + ": " + core_parameters_text(c->parameters));
  return out;
}

bool has_configuration(const Profile& p) {
  const BuiltConfiguration* c = find_configuration(p);
  return c && core_mismatch(c->parameters, p).empty();
}

void load_module(const std::string& library_path) {
  void* handle = dlopen(library_path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw std::runtime_error(std::string("cannot load the RTL module: ") + dlerror());
  const auto abi = reinterpret_cast<const char* (*)()>(dlsym(handle, RASTERSIM_MODULE_ABI_SYMBOL));
  const auto module = reinterpret_cast<const BuiltConfiguration* (*)()>(dlsym(handle, "rastersim_rtl_module"));
  if (!abi || !module) throw std::runtime_error(library_path + " is not an RTL module of rastersim");
  if (abi() != modules::abi_stamp())
    throw std::runtime_error(library_path + " was built against other records (" + abi() + ") than this program (" +
                             modules::abi_stamp() + ")");
  const std::lock_guard<std::mutex> lock(loaded_mutex);
  loaded_table().push_back(*module());
}

int built_max_memory_latency(const Profile& p) {
  const BuiltConfiguration* c = find_configuration(p);
  return c ? int(parameter_value(c->parameters, "MAX_MEMORY_LATENCY")) : 0;
}

std::string configuration_error(const Profile& p) {
  const std::vector<std::string> errors = validate(p);
  if (!errors.empty()) return "invalid profile: " + errors.front();
  // Whatever the geometry: rastersim_top's on-chip memories have no stall pattern.
  if (p.memory_stall_percent > 0)
    return "memory_stall_percent " + std::to_string(p.memory_stall_percent) +
           ": rastersim_top's on-chip memory has no back-pressure; the SystemC backend (--backend systemc) "
           "puts a memory with a stall pattern behind the core";
  const BuiltConfiguration* c = find_configuration(p);
  if (!c) {
    std::string message = "no RTL is built for the core " + core_parameters_text(core_parameters(p, CoreBounds::Largest)) +
                          "; built:";
    for (const std::string& b : built_configurations()) message += " [" + b + "]";
    return message + ". rastersim verilates it on demand (--backend rtl, cosim); to build it in, add an entry to "
                     "RASTERSIM_RTL_CONFIGS in testbench/CMakeLists.txt (name:NAME=value,NAME=value, "
                     "parameters of rastersim_core).";
  }
  if (const int64_t max = parameter_value(c->parameters, "MAX_MEMORY_LATENCY"); p.memory_latency > max)
    return "memory_latency " + std::to_string(p.memory_latency) + " exceeds the built RTL's maximum " +
           std::to_string(max) + " (configuration " + c->name + ")";
  return "";
}

RtlResult run_rtl(const Profile& profile, const std::vector<SnappedTriangle>& triangles, const RtlOptions& options) {
  const std::string error = configuration_error(profile);
  if (!error.empty()) throw std::invalid_argument(error);
  return find_configuration(profile)->run(profile, triangles, options);
}

namespace {

struct CollectFragments : FragmentSink {
  std::vector<Fragment>* out;
  void on_fragment(const Fragment& f) override { out->push_back(f); }
};

}  // namespace

RtlResult run_model(const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                    const TextureBinding& texture) {
  RtlResult out;
  Pipeline pipe(profile);
  pipe.set_texture(texture);
  CollectFragments sink;
  sink.out = &out.fragments;
  pipe.set_fragment_sink(&sink);
  pipe.set_triangle_log(&out.triangles);
  const TriangleSetup setup(profile);
  for (const SnappedTriangle& t : triangles) {
    SetupResult s = setup.run(t);
    if (s.status != SetupStatus::Drawn) s = SetupResult{};
    // Fields the RTL record does not carry (see RtlResult::setups).
    s.front_facing = false;
    s.area2 = 0;
    for (EdgeSetup& e : s.edge) e.owns_samples = false;
    out.setups.push_back(s);
    pipe.submit(t);
  }
  out.stats = pipe.stats();
  out.depth = pipe.zbuffer().depth();
  out.color = pipe.zbuffer().color();
  return out;
}

namespace {

std::string hex_rgb(uint32_t c) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "0x%06x", c);
  return buffer;
}

std::string rgb_text(const Rgb& c) { return hex_rgb((uint32_t(c.r) << 16) | (uint32_t(c.g) << 8) | c.b); }

Divergence divergence(int64_t triangle, const std::string& unit, const std::string& field,
                      const std::string& expected, const std::string& actual, int64_t cycle) {
  Divergence d;
  d.found = true;
  d.triangle = triangle;
  d.unit = unit;
  d.field = field;
  d.expected = expected;
  d.actual = actual;
  d.cycle = cycle;
  std::ostringstream s;
  s << "first divergence: ";
  if (triangle >= 0) s << "triangle " << triangle << ", ";
  s << "unit " << unit << ", field " << field << ": expected " << expected << ", actual " << actual;
  if (cycle >= 0) s << ", cycle " << cycle;
  d.sentence = s.str();
  return d;
}

template <class T>
bool differs(const T& a, const T& b) { return !(a == b); }

// The setup record, field by field (setup_record.h), in the setup unit's output register in cycle
// `cycle` (setup_done).
// Flat shading leaves the colour planes zero on both sides, so every field is compared.
Divergence compare_setup(int64_t t, const SetupResult& m, const SetupResult& r, int64_t cycle) {
  static const std::vector<SetupRecordField> fields = setup_record_fields(derive_widths(Profile{}), true);
  for (const SetupRecordField& f : fields) {
    const int64_t expected = f.get(m), actual = f.get(r);
    if (expected == actual) continue;
    if (f.name == "flat_rgb")
      return divergence(t, "triangle_setup", "record flat colour", rgb_text(m.flat_color), rgb_text(r.flat_color), cycle);
    return divergence(t, "triangle_setup", "record " + f.name, std::to_string(expected), std::to_string(actual), cycle);
  }
  if (m.textured != r.textured)
    return divergence(t, "triangle_setup", "record textured", std::to_string(m.textured), std::to_string(r.textured), cycle);
  static const char* const kCoordinate[3] = {"S", "T", "Q"};
  static const char* const kGroup[kTextureRecordGroups] = {"start", "step x", "step y", "left slot 0 start",
                                                           "left slot 0 step", "left slot 1 start", "left slot 1 step"};
  for (int g = 0; g < kTextureRecordGroups; ++g)
    for (int c = 0; c < 3; ++c) {
      const int64_t expected = texture_record_field(m, g, c), actual = texture_record_field(r, g, c);
      if (expected != actual)
        return divergence(t, "triangle_setup", std::string("record ") + kCoordinate[c] + " plane " + kGroup[g],
                          std::to_string(expected), std::to_string(actual), cycle);
    }
  return {};
}

}  // namespace

Divergence compare(const RtlResult& model, const RtlResult& rtl) {
  using std::to_string;
  // A failed assertion stopped the RTL: what follows it would only differ for that reason.
  if (rtl.assertion_cycle >= 0)
    return divergence(-1, "pipeline", "assertion", "every assertion holds", "one failed (the simulator's message names it)",
                      rtl.assertion_cycle);
  // Fragments grouped by triangle, in emission order.
  size_t next_model = 0, next_rtl = 0;
  const size_t triangles = std::max(model.triangles.size(), rtl.triangles.size());
  for (size_t i = 0; i < triangles; ++i) {
    const int64_t t = int64_t(i);
    if (i >= rtl.triangles.size()) {
      const TriangleRecord& m = model.triangles[i];
      return divergence(t, "triangle_setup", "setup_accept", to_string(m.setup_accept),
                        "never accepted" + (rtl.finished ? std::string() : " (" + rtl.note + ")"), m.setup_accept);
    }
    if (i >= model.triangles.size())
      return divergence(t, "triangle_setup", "setup_accept", "no such triangle", to_string(rtl.triangles[i].setup_accept), -1);
    const TriangleRecord& m = model.triangles[i];
    const TriangleRecord& r = rtl.triangles[i];
    if (m.setup_accept != r.setup_accept)
      return divergence(t, "triangle_setup", "setup_accept", to_string(m.setup_accept), to_string(r.setup_accept), m.setup_accept);
    if (m.status != r.status)
      return divergence(t, "triangle_setup", "status", to_string(m.status), to_string(r.status), m.setup_accept + 1);
    if (m.setup_decided != r.setup_decided)
      return divergence(t, "triangle_setup", "setup_decided", to_string(m.setup_decided), to_string(r.setup_decided),
                        m.setup_decided);
    if (m.setup_done != r.setup_done)
      return divergence(t, "triangle_setup", "setup_done", to_string(m.setup_done), to_string(r.setup_done), m.setup_done);
    if (m.status == SetupStatus::Drawn && i < model.setups.size() && i < rtl.setups.size()) {
      const Divergence d = compare_setup(t, model.setups[i], rtl.setups[i], m.setup_done);
      if (d.found) return d;
    }
    if (m.walker_load != r.walker_load)
      return divergence(t, "scanline_walker", "walker_load", to_string(m.walker_load), to_string(r.walker_load), m.walker_load);
    for (int64_t n = 0;; ++n) {
      const bool has_m = next_model < model.fragments.size() && model.fragments[next_model].tri == t;
      const bool has_r = next_rtl < rtl.fragments.size() && rtl.fragments[next_rtl].tri == t;
      if (!has_m && !has_r) break;
      const std::string which = "fragment " + to_string(n);
      if (!has_r) {
        const Fragment& f = model.fragments[next_model];
        return divergence(t, "scanline_walker", which + " (x, y)", "(" + to_string(f.x) + ", " + to_string(f.y) + ")",
                          "no fragment", f.cycle);
      }
      if (!has_m) {
        const Fragment& f = rtl.fragments[next_rtl];
        return divergence(t, "scanline_walker", which + " (x, y)", "no fragment",
                          "(" + to_string(f.x) + ", " + to_string(f.y) + ")", f.cycle);
      }
      const Fragment& a = model.fragments[next_model++];
      const Fragment& b = rtl.fragments[next_rtl++];
      const std::string at = which + " at (" + to_string(a.x) + ", " + to_string(a.y) + ")";
      if (a.x != b.x || a.y != b.y)
        return divergence(t, "scanline_walker", which + " (x, y)", "(" + to_string(a.x) + ", " + to_string(a.y) + ")",
                          "(" + to_string(b.x) + ", " + to_string(b.y) + ")", a.cycle);
      if (a.cycle != b.cycle)
        return divergence(t, "zbuffer", at + " taken cycle", to_string(a.cycle), to_string(b.cycle), a.cycle);
      if (a.z != b.z) return divergence(t, "z_adder", at + " z", to_string(a.z), to_string(b.z), a.cycle);
      if (differs(a.color, b.color))  // a textured fragment's colour is the texture unit's
        return divergence(t, a.textured ? "texture_unit" : "z_adder", at + " colour", rgb_text(a.color),
                          rgb_text(b.color), a.cycle);
      if (a.pass != b.pass)
        return divergence(t, "zbuffer", at + " depth test pass", to_string(a.pass), to_string(b.pass), a.cycle);
      if (a.tested != b.tested)
        return divergence(t, "zbuffer", at + " depth test cycle", to_string(a.tested), to_string(b.tested), a.cycle);
    }
    if (m.walker_end != r.walker_end)
      return divergence(t, "scanline_walker", "walker_end", to_string(m.walker_end), to_string(r.walker_end), m.walker_end);
    if (m.fragments != r.fragments)
      return divergence(t, "scanline_walker", "fragments", to_string(m.fragments), to_string(r.fragments), m.walker_end);
    if (m.depth_pass != r.depth_pass)
      return divergence(t, "zbuffer", "depth_pass", to_string(m.depth_pass), to_string(r.depth_pass), m.last_write);
    if (m.last_write != r.last_write)
      return divergence(t, "zbuffer", "last_write", to_string(m.last_write), to_string(r.last_write), m.last_write);
  }
  if (!rtl.finished) return divergence(-1, "pipeline", "completion", "finished", rtl.note, -1);
  if (model.depth.size() != rtl.depth.size() || model.color.size() != rtl.color.size())
    return divergence(-1, "zbuffer", "memory size", to_string(model.depth.size()), to_string(rtl.depth.size()), -1);
  for (size_t a = 0; a < model.depth.size(); ++a) {
    if (model.depth[a] != rtl.depth[a])
      return divergence(-1, "zbuffer", "final depth memory word " + to_string(a), to_string(model.depth[a]),
                        to_string(rtl.depth[a]), -1);
    if (model.color[a] != rtl.color[a])
      return divergence(-1, "zbuffer", "final colour memory word " + to_string(a), hex_rgb(model.color[a]),
                        hex_rgb(rtl.color[a]), -1);
  }
  const FrameStats& m = model.stats;
  const FrameStats& r = rtl.stats;
  const struct {
    const char* unit;
    const char* name;
    int64_t expected, actual;
  } fields[] = {
      {"pipeline", "cycles", m.cycles, r.cycles},
      {"triangle_setup", "triangles", m.triangles, r.triangles},
      {"triangle_setup", "triangles_culled", m.triangles_culled, r.triangles_culled},
      {"triangle_setup", "triangles_degenerate", m.triangles_degenerate, r.triangles_degenerate},
      {"triangle_setup", "triangles_offscreen", m.triangles_offscreen, r.triangles_offscreen},
      {"triangle_setup", "triangles_no_centre", m.triangles_no_centre, r.triangles_no_centre},
      {"triangle_setup", "triangles_drawn", m.triangles_drawn, r.triangles_drawn},
      {"scanline_walker", "candidates", m.candidates, r.candidates},
      {"zbuffer", "fragments", m.fragments, r.fragments},
      {"zbuffer", "depth_pass", m.depth_pass, r.depth_pass},
      {"zbuffer", "depth_fail", m.depth_fail, r.depth_fail},
      {"triangle_setup", "busy cycles", m.setup.busy, r.setup.busy},
      {"triangle_setup", "stall cycles", m.setup.stall, r.setup.stall},
      {"scanline_walker", "busy cycles", m.walker.busy, r.walker.busy},
      {"scanline_walker", "stall cycles", m.walker.stall, r.walker.stall},
      {"z_adder", "busy cycles", m.z_adder.busy, r.z_adder.busy},
      {"z_adder", "stall cycles", m.z_adder.stall, r.z_adder.stall},
      {"zbuffer", "busy cycles", m.zbuffer.busy, r.zbuffer.busy},
      {"zbuffer", "stall cycles", m.zbuffer.stall, r.zbuffer.stall},
      {"texture_unit", "busy cycles", m.texture.busy, r.texture.busy},
      {"texture_unit", "stall cycles", m.texture.stall, r.texture.stall},
  };
  for (const auto& f : fields)
    if (f.expected != f.actual)
      return divergence(-1, f.unit, std::string("frame ") + f.name, to_string(f.expected), to_string(f.actual), -1);
  return {};
}

std::string write_replay(const std::string& prefix, const Profile& profile,
                         const std::vector<SnappedTriangle>& triangles, uint64_t seed) {
  const double scale = std::ldexp(1.0, profile.subpixel_bits);
  const double z_max = std::ldexp(1.0, profile.depth_plane_bits()) - 1;  // the depth plane's 2^N - 1
  std::ostringstream tri;
  tri << "# rastersim replay: snapped vertices written back as pixels (x / 2^S) and depths Z / (2^N - 1)\n";
  char buffer[64];
  for (const SnappedTriangle& t : triangles) {
    ScreenTriangle screen;
    for (int k = 0; k < 3; ++k) {
      // A vertex on the guard band's upper limit 2W (2H) comes from an input just below it: the
      // input must be inside [-W, 2W) and snap to it (floor(x 2^S + 1/2)).
      screen.v[k].x = (t.v[k].x - (t.v[k].x >= 2 * profile.width * scale ? 0.25 : 0.0)) / scale;
      screen.v[k].y = (t.v[k].y - (t.v[k].y >= 2 * profile.height * scale ? 0.25 : 0.0)) / scale;
      screen.v[k].z = t.v[k].z / z_max;
      screen.v[k].color = t.v[k].color;
    }
    // The written text must snap back to exactly these vertices.
    const SnappedTriangle back = snap(screen, profile);
    for (int k = 0; k < 3; ++k)
      if (back.v[k].x != t.v[k].x || back.v[k].y != t.v[k].y || back.v[k].z != t.v[k].z)
        throw std::logic_error("replay: a vertex does not snap back to itself");
    for (int k = 0; k < 3; ++k) {
      std::snprintf(buffer, sizeof buffer, "%.17g", screen.v[k].x);
      tri << (k ? " " : "") << buffer;
      std::snprintf(buffer, sizeof buffer, " %.17g", screen.v[k].y);
      tri << buffer;
      std::snprintf(buffer, sizeof buffer, " %.17g", screen.v[k].z);
      tri << buffer;
    }
    for (int k = 0; k < 3; ++k)
      tri << " " << int(t.v[k].color.r) << " " << int(t.v[k].color.g) << " " << int(t.v[k].color.b);
    tri << "\n";
  }
  for (const auto& [path, text] : {std::pair<std::string, std::string>{prefix + ".tri", tri.str()},
                                   std::pair<std::string, std::string>{prefix + ".json", profile_to_json(profile) + "\n"}}) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + path);
  }
  return "rastersim render " + prefix + ".tri --profile " + prefix + ".json --backend cosim --seed " +
         std::to_string(seed);
}

std::pair<int64_t, int64_t> divergence_window(const Divergence& divergence, const RtlResult& model) {
  constexpr int64_t kAround = 32;
  const int64_t last = std::max<int64_t>(0, model.stats.cycles - 1);
  const int64_t at = divergence.cycle >= 0 ? divergence.cycle : last;
  return {std::max<int64_t>(0, at - kAround), at + kAround};
}

CosimReport cosim(const Profile& profile, const std::vector<SnappedTriangle>& triangles, const RtlOptions& options,
                  const std::string& replay_prefix) {
  CosimReport report;
  if (options.model_beside) {
    // (An exception from the RTL's run waits for the model's thread: std::async's future joins.)
    std::future<RtlResult> model =
        std::async(std::launch::async, [&] { return run_model(profile, triangles, options.texture); });
    report.rtl = run_rtl(profile, triangles, options);
    report.model = model.get();
  } else {
    report.model = run_model(profile, triangles, options.texture);
    report.rtl = run_rtl(profile, triangles, options);
  }
  report.divergence = compare(report.model, report.rtl);
  report.passed = !report.divergence.found;
  if (!report.passed && !replay_prefix.empty()) {
    // A .tri replay carries no texture: a textured frame is rerun from its cosim command instead.
    const bool textured = profile.texture_unit && std::any_of(triangles.begin(), triangles.end(),
                                                              [](const SnappedTriangle& t) { return t.textured; });
    report.replay_command = textured ? "none (a textured frame: rerun its cosim command with --frame)"
                                     : write_replay(replay_prefix, profile, triangles, options.seed);
    // The frame again, with a waveform window around the divergence.
    RtlOptions again = options;
    std::tie(again.wave_from, again.wave_to) = divergence_window(report.divergence, report.model);
    again.wave_path = replay_prefix + ".fst";
    again.wave_vcd = false;
    again.wave_fst_scratch.clear();
    again.gtkwave_save_path = gtkwave_save_path(again.wave_path);
    again.wave_marker = report.divergence.cycle;
    again.wave_name.clear();
    run_rtl(profile, triangles, again);
    report.waveform = again.wave_path;
    report.gtkwave_save = again.gtkwave_save_path;
    report.wave_from = again.wave_from;
    report.wave_to = again.wave_to;
  }
  return report;
}

std::string CosimReport::message() const {
  if (passed) return "model and RTL agree";
  std::string text = divergence.sentence;
  if (!replay_command.empty()) text += "; replay: " + replay_command;
  if (!waveform.empty())
    text += "; waveform: " + waveform + " (frame cycles " + std::to_string(wave_from) + ".." +
            std::to_string(wave_to) + ", GTKWave: gtkwave " + gtkwave_save + ")";
  return text;
}

}  // namespace rastersim::rtl
