// Fuzz target: the triangle setup unit (model/triangle_setup.cpp) and the walker behind it, fed raw
// vertex bit patterns on a fuzzed profile. The input is decoded with FuzzedDataProvider:
//   profile: width, height 1..4096, subpixel_bits 1..8, z_bits 16..32, z_guard_bits 0 (derived) or
//            1..24, cull, front_face, traversal, shading;
//   vertices, by the first choice byte:
//     0  x, y, z as raw IEEE-754 double bit patterns through check_screen_triangle and snap (the
//        CLI's path for .tri input; most patterns are refused there, as the CLI refuses them);
//     1  x, y as raw int32 subpixels and z as a raw uint32, kept only inside the setup unit's input
//        range (snapped guard band [-W 2^S, 2W 2^S], z <= 2^N - 1; triangle.h);
//     2  integers drawn inside that range (reaches large and far triangles quickly);
//   colours: nine raw bytes.
// Invariants, each against tests/reference.cpp (written from the rules, not from the model):
//  - setup never throws (no WidthOverflow: the derived widths hold every value);
//  - degenerate exactly when the reference's twice-area is 0; culled only as the profile says;
//  - the bounding box equals the reference's candidate rectangle, offscreen exactly when it is empty;
//  - the span DDA's quotient / remainder pairs recompose the edge values;
//  - at sampled pixels of the box the absolute edge form start + dx step_x + dy step_y fits
//    edge_bits and its sign test equals the reference's coverage (top-left rule), and at covered
//    ones the depth plane's rounded value is within 1 LSB of the exact plane (derived guard bits);
//  - for boxes up to 16384 pixels, both traversals emit exactly the reference's covered pixels in
//    row order, with every plane register equal to its absolute form.
#include <fuzzer/FuzzedDataProvider.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "model/scanline_walker.h"
#include "model/triangle_setup.h"
#include "model/z_adder.h"
#include "tests/fuzz/fuzz_support.h"
#include "tests/reference.h"

namespace {

using namespace rastersim;

Profile consume_profile(FuzzedDataProvider& in) {
  Profile p;
  p.width = in.ConsumeIntegralInRange(1, 4096);
  p.height = in.ConsumeIntegralInRange(1, 4096);
  p.subpixel_bits = in.ConsumeIntegralInRange(1, 8);
  p.z_bits = in.ConsumeIntegralInRange(16, 32);
  p.z_guard_bits = in.ConsumeBool() ? 0 : in.ConsumeIntegralInRange(1, 24);
  p.cull = CullMode(in.ConsumeIntegralInRange(0, 2));
  p.front_face = in.ConsumeBool() ? FrontFace::CCW : FrontFace::CW;
  p.traversal = in.ConsumeBool() ? Traversal::BBox : Traversal::Span;
  p.shading = in.ConsumeBool() ? Shading::Flat : Shading::Gouraud;
  return p;
}

// False when the pattern is outside what the setup unit accepts (the CLI refuses it before).
bool consume_triangle(FuzzedDataProvider& in, const Profile& p, SnappedTriangle& out) {
  const int64_t M = int64_t(1) << p.subpixel_bits;
  const int64_t x_lo = -int64_t(p.width) * M, x_hi = 2 * int64_t(p.width) * M;
  const int64_t y_lo = -int64_t(p.height) * M, y_hi = 2 * int64_t(p.height) * M;
  const uint32_t z_max = p.depth_max();
  const int mode = in.ConsumeIntegralInRange(0, 2);
  if (mode == 0) {
    ScreenTriangle screen;
    for (ScreenVertex& v : screen.v)
      for (double* field : {&v.x, &v.y, &v.z}) {
        const uint64_t bits = in.ConsumeIntegral<uint64_t>();
        std::memcpy(field, &bits, sizeof bits);
      }
    for (ScreenVertex& v : screen.v) v.color = {in.ConsumeIntegral<uint8_t>(), in.ConsumeIntegral<uint8_t>(), in.ConsumeIntegral<uint8_t>()};
    if (!check_screen_triangle(screen, p).empty()) return false;
    out = snap(screen, p);
    for (const SnappedVertex& v : out.v)
      FUZZ_REQUIRE(v.x >= x_lo && v.x <= x_hi && v.y >= y_lo && v.y <= y_hi && v.z <= z_max,
                   "a checked screen triangle snaps outside the setup unit's input range");
    return true;
  }
  for (SnappedVertex& v : out.v) {
    if (mode == 1) {
      v.x = in.ConsumeIntegral<int32_t>();
      v.y = in.ConsumeIntegral<int32_t>();
      v.z = in.ConsumeIntegral<uint32_t>();
      if (v.x < x_lo || v.x > x_hi || v.y < y_lo || v.y > y_hi || v.z > z_max) return false;
    } else {
      v.x = int32_t(in.ConsumeIntegralInRange(x_lo, x_hi));
      v.y = int32_t(in.ConsumeIntegralInRange(y_lo, y_hi));
      v.z = in.ConsumeIntegralInRange<uint32_t>(0, z_max);
    }
    v.color = {in.ConsumeIntegral<uint8_t>(), in.ConsumeIntegral<uint8_t>(), in.ConsumeIntegral<uint8_t>()};
  }
  return true;
}

std::string where(int x, int y) { return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")"; }

// v modulo 2^bits in the two's-complement range: what a wrapping register of `bits` holds.
int64_t reduce(i128 v, int bits) { return wrap_signed(v, bits); }

struct Checker {
  const Profile& p;
  const SnappedTriangle& tri;
  const SetupResult& s;
  const Widths& w;
  bool depth_claim;  // the 1-LSB depth accuracy holds (guard bits at least the derived ones)

  void pixel(int x, int y) const {
    bool inside = true;
    for (const EdgeSetup& e : s.edge) {
      const i128 value = i128(e.start) + i128(x - s.x0) * e.step_x + i128(y - s.y0) * e.step_y;
      FUZZ_REQUIRE(fits_signed(value, w.edge_bits), "edge value outside edge_bits at " + where(x, y));
      inside = inside && value >= 0;
    }
    FUZZ_REQUIRE(inside == reference::covers(tri, p.subpixel_bits, x, y),
                 "edge sign test disagrees with the reference at " + where(x, y));
    if (inside) depth(x, y, reduce(reference::absolute_plane(s.depth, s, x, y), w.z_reg_bits));
  }

  void depth(int x, int y, int64_t depth_register) const {
    if (!depth_claim) return;
    const uint32_t z[3] = {tri.v[0].z, tri.v[1].z, tri.v[2].z};
    const int64_t out = reference::rounded_plane_output(depth_register, w.guard_bits, p.depth_max());
    FUZZ_REQUIRE(reference::within_one_lsb(out, reference::plane_at_centre(tri, z, p.subpixel_bits, x, y)),
                 "depth " + std::to_string(out) + " not within 1 LSB of the exact plane at " + where(x, y));
  }
};

struct WalkSink {
  const Checker* check;
  bool gouraud;
  std::vector<reference::Pixel> pixels;

  int64_t fragment(int x, int y, const ZAdder& adders, int64_t cycle) {
    const SetupResult& s = check->s;
    const Widths& w = check->w;
    pixels.push_back({x, y});
    const int64_t depth = reduce(reference::absolute_plane(s.depth, s, x, y), w.z_reg_bits);
    FUZZ_REQUIRE(adders.depth_register().value() == depth, "depth register differs from its absolute form at " + where(x, y));
    check->depth(x, y, depth);
    if (gouraud)
      for (int c = 0; c < 3; ++c)
        FUZZ_REQUIRE(adders.color_register(c).value() == reduce(reference::absolute_plane(s.color[c], s, x, y), w.color_reg_bits),
                     "colour register differs from its absolute form at " + where(x, y));
    return cycle;
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  const Profile p = consume_profile(in);
  FUZZ_REQUIRE(validate(p).empty(), "the decoder made an invalid profile");
  SnappedTriangle tri;
  if (!consume_triangle(in, p, tri)) return 0;

  const TriangleSetup setup(p);
  const SetupResult s = setup.run(tri);  // a WidthOverflow escapes: a finding
  const Widths& w = setup.widths();

  const i128 area2 = reference::twice_area(tri);
  FUZZ_REQUIRE(i128(s.area2) == area2, "area2 differs from the reference");
  FUZZ_REQUIRE((s.status == SetupStatus::Degenerate) == (area2 == 0), std::string("status ") + to_string(s.status));
  if (s.status == SetupStatus::Degenerate) return 0;
  const bool front = p.front_face == FrontFace::CCW ? area2 < 0 : area2 > 0;  // y down: area2 > 0 is clockwise
  FUZZ_REQUIRE(s.front_facing == front, "facing differs from the winding");
  const bool culled = (p.cull == CullMode::Back && !front) || (p.cull == CullMode::Front && front);
  FUZZ_REQUIRE((s.status == SetupStatus::Culled) == culled, std::string("status ") + to_string(s.status));
  if (culled) return 0;

  const reference::PixelRect box = reference::bounding_box(tri, p);
  const SetupStatus empty_status =
      reference::beyond_outer_centres(tri, p) ? SetupStatus::Offscreen : SetupStatus::NoCentre;
  FUZZ_REQUIRE((s.status == empty_status) == box.empty(), std::string("status ") + to_string(s.status));
  if (box.empty()) return 0;
  FUZZ_REQUIRE(s.x0 == box.x0 && s.x1 == box.x1 && s.y0 == box.y0 && s.y1 == box.y1,
               "bounding box differs from the reference's candidate rectangle");

  for (const EdgeSetup& e : s.edge) {
    if (e.step_x == 0) continue;
    const int64_t d = e.step_x < 0 ? -int64_t(e.step_x) : int64_t(e.step_x);
    FUZZ_REQUIRE(i128(e.span_quot) * d + e.span_rem == i128(e.start) && e.span_rem < d, "span quotient of start");
    FUZZ_REQUIRE(i128(e.span_step_quot) * d + e.span_step_rem == i128(e.step_y) && e.span_step_rem < d,
                 "span quotient of step_y");
  }

  const bool depth_claim = p.z_guard_bits == 0 || p.z_guard_bits >= derived_guard_bits(p.width, p.height);
  const Checker check{p, tri, s, w, depth_claim};
  // The box's corners and 32 more pixels of it, chosen by a generator seeded from the input.
  check.pixel(s.x0, s.y0), check.pixel(s.x1, s.y0), check.pixel(s.x0, s.y1), check.pixel(s.x1, s.y1);
  uint64_t state = 0x9e3779b97f4a7c15ull ^ size;
  for (size_t i = 0; i < size; ++i) state = (state ^ data[i]) * 0x100000001b3ull;
  for (int n = 0; n < 32; ++n) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    const int x = s.x0 + int((state >> 33) % uint64_t(s.x1 - s.x0 + 1));
    const int y = s.y0 + int((state >> 13) % uint64_t(s.y1 - s.y0 + 1));
    check.pixel(x, y);
  }

  if (box.area() > 16384) return 0;
  const std::vector<reference::Pixel> expected = reference::covered_pixels(tri, p);
  for (Traversal traversal : {Traversal::BBox, Traversal::Span}) {
    Profile walked = p;
    walked.traversal = traversal;
    const ScanlineWalker walker(walked, w);
    ZAdder adders(w, p);
    WalkSink sink{&check, p.shading == Shading::Gouraud, {}};
    WalkerCounters counters;
    walker.walk(s, adders, 0, true, sink, counters);
    FUZZ_REQUIRE(sink.pixels.size() == expected.size(),
                 std::string(to_string(traversal)) + " walk emits " + std::to_string(sink.pixels.size()) +
                     " fragments, the reference covers " + std::to_string(expected.size()));
    for (size_t i = 0; i < expected.size(); ++i)
      FUZZ_REQUIRE(sink.pixels[i].x == expected[i].x && sink.pixels[i].y == expected[i].y,
                   std::string(to_string(traversal)) + " fragment " + std::to_string(i) + " is at " +
                       where(sink.pixels[i].x, sink.pixels[i].y) + ", the reference's at " +
                       where(expected[i].x, expected[i].y));
  }
  return 0;
}
