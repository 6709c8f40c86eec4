#include "testbench/functional_compare.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <unordered_map>

namespace rastersim::verify {
namespace {

const char* const kModeNames[] = {"cycle", "stream", "triangle", "frame"};

std::string pixel_text(const Fragment& f) {
  return "triangle " + std::to_string(f.tri) + " pixel (" + std::to_string(f.x) + ", " + std::to_string(f.y) + ")";
}

std::string hex_rgb(uint32_t rgb) {
  char text[8];
  std::snprintf(text, sizeof text, "%06x", rgb & 0xffffffu);
  return text;
}

uint32_t packed(const Rgb& c) { return uint32_t(c.r) << 16 | uint32_t(c.g) << 8 | uint32_t(c.b); }

// Collects mismatches in the order they are found, keeping the first `limit`.
class Findings {
 public:
  Findings(FunctionalReport& report, size_t limit) : report_(report), limit_(limit) {}
  void add(Mismatch m) {
    ++report_.mismatch_count;
    if (report_.mismatches.size() < limit_) report_.mismatches.push_back(std::move(m));
  }

 private:
  FunctionalReport& report_;
  size_t limit_;
};

// The signed difference of each 8-bit channel, design minus model.
std::array<int64_t, 3> channel_errors(uint32_t model, uint32_t design) {
  std::array<int64_t, 3> out{};
  for (int c = 0; c < 3; ++c) out[c] = int64_t((design >> (16 - 8 * c)) & 0xff) - int64_t((model >> (16 - 8 * c)) & 0xff);
  return out;
}

bool colour_within(const std::array<int64_t, 3>& errors, int64_t tolerance) {
  return std::all_of(errors.begin(), errors.end(), [&](int64_t e) { return std::llabs(e) <= tolerance; });
}

// A fragment's attributes, the same pixel of the same triangle on both sides.
void compare_attributes(const Fragment& m, const Fragment& d, const Tolerance& tolerance, FunctionalReport& report,
                        Findings& findings) {
  ++report.fragments_compared;
  const int64_t depth_error = int64_t(d.z) - int64_t(m.z);
  report.depth_error.add(depth_error);
  if (std::llabs(depth_error) > tolerance.depth)
    findings.add({m.tri, m.x, m.y, "z", std::to_string(m.z), std::to_string(d.z)});
  const auto errors = channel_errors(packed(m.color), packed(d.color));
  for (int64_t e : errors) report.color_error.add(e);
  if (!colour_within(errors, tolerance.color))
    findings.add({m.tri, m.x, m.y, "color", hex_rgb(packed(m.color)), hex_rgb(packed(d.color))});
  // The depth test's result follows from the depth: compared where the depths agree.
  if (depth_error == 0 && m.pass != d.pass)
    findings.add({m.tri, m.x, m.y, "pass", m.pass ? "1" : "0", d.pass ? "1" : "0"});
}

void compare_decisions(const rtl::RtlResult& model, const rtl::RtlResult& design, Findings& findings) {
  const size_t n = std::min(model.triangles.size(), design.triangles.size());
  for (size_t i = 0; i < n; ++i) {
    const TriangleRecord& m = model.triangles[i];
    const TriangleRecord& d = design.triangles[i];
    if (m.index != d.index) findings.add({m.index, -1, -1, "decision order", "triangle " + std::to_string(m.index),
                                          "triangle " + std::to_string(d.index)});
    else if (m.status != d.status) findings.add({m.index, -1, -1, "status", to_string(m.status), to_string(d.status)});
  }
  if (model.triangles.size() > n)
    findings.add({model.triangles[n].index, -1, -1, "missing decision", to_string(model.triangles[n].status), "none"});
  else if (design.triangles.size() > n)
    findings.add({design.triangles[n].index, -1, -1, "extra decision", "none", to_string(design.triangles[n].status)});
}

void compare_stream(const rtl::RtlResult& model, const rtl::RtlResult& design, const Tolerance& tolerance,
                    FunctionalReport& report, Findings& findings) {
  const size_t n = std::min(model.fragments.size(), design.fragments.size());
  for (size_t i = 0; i < n; ++i) {
    const Fragment& m = model.fragments[i];
    const Fragment& d = design.fragments[i];
    if (m.tri != d.tri || m.x != d.x || m.y != d.y) {
      // Every later fragment is out of step: one mismatch says it.
      findings.add({m.tri, m.x, m.y, "fragment " + std::to_string(i), pixel_text(m), pixel_text(d)});
      return;
    }
    compare_attributes(m, d, tolerance, report, findings);
  }
  if (model.fragments.size() > n)
    findings.add({model.fragments[n].tri, model.fragments[n].x, model.fragments[n].y, "missing fragment",
                  pixel_text(model.fragments[n]), "the design's stream ended"});
  else if (design.fragments.size() > n)
    findings.add({design.fragments[n].tri, design.fragments[n].x, design.fragments[n].y, "extra fragment",
                  "the model's stream ended", pixel_text(design.fragments[n])});
}

// Cycle mode through the verification interface: each decision and retirement at the model's
// cycle, the frame's end too (the fields themselves as stream mode compares them, exactly).
void compare_interface_cycles(const rtl::RtlResult& model, const rtl::RtlResult& design, Findings& findings) {
  const auto cycle_text = [](int64_t c) { return "cycle " + std::to_string(c); };
  for (size_t i = 0; i < std::min(model.triangles.size(), design.triangles.size()); ++i) {
    const TriangleRecord& m = model.triangles[i];
    const TriangleRecord& d = design.triangles[i];
    if (m.index == d.index && m.setup_decided != d.setup_decided) {
      findings.add({m.index, -1, -1, "decision cycle", cycle_text(m.setup_decided), cycle_text(d.setup_decided)});
      return;
    }
  }
  for (size_t i = 0; i < std::min(model.fragments.size(), design.fragments.size()); ++i) {
    const Fragment& m = model.fragments[i];
    const Fragment& d = design.fragments[i];
    if (m.tri != d.tri || m.x != d.x || m.y != d.y) return;  // stream mode's finding says it
    if (m.tested != d.tested) {
      findings.add({m.tri, m.x, m.y, "retirement cycle", cycle_text(m.tested), cycle_text(d.tested)});
      return;
    }
  }
  if (model.stats.cycles != design.stats.cycles)
    findings.add({-1, -1, -1, "frame_done cycle", cycle_text(model.stats.cycles), cycle_text(design.stats.cycles)});
}

// Fragments grouped by triangle, in first-appearance order.
struct Groups {
  std::vector<int64_t> order;
  std::unordered_map<int64_t, std::vector<const Fragment*>> of;
};
Groups group(const std::vector<Fragment>& fragments) {
  Groups g;
  for (const Fragment& f : fragments) {
    auto& list = g.of[f.tri];
    if (list.empty()) g.order.push_back(f.tri);
    list.push_back(&f);
  }
  return g;
}

void compare_triangles(const rtl::RtlResult& model, const rtl::RtlResult& design, const Tolerance& tolerance,
                       FunctionalReport& report, Findings& findings) {
  const Groups m = group(model.fragments), d = group(design.fragments);
  // Triangles in order, each triangle's fragments together.
  int64_t previous = -1;
  for (size_t i = 0; i < design.fragments.size(); ++i) {
    const Fragment& f = design.fragments[i];
    if (i > 0 && f.tri == design.fragments[i - 1].tri) continue;
    if (f.tri <= previous) {
      findings.add({f.tri, f.x, f.y, "triangle order",
                    "triangle " + std::to_string(f.tri) + "'s fragments together, after those of triangle " +
                        std::to_string(previous) + " and before later triangles'",
                    "fragment " + std::to_string(i) + " of triangle " + std::to_string(f.tri) + " follows triangle " +
                        std::to_string(design.fragments[i - 1].tri) + "'s"});
      break;
    }
    previous = f.tri;
  }
  std::vector<int64_t> triangles = m.order;
  for (int64_t t : d.order)
    if (!m.of.count(t)) triangles.push_back(t);
  std::sort(triangles.begin(), triangles.end());
  for (int64_t t : triangles) {
    std::unordered_map<int64_t, const Fragment*> at;  // the design's, by pixel
    if (auto it = d.of.find(t); it != d.of.end())
      for (const Fragment* f : it->second) at[int64_t(f->y) << 32 | uint32_t(f->x)] = f;
    if (auto it = m.of.find(t); it != m.of.end())
      for (const Fragment* f : it->second) {
        auto found = at.find(int64_t(f->y) << 32 | uint32_t(f->x));
        if (found == at.end()) {
          findings.add({t, f->x, f->y, "missing fragment", "covered", "not covered"});
          continue;
        }
        compare_attributes(*f, *found->second, tolerance, report, findings);
        at.erase(found);
      }
    if (auto it = d.of.find(t); it != d.of.end())
      for (const Fragment* f : it->second)
        if (at.count(int64_t(f->y) << 32 | uint32_t(f->x))) findings.add({t, f->x, f->y, "extra fragment", "not covered", "covered"});
  }
}

void compare_buffers(const Profile& profile, const rtl::RtlResult& model, const rtl::RtlResult& design,
                     const Tolerance& tolerance, bool count_errors, FunctionalReport& report, Findings& findings) {
  for (const auto* words : {&design.depth, &design.color})
    if (words->empty()) return;  // not read back
  if (design.depth.size() != model.depth.size() || design.color.size() != model.color.size()) {
    findings.add({-1, -1, -1, "buffer size", std::to_string(model.depth.size()) + " words",
                  std::to_string(design.depth.size()) + " words"});
    return;
  }
  for (size_t i = 0; i < model.depth.size(); ++i) {
    ++report.words_compared;
    const int x = int(i % size_t(profile.width)), y = int(i / size_t(profile.width));
    const int64_t depth_error = int64_t(design.depth[i]) - int64_t(model.depth[i]);
    const auto errors = channel_errors(model.color[i], design.color[i]);
    if (count_errors) {
      report.depth_error.add(depth_error);
      for (int64_t e : errors) report.color_error.add(e);
    }
    if (std::llabs(depth_error) > tolerance.depth)
      findings.add({-1, x, y, "depth word", std::to_string(model.depth[i]), std::to_string(design.depth[i])});
    if (!colour_within(errors, tolerance.color))
      findings.add({-1, x, y, "colour word", hex_rgb(model.color[i]), hex_rgb(design.color[i])});
  }
}

}  // namespace

const char* to_string(CompareMode mode) { return kModeNames[int(mode)]; }

int64_t design_cycle(const Mismatch& m, const rtl::RtlResult& design) {
  if (m.triangle >= 0 && m.x >= 0)
    for (const Fragment& f : design.fragments)
      if (f.tri == m.triangle && f.x == m.x && f.y == m.y) return f.tested;
  if (m.triangle >= 0)
    for (const TriangleRecord& r : design.triangles)
      if (r.index == m.triangle) return r.setup_decided;
  return std::max<int64_t>(0, design.stats.cycles);
}

std::optional<CompareMode> parse_compare_mode(const std::string& text) {
  for (int i = 0; i < 4; ++i)
    if (text == kModeNames[i]) return CompareMode(i);
  return std::nullopt;
}

std::string parse_tolerance(const std::string& text, Tolerance& out) {
  Tolerance t;
  std::istringstream items(text);
  for (std::string item; std::getline(items, item, ',');) {
    const size_t eq = item.find('=');
    const std::string name = item.substr(0, eq);
    const std::string value = eq == std::string::npos ? "" : item.substr(eq + 1);
    char* end = nullptr;
    const long long n = value.empty() ? -1 : std::strtoll(value.c_str(), &end, 10);
    if (value.empty() || *end != '\0' || n < 0 || n > (1ll << 32))
      return "--tolerance: '" + item + "' is not NAME=N with N a non-negative integer (depth=N,color=M)";
    if (name == "depth") t.depth = n;
    else if (name == "color" || name == "colour") t.color = n;
    else return "--tolerance: '" + name + "' is not depth or color";
  }
  out = t;
  return "";
}

int64_t ErrorDistribution::samples() const {
  int64_t n = 0;
  for (const auto& [error, count] : counts) n += count;
  return n;
}

int64_t ErrorDistribution::max_abs() const {
  int64_t m = 0;
  for (const auto& [error, count] : counts) m = std::max<int64_t>(m, std::llabs(error));
  return m;
}

std::string ErrorDistribution::summary() const {
  std::vector<std::pair<int64_t, int64_t>> by_count(counts.begin(), counts.end());
  std::stable_sort(by_count.begin(), by_count.end(), [](auto a, auto b) { return a.second > b.second; });
  std::string out = std::to_string(samples()) + " samples";
  if (counts.empty()) return out;
  out += ", error " + std::to_string(counts.begin()->first) + ".." + std::to_string(counts.rbegin()->first);
  for (size_t i = 0; i < by_count.size() && i < 5; ++i)
    out += (i ? ", " : ": ") + std::to_string(by_count[i].first) + " x" + std::to_string(by_count[i].second);
  return out;
}

std::string Mismatch::sentence() const {
  std::string where = triangle >= 0 ? "triangle " + std::to_string(triangle) : "the final buffers";
  if (x >= 0) where += ", pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
  return where + ": " + field + ": expected " + expected + ", the design gave " + actual;
}

std::string FunctionalReport::summary() const {
  if (passed())
    return std::string(to_string(mode)) + ": " + std::to_string(fragments_compared) + " fragments and " +
           std::to_string(words_compared) + " buffer words agree";
  return std::string(to_string(mode)) + ": " + std::to_string(mismatch_count) + " mismatches; the first: " +
         mismatches.front().sentence();
}

FunctionalReport compare(const Profile& profile, const rtl::RtlResult& model, const rtl::RtlResult& design,
                         CompareMode mode, const Tolerance& tolerance, size_t max_mismatches) {
  FunctionalReport report;
  report.mode = mode;
  Findings findings(report, std::max<size_t>(1, max_mismatches));
  switch (mode) {
    case CompareMode::Cycle: {
      if (design.interface_only) {  // a design behind the verification interface: its events' cycles
        compare_decisions(model, design, findings);
        compare_stream(model, design, Tolerance{}, report, findings);
        compare_interface_cycles(model, design, findings);
        break;
      }
      const rtl::Divergence d = rtl::compare(model, design);
      report.fragments_compared = int64_t(model.fragments.size());
      report.words_compared = int64_t(model.depth.size());
      if (d.found) findings.add({d.triangle, -1, -1, d.unit + " " + d.field, d.expected, d.actual});
      return report;
    }
    case CompareMode::Stream:
      compare_decisions(model, design, findings);
      compare_stream(model, design, tolerance, report, findings);
      break;
    case CompareMode::Triangle:
      compare_decisions(model, design, findings);
      compare_triangles(model, design, tolerance, report, findings);
      break;
    case CompareMode::Frame:
      break;
  }
  compare_buffers(profile, model, design, tolerance, mode == CompareMode::Frame, report, findings);
  return report;
}

}  // namespace rastersim::verify
