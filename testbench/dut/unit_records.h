// The unit-level verification interfaces (docs/verification.md "Checking one unit: cosim --unit"):
// the setup record a setup unit hands on and a walker takes (rastersim_unit_pkg::setup_record_t,
// testbench/dut/rastersim_unit_pkg.sv, declares the same fields in the same order), what a
// library built for one unit is given for a frame and what it reports back.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "model/pipeline.h"
#include "model/profile.h"
#include "model/triangle.h"
#include "model/triangle_setup.h"

namespace rastersim::dut {

enum class Unit { Setup, Walker, Zbuffer };
inline const char* to_string(Unit u) { return u == Unit::Setup ? "setup" : u == Unit::Walker ? "walker" : "zbuffer"; }

// One field of setup_record_t: its name (as in the package), width in the record, signedness, and
// how it is read from a SetupResult. Edge and plane fields are the model's registers sign-extended
// to 64 bits; pixel fields are unsigned.
struct UnitRecordField {
  std::string name;
  int bits;
  bool is_signed;
  std::string format;
  std::function<int64_t(const SetupResult&)> get;
  std::function<void(SetupResult&, int64_t)> set;
};

inline uint32_t packed_rgb(const Rgb& c) { return uint32_t(c.r) << 16 | uint32_t(c.g) << 8 | uint32_t(c.b); }

// The fields in declaration order: the first is the most significant in the packed struct.
inline const std::vector<UnitRecordField>& unit_record_fields() {
  static const std::vector<UnitRecordField> fields = [] {
    std::vector<UnitRecordField> f;
    auto add = [&f](std::string name, int bits, bool is_signed, std::string format,
                    std::function<int64_t(const SetupResult&)> get, std::function<void(SetupResult&, int64_t)> set) {
      f.push_back({std::move(name), bits, is_signed, std::move(format), std::move(get), std::move(set)});
    };
    add("x0", 16, false, "u16 pixels", [](const SetupResult& s) { return int64_t(s.x0); },
        [](SetupResult& s, int64_t v) { s.x0 = int(v); });
    add("x1", 16, false, "u16 pixels", [](const SetupResult& s) { return int64_t(s.x1); },
        [](SetupResult& s, int64_t v) { s.x1 = int(v); });
    add("y0", 16, false, "u16 pixels", [](const SetupResult& s) { return int64_t(s.y0); },
        [](SetupResult& s, int64_t v) { s.y0 = int(v); });
    add("y1", 16, false, "u16 pixels", [](const SetupResult& s) { return int64_t(s.y1); },
        [](SetupResult& s, int64_t v) { s.y1 = int(v); });
    for (int k = 0; k < 3; ++k) {
      const std::string e = "edge" + std::to_string(k) + "_";
      add(e + "start", 64, true, "s.2S, biased", [k](const SetupResult& s) { return int64_t(s.edge[k].start); },
          [k](SetupResult& s, int64_t v) { s.edge[k].start = v; });
      add(e + "step_x", 64, true, "s.2S", [k](const SetupResult& s) { return int64_t(s.edge[k].step_x); },
          [k](SetupResult& s, int64_t v) { s.edge[k].step_x = v; });
      add(e + "step_y", 64, true, "s.2S", [k](const SetupResult& s) { return int64_t(s.edge[k].step_y); },
          [k](SetupResult& s, int64_t v) { s.edge[k].step_y = v; });
      add(e + "owns_samples", 1, false, "1: the edge owns the samples on it (bias 0, the fill rule)",
          [k](const SetupResult& s) { return int64_t(s.edge[k].owns_samples); },
          [k](SetupResult& s, int64_t v) { s.edge[k].owns_samples = v != 0; });
    }
    auto plane = [&add](const std::string& name, const std::string& format, auto select) {
      add(name + "_start", 64, true, format, [select](const SetupResult& s) { return int64_t(select(s).start); },
          [select](SetupResult& s, int64_t v) { select(s).start = v; });
      add(name + "_step_x", 64, true, format, [select](const SetupResult& s) { return int64_t(select(s).step_x); },
          [select](SetupResult& s, int64_t v) { select(s).step_x = v; });
      add(name + "_step_y", 64, true, format, [select](const SetupResult& s) { return int64_t(select(s).step_y); },
          [select](SetupResult& s, int64_t v) { select(s).step_y = v; });
    };
    plane("depth", "s(N+1).F register", [](auto& s) -> auto& { return s.depth; });
    const char* const channels[] = {"red", "green", "blue"};
    for (int c = 0; c < 3; ++c) plane(channels[c], "s9.F register", [c](auto& s) -> auto& { return s.color[c]; });
    add("flat_rgb", 24, false, "{r, g, b} of vertex 0", [](const SetupResult& s) { return int64_t(packed_rgb(s.flat_color)); },
        [](SetupResult& s, int64_t v) { s.flat_color = Rgb{uint8_t(v >> 16), uint8_t(v >> 8), uint8_t(v)}; });
    return f;
  }();
  return fields;
}

inline int unit_record_bits() {
  int bits = 0;
  for (const UnitRecordField& f : unit_record_fields()) bits += f.bits;
  return bits;
}

// setup_record_t in 32-bit words, least significant first (a VlWide's order).
inline std::vector<uint32_t> pack_unit_record(const SetupResult& s) {
  std::vector<uint32_t> words(size_t((unit_record_bits() + 31) / 32), 0u);
  int lsb = unit_record_bits();
  for (const UnitRecordField& f : unit_record_fields()) {
    lsb -= f.bits;
    const uint64_t value = uint64_t(f.get(s));
    for (int i = 0; i < f.bits; ++i)
      if ((value >> i) & 1u) words[size_t((lsb + i) / 32)] |= 1u << ((lsb + i) % 32);
  }
  return words;
}

inline SetupResult unpack_unit_record(const uint32_t* words) {
  SetupResult s;
  s.status = SetupStatus::Drawn;
  int lsb = unit_record_bits();
  for (const UnitRecordField& f : unit_record_fields()) {
    lsb -= f.bits;
    uint64_t value = 0;
    for (int i = 0; i < f.bits; ++i) value |= uint64_t((words[(lsb + i) / 32] >> ((lsb + i) % 32)) & 1u) << i;
    if (f.is_signed && f.bits < 64 && ((value >> (f.bits - 1)) & 1u)) value |= ~uint64_t(0) << f.bits;
    f.set(s, int64_t(value));
  }
  return s;
}

// A frame as one unit sees it: setup takes `triangles`; the walker takes the drawn triangles'
// `records` (with `record_index`, their triangle) and each record's auxiliary word in rastersim's
// packed layout (testbench/setup_record.h RecordLayout); the z-buffer takes `fragments` in order.
struct UnitFrame {
  Unit unit = Unit::Setup;
  Profile profile;
  std::vector<SnappedTriangle> triangles;
  std::vector<SetupResult> records;
  std::vector<int64_t> record_index;
  std::vector<Fragment> fragments;
  uint64_t seed = 0;  // the walker's frag_ready pattern
};

// What a unit reported: setup its decisions and records in order; the walker its fragments (no
// depth-test result); the z-buffer one depth-test result per fragment, in order, and its final
// buffers.
struct UnitResult {
  std::vector<SetupStatus> decisions;
  std::vector<SetupResult> records;
  std::vector<Fragment> fragments;  // each with the cycle it was handed on (Fragment::cycle)
  std::vector<bool> results;
  std::vector<uint32_t> depth, color;
  // The cycle of each decision, record and result, from the first cycle after reset.
  std::vector<int64_t> decision_cycles, record_cycles, result_cycles;
  int64_t cycles = 0;
};

// The walker's frag_ready: low in this percentage of cycles (memory_stalls with the frame's seed).
constexpr int kWalkerReadyLowPercent = 25;

}  // namespace rastersim::dut
