#include <gtest/gtest.h>

#include <random>

#include "model/pipeline.h"
#include "reference.h"

namespace rastersim {
namespace {

struct Collect : FragmentSink {
  std::vector<Fragment> fragments;
  void on_fragment(const Fragment& f) override { fragments.push_back(f); }
};

TEST(Smoke, RandomTrianglesMatchReference) {
  std::mt19937 rng(1);
  for (int S : {1, 4, 8}) {
    for (Traversal trav : {Traversal::BBox, Traversal::Span}) {
      Profile p;
      p.width = 64, p.height = 48, p.subpixel_bits = S, p.traversal = trav;
      std::uniform_int_distribution<int> cx(-p.width << S, (2 * p.width) << S), cy(-p.height << S, (2 * p.height) << S);
      std::uniform_int_distribution<int> small(-40, 40);
      for (int n = 0; n < 3000; ++n) {
        SnappedTriangle t;
        const bool tiny = n % 2;
        for (int k = 0; k < 3; ++k) {
          t.v[k].x = tiny ? (20 << S) + small(rng) * (1 << S) / 8 : cx(rng);
          t.v[k].y = tiny ? (20 << S) + small(rng) * (1 << S) / 8 : cy(rng);
          t.v[k].z = rng() & 0xffffff;
        }
        Pipeline pipe(p);
        Collect c;
        pipe.set_fragment_sink(&c);
        pipe.submit(t);
        const auto ref = reference::covered_pixels(t, p);
        ASSERT_EQ(ref.size(), c.fragments.size()) << "S=" << S << " n=" << n;
        const uint32_t z[3] = {t.v[0].z, t.v[1].z, t.v[2].z};
        for (size_t i = 0; i < ref.size(); ++i) {
          ASSERT_EQ(ref[i].x, c.fragments[i].x);
          ASSERT_EQ(ref[i].y, c.fragments[i].y);
          ASSERT_TRUE(reference::within_one_lsb(c.fragments[i].z, reference::plane_at_centre(t, z, S, ref[i].x, ref[i].y)));
        }
      }
    }
  }
}

}  // namespace
}  // namespace rastersim
