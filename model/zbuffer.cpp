#include "zbuffer.h"

#include <algorithm>
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif
#include <limits>
#include <stdexcept>

namespace rastersim {
namespace {

// The depth test and conditional write of n fragments, written without branches or 64-bit
// arithmetic shifts so that it vectorizes: every word is stored back, changed or not.
template <bool Gouraud, bool DepthWrite>
inline __attribute__((always_inline)) int64_t run_loop(uint32_t* depth, uint32_t* color, int64_t n, unsigned mask,
                                                        const ZAdder::Run& p) {
  const bool pass_less = mask & ZBuffer::kLess, pass_equal = mask & ZBuffer::kEqual, pass_greater = mask & ZBuffer::kGreater;
  // Local copies: stores through depth and color could otherwise alias the formats' int fields.
  const PlaneFormat depth_format = p.depth_format, color_format = p.color_format;
  uint64_t z_value = p.value[0], r_value = p.value[1], g_value = p.value[2], b_value = p.value[3];
  const uint64_t z_step = p.step_x[0], r_step = p.step_x[1], g_step = p.step_x[2], b_step = p.step_x[3];
  const uint32_t flat = (uint32_t(p.flat.r) << 16) | (uint32_t(p.flat.g) << 8) | p.flat.b;
  int64_t passes = 0;
  for (int64_t i = 0; i < n; ++i) {
    const uint32_t z = depth_format.output_unsigned(z_value);
    const uint32_t stored = depth[i];
    const bool pass = ((z < stored) & pass_less) | ((z == stored) & pass_equal) | ((z > stored) & pass_greater);
    const uint32_t c = Gouraud ? (color_format.output_unsigned(r_value) << 16) |
                                     (color_format.output_unsigned(g_value) << 8) |
                                     color_format.output_unsigned(b_value)
                               : flat;
    if (DepthWrite) depth[i] = pass ? z : stored;
    color[i] = pass ? c : color[i];
    passes += pass;
    z_value += z_step;
    if (Gouraud) r_value += r_step, g_value += g_step, b_value += b_step;
  }
  return passes;
}

// Measured: below this the compiled loops are slower than one fragment at a time.
constexpr int64_t kCompiledShortRun = 24;


template <bool Gouraud>
inline __attribute__((always_inline)) int64_t run_shaded(uint32_t* depth, uint32_t* color, int64_t n, unsigned mask,
                                                          bool depth_write, const ZAdder::Run& planes) {
  return depth_write ? run_loop<Gouraud, true>(depth, color, n, mask, planes)
                     : run_loop<Gouraud, false>(depth, color, n, mask, planes);
}

// The same loop compiled for several instruction sets; the best one this CPU has is used.
#define RASTERSIM_RUN_KERNEL(NAME, ATTRIBUTES)                                                              \
  ATTRIBUTES int64_t NAME(uint32_t* depth, uint32_t* color, int64_t n, unsigned mask, bool depth_write,     \
                          const ZAdder::Run& planes) {                                                      \
    return planes.gouraud ? run_shaded<true>(depth, color, n, mask, depth_write, planes)                   \
                          : run_shaded<false>(depth, color, n, mask, depth_write, planes);                 \
  }
RASTERSIM_RUN_KERNEL(run_generic, )
#if defined(__x86_64__) && defined(__GNUC__)
RASTERSIM_RUN_KERNEL(run_avx2, __attribute__((target("avx2,bmi,bmi2,fma"))))
RASTERSIM_RUN_KERNEL(run_avx512, __attribute__((target("avx512f,avx512bw,avx512dq,avx512vl,avx2,bmi,bmi2,fma"))))
#define RASTERSIM_X86_KERNELS 1

// Written with AVX-512 intrinsics for runs of any length: blocks of 16 pixels, the last one masked
// (masked loads and stores neither read nor write past the run). Depth in 64-bit lanes (its
// register is wider than 32 bits); colour in 32-bit lanes, which is exact when the colour register
// fits in 32 bits: 2^reg_bits divides 2^32, so sums modulo 2^32 hold the register's bits, and the
// shifts below take the same bits as PlaneFormat::output_unsigned's 64-bit ones. Otherwise (z_guard_bits
// above 23) the compiled loop does the run.
// GCC 12's AVX-512 headers start some intrinsics from an undefined vector and warn of it.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#define RASTERSIM_AVX512 __attribute__((target("avx512f,avx512bw,avx512dq,avx512vl,avx2,bmi,bmi2,fma")))
// PlaneFormat::output_unsigned of eight 64-bit registers, narrowed to 32 bits.
RASTERSIM_AVX512 inline __m256i depth_out(__m512i v, __m512i half, __m128i wrap, __m128i round, __m512i max) {
  const __m512i shifted = _mm512_sll_epi64(_mm512_add_epi64(v, half), wrap);
  const __m512i rounded = _mm512_min_epu64(_mm512_srl_epi64(shifted, round), max);
  return _mm512_cvtepi64_epi32(_mm512_maskz_mov_epi64(_mm512_cmpge_epi64_mask(shifted, _mm512_setzero_si512()), rounded));
}
// The same for sixteen registers held modulo 2^32 (shifts 32 less).
RASTERSIM_AVX512 inline __m512i color_out(__m512i v, __m512i half, __m128i wrap, __m128i round, __m512i max) {
  const __m512i shifted = _mm512_sll_epi32(_mm512_add_epi32(v, half), wrap);
  const __m512i rounded = _mm512_min_epu32(_mm512_srl_epi32(shifted, round), max);
  return _mm512_maskz_mov_epi32(_mm512_cmpge_epi32_mask(shifted, _mm512_setzero_si512()), rounded);
}

RASTERSIM_AVX512 int64_t run_avx512_masked(uint32_t* depth, uint32_t* color, int64_t n, unsigned mask,
                                           bool depth_write, const ZAdder::Run& p) {
  const PlaneFormat zf = p.depth_format, cf = p.color_format;
  if (p.gouraud && cf.reg_bits() > 32) return run_avx512(depth, color, n, mask, depth_write, p);
  // Depth: pixels 0..7 and 8..15 of a block; output as PlaneFormat::output_unsigned.
  const __m512i lane8 = _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0);
  const __m512i z_step = _mm512_set1_epi64(int64_t(p.step_x[0]));
  __m512i z_lo = _mm512_add_epi64(_mm512_set1_epi64(int64_t(p.value[0])), _mm512_mullo_epi64(lane8, z_step));
  __m512i z_hi = _mm512_add_epi64(z_lo, _mm512_slli_epi64(z_step, 3));
  const __m512i z_block = _mm512_slli_epi64(z_step, 4);
  const __m512i z_half = _mm512_set1_epi64(int64_t(uint64_t(1) << (zf.guard_bits() - 1)));
  const __m512i z_max = _mm512_set1_epi64(zf.out_max());
  const __m128i z_wrap = _mm_cvtsi32_si128(64 - zf.reg_bits()), z_round = _mm_cvtsi32_si128(64 - zf.reg_bits() + zf.guard_bits());
  // Colour: r, g, b registers modulo 2^32, 16 pixels per vector.
  const __m512i lane16 = _mm512_set_epi32(15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0);
  __m512i c_value[3], c_block[3];
  for (int k = 0; k < 3; ++k) {
    const __m512i step = _mm512_set1_epi32(int32_t(uint32_t(p.step_x[1 + k])));
    c_value[k] = _mm512_add_epi32(_mm512_set1_epi32(int32_t(uint32_t(p.value[1 + k]))), _mm512_mullo_epi32(lane16, step));
    c_block[k] = _mm512_slli_epi32(step, 4);
  }
  const int c_reg = std::min(cf.reg_bits(), 32);
  const __m512i c_half = _mm512_set1_epi32(int32_t(uint32_t(1) << (cf.guard_bits() - 1)));
  const __m512i c_max = _mm512_set1_epi32(int32_t(cf.out_max()));
  const __m128i c_wrap = _mm_cvtsi32_si128(32 - c_reg), c_round = _mm_cvtsi32_si128(32 - c_reg + cf.guard_bits());
  const __m512i flat = _mm512_set1_epi32(int32_t((uint32_t(p.flat.r) << 16) | (uint32_t(p.flat.g) << 8) | p.flat.b));
  const __mmask16 pass_less = (mask & ZBuffer::kLess) ? 0xFFFF : 0, pass_equal = (mask & ZBuffer::kEqual) ? 0xFFFF : 0,
                  pass_greater = (mask & ZBuffer::kGreater) ? 0xFFFF : 0;
  int64_t passes = 0;
  for (int64_t i = 0; i < n; i += 16) {
    const __mmask16 in_run = n - i >= 16 ? __mmask16(0xFFFF) : __mmask16((1u << (n - i)) - 1);
    const __m512i z = _mm512_inserti64x4(_mm512_castsi256_si512(depth_out(z_lo, z_half, z_wrap, z_round, z_max)), depth_out(z_hi, z_half, z_wrap, z_round, z_max), 1);
    const __m512i stored = _mm512_maskz_loadu_epi32(in_run, depth + i);
    const __mmask16 pass = in_run & ((_mm512_cmplt_epu32_mask(z, stored) & pass_less) |
                                     (_mm512_cmpeq_epu32_mask(z, stored) & pass_equal) |
                                     (_mm512_cmpgt_epu32_mask(z, stored) & pass_greater));
    if (depth_write) _mm512_mask_storeu_epi32(depth + i, pass, z);
    __m512i c = flat;
    if (p.gouraud)
      c = _mm512_or_si512(_mm512_or_si512(_mm512_slli_epi32(color_out(c_value[0], c_half, c_wrap, c_round, c_max), 16), _mm512_slli_epi32(color_out(c_value[1], c_half, c_wrap, c_round, c_max), 8)),
                          color_out(c_value[2], c_half, c_wrap, c_round, c_max));
    _mm512_mask_storeu_epi32(color + i, pass, c);
    passes += __builtin_popcount(pass);
    z_lo = _mm512_add_epi64(z_lo, z_block);
    z_hi = _mm512_add_epi64(z_hi, z_block);
    for (int k = 0; k < 3; ++k) c_value[k] = _mm512_add_epi32(c_value[k], c_block[k]);
  }
  return passes;
}
#endif

struct KernelVersion {
  const char* name;
  RunKernel kernel;
  bool available;
  int64_t short_run_limit;  // runs shorter than this are done one fragment at a time instead
};

std::vector<KernelVersion> kernel_versions() {
  std::vector<KernelVersion> versions;
#ifdef RASTERSIM_X86_KERNELS
  __builtin_cpu_init();
  const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("bmi2") && __builtin_cpu_supports("fma");
  const bool avx512 = avx2 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
                      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
  versions.push_back({"avx512-masked", run_avx512_masked, avx512, 1});
  versions.push_back({"avx512", run_avx512, avx512, kCompiledShortRun});
  versions.push_back({"avx2", run_avx2, avx2, kCompiledShortRun});
#endif
  versions.push_back({"generic", run_generic, true, kCompiledShortRun});
  return versions;
}

KernelVersion& selected_kernel() {
  static KernelVersion kernel = [] {
    for (const KernelVersion& v : kernel_versions())
      if (v.available) return v;
    return KernelVersion{"generic", run_generic, true, kCompiledShortRun};
  }();
  return kernel;
}

}  // namespace

ZBuffer::ZBuffer(const Profile& p)
    : width_(p.width), height_(p.height), pass_mask_(pass_mask(p.depth_func)), depth_write_(p.depth_write),
      latency_(p.memory_latency), run_kernel_(selected_kernel().kernel),
      short_run_limit_(selected_kernel().short_run_limit), memory_(p),
      inflight_address_(size_t(p.memory_latency)), inflight_cycle_(size_t(p.memory_latency)) {
  clear();
}

void ZBuffer::clear() {
  memory_.clear();
  std::fill(inflight_address_.begin(), inflight_address_.end(), std::numeric_limits<uint32_t>::max());
  std::fill(inflight_cycle_.begin(), inflight_cycle_.end(), std::numeric_limits<int64_t>::min() / 2);
  slot_ = 0;
  fresh_ = 0;
  busy_until_ = -1;
  counters_ = {};
}

std::vector<std::string> run_kernel_versions() {
  std::vector<std::string> names;
  for (const KernelVersion& v : kernel_versions())
    if (v.available) names.push_back(v.name);
  return names;
}

void select_run_kernel(const std::string& name) {
  for (const KernelVersion& v : kernel_versions())
    if (v.available && name == v.name) {
      selected_kernel() = v;
      return;
    }
  throw std::invalid_argument("run kernel '" + name + "' is not available on this CPU");
}

}  // namespace rastersim
