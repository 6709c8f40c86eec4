// Perspective divide: a textured fragment's u and v from its S = u/w, T = v/w and Q = 1/w plane
// registers (docs/arithmetic.md section 5), the texture sampler's input. The registers share their
// scale (s9.(P+Ft)), so the quotient needs no alignment: with D = Widths::texture_divide_shift,
// u = floor(floor(Vs / 2^D) 2^20 / floor(Vq / 2^D)), clamped to s8.20.
#pragma once

#include <cstdint>

#include "fixed.h"
#include "texture_sampler.h"

namespace rastersim {

struct TextureCoordinate {
  int32_t u = 0, v = 0;  // s8.20
  bool operator==(const TextureCoordinate& o) const { return u == o.u && v == o.v; }
};

// One coordinate: floor(numerator 2^20 / q) clamped to s8.20. q > 0 at every covered pixel (the
// Q plane lies within half an LSB below its vertex values, all at least 2^P / 2^14).
inline int32_t divide_texture_coordinate(int64_t numerator, int64_t q) {
  if (q <= 0) throw WidthOverflow("Q plane register not positive at a covered pixel");
  constexpr i128 kMin = -(i128(1) << (kUvBits - 1)), kMax = (i128(1) << (kUvBits - 1)) - 1;
  const i128 quotient = floor_div(i128(numerator) * (i128(1) << kUvFracBits), q).quotient;
  return int32_t(quotient < kMin ? kMin : quotient > kMax ? kMax : quotient);
}

// The registers' low `shift` bits dropped first (arithmetic shifts: floors).
inline TextureCoordinate perspective_divide(int64_t s, int64_t t, int64_t q, int shift) {
  return {divide_texture_coordinate(s >> shift, q >> shift), divide_texture_coordinate(t >> shift, q >> shift)};
}

}  // namespace rastersim
