// The z-buffer's run kernel for AVX-512 (a RunKernel, fast/run_kernels.h), in a header so that the
// untraced walk can be compiled for AVX-512 with it inlined (fast/fast_walk.cpp).
#pragma once

#include <algorithm>
#include <cstdint>

// Relative, as in model/: installed, these headers are reached as <rastersim/fast/...>.
#include "../model/z_adder.h"
#include "../model/zbuffer.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define RASTERSIM_HAVE_AVX512_KERNEL 1
// GCC 12's AVX-512 headers start many intrinsics from an undefined vector (GCC bug 105593) and
// warn of it wherever this kernel is inlined: off for the rest of each file that includes this.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

namespace rastersim {

#define RASTERSIM_AVX512 __attribute__((target("avx512f,avx512bw,avx512dq,avx512vl,avx2,bmi,bmi2,fma")))

inline bool avx512_masked_fits(const ZAdder::Run& p) { return !p.gouraud || p.color_format.reg_bits() <= 32; }

// A plane format's operands for UnsignedPlaneOutput (fast/run_kernels.h) in vector registers;
// `lane_bits` 64 (depth) or 32 (colour, registers held modulo 2^32: the shifts are 32 less).
struct Avx512Format {
  __m512i addend, max;
  __m128i wrap, round;
};
RASTERSIM_AVX512 inline Avx512Format avx512_format(const PlaneFormat& f, int lane_bits) {
  const int reg_bits = std::min(f.reg_bits(), lane_bits);
  const uint64_t addend = f.rounding_addend();
  return {lane_bits == 64 ? _mm512_set1_epi64(int64_t(addend)) : _mm512_set1_epi32(int32_t(addend)),
          lane_bits == 64 ? _mm512_set1_epi64(f.out_max()) : _mm512_set1_epi32(int32_t(f.out_max())),
          _mm_cvtsi32_si128(lane_bits - reg_bits), _mm_cvtsi32_si128(lane_bits - reg_bits + f.guard_bits())};
}
// UnsignedPlaneOutput of eight 64-bit registers, narrowed to 32 bits.
RASTERSIM_AVX512 inline __m256i avx512_depth_out(__m512i v, const Avx512Format& f) {
  const __m512i shifted = _mm512_sll_epi64(_mm512_add_epi64(v, f.addend), f.wrap);
  const __m512i rounded = _mm512_min_epu64(_mm512_srl_epi64(shifted, f.round), f.max);
  return _mm512_cvtepi64_epi32(_mm512_maskz_mov_epi64(_mm512_cmpge_epi64_mask(shifted, _mm512_setzero_si512()), rounded));
}
// UnsignedPlaneOutput of sixteen registers held modulo 2^32.
RASTERSIM_AVX512 inline __m512i avx512_color_out(__m512i v, const Avx512Format& f) {
  const __m512i shifted = _mm512_sll_epi32(_mm512_add_epi32(v, f.addend), f.wrap);
  const __m512i rounded = _mm512_min_epu32(_mm512_srl_epi32(shifted, f.round), f.max);
  return _mm512_maskz_mov_epi32(_mm512_cmpge_epi32_mask(shifted, _mm512_setzero_si512()), rounded);
}

// The run kernel written with AVX-512 intrinsics, for runs of any length: blocks of 16
// pixels, the last one masked (masked loads and stores neither read nor write past the run).
// Depth in 64-bit lanes (its register is wider than 32 bits); colour in 32-bit lanes, exact when
// the colour register fits in 32 bits: 2^reg_bits divides 2^32, so sums modulo 2^32 hold the
// register's bits, and the shifts take the same bits as the 64-bit ones. The caller checks
// avx512_masked_fits() (otherwise, with z_guard_bits above 23, the compiled loop does the run).
RASTERSIM_AVX512 inline int64_t run_avx512_masked(uint32_t* depth, uint32_t* color, int64_t n, unsigned mask,
                                                  bool depth_write, const ZAdder::Run& p) {
  const Avx512Format z_format = avx512_format(p.depth_format, 64), c_format = avx512_format(p.color_format, 32);
  // Depth registers of pixels 0..7 and 8..15 of a block.
  const uint64_t z_step = p.step_x[0];
  const __m512i lane8 = _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0);
  __m512i z_lo = _mm512_add_epi64(_mm512_set1_epi64(int64_t(p.value[0])),
                                  _mm512_mullo_epi64(lane8, _mm512_set1_epi64(int64_t(z_step))));
  __m512i z_hi = _mm512_add_epi64(z_lo, _mm512_set1_epi64(int64_t(z_step << 3)));
  const __m512i z_block = _mm512_set1_epi64(int64_t(z_step << 4));
  // Colour registers r, g, b modulo 2^32 of the 16 pixels.
  const __m512i lane16 = _mm512_set_epi32(15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0);
  __m512i c_value[3], c_block[3];
  for (int k = 0; k < 3; ++k) {
    const uint32_t step = uint32_t(p.step_x[1 + k]);
    c_value[k] = _mm512_add_epi32(_mm512_set1_epi32(int32_t(uint32_t(p.value[1 + k]))),
                                  _mm512_mullo_epi32(lane16, _mm512_set1_epi32(int32_t(step))));
    c_block[k] = _mm512_set1_epi32(int32_t(step << 4));
  }
  const __m128i red_shift = _mm_cvtsi32_si128(16), green_shift = _mm_cvtsi32_si128(8);  // 0x00RRGGBB
  const __m512i flat = _mm512_set1_epi32(int32_t((uint32_t(p.flat.r) << 16) | (uint32_t(p.flat.g) << 8) | p.flat.b));
  const __mmask16 pass_less = (mask & ZBuffer::kLess) ? 0xFFFF : 0, pass_equal = (mask & ZBuffer::kEqual) ? 0xFFFF : 0,
                  pass_greater = (mask & ZBuffer::kGreater) ? 0xFFFF : 0;
  int64_t passes = 0;
  for (int64_t i = 0; i < n; i += 16) {
    const __mmask16 in_run = n - i >= 16 ? __mmask16(0xFFFF) : __mmask16((1u << (n - i)) - 1);
    const __m512i z = _mm512_inserti64x4(_mm512_castsi256_si512(avx512_depth_out(z_lo, z_format)),
                                         avx512_depth_out(z_hi, z_format), 1);
    const __m512i stored = _mm512_maskz_loadu_epi32(in_run, depth + i);
    const __mmask16 pass = in_run & ((_mm512_cmplt_epu32_mask(z, stored) & pass_less) |
                                     (_mm512_cmpeq_epu32_mask(z, stored) & pass_equal) |
                                     (_mm512_cmpgt_epu32_mask(z, stored) & pass_greater));
    if (depth_write) _mm512_mask_storeu_epi32(depth + i, pass, z);
    __m512i c = flat;
    if (p.gouraud) {
      const __m512i red = _mm512_sll_epi32(avx512_color_out(c_value[0], c_format), red_shift);
      const __m512i green = _mm512_sll_epi32(avx512_color_out(c_value[1], c_format), green_shift);
      c = _mm512_or_si512(_mm512_or_si512(red, green), avx512_color_out(c_value[2], c_format));
    }
    _mm512_mask_storeu_epi32(color + i, pass, c);
    passes += __builtin_popcount(pass);
    z_lo = _mm512_add_epi64(z_lo, z_block);
    z_hi = _mm512_add_epi64(z_hi, z_block);
    for (int k = 0; k < 3; ++k) c_value[k] = _mm512_add_epi32(c_value[k], c_block[k]);
  }
  return passes;
}

}  // namespace rastersim
#endif
