#include "builtin_scenes.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace rastersim {
namespace {

Rgb rgb(int r, int g, int b) { return Rgb{uint8_t(r), uint8_t(g), uint8_t(b)}; }

// A vertex at (u, v) in screen fractions (0..1 spans the screen).
ScreenVertex at(const Profile& p, double u, double v, double z, Rgb color) {
  return ScreenVertex{u * p.width, v * p.height, z, color};
}

// Large Gouraud triangles whose depth planes cross: the z-buffer decides the intersection lines.
std::vector<ScreenTriangle> overlap_scene(const Profile& p) {
  std::vector<ScreenTriangle> tris;
  // Depth rises left to right.
  auto rising = [](double u) { return 0.2 + 0.6 * u; };
  // Depth falls left to right: crosses `rising` at u = 0.5.
  auto falling = [](double u) { return 0.8 - 0.6 * u; };
  // Depth rises top to bottom: crosses both of the others along slanted lines.
  auto sloping = [](double v) { return 0.1 + 0.8 * v; };
  tris.push_back({{at(p, 0.05, 0.10, rising(0.05), rgb(255, 40, 40)),
                   at(p, 0.95, 0.20, rising(0.95), rgb(255, 220, 0)),
                   at(p, 0.30, 0.95, rising(0.30), rgb(200, 0, 255))}});
  tris.push_back({{at(p, 0.10, 0.85, falling(0.10), rgb(0, 230, 255)),
                   at(p, 0.70, 0.05, falling(0.70), rgb(30, 60, 255)),
                   at(p, 0.95, 0.90, falling(0.95), rgb(40, 255, 80))}});
  tris.push_back({{at(p, 0.40, 0.02, sloping(0.02), rgb(255, 140, 0)),
                   at(p, 0.98, 0.55, sloping(0.55), rgb(255, 255, 255)),
                   at(p, 0.02, 0.60, sloping(0.60), rgb(255, 0, 140))}});
  // A small flat-looking (one colour) triangle in front of everything, wound the other way.
  const Rgb grey = rgb(180, 180, 180);
  tris.push_back({{at(p, 0.55, 0.55, 0.05, grey), at(p, 0.62, 0.80, 0.05, grey), at(p, 0.75, 0.60, 0.05, grey)}});
  return tris;
}

// Deterministic value in [-1, 1) for a grid vertex (a hash, so any vertex's jitter is independent of
// generation order).
double jitter(int i, int j, int axis) {
  uint64_t h = uint64_t(i) * 0x9E3779B97F4A7C15ull ^ uint64_t(j) * 0xC2B2AE3D27D4EB4Full ^ uint64_t(axis + 1) * 0x165667B19E3779F9ull;
  h ^= h >> 31;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 29;
  return double(h >> 11) * 0x1p-52 - 1.0;
}

// A watertight mesh over the whole screen: a grid of jittered vertices shared between neighbours,
// each cell split along alternating diagonals with alternating winding; the 2x2 cells round the
// centre vertex are a triangle fan instead. Every pixel centre is covered exactly once.
std::vector<ScreenTriangle> fan_scene(const Profile& p) {
  constexpr int kCols = 8, kRows = 6;
  auto vertex = [&](int i, int j) {
    double u = double(i) / kCols, v = double(j) / kRows;
    // Interior vertices move up to a fifth of a cell: every cell stays convex.
    if (i > 0 && i < kCols) u += 0.2 * jitter(i, j, 0) / kCols;
    if (j > 0 && j < kRows) v += 0.2 * jitter(i, j, 1) / kRows;
    const double z = 0.5 + 0.3 * std::sin(6.0 * u) * std::cos(4.0 * v);
    // A colour of its own per vertex (shared by every triangle using it) makes the mesh visible.
    auto channel = [&](int axis) { return int(std::lround(127.5 + 127.5 * jitter(i, j, axis))); };
    const Rgb color = rgb(channel(2), channel(3), channel(4));
    return at(p, u, v, z, color);
  };
  const int ci = kCols / 2, cj = kRows / 2;  // the fan's centre vertex
  std::vector<ScreenTriangle> tris;
  for (int j = 0; j < kRows; ++j) {
    for (int i = 0; i < kCols; ++i) {
      if ((i == ci - 1 || i == ci) && (j == cj - 1 || j == cj)) continue;  // the fan's cells
      const ScreenVertex a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
      const bool flip_diagonal = (i + j) % 2 == 1;
      const bool reverse_first = (i + 2 * j) % 3 == 0;  // reverse one of the two: mixed winding
      ScreenTriangle t1 = flip_diagonal ? ScreenTriangle{{a, b, d}} : ScreenTriangle{{a, b, c}};
      ScreenTriangle t2 = flip_diagonal ? ScreenTriangle{{b, c, d}} : ScreenTriangle{{a, c, d}};
      if (reverse_first) std::swap(t1.v[1], t1.v[2]);
      else std::swap(t2.v[1], t2.v[2]);
      tris.push_back(t1);
      tris.push_back(t2);
    }
  }
  const int ring[8][2] = {{ci - 1, cj - 1}, {ci, cj - 1}, {ci + 1, cj - 1}, {ci + 1, cj},
                          {ci + 1, cj + 1}, {ci, cj + 1}, {ci - 1, cj + 1}, {ci - 1, cj}};
  for (int k = 0; k < 8; ++k) {
    const int* a = ring[k];
    const int* b = ring[(k + 1) % 8];
    ScreenTriangle t{{vertex(ci, cj), vertex(a[0], a[1]), vertex(b[0], b[1])}};
    if (k % 2) std::swap(t.v[1], t.v[2]);
    tris.push_back(t);
  }
  return tris;
}

std::vector<ScreenTriangle> stress_scene(const Profile& p) { return random_triangles(5000, 2, 24, 0x5eed, p); }

}  // namespace

std::vector<ScreenTriangle> random_triangles(int64_t count, double min_size, double max_size, uint64_t seed,
                                             const Profile& p) {
  std::mt19937_64 rng(seed);
  auto unit = [&] { return double(rng() >> 11) * 0x1p-53; };  // [0, 1)
  auto byte = [&] { return uint8_t(rng() >> 56); };
  // The guard band [-W, 2W) x [-H, 2H).
  const double x_lo = -p.width, x_hi = std::nextafter(2.0 * p.width, 0.0);
  const double y_lo = -p.height, y_hi = std::nextafter(2.0 * p.height, 0.0);
  std::vector<ScreenTriangle> tris;
  tris.reserve(size_t(std::max<int64_t>(count, 0)));
  for (int64_t n = 0; n < count; ++n) {
    const double cx = unit() * p.width, cy = unit() * p.height;
    const double size = min_size + unit() * (max_size - min_size);
    ScreenTriangle t;
    for (ScreenVertex& v : t.v) {
      v.x = std::clamp(cx + (unit() - 0.5) * size, x_lo, x_hi);
      v.y = std::clamp(cy + (unit() - 0.5) * size, y_lo, y_hi);
      v.z = unit();
      v.color = Rgb{byte(), byte(), byte()};
    }
    tris.push_back(t);
  }
  return tris;
}

const std::vector<BuiltinScene>& builtin_scenes() {
  static const std::vector<BuiltinScene> scenes = {
      {"overlap", "large Gouraud triangles at crossing depths: the z-buffer cuts their intersection lines",
       overlap_scene},
      {"fan", "watertight jittered grid mesh with a central fan, mixed winding: every pixel covered once",
       fan_scene},
      {"stress", "5000 small random Gouraud triangles (2..24 pixels, seed 0x5eed)", stress_scene},
  };
  return scenes;
}

const BuiltinScene* find_builtin_scene(const std::string& name) {
  for (const BuiltinScene& scene : builtin_scenes())
    if (scene.name == name) return &scene;
  return nullptr;
}

}  // namespace rastersim
