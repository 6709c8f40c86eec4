#include "testbench/waveform.h"

#include <gtkwave/fstapi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <stdexcept>
#include <vector>

namespace rastersim::rtl {
namespace {

struct FstReader {
  explicit FstReader(const std::string& path) : ctx(fstReaderOpen(path.c_str())) {
    if (!ctx) throw std::runtime_error("cannot read the waveform " + path);
  }
  ~FstReader() { fstReaderClose(ctx); }
  FstReader(const FstReader&) = delete;
  FstReader& operator=(const FstReader&) = delete;
  void* ctx;
};

// "name [9:0]" (as Verilator declares a vector) to GTKWave's "name[9:0]"; a vector without a
// range gets one.
std::string gtkwave_name(std::string name, uint32_t length) {
  const size_t space = name.find(" [");
  if (space != std::string::npos) return name.erase(space, 1);
  if (length > 1 && name.find('[') == std::string::npos) name += "[" + std::to_string(length - 1) + ":0]";
  return name;
}

// The save file's view lines: the first time shown, the window's size, the zoom that fits
// [start, end] into about 1000 pixels (GTKWave shows 2^zoom pixels per time unit), the primary
// marker and the named markers.
void write_view(std::ostream& out, const WaveView& view) {
  constexpr int kNamedMarkers = 26;  // GTKWave's A..Z
  out << "[timestart] " << std::max<int64_t>(0, view.start) << "\n"
      << "[size] 1400 900\n";
  const double zoom = view.end > view.start ? std::floor(std::log2(1000.0 / double(view.end - view.start + 1))) : -6.0;
  char zoom_text[32];
  std::snprintf(zoom_text, sizeof zoom_text, "%f", zoom);
  out << "*" << zoom_text << " " << view.primary_marker;
  for (int i = 0; i < kNamedMarkers; ++i) out << " " << (size_t(i) < view.markers.size() ? view.markers[size_t(i)].second : -1);
  out << "\n";
  for (size_t i = 0; i < view.markers.size() && i < size_t(kNamedMarkers); ++i)
    out << "[markername] " << char('A' + i) << view.markers[i].first << "\n";
}

}  // namespace

void fst_to_vcd(const std::string& fst_path, const std::string& vcd_path) {
  FstReader reader(fst_path);
  std::unique_ptr<FILE, int (*)(FILE*)> out(std::fopen(vcd_path.c_str(), "wb"), &std::fclose);
  if (!out) throw std::runtime_error("cannot write the waveform " + vcd_path);
  // The header and the value changes, as gtkwave's fst2vcd writes them.
  fstReaderProcessHier(reader.ctx, out.get());
  fstReaderSetFacProcessMaskAll(reader.ctx);
  fstReaderIterBlocks(reader.ctx, nullptr, nullptr, out.get());
  if (std::fflush(out.get()) != 0 || std::ferror(out.get())) throw std::runtime_error("cannot write the waveform " + vcd_path);
}

void write_design_gtkwave_save(const std::string& fst_path, const std::string& dumpfile, const std::string& save_path,
                               const WaveView& view) {
  FstReader reader(fst_path);
  // The outermost scope holds the top module's ports (Verilator's TOP).
  int depth = 0;
  std::string top;
  std::vector<std::string> ports;
  while (const fstHier* h = fstReaderIterateHier(reader.ctx)) {
    if (h->htyp == FST_HT_SCOPE && ++depth == 1) top.assign(h->u.scope.name, h->u.scope.name_length);
    else if (h->htyp == FST_HT_UPSCOPE) --depth;
    else if (h->htyp == FST_HT_VAR && depth == 1)
      ports.push_back(top + "." + gtkwave_name(std::string(h->u.var.name, h->u.var.name_length), h->u.var.length));
  }
  std::ofstream out(save_path, std::ios::binary);
  out << "[*] rastersim: a design behind the verification interface, the mismatch at the marker "
         "(docs/verification.md)\n"
      << "[dumpfile] \"" << std::filesystem::absolute(dumpfile).string() << "\"\n";
  write_view(out, view);
  out << "@800200\n-interface\n";
  for (const std::string& p : ports) out << (p.back() == ']' ? "@24\n" : "@28\n") << p << "\n";
  out << "@1000200\n-interface\n";
  if (!out.flush()) throw std::runtime_error("cannot write " + save_path);
}

void write_gtkwave_save(const std::string& fst_path, const std::string& dumpfile, const std::string& save_path,
                        const WaveView& view) {
  FstReader reader(fst_path);
  // Signals by scope, in declaration order; ports only for the units.
  std::vector<std::string> scope;
  std::map<std::string, std::vector<std::pair<std::string, bool>>> signals;  // scope -> (name, is a port)
  std::map<std::string, uint32_t> lengths;
  while (const fstHier* h = fstReaderIterateHier(reader.ctx)) {
    switch (h->htyp) {
      case FST_HT_SCOPE: scope.emplace_back(h->u.scope.name, h->u.scope.name_length); break;
      case FST_HT_UPSCOPE: if (!scope.empty()) scope.pop_back(); break;
      case FST_HT_VAR: {
        std::string path;
        for (const std::string& s : scope) path += (path.empty() ? "" : ".") + s;
        const std::string name = gtkwave_name(std::string(h->u.var.name, h->u.var.name_length), h->u.var.length);
        const bool port = h->u.var.direction != FST_VD_IMPLICIT;
        signals[path].emplace_back(name, port);
        lengths[path + "." + name] = h->u.var.length;
        break;
      }
      default: break;
    }
  }
  // rastersim_top's scope: the one holding the debug monitor (the model's name, then the module's).
  std::string top;
  for (const auto& [path, vars] : signals)
    if (path.size() > 6 && path.compare(path.size() - 6, 6, ".debug") == 0) top = path.substr(0, path.size() - 6);
  if (top.empty()) throw std::runtime_error("the waveform " + fst_path + " has no debug monitor (rastersim_debug)");
  // Ports when the dump marks them; otherwise every signal of the unit's own scope.
  bool directions = false;
  for (const auto& [path, vars] : signals)
    for (const auto& [name, port] : vars) directions |= port;
  std::ofstream out(save_path, std::ios::binary);
  out << "[*] rastersim: the waveform's units, grouped (docs/debugging.md)\n"
      << "[dumpfile] \"" << std::filesystem::absolute(dumpfile).string() << "\"\n";
  write_view(out, view);
  auto group = [&](const std::string& title, const std::vector<std::string>& names) {
    if (names.empty()) return;
    out << "@800200\n-" << title << "\n";
    for (const std::string& n : names) out << (lengths[n] > 1 ? "@24\n" : "@28\n") << n << "\n";
    out << "@1000200\n-" << title << "\n";
  };
  std::vector<std::string> frame;
  for (const auto& [name, port] : signals[top])
    for (const char* wanted : {"clk", "rst", "frame_ready", "cmd_valid", "cmd_ready"})
      if (name == wanted) frame.push_back(top + "." + name);
  for (const auto& [name, port] : signals[top + ".debug"])
    for (const char* wanted : {"frame_cycle[31:0]", "setup_triangle[31:0]", "walker_triangle[31:0]", "zbuffer_triangle[31:0]"})
      if (name == wanted) frame.push_back(top + ".debug." + name);
  group("frame", frame);
  // The units in pipeline order, each with its ports.
  const std::pair<const char*, const char*> units[] = {{"core.setup", "triangle_setup"},   {"core.record_fifo", "setup_fifo"},
                                                       {"core.walker", "scanline_walker"}, {"core.adders", "z_adder"},
                                                       {"core.zbuf", "zbuffer"},           {"zmem", "zbuffer_memory"}};
  for (const auto& [instance, unit] : units) {
    std::vector<std::string> ports;
    for (const auto& [name, port] : signals[top + "." + instance])
      if (port || !directions) ports.push_back(top + "." + instance + "." + name);
    group(unit, ports);
  }
  if (!out.flush()) throw std::runtime_error("cannot write " + save_path);
}

}  // namespace rastersim::rtl
