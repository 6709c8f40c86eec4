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
  // The planes along the left edges: rec_left_start and rec_left_step hold slot j at
  // [j * (z_reg_bits + 3 color_reg_bits)], its depth first, then r, g, b.
  const int slot_bits = w.z_reg_bits + 3 * w.color_reg_bits;
  for (int j = 0; j < kLeftEdgeSlots; ++j) {
    const std::string slot = "left" + std::to_string(j) + "_";
    auto along = [&](const std::string& name, auto select, int bits, int lo) {
      const std::string edge_text = "left-edge slot " + std::to_string(j) + ": the " + name + " plane";
      add(slot + name + "_start", bits, true, edge_text + " at the edge's span start on the first row", "rec_left_start",
          j * slot_bits + lo, [j, select](const SetupResult& s) { return int64_t(select(s.left[j]).start); },
          [j, select](SetupResult& s, int64_t v) { select(s.left[j]).start = v; });
      add(slot + name + "_step", bits, true, edge_text + "'s change per row without the DDA carry", "rec_left_step",
          j * slot_bits + lo, [j, select](const SetupResult& s) { return int64_t(select(s.left[j]).step); },
          [j, select](SetupResult& s, int64_t v) { select(s.left[j]).step = v; });
    };
    along("depth", [](auto& l) -> auto& { return l.depth; }, w.z_reg_bits, 0);
    if (gouraud) {
      const char* const channels[] = {"red", "green", "blue"};
      for (int c = 0; c < 3; ++c)
        along(channels[c], [c](auto& l) -> auto& { return l.color[c]; }, w.color_reg_bits,
              w.z_reg_bits + c * w.color_reg_bits);
    }
  }
  return f;
}

// rastersim_core's packed record (rs_rec_lsb in rtl/rastersim_widths.vh): the rec_* wires one after
// another from bit 0, in the order of their first field in setup_record_fields, each as wide as
// its fields reach; a field sits at its wire's position plus its wire_lo. Built once per profile,
// then packs and unpacks records in 32-bit words, least significant first (a VlWide's order).
class RecordLayout {
 public:
  // `gouraud` false leaves the colour planes out of unpack(), as the model leaves them zero.
  RecordLayout(const Widths& w, bool gouraud) : fields_(setup_record_fields(w, gouraud)) {
    std::vector<std::pair<std::string, int>> wires;  // name, width
    for (const SetupRecordField& f : setup_record_fields(w, true)) {
      auto it = std::find_if(wires.begin(), wires.end(), [&f](const auto& r) { return r.first == f.wire; });
      if (it == wires.end()) it = wires.insert(wires.end(), {f.wire, 0});
      it->second = std::max(it->second, std::max(f.wire_lo, 0) + f.bits);
    }
    for (const SetupRecordField& f : fields_) {
      int lsb = 0;
      for (const auto& [name, width] : wires) {
        if (name == f.wire) break;
        lsb += width;
      }
      lsb_.push_back(lsb + std::max(f.wire_lo, 0));
    }
    for (const auto& wire : wires) bits_ += wire.second;
  }

  int bits() const { return bits_; }

  std::vector<uint32_t> pack(const SetupResult& s) const {
    std::vector<uint32_t> words(size_t((bits_ + 31) / 32), 0u);
    for (size_t k = 0; k < fields_.size(); ++k) {
      const uint64_t value = uint64_t(fields_[k].get(s));
      for (int i = 0; i < fields_[k].bits; ++i)
        if ((value >> i) & 1u) words[size_t((lsb_[k] + i) / 32)] |= 1u << ((lsb_[k] + i) % 32);
    }
    return words;
  }

  SetupResult unpack(const uint32_t* words) const {
    SetupResult s;
    s.status = SetupStatus::Drawn;
    for (size_t k = 0; k < fields_.size(); ++k) {
      const SetupRecordField& f = fields_[k];
      uint64_t value = 0;
      for (int i = 0; i < f.bits; ++i) value |= uint64_t((words[(lsb_[k] + i) / 32] >> ((lsb_[k] + i) % 32)) & 1u) << i;
      if (f.is_signed && f.bits < 64 && (value >> (f.bits - 1)) & 1u) value |= ~uint64_t(0) << f.bits;
      f.set(s, int64_t(value));
    }
    return s;
  }

 private:
  std::vector<SetupRecordField> fields_;
  std::vector<int> lsb_;  // per field of fields_
  int bits_ = 0;
};

// The texture record beside the setup record (triangle_setup's out_texture with TEXTURE = 1;
// rs_texture_record_bits in rtl/rastersim_widths.vh), in 32-bit words, least significant first:
// bit 0 the textured flag, then 21 registers of texture_reg_bits (s9.(P+Ft), two's complement),
// register 3 g + c at bit 1 + (3 g + c) texture_reg_bits, c = 0 S, 1 T, 2 Q, and the groups g:
// 0 start, 1 step x, 2 step y, 3 left-edge slot 0 start, 4 its step, 5 slot 1 start, 6 its step.
// An untextured triangle's record is all zeros (the model's planes are zero, textured false).
constexpr int kTextureRecordGroups = 7;
inline int texture_record_bits(const Widths& w) { return 1 + 3 * kTextureRecordGroups * w.texture_reg_bits; }

inline bool texture_record_flag(const uint32_t* words) { return (words[0] & 1u) != 0; }

// Register 3 g + c, sign-extended.
inline int64_t texture_record_register(const uint32_t* words, const Widths& w, int group, int c) {
  const int bits = w.texture_reg_bits, lsb = 1 + (3 * group + c) * bits;
  uint64_t value = 0;
  for (int i = 0; i < bits; ++i) value |= uint64_t((words[(lsb + i) / 32] >> ((lsb + i) % 32)) & 1u) << i;
  if (bits < 64 && ((value >> (bits - 1)) & 1u)) value |= ~uint64_t(0) << bits;
  return int64_t(value);
}

// The model's field of register 3 g + c (R: SetupResult or const SetupResult): plane c's start,
// step x, step y, then its planes along the left-edge slots.
template <class R>
auto& texture_record_field(R& s, int group, int c) {
  switch (group) {
    case 0: return s.texture[c].start;
    case 1: return s.texture[c].step_x;
    case 2: return s.texture[c].step_y;
    case 3: return s.left[0].texture[c].start;
    case 4: return s.left[0].texture[c].step;
    case 5: return s.left[1].texture[c].start;
    default: return s.left[1].texture[c].step;
  }
}

// The texture record into `s`: textured, texture[c] and left[j].texture[c].
inline void unpack_texture_record(const uint32_t* words, const Widths& w, SetupResult& s) {
  s.textured = texture_record_flag(words);
  for (int g = 0; g < kTextureRecordGroups; ++g)
    for (int c = 0; c < 3; ++c) texture_record_field(s, g, c) = texture_record_register(words, w, g, c);
}

inline std::vector<uint32_t> pack_texture_record(const SetupResult& s, const Widths& w) {
  std::vector<uint32_t> words(size_t((texture_record_bits(w) + 31) / 32), 0u);
  words[0] = s.textured ? 1u : 0u;
  for (int g = 0; g < kTextureRecordGroups; ++g)
    for (int c = 0; c < 3; ++c) {
      const uint64_t value = uint64_t(texture_record_field(s, g, c));
      const int lsb = 1 + (3 * g + c) * w.texture_reg_bits;
      for (int i = 0; i < w.texture_reg_bits; ++i)
        if ((value >> i) & 1u) words[size_t((lsb + i) / 32)] |= 1u << ((lsb + i) % 32);
    }
  return words;
}

}  // namespace rastersim::rtl
