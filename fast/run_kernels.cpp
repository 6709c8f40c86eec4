// The z-buffer's run kernels: the depth test and conditional write of a run of fragments, compiled
// for several instruction sets. The same results as one fragment at a time (tests/test_fast_path.cpp
// runs every version this CPU has).
#include "fast/run_kernels.h"

#include <stdexcept>

#include "fast/zbuffer_avx512.h"
#include "model/zbuffer.h"

namespace rastersim {
namespace {

// The depth test and conditional write of n fragments, written without branches or 64-bit
// arithmetic shifts so that it vectorizes: every word is stored back, changed or not.
template <bool Gouraud, bool DepthWrite>
inline __attribute__((always_inline)) int64_t run_loop(uint32_t* depth, uint32_t* color, int64_t n, unsigned mask,
                                                        const ZAdder::Run& p) {
  const bool pass_less = mask & ZBuffer::kLess, pass_equal = mask & ZBuffer::kEqual, pass_greater = mask & ZBuffer::kGreater;
  // Local copies: stores through depth and color could otherwise alias the formats' int fields.
  const UnsignedPlaneOutput depth_output(p.depth_format), color_output(p.color_format);
  uint64_t z_value = p.value[0], r_value = p.value[1], g_value = p.value[2], b_value = p.value[3];
  const uint64_t z_step = p.step_x[0], r_step = p.step_x[1], g_step = p.step_x[2], b_step = p.step_x[3];
  const uint32_t flat = (uint32_t(p.flat.r) << 16) | (uint32_t(p.flat.g) << 8) | p.flat.b;
  int64_t passes = 0;
  for (int64_t i = 0; i < n; ++i) {
    const uint32_t z = depth_output(z_value);
    const uint32_t stored = depth[i];
    const bool pass = ((z < stored) & pass_less) | ((z == stored) & pass_equal) | ((z > stored) & pass_greater);
    const uint32_t c = Gouraud ? (color_output(r_value) << 16) | (color_output(g_value) << 8) | color_output(b_value)
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

RASTERSIM_AVX512 int64_t run_masked(uint32_t* depth, uint32_t* color, int64_t n, unsigned mask, bool depth_write,
                                    const ZAdder::Run& p) {
  return avx512_masked_fits(p) ? run_avx512_masked(depth, color, n, mask, depth_write, p)
                               : run_avx512(depth, color, n, mask, depth_write, p);
}
#endif

struct KernelVersion {
  RunKernelVersion version;
  bool available;
};

std::vector<KernelVersion> kernel_versions() {
  std::vector<KernelVersion> versions;
#ifdef RASTERSIM_X86_KERNELS
  __builtin_cpu_init();
  const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("bmi2") && __builtin_cpu_supports("fma");
  const bool avx512 = avx2 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
                      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
  versions.push_back({{"avx512-masked", run_masked, 1}, avx512});
  versions.push_back({{"avx512", run_avx512, kCompiledShortRun}, avx512});
  versions.push_back({{"avx2", run_avx2, kCompiledShortRun}, avx2});
#endif
  versions.push_back({{"generic", run_generic, kCompiledShortRun}, true});
  return versions;
}

RunKernelVersion& selected() {
  static RunKernelVersion kernel = [] {
    for (const KernelVersion& v : kernel_versions())
      if (v.available) return v.version;
    return RunKernelVersion{"generic", run_generic, kCompiledShortRun};
  }();
  return kernel;
}

}  // namespace

const RunKernelVersion& selected_run_kernel_version() { return selected(); }

std::vector<std::string> run_kernel_versions() {
  std::vector<std::string> names;
  for (const KernelVersion& v : kernel_versions())
    if (v.available) names.push_back(v.version.name);
  return names;
}

void select_run_kernel(const std::string& name) {
  for (const KernelVersion& v : kernel_versions())
    if (v.available && name == v.version.name) {
      selected() = v.version;
      return;
    }
  throw std::invalid_argument("run kernel '" + name + "' is not available on this CPU");
}

}  // namespace rastersim
