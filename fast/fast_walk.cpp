#include "fast/fast_walk.h"

#include "fast/zbuffer_avx512.h"

namespace rastersim {

// The walker's output as Pipeline::StepSink has it, and runs: without a trace, once no hazard can
// stall them, a run of fragments is accepted one per cycle: the z-buffer's timing at once, then each
// fragment's depth test and write in order.
template <bool Avx512>
struct FastWalk::Sink {
  Pipeline& p;
  TriangleRecord& record;
  int64_t fragment(int x, int y, const ZAdder& adders, int64_t cycle) {
    return p.take_fragment<false>(x, y, adders, cycle, record);
  }
  bool run(int x, int y, int64_t n, ZAdder& adders, int64_t cycle) {
    ZBuffer& zbuffer = p.zbuffer_;
    if (!zbuffer.settled(cycle)) return false;
    const uint32_t address = uint32_t(y) * uint32_t(p.profile_.width) + uint32_t(x);
    zbuffer.take_run(address, cycle, n);
    int64_t passes;
    zbuffer.prefetch_rows_below(address, n, 2);
#ifdef RASTERSIM_HAVE_AVX512_KERNEL
    if (Avx512) {  // every run, inlined
      record.depth_pass += zbuffer.test_and_write_run(address, n, adders.run(), run_avx512_masked);
      adders.step_x(n);
      record.fragments += n;
      return true;
    }
#endif
    if (n < zbuffer.short_run_limit()) {
      const ZAdder values = adders;  // a local copy the compiler keeps in machine registers
      passes = zbuffer.test_and_write_short_run(address, n, values);
    } else {
      passes = zbuffer.test_and_write_run(address, n, adders.run());
    }
    adders.step_x(n);
    record.fragments += n;
    record.depth_pass += passes;
    return true;
  }
};

bool FastWalk::avx512_applies(const Pipeline& p) {
#ifdef RASTERSIM_HAVE_AVX512_KERNEL
  return p.zbuffer_.selected_run_kernel() == "avx512-masked" && avx512_masked_fits(p.adders_.run());
#else
  (void)p;
  return false;
#endif
}

int64_t FastWalk::walk(Pipeline& p, const SetupResult& s, int64_t load_cycle, TriangleRecord& record) {
#ifdef RASTERSIM_HAVE_AVX512_KERNEL
  if (p.avx512_walk_) return walk_avx512(p, s, load_cycle, record);
#endif
  Sink<false> sink{p, record};
  return p.walker_.walk(s, p.adders_, load_cycle, p.walker_idle_load_, sink, p.walker_counters_);
}

#ifdef RASTERSIM_HAVE_AVX512_KERNEL
// The walk compiled for AVX-512 with the run kernel inlined (flatten): no call per row.
RASTERSIM_AVX512 __attribute__((flatten)) int64_t FastWalk::walk_avx512(Pipeline& p, const SetupResult& s,
                                                                         int64_t load_cycle, TriangleRecord& record) {
  Sink<true> sink{p, record};
  return p.walker_.walk(s, p.adders_, load_cycle, p.walker_idle_load_, sink, p.walker_counters_);
}
#else
int64_t FastWalk::walk_avx512(Pipeline& p, const SetupResult& s, int64_t load_cycle, TriangleRecord& record) {
  return walk(p, s, load_cycle, record);
}
#endif

}  // namespace rastersim
