#include "testbench/unit_compare.h"

#include <algorithm>

#include "model/triangle_setup.h"

namespace rastersim::verify {
namespace {

// Collects mismatches in the order found, keeping the first `limit`.
struct Collect {
  FunctionalReport& report;
  size_t limit;
  void operator()(Mismatch m) {
    ++report.mismatch_count;
    if (report.mismatches.size() < limit) report.mismatches.push_back(std::move(m));
  }
};

// The model's setup of every triangle: a setup unit computes the colour planes whatever the shading.
std::vector<SetupResult> model_setups(const Profile& profile, const std::vector<SnappedTriangle>& triangles) {
  Profile p = profile;
  p.shading = Shading::Gouraud;
  const TriangleSetup setup(p);
  std::vector<SetupResult> out;
  for (const SnappedTriangle& t : triangles) out.push_back(setup.run(t));
  return out;
}

void compare_setup(const dut::UnitFrame& frame, const dut::UnitResult& design, FunctionalReport& report,
                   Collect& add) {
  const std::vector<SetupResult> want = model_setups(frame.profile, frame.triangles);
  const size_t n = std::min(want.size(), design.decisions.size());
  for (size_t i = 0; i < n; ++i)
    if (want[i].status != design.decisions[i])
      add({int64_t(i), -1, -1, "status", to_string(want[i].status), to_string(design.decisions[i])});
  if (want.size() > n) add({int64_t(n), -1, -1, "missing decision", to_string(want[n].status), "none"});
  else if (design.decisions.size() > n) add({int64_t(n), -1, -1, "extra decision", "none", to_string(design.decisions[n])});
  // The k-th record is the k-th drawn triangle's.
  std::vector<size_t> drawn;
  for (size_t i = 0; i < want.size(); ++i)
    if (want[i].status == SetupStatus::Drawn) drawn.push_back(i);
  const size_t m = std::min(drawn.size(), design.records.size());
  for (size_t k = 0; k < m; ++k) {
    ++report.fragments_compared;
    for (const dut::UnitRecordField& f : dut::unit_record_fields())
      if (f.get(want[drawn[k]]) != f.get(design.records[k]))
        add({int64_t(drawn[k]), -1, -1, f.name, std::to_string(f.get(want[drawn[k]])),
             std::to_string(f.get(design.records[k]))});
  }
  if (drawn.size() > m) add({int64_t(drawn[m]), -1, -1, "missing record", "its record", "none"});
  else if (design.records.size() > m)
    add({-1, -1, -1, "extra record", std::to_string(drawn.size()) + " records (one per drawn triangle)",
         "record " + std::to_string(m) + " too"});
}

}  // namespace

std::string unit_mode_error(dut::Unit unit, CompareMode mode) {
  const bool ok = mode == CompareMode::Stream || (unit == dut::Unit::Walker && mode == CompareMode::Triangle) ||
                  (unit == dut::Unit::Zbuffer && mode == CompareMode::Frame);
  if (ok) return "";
  const char* modes = unit == dut::Unit::Setup    ? "stream (records in order)"
                      : unit == dut::Unit::Walker ? "stream or triangle"
                                                  : "stream (every result and the buffers) or frame (the buffers)";
  return std::string("--unit ") + dut::to_string(unit) + " compares with " + modes + ", not --compare " +
         to_string(mode);
}

dut::UnitFrame unit_frame(dut::Unit unit, const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                          const rtl::RtlResult& model, uint64_t seed) {
  dut::UnitFrame f;
  f.unit = unit;
  f.profile = profile;
  f.seed = seed;
  switch (unit) {
    case dut::Unit::Setup:
      f.triangles = triangles;
      break;
    case dut::Unit::Walker: {
      const TriangleSetup setup(profile);
      for (size_t i = 0; i < triangles.size(); ++i) {
        SetupResult r = setup.run(triangles[i]);
        if (r.status != SetupStatus::Drawn) continue;
        f.records.push_back(r);
        f.record_index.push_back(int64_t(i));
      }
      break;
    }
    case dut::Unit::Zbuffer:
      f.fragments = model.fragments;
      break;
  }
  return f;
}

FunctionalReport compare_unit(const dut::UnitFrame& frame, const rtl::RtlResult& model, const dut::UnitResult& design,
                              CompareMode mode, const Tolerance& tolerance, size_t max_mismatches) {
  FunctionalReport report;
  report.mode = mode;
  Collect add{report, std::max<size_t>(1, max_mismatches)};
  switch (frame.unit) {
    case dut::Unit::Setup:
      compare_setup(frame, design, report, add);
      break;
    case dut::Unit::Walker: {
      // The fragments alone: no decisions, no depth-test result, no buffers.
      rtl::RtlResult want, given;
      want.fragments = model.fragments;
      given.fragments = design.fragments;
      for (auto* list : {&want.fragments, &given.fragments})
        for (Fragment& f : *list) f.pass = false;
      report = compare(frame.profile, want, given, mode, tolerance, max_mismatches);
      break;
    }
    case dut::Unit::Zbuffer: {
      if (mode != CompareMode::Frame) {
        const size_t n = std::min(model.fragments.size(), design.results.size());
        for (size_t i = 0; i < n; ++i) {
          const Fragment& f = model.fragments[i];
          ++report.fragments_compared;
          if (f.pass != design.results[i]) add({f.tri, f.x, f.y, "pass", f.pass ? "1" : "0", design.results[i] ? "1" : "0"});
        }
        if (model.fragments.size() > n) {
          const Fragment& f = model.fragments[n];
          add({f.tri, f.x, f.y, "missing result", "result of fragment " + std::to_string(n), "none"});
        } else if (design.results.size() > n) {
          add({-1, -1, -1, "extra result", std::to_string(n) + " results (one per fragment)",
               "result " + std::to_string(n) + " too"});
        }
      }
      rtl::RtlResult given;
      given.depth = design.depth;
      given.color = design.color;
      const FunctionalReport buffers = compare(frame.profile, model, given, CompareMode::Frame, tolerance, max_mismatches);
      report.words_compared = buffers.words_compared;
      if (mode == CompareMode::Frame) report.depth_error = buffers.depth_error, report.color_error = buffers.color_error;
      for (const Mismatch& m : buffers.mismatches) add(m);
      report.mismatch_count += buffers.mismatch_count - int64_t(buffers.mismatches.size());
      break;
    }
  }
  return report;
}

int64_t unit_design_cycle(const Mismatch& m, const dut::UnitFrame& frame, const dut::UnitResult& design) {
  const auto at = [](const std::vector<int64_t>& cycles, size_t k) -> int64_t { return k < cycles.size() ? cycles[k] : -1; };
  int64_t cycle = -1;
  if (m.triangle >= 0 && m.x >= 0) {
    for (const Fragment& f : design.fragments)  // the walker's
      if (f.tri == m.triangle && f.x == m.x && f.y == m.y) return f.cycle;
    for (size_t k = 0; k < frame.fragments.size(); ++k) {  // the z-buffer's result of that fragment
      const Fragment& f = frame.fragments[k];
      if (f.tri == m.triangle && f.x == m.x && f.y == m.y) cycle = at(design.result_cycles, k);
      if (cycle >= 0) return cycle;
    }
  }
  if (m.triangle >= 0) {
    if (m.field == "status" || m.field == "missing decision" || m.field == "extra decision")
      cycle = at(design.decision_cycles, size_t(m.triangle));
    for (size_t k = 0; cycle < 0 && k < frame.record_index.size(); ++k)  // a record's field
      if (frame.record_index[k] == m.triangle) cycle = at(design.record_cycles, k);
    for (const Fragment& f : design.fragments)  // the walker's first fragment of the triangle
      if (cycle < 0 && f.tri == m.triangle) cycle = f.cycle;
  }
  return cycle >= 0 ? cycle : design.cycles;
}

}  // namespace rastersim::verify
