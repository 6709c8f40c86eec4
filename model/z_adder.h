// Z register adder: the depth register adds depth.step_x on each x step and depth.step_y on a new
// row (a row register keeps the row start); no multiplication per pixel. The colour adders are the
// same circuit on the r, g, b planes. All registers wrap (two's complement of `reg_bits`): only
// values at covered pixels are used, and those are proven in range (docs/arithmetic.md).
#pragma once

#include <cstdint>

#include "triangle_setup.h"

namespace rastersim {

// One plane register as the hardware holds it: a two's-complement value of `reg_bits` with
// `guard_bits` fraction bits (depth s(N+1).F, colour s9.F).
class PlaneRegister {
 public:
  PlaneRegister(int64_t value, int reg_bits, int guard_bits, int64_t out_max)
      : value_(int64_t(uint64_t(value) << (64 - reg_bits)) >> (64 - reg_bits)),
        guard_bits_(guard_bits), out_max_(out_max), reg_bits_(reg_bits) {}
  int64_t value() const { return value_; }
  // Rounded integer output, clamped to [0, out_max]: (value + 2^(F-1)) >> F.
  int64_t output() const {
    const int shift = 64 - reg_bits_;
    const int64_t sum = int64_t(uint64_t(value_ + (int64_t(1) << (guard_bits_ - 1))) << shift) >> shift;
    const int64_t rounded = sum >> guard_bits_;
    return rounded < 0 ? 0 : (rounded > out_max_ ? out_max_ : rounded);
  }

 private:
  int64_t value_;
  int guard_bits_;
  int64_t out_max_;
  int reg_bits_;
};

// The unit: the depth register and three colour registers (used for Gouraud shading), stepped
// together. The model accumulates modulo 2^64 and reduces to the register width when a value is
// read: 2^reg_bits divides 2^64, so this equals wrapping at every step, with fewer operations.
class ZAdder {
 public:
  ZAdder(const Widths& widths, int z_bits, bool gouraud)
      : gouraud_(gouraud), guard_bits_(widths.guard_bits), z_reg_bits_(widths.z_reg_bits),
        color_reg_bits_(widths.color_reg_bits), z_max_((int64_t(1) << z_bits) - 1) {}

  void load(const SetupResult& s) {
    const PlaneSetup* planes[kPlanes] = {&s.depth, &s.color[0], &s.color[1], &s.color[2]};
    for (int k = 0; k < kPlanes; ++k) {
      const bool used = k == 0 || gouraud_;
      step_x_[k] = used ? uint64_t(planes[k]->step_x) : 0;
      step_y_[k] = used ? uint64_t(planes[k]->step_y) : 0;
      row_[k] = value_[k] = used ? uint64_t(planes[k]->start) : 0;
    }
    flat_ = s.flat_color;
  }
  void step_x() {
    for (int k = 0; k < kPlanes; ++k) value_[k] += step_x_[k];
  }
  void next_row() {
    for (int k = 0; k < kPlanes; ++k) value_[k] = row_[k] += step_y_[k];
  }
  // Span walker: enter the row at pixel offset t >= 0 from the bounding box's x0. A small
  // multiplier (t has x_bits) once per row, never per pixel.
  void enter_row_at(int64_t t) {
    for (int k = 0; k < kPlanes; ++k) value_[k] = row_[k] + uint64_t(t) * step_x_[k];
  }

  PlaneRegister depth_register() const { return {int64_t(value_[0]), z_reg_bits_, guard_bits_, z_max_}; }
  PlaneRegister color_register(int c) const { return {int64_t(value_[1 + c]), color_reg_bits_, guard_bits_, 255}; }
  uint32_t depth() const { return uint32_t(depth_register().output()); }
  Rgb color() const {
    if (!gouraud_) return flat_;
    return Rgb{uint8_t(color_register(0).output()), uint8_t(color_register(1).output()),
               uint8_t(color_register(2).output())};
  }

 private:
  static constexpr int kPlanes = 4;  // depth, r, g, b
  bool gouraud_;
  int guard_bits_, z_reg_bits_, color_reg_bits_;
  int64_t z_max_;
  Rgb flat_;
  uint64_t step_x_[kPlanes] = {}, step_y_[kPlanes] = {}, row_[kPlanes] = {}, value_[kPlanes] = {};
};

}  // namespace rastersim
