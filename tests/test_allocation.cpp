// The pipeline's hot loop allocates nothing: with the global operator new replaced by a counting
// one, submitting drawn triangles (small and large, both traversals, both shadings, with and
// without a fragment sink) performs zero allocations once the Pipeline is constructed.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "model/pipeline.h"
#include "test_util.h"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<int64_t> g_allocations{0};
}  // namespace

// Replacements for the whole test executable; they only count while g_counting is set.
void* operator new(std::size_t size) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return ::operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace rastersim {
namespace {

// Counts allocations made by `work`.
template <class Work>
int64_t allocations_during(Work&& work) {
  g_allocations = 0;
  g_counting = true;
  work();
  g_counting = false;
  return g_allocations.load();
}

// A sink that stores nothing, so that any allocation seen is the pipeline's.
struct CountingSink : FragmentSink {
  int64_t fragments = 0;
  void on_fragment(const Fragment&) override { ++fragments; }
};

TEST(Allocation, TheCounterSeesAllocations) {
  const int64_t seen = allocations_during([] { ::operator delete(::operator new(64)); });
  EXPECT_EQ(seen, 1) << "the replaced operator new must count, or the test below proves nothing";
}

TEST(Allocation, SubmitAllocatesNothing) {
  for (Traversal traversal : {Traversal::BBox, Traversal::Span})
    for (Shading shading : {Shading::Gouraud, Shading::Flat})
      for (bool with_sink : {false, true}) {
        Profile p = test::make_profile(640, 480, 4, traversal, 24);
        p.shading = shading;
        p.depth_func = DepthFunc::Less;
        p.memory_latency = 8;
        SCOPED_TRACE(::testing::Message() << test::describe(p) << (with_sink ? " with" : " without") << " a sink");
        test::TriangleGen gen(p, 3);
        std::vector<SnappedTriangle> triangles;
        for (int n = 0; n < 300; ++n)
          triangles.push_back(n % 3 == 0 ? gen.guard_band() : n % 3 == 1 ? gen.near_screen(30) : gen.tiny());
        Pipeline pipe(p);
        CountingSink sink;
        if (with_sink) pipe.set_fragment_sink(&sink);
        pipe.submit(triangles[0]);  // anything lazily set up happens here, outside the count
        const int64_t allocations = allocations_during([&] {
          for (const SnappedTriangle& t : triangles) pipe.submit(t);
        });
        EXPECT_EQ(allocations, 0);
        const FrameStats& stats = pipe.stats();
        EXPECT_GT(stats.triangles_drawn, 150) << "the triangles must really be drawn";
        EXPECT_GT(stats.fragments, 10000);
      }
}

}  // namespace
}  // namespace rastersim
