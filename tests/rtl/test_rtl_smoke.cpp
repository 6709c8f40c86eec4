#include <gtest/gtest.h>

#include "testbench/rtl_backend.h"

namespace rastersim::rtl {
namespace {

SnappedTriangle make(int S, std::initializer_list<std::array<int, 3>> v) {
  SnappedTriangle t;
  int k = 0;
  for (const auto& p : v) {
    t.v[k].x = p[0] << S;
    t.v[k].y = p[1] << S;
    t.v[k].z = uint32_t(p[2]);
    t.v[k].color = Rgb{uint8_t(40 * k), uint8_t(200 - 50 * k), uint8_t(90 + k)};
    ++k;
  }
  return t;
}

TEST(RtlSmoke, OneTriangle) {
  Profile p;
  p.width = 64, p.height = 48;
  std::vector<SnappedTriangle> tris = {make(4, {{2, 3, 1000}, {30, 5, 200000}, {10, 25, 50000}})};
  const RtlResult model = run_model(p, tris);
  const RtlResult rtl = run_rtl(p, tris);
  const Divergence d = compare(model, rtl);
  EXPECT_FALSE(d.found) << d.sentence;
}

}  // namespace
}  // namespace rastersim::rtl
