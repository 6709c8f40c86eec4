// The untraced walk: without a fragment sink the pipeline takes whole runs of fragments at once
// once no hazard can stall them (ZBuffer::settled, take_run), through the z-buffer's run kernels
// (fast/run_kernels.h), and with the AVX-512 kernel the whole walk is compiled for AVX-512 with the
// kernel inlined. A fast path beside the model: the same fragments, buffers, counters and cycles as
// the traced walk (Pipeline::walk_stepwise), which tests/test_fast_path.cpp checks.
#pragma once

#include <cstdint>

#include "model/pipeline.h"

namespace rastersim {

struct FastWalk {
  // True when the inline AVX-512 kernel is the selected one and holds the profile's colour registers.
  static bool avx512_applies(const Pipeline& p);
  // Walks a drawn triangle's record loaded in `load_cycle`; returns the walker's last cycle.
  static int64_t walk(Pipeline& p, const SetupResult& s, int64_t load_cycle, TriangleRecord& record);

  template <bool Avx512>
  struct Sink;
  static int64_t walk_avx512(Pipeline& p, const SetupResult& s, int64_t load_cycle, TriangleRecord& record);
};

}  // namespace rastersim
