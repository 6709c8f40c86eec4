// Z register adder: the depth register adds depth.step_x on each x step and depth.step_y on a new
// row (a row register keeps the row start); the span walker enters a row at x0 or at a left edge's
// span start, whose plane value each left-edge slot steps from row to row. No multiplication. The
// colour adders are the same circuit on the r, g, b planes. All registers wrap (two's complement
// of `reg_bits`): only values at covered pixels are used, and those are proven in range
// (docs/arithmetic.md).
#pragma once

#include <algorithm>
#include <cstdint>

#include "texture_divide.h"
#include "triangle_setup.h"

namespace rastersim {

// The format of a plane register: a two's-complement value of `reg_bits` with `guard_bits` fraction
// bits (depth s(N+1).F, colour s9.F), and its output: the integer rounded by the profile's
// depth_rounding or color_rounding (docs/arithmetic.md section 7), clamped to [0, out_max].
class PlaneFormat {
 public:
  PlaneFormat(int reg_bits, int guard_bits, int64_t out_max, Rounding rounding)
      : wrap_shift_(64 - reg_bits), round_shift_(64 - reg_bits + guard_bits),
        rounding_addend_(rounding == Rounding::Nearest ? uint64_t(1) << (guard_bits - 1) : 0), out_max_(out_max) {}

  // v modulo 2^reg_bits: what the register holds.
  int reg_bits() const { return 64 - wrap_shift_; }
  int guard_bits() const { return round_shift_ - wrap_shift_; }
  int64_t out_max() const { return out_max_; }
  // What is added before the fraction bits are dropped: 2^(F-1) to round to nearest, 0 to truncate.
  uint64_t rounding_addend() const { return rounding_addend_; }

  int64_t wrap(uint64_t v) const { return int64_t(v << wrap_shift_) >> wrap_shift_; }
  // clamp((value + rounding_addend) >> F, 0, out_max), the sum taken in the register's width. `value` may be
  // held modulo 2^64: 2^reg_bits divides 2^64, so wrapping the sum once gives the register's result
  // (the wrap's right shift and the rounding shift are one shift).
  int64_t output(uint64_t value) const {
    const int64_t rounded = int64_t((value + rounding_addend_) << wrap_shift_) >> round_shift_;
    return rounded < 0 ? 0 : (rounded > out_max_ ? out_max_ : rounded);
  }

 private:
  int wrap_shift_, round_shift_;
  uint64_t rounding_addend_;
  int64_t out_max_;
};

// One plane register as the hardware holds it.
class PlaneRegister {
 public:
  PlaneRegister(uint64_t value, PlaneFormat format) : value_(format.wrap(value)), format_(format) {}
  int64_t value() const { return value_; }
  int64_t output() const { return format_.output(uint64_t(value_)); }

 private:
  int64_t value_;
  PlaneFormat format_;
};

// The depth word (docs/arithmetic.md section 6): the plane output X (0 <= X < 2^Np) as it is stored,
// X itself for the fixed-point word (Ne = 0), else an unsigned float of z_bits bits, Ne exponent bits
// above Nm = z_bits - Ne mantissa bits, truncated.
class DepthWord {
 public:
  DepthWord(int z_bits, int exponent_bits) : exponent_bits_(exponent_bits), mantissa_bits_(z_bits - exponent_bits) {}
  explicit DepthWord(const Profile& p) : DepthWord(p.z_bits, p.depth_exponent_bits) {}

  uint32_t encode(uint64_t x) const {
    if (exponent_bits_ == 0 || x < (uint64_t(1) << mantissa_bits_)) return uint32_t(x);
    const int e = 63 - __builtin_clzll(x) - mantissa_bits_ + 1;
    return uint32_t((uint64_t(e) << mantissa_bits_) + (x >> (e - 1)) - (uint64_t(1) << mantissa_bits_));
  }
  // The smallest X with this word (every X of the word lies below decode + 2^(e-1)).
  uint64_t decode(uint32_t word) const {
    if (exponent_bits_ == 0) return word;
    const int e = int(word >> mantissa_bits_);
    const uint64_t mantissa = word & ((uint64_t(1) << mantissa_bits_) - 1);
    return e == 0 ? mantissa : ((uint64_t(1) << mantissa_bits_) + mantissa) << (e - 1);
  }
  // One exponent bit is the fixed-point word bit for bit (exponent 1 is X's top bit).
  bool fixed_point() const { return exponent_bits_ <= 1; }

 private:
  int exponent_bits_, mantissa_bits_;
};

// The depth output stage: a triangle's depth bias B from its depth plane's steps, and a depth
// register value V to the depth word: X = clamp((V + B + 2^(F-1)) >> F, 0, 2^Np - 1), encoded
// (docs/arithmetic.md section 6). Logic between the register and the fragment, no cycles.
class DepthOutput {
 public:
  // The bias unit (rtl/depth_bias.sv) forms B from a record in 7 stages, the record's setup_done
  // the first, and a record is ready for the walker once its B is (docs/cycle-model.md).
  static constexpr int kBiasStages = 7;

  DepthOutput(const PlaneFormat& plane, const Profile& p)
      : plane_(plane), word_(p), constant_(p.depth_bias_constant), slope_factor_(p.depth_bias_slope) {}

  // Without a bias and with the fixed-point word the output is the plane register's own.
  bool plain() const { return word_.fixed_point() && constant_ == 0 && slope_factor_ == 0; }

  // B = clamp(c 2^F + floor(f max(|step_x|, |step_y|) / 16), -2^(Np+F), 2^(Np+F)), the steps read as
  // the register holds them.
  int64_t bias(uint64_t step_x, uint64_t step_y) const {
    if (constant_ == 0 && slope_factor_ == 0) return 0;
    const int64_t sx = plane_.wrap(step_x), sy = plane_.wrap(step_y);
    const __int128 slope = std::max(sx < 0 ? -__int128(sx) : __int128(sx), sy < 0 ? -__int128(sy) : __int128(sy));
    const __int128 limit = __int128(1) << (plane_.reg_bits() - 1);  // 2^(Np+F)
    const __int128 b = __int128(constant_) * (__int128(1) << plane_.guard_bits()) + ((slope_factor_ * slope) >> 4);
    return int64_t(std::clamp(b, -limit, limit));
  }
  uint32_t word(uint64_t value, int64_t bias) const {
    if (bias == 0) return word_.encode(uint64_t(plane_.output(value)));
    const __int128 sum = __int128(plane_.wrap(value)) + bias + __int128(plane_.rounding_addend());
    const __int128 rounded = sum >> plane_.guard_bits();  // arithmetic: floor
    return word_.encode(uint64_t(std::clamp(rounded, __int128(0), __int128(plane_.out_max()))));
  }

 private:
  PlaneFormat plane_;
  DepthWord word_;
  int64_t constant_;
  int slope_factor_;
};

// The unit: the depth register and three colour registers (used for Gouraud shading), and for a
// textured triangle the S, T, Q registers (docs/arithmetic.md section 5), stepped together. The
// model accumulates modulo 2^64 and reduces to the register width when a value is read:
// 2^reg_bits divides 2^64, so this equals wrapping at every step, with fewer operations.
class ZAdder {
 public:
  ZAdder(const Widths& widths, const Profile& profile)
      : gouraud_(profile.shading == Shading::Gouraud),
        depth_format_{widths.z_reg_bits, widths.guard_bits, (int64_t(1) << profile.depth_plane_bits()) - 1,
                      profile.depth_rounding},
        color_format_{widths.color_reg_bits, widths.guard_bits, 255, profile.color_rounding},
        texture_format_{widths.texture_reg_bits, widths.texture_guard_bits, 0, Rounding::Nearest},
        texture_divide_shift_(widths.texture_divide_shift),
        depth_output_{depth_format_, profile} {}

  // The depth output is the depth register's rounded value (no bias, the fixed-point word): what the
  // fast paths (fast/) compute from ZAdder::Run.
  bool plain_depth_output() const { return depth_output_.plain(); }

  void load(const SetupResult& s) {
    const PlaneSetup* planes[kPlanes] = {&s.depth, &s.color[0], &s.color[1], &s.color[2]};
    for (int k = 0; k < kPlanes; ++k) {
      const bool used = k == 0 || gouraud_;
      step_x_[k] = used ? uint64_t(planes[k]->step_x) : 0;
      step_y_[k] = used ? uint64_t(planes[k]->step_y) : 0;
      row_[k] = value_[k] = used ? uint64_t(planes[k]->start) : 0;
      for (int j = 0; j < kLeftEdgeSlots; ++j) {
        const EdgePlane& along = k == 0 ? s.left[j].depth : s.left[j].color[k - 1];
        along_[j][k] = used ? uint64_t(along.start) : 0;
        along_step_[j][k] = used ? uint64_t(along.step) : 0;
      }
    }
    depth_bias_ = depth_output_.bias(step_x_[0], step_y_[0]);
    flat_ = s.flat_color;
    textured_ = s.textured;
    if (textured_) texture_.load(s);
  }
  void step_x() {
    for (int k = 0; k < kPlanes; ++k) value_[k] += step_x_[k];
    if (textured_) texture_.step_x(1);
  }
  // n steps at once: value + n step_x, equal to n additions modulo 2^64 (and so modulo 2^reg_bits).
  void step_x(int64_t n) {
    for (int k = 0; k < kPlanes; ++k) value_[k] += uint64_t(n) * step_x_[k];
    if (textured_) texture_.step_x(n);
  }
  void next_row() {
    for (int k = 0; k < kPlanes; ++k) value_[k] = row_[k] += step_y_[k];
    if (textured_) texture_.next_row();
  }
  // Span walker: enter the current row at the bounding box's x0 (slot < 0) or at the span start
  // of the left edge in `slot` (docs/cycle-model.md).
  void enter_span_row(int slot) {
    for (int k = 0; k < kPlanes; ++k) value_[k] = slot < 0 ? row_[k] : along_[slot][k];
    if (textured_) texture_.enter_span_row(slot);
  }
  // The registers at offset t >= 0 from x0 on the current row, with a multiplier: equal modulo
  // 2^reg_bits to what enter_span_row() gives at the span start t (a left-edge slot holds
  // row + t step_x there), so every output is the same. For the fast walks (fast/), where a
  // multiply per row costs less than stepping the slots; the hardware has no multiplier here.
  void enter_row_at(int64_t t) {
    for (int k = 0; k < kPlanes; ++k) value_[k] = row_[k] + uint64_t(t) * step_x_[k];
    if (textured_) texture_.enter_row_at(t);
  }
  // Each left-edge slot to the next row: its edge's quotient moves by span_step_quot, and by one
  // more on the DDA's carry, which moves the span start one pixel left of where `step` took it.
  // A mask, not a branch per plane: a slot's four registers are then written as one vector, which
  // enter_span_row() reads back whole in the next row (a read of several smaller writes stalls).
  void step_left_edges(const bool carry[kLeftEdgeSlots]) {
    for (int j = 0; j < kLeftEdgeSlots; ++j) {
      const uint64_t carried = carry[j] ? ~uint64_t(0) : 0;
      for (int k = 0; k < kPlanes; ++k) along_[j][k] += along_step_[j][k] - (step_x_[k] & carried);
    }
    if (textured_) texture_.step_left_edges(carry);
  }

  bool textured() const { return textured_; }
  // A textured triangle's u, v at the current pixel: the perspective divide of its S, T, Q registers.
  TextureCoordinate texture_coordinate() const {
    const uint64_t* v = texture_.value;
    return perspective_divide(texture_format_.wrap(v[0]), texture_format_.wrap(v[1]), texture_format_.wrap(v[2]),
                              texture_divide_shift_);
  }

  PlaneRegister depth_register() const { return {value_[0], depth_format_}; }
  PlaneRegister color_register(int c) const { return {value_[1 + c], color_format_}; }
  // The registers at the current pixel and their x steps, for a run of pixels taken at once
  // (fast/zbuffer_runs.h).
  struct Run {
    uint64_t value[4], step_x[4];  // depth, r, g, b
    PlaneFormat depth_format, color_format;
    bool gouraud;
    Rgb flat;
  };
  Run run() const {
    return {{value_[0], value_[1], value_[2], value_[3]}, {step_x_[0], step_x_[1], step_x_[2], step_x_[3]},
            depth_format_, color_format_, gouraud_, flat_};
  }

  uint32_t depth() const { return depth_at(0); }
  Rgb color() const { return color_at(0); }
  // The outputs i pixels to the right (the values after i step_x() calls), for a loop over a run
  // of pixels that steps the registers once at its end.
  uint32_t depth_at(int64_t i) const { return depth_output_.word(value_[0] + uint64_t(i) * step_x_[0], depth_bias_); }
  Rgb color_at(int64_t i) const {
    if (!gouraud_) return flat_;
    auto channel = [&](int k) { return uint8_t(color_format_.output(value_[k] + uint64_t(i) * step_x_[k])); };
    return Rgb{channel(1), channel(2), channel(3)};
  }

 private:
  static constexpr int kPlanes = 4;  // depth, r, g, b
  // The S, T, Q registers: the same circuit, kept apart so that an untextured triangle pays nothing.
  struct TextureRegisters {
    static constexpr int kCount = 3;
    uint64_t per_x[kCount] = {}, per_row[kCount] = {}, row[kCount] = {}, value[kCount] = {};
    uint64_t along[kLeftEdgeSlots][kCount] = {}, along_step[kLeftEdgeSlots][kCount] = {};
    void load(const SetupResult& s) {
      for (int k = 0; k < kCount; ++k) {
        per_x[k] = uint64_t(s.texture[k].step_x);
        per_row[k] = uint64_t(s.texture[k].step_y);
        row[k] = value[k] = uint64_t(s.texture[k].start);
        for (int j = 0; j < kLeftEdgeSlots; ++j) {
          along[j][k] = uint64_t(s.left[j].texture[k].start);
          along_step[j][k] = uint64_t(s.left[j].texture[k].step);
        }
      }
    }
    void step_x(int64_t n) {
      for (int k = 0; k < kCount; ++k) value[k] += uint64_t(n) * per_x[k];
    }
    void next_row() {
      for (int k = 0; k < kCount; ++k) value[k] = row[k] += per_row[k];
    }
    void enter_span_row(int slot) {
      for (int k = 0; k < kCount; ++k) value[k] = slot < 0 ? row[k] : along[slot][k];
    }
    void enter_row_at(int64_t t) {
      for (int k = 0; k < kCount; ++k) value[k] = row[k] + uint64_t(t) * per_x[k];
    }
    void step_left_edges(const bool carry[kLeftEdgeSlots]) {
      for (int j = 0; j < kLeftEdgeSlots; ++j)
        for (int k = 0; k < kCount; ++k) along[j][k] += along_step[j][k] - (carry[j] ? per_x[k] : 0);
    }
  };
  bool gouraud_;
  bool textured_ = false;
  PlaneFormat depth_format_, color_format_, texture_format_;
  int texture_divide_shift_;  // Widths::texture_divide_shift
  DepthOutput depth_output_;
  int64_t depth_bias_ = 0;  // the loaded triangle's B (DepthOutput::bias)
  TextureRegisters texture_;
  Rgb flat_;
  uint64_t step_x_[kPlanes] = {}, step_y_[kPlanes] = {}, row_[kPlanes] = {}, value_[kPlanes] = {};
  // Per left-edge slot: the plane at its edge's span start on the current row, and its step per row.
  uint64_t along_[kLeftEdgeSlots][kPlanes] = {}, along_step_[kLeftEdgeSlots][kPlanes] = {};
};

}  // namespace rastersim
