// The z-buffer's run kernels: one loop over a run of fragments (depth test, conditional write),
// compiled for several instruction sets; the best this CPU has is used. A fast path beside the
// model (ZBuffer::test_and_write one fragment at a time, model/zbuffer.h): the same results,
// checked by tests/test_fast_path.cpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

// Relative, as in model/: installed, these headers are reached as <rastersim/fast/...>.
#include "../model/z_adder.h"

namespace rastersim {

// PlaneFormat::output() without a 64-bit arithmetic shift (SIMD units up to AVX2 have none): a
// negative register gives 0; otherwise the logical shift equals the arithmetic one. The same result
// for every value; the compiled run kernels use it so that the compiler can vectorize.
class UnsignedPlaneOutput {
 public:
  explicit UnsignedPlaneOutput(const PlaneFormat& f)
      : wrap_shift_(64 - f.reg_bits()), round_shift_(64 - f.reg_bits() + f.guard_bits()),
        addend_(f.rounding_addend()), out_max_(uint64_t(f.out_max())) {}
  uint32_t operator()(uint64_t value) const {
    const uint64_t shifted = (value + addend_) << wrap_shift_;
    const uint64_t rounded = shifted >> round_shift_;
    return int64_t(shifted) < 0 ? 0u : uint32_t(rounded > out_max_ ? out_max_ : rounded);
  }

 private:
  int wrap_shift_, round_shift_;
  uint64_t addend_, out_max_;
};

// The depth test and conditional write of n fragments at consecutive words from `depth` and
// `color`, fragment i's values i x steps on from `planes`; returns how many passed.
using RunKernel = int64_t (*)(uint32_t* depth, uint32_t* color, int64_t n, unsigned pass_mask, bool depth_write,
                              const ZAdder::Run& planes);

struct RunKernelVersion {
  const char* name;         // avx512-masked, avx512, avx2 (x86-64) or generic
  RunKernel kernel;
  int64_t short_run_limit;  // runs shorter than this are done one fragment at a time instead
};

std::vector<std::string> run_kernel_versions();  // those this CPU can run, best first
void select_run_kernel(const std::string& name);  // throws std::invalid_argument if not available
// The version a pipeline constructed now walks with (fast/fast_walk.h): the best available, or the
// one selected.
const RunKernelVersion& selected_run_kernel_version();

}  // namespace rastersim
