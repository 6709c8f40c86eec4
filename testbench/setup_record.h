// The setup record's fields, defined once for C++: their order (rastersim_core's packed record and
// a vector package's setup.hex word), names, widths, signedness and meaning, the rec_* wire of
// rastersim_core that carries each (and the bit offset in it), and how each is read from and
// written into a SetupResult. The co-simulation's comparison, the RTL harness's record reader and
// the vector layout all walk this table.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "model/triangle_setup.h"
#include "model/widths.h"

namespace rastersim::rtl {

struct SetupRecordField {
  std::string name;     // as in setup.hex and the package README: "edge0_span_quot"
  int bits;
  bool is_signed;
  std::string meaning;
  std::string wire;     // rastersim_core wire: "rec_span_quot"
  int wire_lo;          // bit offset of the field in the wire; -1: the wire is this field alone
  std::function<int64_t(const SetupResult&)> get;
  std::function<void(SetupResult&, int64_t)> set;
};

inline uint32_t rgb_word(const Rgb& c) { return (uint32_t(c.r) << 16) | (uint32_t(c.g) << 8) | c.b; }

// The fields of a drawn triangle's record; the colour planes only with Gouraud shading (flat
// shading leaves them zero in the model and does not compare them).
inline std::vector<SetupRecordField> setup_record_fields(const Widths& w, bool gouraud) {
  std::vector<SetupRecordField> f;
  auto add = [&f](std::string name, int bits, bool is_signed, std::string meaning, std::string wire, int lo,
                  std::function<int64_t(const SetupResult&)> get, std::function<void(SetupResult&, int64_t)> set) {
    f.push_back({std::move(name), bits, is_signed, std::move(meaning), std::move(wire), lo, std::move(get),
                 std::move(set)});
  };
  add("x0", w.x_bits, false, "first candidate column (bounding box clipped to the screen)", "rec_x0", -1,
      [](const SetupResult& s) { return int64_t(s.x0); }, [](SetupResult& s, int64_t v) { s.x0 = int(v); });
  add("x1", w.x_bits, false, "last candidate column", "rec_x1", -1,
      [](const SetupResult& s) { return int64_t(s.x1); }, [](SetupResult& s, int64_t v) { s.x1 = int(v); });
  add("y0", w.y_bits, false, "first candidate row", "rec_y0", -1,
      [](const SetupResult& s) { return int64_t(s.y0); }, [](SetupResult& s, int64_t v) { s.y0 = int(v); });
  add("y1", w.y_bits, false, "last candidate row", "rec_y1", -1,
      [](const SetupResult& s) { return int64_t(s.y1); }, [](SetupResult& s, int64_t v) { s.y1 = int(v); });
  for (int k = 0; k < 3; ++k) {
    const std::string e = "edge" + std::to_string(k) + "_";
    // One edge field: its member, width, meaning and wire.
    auto edge = [&](const char* field, auto member, int bits, bool is_signed, const char* meaning, const char* wire) {
      add(e + field, bits, is_signed, meaning, wire, k * bits,
          [k, member](const SetupResult& s) { return int64_t(s.edge[k].*member); },
          [k, member](SetupResult& s, int64_t v) { s.edge[k].*member = v; });
    };
    edge("start", &EdgeSetup::start, w.edge_bits, true, "edge function at the first candidate's centre, s.2S, biased",
         "rec_edge_start");
    edge("step_x", &EdgeSetup::step_x, w.edge_step_x_bits, true, "edge change per pixel in x, s.2S", "rec_edge_step_x");
    edge("step_y", &EdgeSetup::step_y, w.edge_step_y_bits, true, "edge change per pixel in y, s.2S", "rec_edge_step_y");
    edge("span_quot", &EdgeSetup::span_quot, w.edge_bits, true, "span walker: floor(start / |step_x|)", "rec_span_quot");
    edge("span_rem", &EdgeSetup::span_rem, w.span_rem_bits, false, "span walker: start mod |step_x|", "rec_span_rem");
    edge("span_step_quot", &EdgeSetup::span_step_quot, w.edge_step_y_bits, true,
         "span walker: floor(step_y / |step_x|)", "rec_span_step_quot");
    edge("span_step_rem", &EdgeSetup::span_step_rem, w.span_rem_bits, false, "span walker: step_y mod |step_x|",
         "rec_span_step_rem");
  }
  // One plane's three fields; `plane` selects the plane in a record, `lo` is its offset in the wires.
  auto plane = [&](const std::string& name, auto select, int bits, const std::string& format, const std::string& wire,
                   int lo) {
    const std::string register_text = name + " plane register, " + format;
    add(name + "_start", bits, true, register_text + ", at the first candidate", wire + "_start", lo,
        [select](const SetupResult& s) { return int64_t(select(s).start); },
        [select](SetupResult& s, int64_t v) { select(s).start = v; });
    add(name + "_step_x", bits, true, register_text + ", per pixel in x", wire + "_step_x", lo,
        [select](const SetupResult& s) { return int64_t(select(s).step_x); },
        [select](SetupResult& s, int64_t v) { select(s).step_x = v; });
    add(name + "_step_y", bits, true, register_text + ", per pixel in y", wire + "_step_y", lo,
        [select](const SetupResult& s) { return int64_t(select(s).step_y); },
        [select](SetupResult& s, int64_t v) { select(s).step_y = v; });
  };
  plane("depth", [](auto& s) -> auto& { return s.depth; }, w.z_reg_bits, "s(N+1).F, wrapped", "rec_depth", -1);
  if (gouraud) {
    const char* const channels[] = {"red", "green", "blue"};
    for (int c = 0; c < 3; ++c)
      plane(channels[c], [c](auto& s) -> auto& { return s.color[c]; }, w.color_reg_bits, "s9.F", "rec_color",
            c * w.color_reg_bits);
  }
  add("flat_rgb", 24, false, "provoking (first) vertex colour 0xRRGGBB", "rec_flat_rgb", -1,
      [](const SetupResult& s) { return int64_t(rgb_word(s.flat_color)); },
      [](SetupResult& s, int64_t v) { s.flat_color = Rgb{uint8_t(v >> 16), uint8_t(v >> 8), uint8_t(v)}; });
  return f;
}

// rastersim_core's packed record (rs_rec_lsb in rtl/rastersim_widths.vh): the rec_* wires one after
// another from bit 0, in the order of their first field in setup_record_fields, each as wide as
// its fields reach. The walker part (rs_rec_walker_bits) is the wires up to rec_span_step_rem.
struct RecordWire {
  std::string name;  // "rec_edge_start"
  int lsb = 0;
  int bits = 0;
};

inline std::vector<RecordWire> record_wires(const Widths& w) {
  std::vector<RecordWire> wires;
  for (const SetupRecordField& f : setup_record_fields(w, true)) {
    auto it = std::find_if(wires.begin(), wires.end(), [&f](const RecordWire& r) { return r.name == f.wire; });
    if (it == wires.end()) it = wires.insert(wires.end(), RecordWire{f.wire, 0, 0});
    it->bits = std::max(it->bits, std::max(f.wire_lo, 0) + f.bits);
  }
  int lsb = 0;
  for (RecordWire& r : wires) r.lsb = lsb, lsb += r.bits;
  return wires;
}

inline int record_bits(const Widths& w) {
  const RecordWire last = record_wires(w).back();
  return last.lsb + last.bits;
}

// The packed record in 32-bit words, least significant first (a verilated VlWide's order), and
// back. `gouraud` false leaves the colour planes zero, as the model does with flat shading.
inline std::vector<uint32_t> pack_record(const SetupResult& s, const Widths& w) {
  const std::vector<RecordWire> wires = record_wires(w);
  std::vector<uint32_t> words(size_t((record_bits(w) + 31) / 32), 0u);
  for (const SetupRecordField& f : setup_record_fields(w, true)) {
    const auto wire = std::find_if(wires.begin(), wires.end(), [&f](const RecordWire& r) { return r.name == f.wire; });
    const int lsb = wire->lsb + std::max(f.wire_lo, 0);
    const uint64_t value = uint64_t(f.get(s));
    for (int i = 0; i < f.bits; ++i)
      if ((value >> i) & 1u) words[size_t((lsb + i) / 32)] |= 1u << ((lsb + i) % 32);
  }
  return words;
}

inline SetupResult unpack_record(const uint32_t* words, const Widths& w, bool gouraud) {
  const std::vector<RecordWire> wires = record_wires(w);
  SetupResult s;
  s.status = SetupStatus::Drawn;
  for (const SetupRecordField& f : setup_record_fields(w, gouraud)) {
    const auto wire = std::find_if(wires.begin(), wires.end(), [&f](const RecordWire& r) { return r.name == f.wire; });
    const int lsb = wire->lsb + std::max(f.wire_lo, 0);
    uint64_t value = 0;
    for (int i = 0; i < f.bits; ++i) value |= uint64_t((words[(lsb + i) / 32] >> ((lsb + i) % 32)) & 1u) << i;
    if (f.is_signed && f.bits < 64 && (value >> (f.bits - 1)) & 1u) value |= ~uint64_t(0) << f.bits;
    f.set(s, int64_t(value));
  }
  return s;
}

}  // namespace rastersim::rtl
