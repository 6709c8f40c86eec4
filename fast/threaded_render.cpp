#include "fast/threaded_render.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <memory>
#include <thread>

#include "fast/fast_setup.h"
#include "fast/run_kernels.h"
#include "fast/zbuffer_runs.h"

namespace rastersim {
namespace {

// The timing pass's walk: runs that no hazard can stall go through the z-buffer's timing at once
// (ZBufferRuns::take_run); the rest, and every fragment with a texture unit (its timing is per
// fragment), one at a time through the timing-only pipeline.
struct TimingRuns {
  bool texture_unit;
  bool run(ZBuffer& zbuffer, uint32_t address, int64_t n, int64_t cycle, TriangleRecord& record) {
    if (texture_unit) return false;
    ZBufferRuns z(zbuffer);
    if (!z.can_take_run(address, n, cycle)) return false;
    z.take_run(address, cycle, n);
    record.fragments += n;
    return true;
  }
};

class TimingWalk final : public WalkRunner {
 public:
  // Neither this walk nor the workers' (BandSink enters rows with enter_row_at) reads the planes
  // along the left edges.
  void set_up(const TriangleSetup& setup, const SnappedTriangle& t, SetupResult& r) const override {
    fast_set_up(setup, t, r);
  }
  int64_t walk(Pipeline& p, const SetupResult& s, int64_t load_cycle, TriangleRecord& record) const override {
    TimingRuns runs{p.profile().texture_unit};
    return p.walk_timing_offering_runs(s, load_cycle, record, runs);
  }
};

// What a worker needs of the pipeline, read before the threads start: the timing thread changes
// the z-buffer's registers meanwhile, never its words.
struct Frame {
  uint32_t* depth;
  uint32_t* color;
  int width;
  unsigned pass_mask;
  bool depth_write;
  bool plain_depth;
  const TextureBinding* texture;
  RunKernel kernel;
};

// One worker's walk of a triangle: the same fragments as the pipeline's walk (the span traversal's,
// which are the bbox one's), of which it tests and writes those in its rows.
struct BandSink {
  static constexpr bool kEntersRowsAtOffset = true;
  const Frame& f;
  unsigned id, threads;
  int64_t passes = 0, tested = 0;

  bool mine(int y) const { return unsigned(y) / kBandRows % threads == id; }

  int64_t fragment(int x, int y, const ZAdder& adders, int64_t cycle) {
    if (!mine(y)) return cycle;
    const size_t a = size_t(y) * size_t(f.width) + size_t(x);
    const uint32_t z = adders.depth();
    Rgb color = adders.color();
    if (adders.textured()) {  // as Pipeline::take_fragment
      const TextureCoordinate uv = adders.texture_coordinate();
      const Texture* texture = f.texture->texture.get();
      color = modulate(texture ? texture->sample(uv.u, uv.v, f.texture->filter, f.texture->wrap) : Rgb{}, color);
    }
    ++tested;
    if (ZBuffer::depth_test(f.pass_mask, z, f.depth[a])) {
      if (f.depth_write) f.depth[a] = z;
      f.color[a] = ZBuffer::packed(color);
      ++passes;
    }
    return cycle;
  }
  // Rows of other threads are skipped whole; the next row is entered afresh (enter_row_at), so
  // the adders need not step past a run.
  bool run(int x, int y, int64_t n, ZAdder& adders, int64_t) {
    if (!mine(y)) return true;
    if (!f.plain_depth || adders.textured()) return false;
    const size_t a = size_t(y) * size_t(f.width) + size_t(x);
    passes += f.kernel(f.depth + a, f.color + a, n, f.pass_mask, f.depth_write, adders.run());
    tested += n;
    return true;
  }
};

// A worker's walk of one triangle, inlined whole (flatten): a call per row costs more than the row.
__attribute__((flatten)) void walk_band(const ScanlineWalker& walker, const SetupResult& s, ZAdder& adders,
                                        BandSink& sink) {
  WalkerCounters unused;
  walker.walk(s, adders, 0, false, sink, unused);
}

bool touches_band(const SetupResult& s, unsigned id, unsigned threads) {
  for (int64_t band = s.y0 / kBandRows; band <= s.y1 / kBandRows; ++band)
    if (uint64_t(band) % threads == id) return true;
  return false;
}

// The drawn triangles' setup results, from the timing thread to every worker in submission order
// (the setup is done once): a ring whose slot is written again once every worker has walked the
// triangle in it. A waiting thread yields its core.
class SetupRing {
 public:
  struct Slot {
    size_t triangle;
    SetupResult setup;
  };

  explicit SetupRing(unsigned readers) : readers_(readers), read_(new Counter[readers]) {}

  // The timing thread: the k-th drawn triangle.
  void push(size_t triangle, const SetupResult& s) {
    const uint64_t k = written_.value.load(std::memory_order_relaxed);
    while (slowest_reader() + kSlots <= k) std::this_thread::yield();
    slots_[k % kSlots] = Slot{triangle, s};
    written_.value.store(k + 1, std::memory_order_release);
  }
  // No more triangles (also after a failure).
  void close() { closed_.value.store(1, std::memory_order_release); }

  // A worker: the k-th drawn triangle, or nullptr after the last.
  const Slot* at(uint64_t k) const {
    for (;;) {
      if (written_.value.load(std::memory_order_acquire) > k) return &slots_[k % kSlots];
      if (closed_.value.load(std::memory_order_acquire))
        return written_.value.load(std::memory_order_acquire) > k ? &slots_[k % kSlots] : nullptr;
      std::this_thread::yield();
    }
  }
  // Worker `reader` is done with the k-th (and every earlier) triangle; with k = UINT64_MAX - 1, with
  // all of them (a worker that failed must not hold the timing thread).
  void release(unsigned reader, uint64_t k) { read_[reader].value.store(k + 1, std::memory_order_release); }

 private:
  static constexpr uint64_t kSlots = 1024;
  struct alignas(64) Counter {
    std::atomic<uint64_t> value{0};
  };
  uint64_t slowest_reader() const {
    uint64_t slowest = UINT64_MAX;
    for (unsigned r = 0; r < readers_; ++r) slowest = std::min(slowest, read_[r].value.load(std::memory_order_acquire));
    return slowest;
  }
  unsigned readers_;
  std::unique_ptr<Counter[]> read_;
  Counter written_, closed_;
  std::unique_ptr<Slot[]> slots_{new Slot[kSlots]};
};

// A worker takes the drawn triangles from the ring in submission order and walks each that
// touches its bands.
void work(const Pipeline& p, const Frame& f, SetupRing& ring, unsigned id, unsigned threads,
          std::vector<int64_t>& passes, int64_t& tested, std::exception_ptr& failure) {
  try {
    Profile span = p.profile();
    span.traversal = Traversal::Span;
    const ScanlineWalker walker(span, p.widths());
    ZAdder adders(p.widths(), p.profile());
    int64_t count = 0;  // a local: the workers' totals share a cache line
    for (uint64_t k = 0;; ++k) {
      const SetupRing::Slot* slot = ring.at(k);
      if (!slot) break;
      if (touches_band(slot->setup, id, threads)) {
        BandSink sink{f, id, threads};
        walk_band(walker, slot->setup, adders, sink);
        passes[slot->triangle] = sink.passes;
        count += sink.tested;
      }
      ring.release(id, k);
    }
    tested = count;
  } catch (...) {
    failure = std::current_exception();
    ring.release(id, UINT64_MAX - 1);  // the timing thread must not wait for it
  }
}

}  // namespace

void render_threaded(Pipeline& p, const std::vector<SnappedTriangle>& triangles, int threads) {
  if (threads <= 1) {
    for (const SnappedTriangle& t : triangles) p.submit(t);
    return;
  }
  ZBufferState& z = p.zbuffer_words().state();
  const Frame frame{z.memory_.depth_words(), z.memory_.color_words(), z.width_, z.pass_mask_, z.depth_write_,
                    p.z_adder().plain_depth_output(), &p.texture(), selected_run_kernel_version().kernel};
  std::vector<TriangleRecord>* log = p.triangle_log();
  const size_t log_start = log ? log->size() : 0;
  // The calling thread is one of the threads: it sets up every triangle and does the timing.
  const unsigned count = unsigned(threads - 1);
  SetupRing ring(count);
  std::vector<std::vector<int64_t>> passes(count, std::vector<int64_t>(triangles.size(), 0));
  std::vector<int64_t> tested(count, 0);
  std::vector<std::exception_ptr> failures(count + 1);
  std::vector<std::thread> workers;
  for (unsigned id = 0; id < count; ++id)
    workers.emplace_back(work, std::cref(p), std::cref(frame), std::ref(ring), id, count, std::ref(passes[id]),
                         std::ref(tested[id]), std::ref(failures[id]));

  p.set_walk_runner(std::make_shared<const TimingWalk>());
  p.set_timing_only(true);
  try {
    for (size_t i = 0; i < triangles.size(); ++i) {
      p.submit(triangles[i]);
      if (p.last_setup().status == SetupStatus::Drawn) ring.push(i, p.last_setup());
    }
  } catch (...) {
    failures[count] = std::current_exception();
  }
  ring.close();
  for (std::thread& t : workers) t.join();
  p.set_timing_only(false);
  const WalkRunnerChoice choice = Pipeline::walk_runner_choice();
  p.set_walk_runner(choice ? choice(p) : nullptr);
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);

  int64_t all_passes = 0, all_tested = 0;
  for (unsigned id = 0; id < count; ++id) {
    all_tested += tested[id];
    for (size_t i = 0; i < triangles.size(); ++i) {
      all_passes += passes[id][i];
      if (log) (*log)[log_start + i].depth_pass += passes[id][i];
    }
  }
  p.add_depth_results(all_passes, all_tested - all_passes);
}

int machine_threads() {
  const unsigned cores = std::thread::hardware_concurrency();
  return cores == 0 ? 1 : int(std::min(cores, 256u));
}

int default_threads(const std::vector<SnappedTriangle>& triangles, const Profile& profile) {
  if (triangles.empty()) return 1;
  const int S = profile.subpixel_bits;
  int64_t pixels = 0;
  for (const SnappedTriangle& t : triangles) {
    const SnappedVertex* v = t.v;
    auto clamp = [](int64_t value, int64_t limit) { return std::min(std::max<int64_t>(value, 0), limit); };
    const int64_t x0 = clamp(std::min({v[0].x, v[1].x, v[2].x}) >> S, profile.width);
    const int64_t x1 = clamp((std::max({v[0].x, v[1].x, v[2].x}) >> S) + 1, profile.width);
    const int64_t y0 = clamp(std::min({v[0].y, v[1].y, v[2].y}) >> S, profile.height);
    const int64_t y1 = clamp((std::max({v[0].y, v[1].y, v[2].y}) >> S) + 1, profile.height);
    // The triangle's area in pixels, at most its box's on the screen.
    const int64_t area2 = int64_t(v[1].x - v[0].x) * (v[2].y - v[0].y) - int64_t(v[2].x - v[0].x) * (v[1].y - v[0].y);
    pixels += std::min((area2 < 0 ? -area2 : area2) >> (2 * S + 1), (x1 - x0) * (y1 - y0));
  }
  return pixels >= kThreadedPixels * int64_t(triangles.size()) && pixels >= kThreadedFramePixels ? machine_threads() : 1;
}

}  // namespace rastersim
