// Fixed-point and integer helpers shared by every model unit.
// The model keeps register values in int64_t (or __int128 for the setup dividends); the width a
// value is allowed to occupy comes from the profile (see widths.h) and is checked here.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace rastersim {

using i128 = __int128;

// Thrown when a value leaves the width the hardware declares for it. In the hardware this would be
// a silent wrap, so the model treats it as a specification bug, never as data.
class WidthOverflow : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

// Smallest two's-complement width b holding v: -2^(b-1) <= v < 2^(b-1).
constexpr int signed_bits(i128 v) {
  int bits = 1;
  while (!(v >= -(i128(1) << (bits - 1)) && v < (i128(1) << (bits - 1)))) ++bits;
  return bits;
}

// Smallest unsigned width b holding v >= 0: v < 2^b (at least 1).
constexpr int unsigned_bits(i128 v) {
  if (v < 2) return 1;
  const uint64_t high = uint64_t((unsigned __int128)v >> 64), low = uint64_t(v);
  return high != 0 ? 128 - __builtin_clzll(high) : 64 - __builtin_clzll(low);
}

constexpr bool fits_signed(i128 v, int bits) {
  return v >= -(i128(1) << (bits - 1)) && v < (i128(1) << (bits - 1));
}

std::string to_string_i128(i128 v);

[[noreturn]] void throw_register_overflow(int64_t value, int bits, bool is_signed);  // out of line: a rare path

// A register whose width and signedness are part of its type. `Bits` is the register's width in
// the largest profile (widths.h asserts that it covers derive_widths there); a value enters only
// through a check, so storing a value the register cannot hold throws instead of wrapping. The
// profile's own, usually narrower, width is checked where the setup unit makes the value.
// Reading converts to int64_t, so arithmetic on register values reads like arithmetic on integers.
template <int Bits, bool Signed = true>
class Reg {
  static_assert(Bits >= 1 && Bits <= (Signed ? 64 : 63), "a Reg is held in an int64_t");

 public:
  static constexpr int bits = Bits;
  static constexpr bool is_signed = Signed;
  static constexpr int64_t min = Signed ? int64_t(uint64_t(-1) << (Bits - 1)) : 0;
  static constexpr int64_t max = Signed ? int64_t((uint64_t(1) << (Bits - 1)) - 1) : int64_t((uint64_t(1) << Bits) - 1);

  constexpr Reg() = default;
  constexpr Reg(int64_t value) : value_(checked(value)) {}  // NOLINT: implicit, always checked
  constexpr operator int64_t() const { return value_; }      // NOLINT
  constexpr int64_t value() const { return value_; }
  constexpr Reg& operator+=(int64_t v) { return *this = Reg(value_ + v); }
  constexpr Reg& operator-=(int64_t v) { return *this = Reg(value_ - v); }

 private:
  static constexpr int64_t checked(int64_t value) {
    if (value < min || value > max) throw_register_overflow(value, Bits, Signed);
    return value;
  }
  int64_t value_ = 0;
};

// Throws WidthOverflow naming the register when v does not fit a signed register of `bits`.
[[noreturn]] void throw_width_overflow(i128 v, int bits, const char* what);  // kept out of line: a rare path
inline void check_signed(i128 v, int bits, const char* what) {
  if (!fits_signed(v, bits)) throw_width_overflow(v, bits, what);
}

// Reduces v modulo 2^bits into the signed range: what a two's-complement register of `bits` holds.
// Used only for registers the hardware deliberately lets wrap (the plane registers).
// Only v's low 64 bits reach the result (a register of 64 bits or fewer), so the shifts are 64-bit.
inline int64_t wrap_signed(i128 v, int bits) {
  const unsigned shift = bits >= 64 ? 0u : 64u - unsigned(bits);
  return int64_t(uint64_t(v) << shift) >> shift;
}

// Floor division (rounds toward minus infinity) with a positive divisor, exactly as the setup
// unit's divider computes it: an unsigned restoring division of |n| by d, then for a negative
// dividend q = -q0 - (r0 != 0).
struct FloorDiv {
  i128 quotient;
  i128 remainder;  // 0 <= remainder < divisor
};
// The signed result from |n| = q0 d + r0.
inline FloorDiv floor_from_magnitude(bool negative, unsigned __int128 q0, unsigned __int128 r0, i128 d) {
  if (!negative) return {i128(q0), i128(r0)};
  if (r0 == 0) return {-i128(q0), 0};
  return {-i128(q0) - 1, d - i128(r0)};
}

inline FloorDiv floor_div(i128 n, i128 d) {
  const unsigned __int128 mag = n < 0 ? (unsigned __int128)(-n) : (unsigned __int128)n;
  unsigned __int128 q0, r0;
  if ((mag >> 64) == 0 && ((unsigned __int128)d >> 64) == 0) {
    q0 = uint64_t(mag) / uint64_t(d);  // the same numbers; one 64-bit division instead of two 128-bit calls
    r0 = uint64_t(mag) % uint64_t(d);
  } else {
    q0 = mag / (unsigned __int128)d;
    r0 = mag % (unsigned __int128)d;
  }
  return floor_from_magnitude(n < 0, q0, r0, d);
}

// floor_div() by one divisor 0 < d < 2^64 many times (the setup divides every plane by the same
// area): with inv = floor((2^64 - 1) / d) >= 2^64 / d - 1, the estimate floor(|n| inv / 2^64) is at
// most 2 below the quotient when |n| < 2^64, and corrections make it exact. Larger |n| divide.
class FloorDivider {
 public:
  explicit FloorDivider(i128 d) : d_(d), wide_(((unsigned __int128)d >> 64) != 0), inv_(wide_ ? 0 : ~uint64_t(0) / uint64_t(d)) {}
  FloorDiv operator()(i128 n) const {
    const unsigned __int128 mag = n < 0 ? (unsigned __int128)(-n) : (unsigned __int128)n;
    if (wide_ || (mag >> 64) != 0) return floor_div(n, d_);
    const uint64_t m = uint64_t(mag), d = uint64_t(d_);
    uint64_t q = uint64_t(((unsigned __int128)m * inv_) >> 64);
    uint64_t r = m - q * d;
    while (r >= d) r -= d, ++q;
    return floor_from_magnitude(n < 0, q, r, d_);
  }

 private:
  i128 d_;
  bool wide_;
  uint64_t inv_;
};

// Arithmetic shift right = floor division by 2^s for any sign.
constexpr int64_t asr(int64_t v, int s) { return v >> s; }

}  // namespace rastersim
