// The z-buffer's run kernels: one loop over a run of fragments (depth test, conditional write),
// compiled for several instruction sets; the best this CPU has is used. A fast path beside the
// model (model/zbuffer.h test_and_write_run): the same results, checked by tests/test_fast_path.cpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/z_adder.h"

namespace rastersim {

using RunKernel = int64_t (*)(uint32_t* depth, uint32_t* color, int64_t n, unsigned pass_mask, bool depth_write,
                              const ZAdder::Run& planes);

struct RunKernelVersion {
  const char* name;         // avx512-masked, avx512, avx2 (x86-64) or generic
  RunKernel kernel;
  int64_t short_run_limit;  // runs shorter than this are done one fragment at a time instead
};

std::vector<std::string> run_kernel_versions();  // those this CPU can run, best first
void select_run_kernel(const std::string& name);  // throws std::invalid_argument if not available
// The version a ZBuffer constructed now uses: the best available, or the one selected.
const RunKernelVersion& selected_run_kernel_version();

}  // namespace rastersim
