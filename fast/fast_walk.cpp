#include "fast/fast_walk.h"

#include <algorithm>
#include <cstring>

#include "fast/fast_setup.h"
#include "fast/run_kernels.h"
#include "fast/zbuffer_avx512.h"
#include "fast/zbuffer_runs.h"

namespace rastersim {
namespace {

// Fragment i's outputs of a run from the registers at its start (ZAdder::Run: the plain depth
// output, which fast_walk_runner requires), for the short runs taken one fragment at a time. A
// local value, kept in machine registers: a copy of the whole ZAdder (texture and left-edge
// registers too) cost more than the short run itself.
struct RunOutputs {
  ZAdder::Run planes;
  uint32_t depth_at(int64_t i) const {
    return uint32_t(planes.depth_format.output(planes.value[0] + uint64_t(i) * planes.step_x[0]));
  }
  Rgb color_at(int64_t i) const {
    if (!planes.gouraud) return planes.flat;
    auto channel = [&](int k) {
      return uint8_t(planes.color_format.output(planes.value[k] + uint64_t(i) * planes.step_x[k]));
    };
    return Rgb{channel(1), channel(2), channel(3)};
  }
};

// Runs offered by the walk (Pipeline::walk_offering_runs): once no hazard can stall them, taken
// one per cycle: the z-buffer's timing at once, then each fragment's depth test and write in order.
template <bool Avx512>
struct Runs {
  RunKernelVersion kernel;  // unused with Avx512: run_avx512_masked, inlined
  bool run(ZBuffer& zbuffer, uint32_t address, int64_t n, ZAdder& adders, int64_t cycle, TriangleRecord& record) {
    ZBufferRuns z(zbuffer);
    if (!z.can_take_run(address, n, cycle)) return false;
    z.take_run(address, cycle, n);
    int64_t passes;
    z.prefetch_rows_below(address, n, 2);
#ifdef RASTERSIM_HAVE_AVX512_KERNEL
    if (Avx512) {  // every run, inlined
      record.depth_pass += z.test_and_write_run(address, n, adders.run(), run_avx512_masked);
      record.fragments += n;
      return true;
    }
#endif
    if (n < kernel.short_run_limit) {
      passes = z.test_and_write_short_run(address, n, RunOutputs{adders.run()});
    } else {
      passes = z.test_and_write_run(address, n, adders.run(), kernel.kernel);
    }
    record.fragments += n;
    record.depth_pass += passes;
    return true;
  }
};

// The words of a triangle's first two rows, which the walk's own prefetch (two rows below each
// run) does not ask for: the rows of its vertices' box, before the setup.
void prefetch_first_rows(Pipeline& p, const SnappedTriangle& t) {
  const int S = p.profile().subpixel_bits;
  const SnappedVertex* v = t.v;
  const int64_t x0 = std::min({v[0].x, v[1].x, v[2].x}) >> S, x1 = std::max({v[0].x, v[1].x, v[2].x}) >> S;
  const int64_t y0 = std::min({v[0].y, v[1].y, v[2].y}) >> S;
  ZBufferRuns(p.zbuffer_words()).prefetch_box(x0, x1, y0, 2);
}

// The walk with a run kernel called per run; the rest of the walk inlined (flatten).
class KernelWalk final : public WalkRunner {
 public:
  void prefetch(Pipeline& p, const SnappedTriangle& t) const override { prefetch_first_rows(p, t); }
  void set_up(const TriangleSetup& setup, const SnappedTriangle& t, SetupResult& r) const override {
    fast_set_up(setup, t, r);  // rows entered with enter_row_at
  }
  explicit KernelWalk(const RunKernelVersion& kernel) : kernel_(kernel) {}
  __attribute__((flatten)) int64_t walk(Pipeline& p, const SetupResult& s, int64_t load_cycle,
                                        TriangleRecord& record) const override {
    Runs<false> runs{kernel_};
    return p.walk_offering_runs(s, load_cycle, record, runs);
  }

 private:
  RunKernelVersion kernel_;
};

#ifdef RASTERSIM_HAVE_AVX512_KERNEL
// The walk compiled for AVX-512 with the run kernel inlined (flatten): no call per row.
RASTERSIM_AVX512 __attribute__((flatten)) int64_t walk_avx512(Pipeline& p, const SetupResult& s, int64_t load_cycle,
                                                               TriangleRecord& record) {
  Runs<true> runs{};
  return p.walk_offering_runs(s, load_cycle, record, runs);
}

class Avx512Walk final : public WalkRunner {
 public:
  void prefetch(Pipeline& p, const SnappedTriangle& t) const override { prefetch_first_rows(p, t); }
  void set_up(const TriangleSetup& setup, const SnappedTriangle& t, SetupResult& r) const override {
    fast_set_up(setup, t, r);  // rows entered with enter_row_at
  }
  int64_t walk(Pipeline& p, const SetupResult& s, int64_t load_cycle, TriangleRecord& record) const override {
    return walk_avx512(p, s, load_cycle, record);
  }
};
#endif

}  // namespace

std::shared_ptr<const WalkRunner> fast_walk_runner(const Pipeline& p) {
  // The runs go straight to the z-buffer and take the plain depth output.
  if (p.profile().texture_unit || !p.z_adder().plain_depth_output()) return nullptr;
  const RunKernelVersion& kernel = selected_run_kernel_version();
#ifdef RASTERSIM_HAVE_AVX512_KERNEL
  // The inline kernel when it is the selected one and holds the profile's colour registers.
  if (std::strcmp(kernel.name, "avx512-masked") == 0 && avx512_masked_fits(p.z_adder().run()))
    return std::make_shared<const Avx512Walk>();
#endif
  return std::make_shared<const KernelWalk>(kernel);
}

void use_fast_walk() { Pipeline::set_walk_runner_choice(fast_walk_runner); }

}  // namespace rastersim
