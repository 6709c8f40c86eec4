// Z register adder: the depth register adds depth.step_x on each x step and depth.step_y on a new
// row (a row register keeps the row start); no multiplication per pixel. The colour adders are the
// same circuit on the r, g, b planes. All registers wrap (two's complement of `reg_bits`): only
// values at covered pixels are used, and those are proven in range (docs/arithmetic.md).
#pragma once

#include <cstdint>

#include "triangle_setup.h"

namespace rastersim {

class PlaneRegister {
 public:
  void configure(int reg_bits, int guard_bits, int64_t out_max) {
    shift_ = 64 - reg_bits;
    guard_bits_ = guard_bits;
    out_max_ = out_max;
  }
  void load(const PlaneSetup& p) {
    step_x_ = p.step_x;
    step_y_ = p.step_y;
    row_ = value_ = p.start;
  }
  void step_x() { value_ = wrap(value_ + step_x_); }
  void next_row() { row_ = value_ = wrap(row_ + step_y_); }
  // Span walker: enter the row at pixel offset t >= 0 from the bounding box's x0. A small
  // multiplier (t has x_bits) once per row, never per pixel.
  void enter_row_at(int64_t t) { value_ = wrap(row_ + int64_t(uint64_t(t) * uint64_t(step_x_))); }
  // Rounded integer output, clamped to [0, out_max]: (value + 2^(F-1)) >> F.
  int64_t output() const {
    const int64_t rounded = wrap(value_ + (int64_t(1) << (guard_bits_ - 1))) >> guard_bits_;
    return rounded < 0 ? 0 : (rounded > out_max_ ? out_max_ : rounded);
  }
  int64_t value() const { return value_; }

 private:
  int64_t wrap(int64_t v) const { return int64_t(uint64_t(v) << shift_) >> shift_; }
  int shift_ = 0, guard_bits_ = 1;
  int64_t out_max_ = 0;
  int64_t step_x_ = 0, step_y_ = 0, row_ = 0, value_ = 0;
};

// The unit: one depth register and, for Gouraud shading, three colour registers, stepped together.
class ZAdder {
 public:
  ZAdder(const Widths& widths, int z_bits, bool gouraud) : gouraud_(gouraud) {
    depth_.configure(widths.z_reg_bits, widths.guard_bits, (int64_t(1) << z_bits) - 1);
    for (PlaneRegister& c : color_) c.configure(widths.color_reg_bits, widths.guard_bits, 255);
  }
  void load(const SetupResult& s) {
    depth_.load(s.depth);
    flat_ = s.flat_color;
    if (gouraud_)
      for (int c = 0; c < 3; ++c) color_[c].load(s.color[c]);
  }
  void step_x() {
    depth_.step_x();
    if (gouraud_)
      for (PlaneRegister& c : color_) c.step_x();
  }
  void next_row() {
    depth_.next_row();
    if (gouraud_)
      for (PlaneRegister& c : color_) c.next_row();
  }
  void enter_row_at(int64_t t) {
    depth_.enter_row_at(t);
    if (gouraud_)
      for (PlaneRegister& c : color_) c.enter_row_at(t);
  }
  uint32_t depth() const { return uint32_t(depth_.output()); }
  Rgb color() const {
    if (!gouraud_) return flat_;
    return Rgb{uint8_t(color_[0].output()), uint8_t(color_[1].output()), uint8_t(color_[2].output())};
  }
  const PlaneRegister& depth_register() const { return depth_; }
  const PlaneRegister& color_register(int c) const { return color_[c]; }

 private:
  bool gouraud_;
  Rgb flat_;
  PlaneRegister depth_;
  PlaneRegister color_[3];
};

}  // namespace rastersim
