#include "fast/fast_setup.h"

namespace rastersim {
namespace {

uint64_t magnitude(int64_t v) { return v < 0 ? 0 - uint64_t(v) : uint64_t(v); }
int bits_of(uint64_t magnitude_or) { return magnitude_or == 0 ? 0 : 64 - __builtin_clzll(magnitude_or); }

// The plane weights of the vertices' differences: edges 1 and 2 at the first candidate and their
// steps (the specification weights v0 by edge 1, v1 by edge 2 and v2 by edge 0).
struct Weights {
  int64_t at_start[2], step_x[2], step_y[2];
  int bits;  // every weight's magnitude is below 2^bits
};

// A plane from its vertex values (TriangleSetup::plane) by the vertex differences d0 = v0 - v2 and
// d1 = v1 - v2: the edge functions sum to area2 at every point and their steps to 0, so the
// specification's numerators are d0 E1 + d1 E2 + v2 area2 at the start and d0 s1 + d1 s2 for each
// step, and floor(2^F P) at the start is v2 2^F + floor((d0 E1 + d1 E2) 2^F / area2): six products.
class FastPlane {
 public:
  FastPlane(int guard_bits, int reg_bits, int divider_bits)
      : guard_bits_(guard_bits), reg_bits_(reg_bits), dividend_limit_((unsigned __int128)1 << (divider_bits - guard_bits)) {}

  // Whether the plane's shifted numerators fit in 64 bits (then make() applies).
  bool fits(const int64_t value[3], const Weights& w) const {
    const int d_bits = bits_of(magnitude(value[0] - value[2]) | magnitude(value[1] - value[2]));
    return d_bits + w.bits + 1 + guard_bits_ <= 63;
  }

  PlaneSetup make(const int64_t value[3], const Weights& w, int64_t area, const FloorDivider& by_area,
                  const char* what) const {
    const int64_t d0 = value[0] - value[2], d1 = value[1] - value[2];
    const int64_t start = d0 * w.at_start[0] + d1 * w.at_start[1];
    const int64_t step_x = d0 * w.step_x[0] + d1 * w.step_x[1];
    const int64_t step_y = d0 * w.step_y[0] + d1 * w.step_y[1];
    // The specification's dividend check, on its own numerators.
    check_dividend(i128(start) + i128(value[2]) * area, what);
    check_dividend(step_x, what);
    check_dividend(step_y, what);
    PlaneSetup p;
    // Modulo 2^64 is enough: the register keeps reg_bits <= 64 of it.
    p.start = wrap_signed(i128(uint64_t(value[2]) << guard_bits_) + uint64_t(quotient(start, by_area)), reg_bits_);
    p.step_x = wrap_signed(quotient(step_x, by_area), reg_bits_);
    p.step_y = wrap_signed(quotient(step_y, by_area), reg_bits_);
    return p;
  }

 private:
  int64_t quotient(int64_t numerator, const FloorDivider& by_area) const {
    return int64_t(by_area(int64_t(uint64_t(numerator) << guard_bits_)).quotient);
  }
  void check_dividend(i128 numerator, const char* what) const {
    const unsigned __int128 m = numerator < 0 ? (unsigned __int128)(-numerator) : (unsigned __int128)numerator;
    if (m >= dividend_limit_) throw WidthOverflow(std::string(what) + " dividend exceeds its divider width");
  }
  int guard_bits_, reg_bits_;
  unsigned __int128 dividend_limit_;  // 2^(divider_bits - F): |numerator| 2^F must stay below 2^divider_bits
};

}  // namespace

void fast_set_up(const TriangleSetup& setup, const SnappedTriangle& tri, SetupResult& r) {
  SetupEdges edges;
  if (!setup.front(tri, r, edges)) return;
  const bool gouraud = setup.profile().shading == Shading::Gouraud;
  const SnappedVertex& v0 = *edges.v[0];
  const SnappedVertex& v1 = *edges.v[1];
  const SnappedVertex& v2 = *edges.v[2];
  Weights w;
  uint64_t all = 0;
  for (int j = 0; j < 2; ++j) {
    w.at_start[j] = int64_t(edges.unbiased[j + 1]);  // edge_bits <= 63 (model/widths.h)
    w.step_x[j] = edges.step_x[j + 1];
    w.step_y[j] = edges.step_y[j + 1];
    all |= magnitude(w.at_start[j]) | magnitude(w.step_x[j]) | magnitude(w.step_y[j]);
  }
  w.bits = bits_of(all);
  const Widths& widths = setup.widths();
  const FastPlane depth_plane(widths.guard_bits, widths.z_reg_bits, widths.divider_bits);
  const FastPlane color_plane(widths.guard_bits, widths.color_reg_bits, widths.divider_bits);
  const int64_t z[3] = {v0.z, v1.z, v2.z};
  const int64_t color[3][3] = {{v0.color.r, v1.color.r, v2.color.r},
                               {v0.color.g, v1.color.g, v2.color.g},
                               {v0.color.b, v1.color.b, v2.color.b}};
  // The texture planes and wide numerators take the specification's planes.
  bool fits = !r.textured && depth_plane.fits(z, w);
  if (gouraud)
    for (const int64_t* c : color) fits = fits && color_plane.fits(c, w);
  if (!fits) return setup.planes(edges, r);
  const FloorDivider by_area(edges.area);
  r.depth = depth_plane.make(z, w, edges.area, by_area, "depth plane");
  if (gouraud) {
    static const char* const names[3] = {"red plane", "green plane", "blue plane"};
    for (int c = 0; c < 3; ++c) r.color[c] = color_plane.make(color[c], w, edges.area, by_area, names[c]);
  }
  for (PlaneSetup& p : r.texture) p = PlaneSetup{};
}

}  // namespace rastersim
