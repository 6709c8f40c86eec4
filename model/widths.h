// Every register width of the pipeline, derived from the profile in one place.
// The derivation is constexpr so that the RTL build can static_assert its package localparams
// against it. docs/widths.md proves each bound; tests/test_widths.cpp drives the extremes.
#pragma once

#include <algorithm>

#include "fixed.h"
#include "profile.h"

namespace rastersim {

// Textured triangles (docs/arithmetic.md section 5): the vertices' Q = 1/w, S = u/w, T = v/w carry
// P fraction bits, and one triangle's w ratio is at most 2^kMaxTextureWRatioLog2, which with P bounds
// the divided u, v within 0.0025 texel of a 1024-texel texture. P = 41 makes the largest profile's
// texture registers exactly 64 bits (docs/widths.md).
constexpr int kTextureFractionBits = 41;
constexpr int kMaxTextureWRatioLog2 = 14;
// The perspective divide keeps this many of the registers' Ft guard bits (the rest shifted out of
// dividend and divisor, a divisor of P + 1 + min(Ft, 4) bits): the bound's constant grows from 194
// to 202 and the divider's steps shorten (docs/arithmetic.md section 5).
constexpr int kTextureDivideGuardBits = 4;
constexpr int kTextureVertexBits = kTextureFractionBits + 9;  // m_t: S, T s8.P (Q u1.P with leading zeros)

struct Widths {
  // Plane registers: F fraction (guard) bits. Chosen so that the accumulated floor error of the
  // start value and (W-1)+(H-1) steps stays at most half an LSB: 2^F >= 2 (W + H - 1).
  int guard_bits;
  int coord_bits;        // vertex coordinate in subpixels, s(coord_bits-S).S; guard band [-W, 2W]
  int delta_bits;        // vertex difference, s.S
  int area_bits;         // twice the signed area and each cross product, s.2S
  int edge_bits;         // edge function value (biased) at any on-screen pixel centre, s.2S
  int edge_step_x_bits;  // edge_step_x = -dy * 2^S, s.2S
  int edge_step_y_bits;  // edge_step_y = dx * 2^S, s.2S
  int span_rem_bits;     // span walker remainder, 0 <= r < |edge_step_x|, u.2S
  int divider_bits;      // widest dividend magnitude; the divider takes this many cycles
  int z_reg_bits;        // depth plane register, s(N+1).F, wraps (modular, see docs/arithmetic.md)
  int color_reg_bits;    // colour plane register, s9.F, wraps
  int texture_guard_bits;    // Ft, the texture planes' fraction bits beyond P: always the derived F
  int texture_reg_bits;      // texture plane registers (S, T, Q), s9.(P+Ft), wrap
  int texture_divider_bits;  // widest texture plane dividend magnitude
  int texture_divide_shift;  // Ft - min(Ft, kTextureDivideGuardBits): register bits the divide drops
  int x_bits;            // pixel x counter, u
  int y_bits;            // pixel y counter, u
  int addr_bits;         // z-buffer word address y * W + x
  // Cycle-model constants (docs/cycle-model.md); the setup unit's are in SetupTiming below.
  int walker_load_cycles;   // cycles from a record load to the first candidate (and of an idle load)
};

constexpr int ceil_log2(i128 v) {  // smallest b with 2^b >= v, v >= 1
  int b = 0;
  while ((i128(1) << b) < v) ++b;
  return b;
}

constexpr int derived_guard_bits(int width, int height) {
  const int f = ceil_log2(i128(2) * (width + height - 1));
  return f < 1 ? 1 : f;
}

constexpr Widths derive_widths(int width, int height, int subpixel_bits, int z_bits, int z_guard_bits) {
  Widths w{};
  const i128 W = width, H = height, M = i128(1) << subpixel_bits;
  const i128 WH = W * H * M * M;
  const i128 big = W > H ? W : H;
  const i128 z_max = (i128(1) << z_bits) - 1;
  w.guard_bits = z_guard_bits > 0 ? z_guard_bits : derived_guard_bits(width, height);
  w.coord_bits = signed_bits(2 * big * M);
  w.delta_bits = signed_bits(3 * big * M);
  w.area_bits = signed_bits(9 * WH);
  w.edge_bits = signed_bits(12 * WH + 1);
  w.edge_step_x_bits = signed_bits(3 * H * M * M);
  w.edge_step_y_bits = signed_bits(3 * W * M * M);
  w.span_rem_bits = unsigned_bits(3 * H * M * M);
  // The depth start numerator sum_k Z_k e_k dominates every other dividend (docs/widths.md).
  w.divider_bits = unsigned_bits(36 * z_max * WH * (i128(1) << w.guard_bits));
  w.z_reg_bits = z_bits + w.guard_bits + 1;
  w.color_reg_bits = 8 + w.guard_bits + 1;
  w.texture_guard_bits = derived_guard_bits(width, height);
  w.texture_reg_bits = kTextureFractionBits + w.texture_guard_bits + 9;
  w.texture_divider_bits =
      unsigned_bits(36 * (i128(1) << (kTextureFractionBits + 7)) * WH * (i128(1) << w.texture_guard_bits));
  w.texture_divide_shift =
      w.texture_guard_bits > kTextureDivideGuardBits ? w.texture_guard_bits - kTextureDivideGuardBits : 0;
  w.x_bits = unsigned_bits(W - 1);
  w.y_bits = unsigned_bits(H - 1);
  w.addr_bits = unsigned_bits(W * H - 1);
  w.walker_load_cycles = 1;
  return w;
}

inline Widths derive_widths(const Profile& p) {
  return derive_widths(p.width, p.height, p.subpixel_bits, p.depth_plane_bits(), p.z_guard_bits);
}

// When the setup unit handles a triangle (docs/cycle-model.md). `setup_interval` 0 is the serial
// unit: one shared shift-and-add / restoring-divide datapath runs a fixed program of operations for
// one triangle at a time. I >= 2 is the pipelined unit: one triangle per slot of I cycles through a
// FRONT slot, the edge slots, the numerator slots and the divide slots, every multiply and divide
// digit-serial with at most kSetupStepsPerCycle steps chained in a cycle (the area's two products in
// FRONT are the only others).
constexpr int kSetupStepsPerCycle = 4;

struct SetupTiming {
  int interval;        // I: cycles between two accepts at best (0: the serial unit)
  bool texture;        // the units compute the texture planes (profile texture_unit)
  int edge_stages;     // slots of the edge values (shift-add over the coord_bits + 1 bits of rel_x, rel_y)
  int edge_steps;      // shift-add steps per cycle in an edge slot
  int numer_stages;    // slots of the plane numerators (Horner over the vertex values' z_bits bits)
  int numer_steps;     // shift-add steps per cycle in a numerator slot
  int divide_stages;   // slots of the 18 restoring divisions (divider_bits steps)
  int divide_steps;    // restoring steps per cycle in a divide slot
  int product_stages;  // slots of the 16 planes along the left edges (setup_product_bits steps)
  int product_steps;   // multiply steps per cycle in a product slot
  int drawn_latency;   // accept -> record in the output register (setup_done - setup_accept)
  int textured_drawn_latency;  // the same for a textured triangle (differs in the serial unit only)
  int rejected_latency;  // accept -> decision
  int free_after;      // accept -> first cycle the unit may accept again (0: after setup_done)
};

constexpr int ceil_div(int a, int b) { return (a + b - 1) / b; }

// The serial unit's datapath: H = edge_bits + 3 bits of accumulator above the multiplier bits, enough
// for the sum of three products of edge values (docs/cycle-model.md).
constexpr int serial_setup_datapath_bits(const Widths& w) { return w.edge_bits + 3; }

// PB: the multiplier bits of a plane along a left edge, `start - quot * step_x` and
// `step_y - step_quot * step_x` modulo the plane register: the quotient as a two's-complement value
// of PB bits (its higher bits do not change the product modulo 2^z_reg_bits, the widest register).
constexpr int setup_product_bits(const Widths& w) { return w.z_reg_bits < w.edge_bits ? w.z_reg_bits : w.edge_bits; }

// The serial unit's program, operation by operation as docs/cycle-model.md tables it: every operation
// takes one load cycle and its steps; operation 0 starts the cycle after the accept.
constexpr int serial_setup_drawn_latency(const Widths& w, int subpixel_bits, int z_bits) {
  const int D = w.delta_bits, C = w.coord_bits, H = serial_setup_datapath_bits(w), F = w.guard_bits;
  const int S = subpixel_bits;
  int cycles = 1;                                 // the accept cycle
  cycles += 1 + 2 * D;                            // AREA
  cycles += 1;                                    // DECIDE
  cycles += 3 * (1 + 2 * (C + 1));                // EDGE 0..2
  cycles += 3 * (1 + H + 1) + 3 * (1 + H + S + 1);  // SPAN START and SPAN STEP 0..2
  for (int m : {z_bits, 8, 8, 8}) {               // depth, red, green, blue
    cycles += 3 * (1 + 3 * m);                    // numerators of start, step x, step y
    cycles += (1 + H + m + F) + 2 * (1 + H + m + F + S);  // their divisions
  }
  cycles += 16 * (1 + setup_product_bits(w) + 1);  // PRODUCT: 4 planes x 2 left-edge slots x start, step
  cycles += 1;                                    // FINAL
  return cycles;
}

// PBt: the multiplier bits of a texture plane along a left edge, as PB for the texture registers.
constexpr int setup_texture_product_bits(const Widths& w) {
  return w.texture_reg_bits < w.edge_bits ? w.texture_reg_bits : w.edge_bits;
}

// What the S, T, Q planes add to the serial unit's program for a textured triangle: per plane the
// depth plane's six operations with m_t-bit vertex values and Ft guard bits, then 12 PRODUCT
// operations (docs/cycle-model.md, "The setup units with the texture unit").
constexpr int serial_setup_texture_cycles(const Widths& w, int subpixel_bits) {
  const int H = serial_setup_datapath_bits(w), m = kTextureVertexBits, F = w.texture_guard_bits, S = subpixel_bits;
  return 3 * (3 * (1 + 3 * m) + (1 + H + m + F) + 2 * (1 + H + m + F + S)) + 12 * (setup_texture_product_bits(w) + 2);
}

constexpr SetupTiming setup_timing(const Widths& w, int subpixel_bits, int z_bits, int interval, bool texture = false) {
  SetupTiming t{};
  t.interval = interval;
  t.texture = texture;
  if (interval == 0) {
    t.rejected_latency = 2 + 2 * w.delta_bits;  // the DECIDE cycle
    t.drawn_latency = serial_setup_drawn_latency(w, subpixel_bits, z_bits);
    t.textured_drawn_latency = t.drawn_latency + (texture ? serial_setup_texture_cycles(w, subpixel_bits) : 0);
    t.free_after = 0;  // the unit is free after its output (or decision) cycle
    return t;
  }
  // With the texture planes every slot is sized for them, whatever the triangle.
  const int numer_bits = texture ? std::max(z_bits, kTextureVertexBits) : z_bits;
  const int divide_bits = texture ? std::max(w.divider_bits, w.texture_divider_bits) : w.divider_bits;
  const int product_bits =
      texture ? std::max(setup_product_bits(w), setup_texture_product_bits(w)) : setup_product_bits(w);
  t.rejected_latency = 1;
  t.edge_stages = ceil_div(w.coord_bits + 1, interval * kSetupStepsPerCycle);
  t.edge_steps = ceil_div(w.coord_bits + 1, interval * t.edge_stages);
  t.numer_stages = ceil_div(numer_bits, interval * kSetupStepsPerCycle);
  t.numer_steps = ceil_div(numer_bits, interval * t.numer_stages);
  t.divide_stages = ceil_div(divide_bits, interval * kSetupStepsPerCycle);
  t.divide_steps = ceil_div(divide_bits, interval * t.divide_stages);
  t.product_stages = ceil_div(product_bits, interval * kSetupStepsPerCycle);
  t.product_steps = ceil_div(product_bits, interval * t.product_stages);
  t.drawn_latency = interval * (1 + t.edge_stages + t.numer_stages + t.divide_stages + t.product_stages);
  t.textured_drawn_latency = t.drawn_latency;
  t.free_after = interval;
  return t;
}

inline SetupTiming setup_timing(const Profile& p) {
  return setup_timing(derive_widths(p), p.subpixel_bits, p.depth_plane_bits(), p.setup_interval, p.texture_unit);
}

// The docs' worked example and the default profile (docs/cycle-model.md).
static_assert(serial_setup_drawn_latency(derive_widths(16, 12, 4, 16, 0), 4, 16) == 1533);
static_assert(serial_setup_drawn_latency(derive_widths(640, 480, 4, 24, 0), 4, 24) == 2081);
static_assert(setup_timing(derive_widths(16, 12, 4, 16, 0), 4, 16, 4).drawn_latency == 32);
static_assert(setup_timing(derive_widths(640, 480, 4, 24, 0), 4, 24, 2).drawn_latency == 40);
static_assert(setup_timing(derive_widths(640, 480, 4, 24, 0), 4, 24, 4).drawn_latency == 48);
static_assert(setup_timing(derive_widths(640, 480, 4, 24, 0), 4, 24, 16).drawn_latency == 96);
static_assert(setup_timing(derive_widths(640, 480, 4, 24, 0), 4, 24, 64).drawn_latency == 320);
static_assert(setup_timing(derive_widths(640, 480, 4, 24, 0), 4, 24, 0, true).textured_drawn_latency == 4733);
static_assert(setup_timing(derive_widths(640, 480, 4, 24, 0), 4, 24, 0, true).drawn_latency == 2081);
static_assert(setup_timing(derive_widths(640, 480, 4, 24, 0), 4, 24, 4, true).drawn_latency == 60);

// The largest profile must fit the model's storage: plane registers and edge values in int64_t,
// dividends in i128.
static_assert(derive_widths(4096, 4096, 8, 32, 0).edge_bits <= 63);
static_assert(derive_widths(4096, 4096, 8, 32, 0).z_reg_bits <= 63);
static_assert(derive_widths(4096, 4096, 8, 32, 24).z_reg_bits <= 63);
static_assert(derive_widths(4096, 4096, 8, 32, 24).divider_bits <= 126);
static_assert(derive_widths(4096, 4096, 8, 32, 0).texture_reg_bits <= 64);
static_assert(derive_widths(4096, 4096, 8, 32, 0).texture_divider_bits <= 126);

}  // namespace rastersim
