#include "triangle_setup.h"

#include <algorithm>
#include <utility>

namespace rastersim {

const char* to_string(SetupStatus status) {
  switch (status) {
    case SetupStatus::Drawn: return "drawn";
    case SetupStatus::Degenerate: return "degenerate";
    case SetupStatus::Culled: return "culled";
    case SetupStatus::Offscreen: return "offscreen";
    case SetupStatus::NoCentre: return "no_centre";
  }
  return "?";
}

bool owns_samples_on_edge(FillRule rule, int64_t dx, int64_t dy) {
  // The ordered triangle (area2 > 0) has its interior to the right of each edge as y points down:
  // dy < 0 is a left edge, dy > 0 a right one; a horizontal edge with dx > 0 has the interior
  // below it (a top edge), with dx < 0 above it (a bottom edge).
  const bool left = rule == FillRule::TopLeft || rule == FillRule::BottomLeft;
  const bool top = rule == FillRule::TopLeft || rule == FillRule::TopRight;
  if (dy != 0) return left ? dy < 0 : dy > 0;
  return top ? dx > 0 : dx < 0;
}

TriangleSetup::TriangleSetup(const Profile& profile) : profile_(profile), widths_(derive_widths(profile)) {}

// Plane through the three vertex values, by barycentric weights of the edge functions:
// P(Q) = (v0 E1(Q) + v1 E2(Q) + v2 E0(Q)) / area2, edge k opposite vertex k+2.
PlaneSetup TriangleSetup::plane(const i128 value[3], const i128 edge_at_start[3], const int64_t step_x[3],
                                const int64_t step_y[3], const FloorDivider& by_area2, PlaneFormatBits format,
                                const char* what) const {
  const int F = format.guard_bits;
  // Every factor fits in 64 bits (vertex values; edge functions and steps, edge_bits <= 63 by
  // model/widths.h): 64 x 64 -> 128-bit products.
  auto product = [](i128 a, i128 b) { return i128(int64_t(a)) * int64_t(b); };
  auto weighted = [&](auto edge) {
    return product(value[0], edge(1)) + product(value[1], edge(2)) + product(value[2], edge(0));
  };
  const i128 start_num = weighted([&](int k) { return edge_at_start[k]; });
  const i128 step_x_num = weighted([&](int k) { return i128(step_x[k]); });
  const i128 step_y_num = weighted([&](int k) { return i128(step_y[k]); });
  // num 2^F, shifted as an unsigned value: a left shift of a negative value is undefined
  // behaviour in C++17 (and |num 2^F| < 2^127 here: its width is checked against the divider's).
  auto quotient = [&](i128 num) {
    const i128 dividend = i128((unsigned __int128)num << F);
    if (unsigned_bits(dividend < 0 ? -dividend : dividend) > format.divider_bits)
      throw WidthOverflow(std::string(what) + " dividend exceeds its divider width");
    return wrap_signed(by_area2(dividend).quotient, format.reg_bits);
  };
  PlaneSetup p;
  p.start = quotient(start_num);
  p.step_x = quotient(step_x_num);
  p.step_y = quotient(step_y_num);
  return p;
}

void TriangleSetup::run(const SnappedTriangle& tri, SetupResult& r) const {
  SetupEdges edges;
  if (!front(tri, r, edges)) return;
  planes(edges, r);
  left_edge_planes(r);
}

bool TriangleSetup::front(const SnappedTriangle& input, SetupResult& r, SetupEdges& edges) const {
  const Widths& w = widths_;
  const int S = profile_.subpixel_bits;
  // The record is not cleared for every triangle: a drawn one's fields are all written by the
  // stages, a rejected one's record is made fresh here.
  auto reject = [&r](SetupStatus status) {
    SetupResult fresh;
    fresh.status = status;
    fresh.front_facing = r.front_facing;
    fresh.area2 = r.area2;
    fresh.flat_color = r.flat_color;
    if (status == SetupStatus::Offscreen || status == SetupStatus::NoCentre) fresh.x0 = r.x0, fresh.y0 = r.y0, fresh.x1 = r.x1, fresh.y1 = r.y1;
    r = fresh;
    return false;
  };
  r.front_facing = false;
  SnappedVertex v[3] = {input.v[0], input.v[1], input.v[2]};
  for (const SnappedVertex& vertex : v) {
    check_signed(vertex.x, w.coord_bits, "vertex x");
    check_signed(vertex.y, w.coord_bits, "vertex y");
  }
  r.flat_color = v[0].color;

  // Front stage: area, facing, cull, bounding box.
  const int64_t area2 = int64_t(v[1].x - v[0].x) * (v[2].y - v[0].y) - int64_t(v[2].x - v[0].x) * (v[1].y - v[0].y);
  check_signed(area2, w.area_bits, "area2");
  r.area2 = area2;
  if (area2 == 0) return reject(SetupStatus::Degenerate);
  // y points down, so area2 > 0 is clockwise as the viewer sees the screen.
  r.front_facing = profile_.front_face == FrontFace::CCW ? area2 < 0 : area2 > 0;
  if ((profile_.cull == CullMode::Back && !r.front_facing) || (profile_.cull == CullMode::Front && r.front_facing))
    return reject(SetupStatus::Culled);
  if (area2 < 0) std::swap(v[1], v[2]);  // either winding rasterizes: order to area2 > 0
  edges.v[0] = &input.v[0];
  edges.v[1] = &input.v[area2 < 0 ? 2 : 1];
  edges.v[2] = &input.v[area2 < 0 ? 1 : 2];
  const int64_t area = area2 < 0 ? -area2 : area2;
  edges.area = area;

  const int64_t half = profile_.sample_offset();  // the sample point within a pixel: 2^(S-1) or 0
  const int64_t x_min = std::min({v[0].x, v[1].x, v[2].x}), x_max = std::max({v[0].x, v[1].x, v[2].x});
  const int64_t y_min = std::min({v[0].y, v[1].y, v[2].y}), y_max = std::max({v[0].y, v[1].y, v[2].y});
  // Pixel i is a candidate when its sample point i 2^S + half lies in [min, max]: columns [xa, xb]
  // and rows [ya, yb] of the whole grid, then clipped to the screen.
  const int64_t xa = (x_min - half + (int64_t(1) << S) - 1) >> S, xb = (x_max - half) >> S;
  const int64_t ya = (y_min - half + (int64_t(1) << S) - 1) >> S, yb = (y_max - half) >> S;
  r.x0 = int(std::max<int64_t>(0, xa));
  r.x1 = int(std::min<int64_t>(profile_.width - 1, xb));
  r.y0 = int(std::max<int64_t>(0, ya));
  r.y1 = int(std::min<int64_t>(profile_.height - 1, yb));
  if (xb < 0 || yb < 0 || xa > profile_.width - 1 || ya > profile_.height - 1) return reject(SetupStatus::Offscreen);
  // Otherwise the clipped box is empty only when the whole-grid one is: xa > xb or ya > yb.
  if (r.x0 > r.x1 || r.y0 > r.y1) return reject(SetupStatus::NoCentre);
  r.status = SetupStatus::Drawn;

  // Edge functions at the first candidate's sample point.
  const int64_t px = (int64_t(r.x0) << S) + half, py = (int64_t(r.y0) << S) + half;
  i128* unbiased = edges.unbiased;
  int64_t* step_x = edges.step_x;
  int64_t* step_y = edges.step_y;
  for (int k = 0; k < 3; ++k) {
    const SnappedVertex& a = v[k];
    const SnappedVertex& b = v[(k + 1) % 3];
    const int64_t dx = b.x - a.x, dy = b.y - a.y;
    check_signed(dx, w.delta_bits, "edge dx");
    check_signed(dy, w.delta_bits, "edge dy");
    EdgeSetup& e = r.edge[k];
    e.owns_samples = owns_samples_on_edge(profile_.fill_rule, dx, dy);
    unbiased[k] = i128(dx) * (py - a.y) - i128(dy) * (px - a.x);
    e.start = int64_t(unbiased[k]) - (e.owns_samples ? 0 : 1);
    e.step_x = -dy * (int64_t(1) << S);
    e.step_y = dx * (int64_t(1) << S);
    check_signed(unbiased[k], w.edge_bits, "edge start");
    check_signed(e.step_x, w.edge_step_x_bits, "edge step_x");
    check_signed(e.step_y, w.edge_step_y_bits, "edge step_y");
    step_x[k] = e.step_x;
    step_y[k] = e.step_y;
    if (e.step_x != 0) {
      const int64_t d = e.step_x < 0 ? -int64_t(e.step_x) : int64_t(e.step_x);
      const FloorDivider by_d(d);  // one divide for both quotients
      const FloorDiv q0 = by_d(e.start), q1 = by_d(e.step_y);
      e.span_quot = int64_t(q0.quotient);
      e.span_rem = int64_t(q0.remainder);
      e.span_step_quot = int64_t(q1.quotient);
      e.span_step_rem = int64_t(q1.remainder);
    } else {
      e.span_quot = 0, e.span_rem = 0, e.span_step_quot = 0, e.span_step_rem = 0;
    }
  }

  // Without the profile's texture unit the hardware has no texture planes: coordinates are ignored.
  r.textured = input.textured && profile_.texture_unit;
  return true;
}

void TriangleSetup::planes(const SetupEdges& edges, SetupResult& r) const {
  const Widths& w = widths_;
  const SnappedVertex& v0 = *edges.v[0];
  const SnappedVertex& v1 = *edges.v[1];
  const SnappedVertex& v2 = *edges.v[2];
  const i128* unbiased = edges.unbiased;
  const int64_t* step_x = edges.step_x;
  const int64_t* step_y = edges.step_y;
  // Depth always, colour for Gouraud shading.
  const i128 z[3] = {v0.z, v1.z, v2.z};
  const FloorDivider by_area(edges.area);
  const PlaneFormatBits depth_format{w.guard_bits, w.z_reg_bits, w.divider_bits};
  const PlaneFormatBits color_format{w.guard_bits, w.color_reg_bits, w.divider_bits};
  const PlaneFormatBits texture_format{w.texture_guard_bits, w.texture_reg_bits, w.texture_divider_bits};
  r.depth = plane(z, unbiased, step_x, step_y, by_area, depth_format, "depth plane");
  if (profile_.shading == Shading::Gouraud) {
    const i128 red[3] = {v0.color.r, v1.color.r, v2.color.r};
    const i128 green[3] = {v0.color.g, v1.color.g, v2.color.g};
    const i128 blue[3] = {v0.color.b, v1.color.b, v2.color.b};
    r.color[0] = plane(red, unbiased, step_x, step_y, by_area, color_format, "red plane");
    r.color[1] = plane(green, unbiased, step_x, step_y, by_area, color_format, "green plane");
    r.color[2] = plane(blue, unbiased, step_x, step_y, by_area, color_format, "blue plane");
  }
  // Texture planes (docs/arithmetic.md section 5); an untextured record keeps them zero.
  if (r.textured) {
    for (const SnappedVertex* vertex_at : edges.v) {
      const SnappedVertex& vertex = *vertex_at;
      if (vertex.q <= 0 || vertex.q > (int64_t(1) << kTextureFractionBits))
        throw_width_overflow(vertex.q, kTextureFractionBits + 1, "vertex Q");
      check_signed(vertex.s, kTextureFractionBits + 9, "vertex S");
      check_signed(vertex.t, kTextureFractionBits + 9, "vertex T");
    }
    const i128 s[3] = {v0.s, v1.s, v2.s};
    const i128 t[3] = {v0.t, v1.t, v2.t};
    const i128 q[3] = {v0.q, v1.q, v2.q};
    r.texture[0] = plane(s, unbiased, step_x, step_y, by_area, texture_format, "S plane");
    r.texture[1] = plane(t, unbiased, step_x, step_y, by_area, texture_format, "T plane");
    r.texture[2] = plane(q, unbiased, step_x, step_y, by_area, texture_format, "Q plane");
  } else {
    for (PlaneSetup& p : r.texture) p = PlaneSetup{};
  }
}

// Planes along the left edges (docs/cycle-model.md): slot j takes the j-th edge with step_x > 0.
void TriangleSetup::left_edge_planes(SetupResult& r) const {
  const Widths& w = widths_;
  int left_edge[kLeftEdgeSlots] = {-1, -1};
  for (int k = 0, slot = 0; k < 3 && slot < kLeftEdgeSlots; ++k)
    if (r.edge[k].step_x > 0) left_edge[slot++] = k;
  auto along = [](const PlaneSetup& p, int64_t quot, int64_t step_quot, int reg_bits) {
    EdgePlane e;
    e.start = wrap_signed(i128(p.start) - i128(quot) * i128(p.step_x), reg_bits);
    e.step = wrap_signed(i128(p.step_y) - i128(step_quot) * i128(p.step_x), reg_bits);
    return e;
  };
  for (int j = 0; j < kLeftEdgeSlots; ++j) {
    const int k = left_edge[j];
    const int64_t quot = k >= 0 ? int64_t(r.edge[k].span_quot) : 0;
    const int64_t step_quot = k >= 0 ? int64_t(r.edge[k].span_step_quot) : 0;
    r.left[j].depth = along(r.depth, quot, step_quot, w.z_reg_bits);
    if (profile_.shading == Shading::Gouraud)
      for (int c = 0; c < 3; ++c) r.left[j].color[c] = along(r.color[c], quot, step_quot, w.color_reg_bits);
    for (int c = 0; c < 3; ++c)
      r.left[j].texture[c] = r.textured ? along(r.texture[c], quot, step_quot, w.texture_reg_bits) : EdgePlane{};
  }
}

}  // namespace rastersim
