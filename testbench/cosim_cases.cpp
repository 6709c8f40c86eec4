#include "testbench/cosim_cases.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "model/widths.h"

namespace rastersim::rtl {
namespace {

class Generator {
 public:
  Generator(const Profile& p, uint64_t seed)
      : p_(p), rng_(seed), one_(int64_t(1) << p.subpixel_bits), z_max_((int64_t(1) << p.depth_plane_bits()) - 1) {}

  int64_t uniform(int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng_); }
  // Pixel (px, py)'s sample point in subpixels (its centre, or its corner by the profile's pixel_center).
  int64_t sample_x(int px) const { return px * one_ + p_.sample_offset(); }
  int64_t sample_y(int py) const { return py * one_ + p_.sample_offset(); }
  // Guard band in subpixels: x in [-W, 2W], y in [-H, 2H] pixels.
  int64_t gx() { return uniform(-p_.width * one_, 2 * p_.width * one_); }
  int64_t gy() { return uniform(-p_.height * one_, 2 * p_.height * one_); }
  int64_t clamp_x(int64_t x) const { return std::clamp<int64_t>(x, -p_.width * one_, 2 * p_.width * one_); }
  int64_t clamp_y(int64_t y) const { return std::clamp<int64_t>(y, -p_.height * one_, 2 * p_.height * one_); }
  uint32_t z() { return uint32_t(uniform(0, z_max_)); }
  Rgb color() { return Rgb{uint8_t(uniform(0, 255)), uint8_t(uniform(0, 255)), uint8_t(uniform(0, 255))}; }

  SnappedTriangle triangle(const int64_t (&xy)[6]) {
    SnappedTriangle t;
    for (int k = 0; k < 3; ++k) {
      t.v[k].x = int32_t(clamp_x(xy[2 * k]));
      t.v[k].y = int32_t(clamp_y(xy[2 * k + 1]));
      t.v[k].z = z();
      t.v[k].color = color();
    }
    return t;
  }

  // Anywhere in the guard band: mostly huge triangles, many partly off screen.
  SnappedTriangle huge() { return triangle({gx(), gy(), gx(), gy(), gx(), gy()}); }
  // A few pixels around one pixel: back-to-back tiny triangles on the same pixel stress the hazards.
  SnappedTriangle tiny_at(int px, int py) {
    const int64_t cx = sample_x(px), cy = sample_y(py), r = 2 * one_;
    return triangle({cx + uniform(-r, r), cy + uniform(-r, r), cx + uniform(-r, r), cy + uniform(-r, r),
                     cx + uniform(-r, r), cy + uniform(-r, r)});
  }
  SnappedTriangle tiny() { return tiny_at(int(uniform(0, p_.width - 1)), int(uniform(0, p_.height - 1))); }
  // Medium, on screen.
  SnappedTriangle medium() {
    const int64_t w = p_.width * one_, h = p_.height * one_;
    return triangle({uniform(0, w), uniform(0, h), uniform(0, w), uniform(0, h), uniform(0, w), uniform(0, h)});
  }
  // Zero area: a repeated vertex or three collinear vertices.
  SnappedTriangle degenerate() {
    const int64_t x0 = gx(), y0 = gy(), x1 = gx(), y1 = gy();
    if (uniform(0, 1)) return triangle({x0, y0, x1, y1, x0, y0});
    // Midpoint of an even-sized segment keeps the three vertices exactly collinear.
    const int64_t dx = (x1 - x0) / 2 * 2, dy = (y1 - y0) / 2 * 2;
    return triangle({x0, y0, x0 + dx, y0 + dy, x0 + dx / 2, y0 + dy / 2});
  }
  // Entirely beside the screen (left, right, above or below) but inside the guard band.
  SnappedTriangle offscreen() {
    const int64_t w = p_.width * one_, h = p_.height * one_;
    int64_t xy[6];
    const int side = int(uniform(0, 3));
    for (int k = 0; k < 3; ++k) {
      xy[2 * k] = side == 0 ? uniform(-w, -one_) : side == 1 ? uniform(w + one_, 2 * w) : gx();
      xy[2 * k + 1] = side == 2 ? uniform(-h, -one_) : side == 3 ? uniform(h + one_, 2 * h) : gy();
    }
    return triangle(xy);
  }
  // On the screen between two pixel-centre columns (or rows), so that its box holds no centre
  // (status no_centre; with one subpixel bit such a box has one coordinate and the area is zero).
  SnappedTriangle between_centres() {
    if (p_.width < 2 && p_.height < 2) return offscreen();
    const bool columns = p_.width >= 2 && (p_.height < 2 || uniform(0, 1));
    const int64_t i = uniform(0, (columns ? p_.width : p_.height) - 2);
    auto between = [&] { return i * one_ + one_ / 2 + uniform(1, std::max<int64_t>(1, one_ - 1)); };
    auto across = [&] { return uniform(0, (columns ? p_.height : p_.width) * one_); };
    int64_t xy[6];
    for (int k = 0; k < 3; ++k) {
      xy[2 * k] = columns ? between() : across();
      xy[2 * k + 1] = columns ? across() : between();
    }
    return triangle(xy);
  }
  // A thin triangle across the whole screen width: long rows.
  SnappedTriangle long_row() {
    const int64_t w = p_.width * one_, y = uniform(0, p_.height * one_);
    return triangle({uniform(-w, 0), y, uniform(w, 2 * w), y + uniform(-one_, one_), uniform(-w, 2 * w),
                     y + uniform(-3 * one_, 3 * one_)});
  }
  // Vertices on pixel centres and on the half-pixel grid: edges through pixel centres (top-left ties).
  SnappedTriangle centre_ties() {
    auto grid_x = [&] { return uniform(-2, p_.width + 1) * one_ + (uniform(0, 1) ? one_ / 2 : 0); };
    auto grid_y = [&] { return uniform(-2, p_.height + 1) * one_ + (uniform(0, 1) ? one_ / 2 : 0); };
    const int64_t x0 = grid_x(), y0 = grid_y();
    switch (uniform(0, 2)) {
      case 0: return triangle({x0, y0, grid_x(), y0, grid_x(), grid_y()});  // horizontal edge
      case 1: return triangle({x0, y0, x0, grid_y(), grid_x(), grid_y()});  // vertical edge
      default: return triangle({x0, y0, grid_x(), grid_y(), grid_x(), grid_y()});
    }
  }

  // A right triangle whose last bounding-box candidate is the covered pixel (px, py) (vertical right
  // edge and horizontal bottom edge a quarter pixel past its sample point): a long walk ending on P.
  SnappedTriangle ending_at(int px, int py) {
    const int64_t cx = sample_x(px), cy = sample_y(py), quarter = one_ / 4;
    return triangle({cx - 20 * one_, cy + quarter, cx + quarter, cy + quarter, cx + quarter, cy - 20 * one_});
  }
  // A small right triangle whose first candidate is the covered pixel (px, py).
  SnappedTriangle starting_at(int px, int py) {
    const int64_t cx = sample_x(px), cy = sample_y(py), quarter = one_ / 4;
    return triangle({cx - quarter, cy - quarter, cx + 2 * one_, cy - quarter, cx - quarter, cy + 2 * one_});
  }
  // A small triangle around the sample point of pixel (px, py), covering it.
  SnappedTriangle around(int px, int py) {
    const int64_t cx = sample_x(px), cy = sample_y(py);
    return triangle({cx - one_, cy - one_, cx + one_, cy - one_, cx, cy + one_});
  }
  // A triangle inside the square of half-width d around the sample point of pixel (px, py): it
  // covers that pixel alone (d < one pixel's half-width beyond S = 1; at S = 1 the neighbours'
  // sample points are 2 away).
  SnappedTriangle only(int px, int py) {
    const int64_t cx = sample_x(px), cy = sample_y(py), d = std::max<int64_t>(1, one_ / 4);
    return triangle({cx - d, cy - d, cx + d, cy, cx - d, cy + d});
  }
  // Constant depth equal to the clear value: the equal and gequal tests can pass on a cleared buffer.
  SnappedTriangle at_clear_depth(SnappedTriangle t) {
    for (SnappedVertex& v : t.v) v.z = p_.depth_clear_value();
    return t;
  }

  SnappedTriangle any() {
    switch (uniform(0, 9)) {
      case 0: return huge();
      case 1: case 2: return tiny();
      case 3: return degenerate();
      case 4: return offscreen();
      case 5: return long_row();
      case 6: return centre_ties();
      case 7: return at_clear_depth(medium());
      default: return medium();
    }
  }

  std::mt19937_64& rng() { return rng_; }

 private:
  Profile p_;
  std::mt19937_64 rng_;
  int64_t one_;
  uint32_t z_max_;
};

}  // namespace

namespace {

// Texture coordinates as the snap makes them (model/triangle.cpp): u, v mostly within a few repeats,
// sometimes near the limits +-128; w spread from none to the divide's limit 2^14.
void texture_triangle(std::mt19937_64& rng, SnappedTriangle& t) {
  auto real = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  const int kind = int(rng() % 8);
  const double reach = kind == 0 ? 127.0 : kind < 3 ? 1.0 : 4.0;
  const double log2_spread = kind == 7 ? 14.0 : real(0.0, 6.0);
  double w[3], w_min = 0;
  for (double& x : w) x = std::exp2(real(0.0, log2_spread));
  w[rng() % 3] = 1.0;  // the smallest is 1, the largest within the limit
  w_min = std::min({w[0], w[1], w[2]});
  for (int k = 0; k < 3; ++k) {
    t.v[k].q = texture_q(w_min, w[k]);
    t.v[k].s = texture_scaled(real(-reach, reach), t.v[k].q);
    t.v[k].t = texture_scaled(real(-reach, reach), t.v[k].q);
  }
  t.textured = true;
}

// `t` textured with u, v in [-reach, reach] and the given w per vertex (the smallest first scaled
// to q = 2^P, as the snap does).
void texture_with_w(std::mt19937_64& rng, SnappedTriangle& t, double reach, const double (&w)[3]) {
  auto real = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  const double w_min = std::min({w[0], w[1], w[2]});
  for (int k = 0; k < 3; ++k) {
    t.v[k].q = texture_q(w_min, w[k]);
    t.v[k].s = texture_scaled(real(-reach, reach), t.v[k].q);
    t.v[k].t = texture_scaled(real(-reach, reach), t.v[k].q);
  }
  t.textured = true;
}

// A texture of noise texels, 2^log2_width x 2^log2_height: a wrong texel shows.
std::shared_ptr<const Texture> noise_texture(std::mt19937_64& rng, int log2_width, int log2_height) {
  std::vector<uint32_t> texels(size_t(1) << (log2_width + log2_height));
  for (uint32_t& texel : texels) texel = uint32_t(rng()) & 0xFFFFFFu;
  return std::make_shared<const Texture>(log2_width, log2_height, std::move(texels));
}

// A texture of random size (1 to 256 texels a side, powers of two) and texels; patterns that show
// a wrong texel: noise, or a checkerboard of random colours.
std::shared_ptr<const Texture> random_texture(std::mt19937_64& rng) {
  const int log2_width = int(rng() % 9), log2_height = int(rng() % 9);
  const bool noise = rng() % 2 == 0;
  const uint32_t a = uint32_t(rng()) & 0xFFFFFFu, b = uint32_t(rng()) & 0xFFFFFFu;
  std::vector<uint32_t> texels(size_t(1) << (log2_width + log2_height));
  for (size_t i = 0; i < texels.size(); ++i) {
    const size_t x = i & ((size_t(1) << log2_width) - 1), y = i >> log2_width;
    texels[i] = noise ? uint32_t(rng()) & 0xFFFFFFu : ((x ^ y) & 1 ? a : b);
  }
  return std::make_shared<const Texture>(log2_width, log2_height, std::move(texels));
}

}  // namespace

CosimCase random_case(const Profile& profile, uint64_t seed, int count) {
  Generator g(profile, seed);
  CosimCase c{"random seed " + std::to_string(seed), {}, profile, {}};
  while (int(c.triangles.size()) < count) {
    // Now and then repeat or re-colour a previous triangle: equal depths for the depth functions.
    if (!c.triangles.empty() && g.uniform(0, 9) == 0) {
      SnappedTriangle t = c.triangles[size_t(g.uniform(0, int64_t(c.triangles.size()) - 1))];
      for (SnappedVertex& v : t.v) v.color = g.color();
      c.triangles.push_back(t);
    } else {
      c.triangles.push_back(g.any());
    }
  }
  if (profile.texture_unit) {
    // A stream of its own, so that the triangles' geometry is that of an untextured frame.
    std::mt19937_64 rng(seed ^ 0x7e87c7e5ULL);
    for (SnappedTriangle& t : c.triangles)
      if (rng() % 4 != 0) texture_triangle(rng, t);
    if (rng() % 8 != 0) c.texture.texture = random_texture(rng);
    c.texture.filter = rng() % 2 ? TextureFilter::Bilinear : TextureFilter::Nearest;
    c.texture.wrap = rng() % 2 ? TextureWrap::Clamp : TextureWrap::Repeat;
  }
  return c;
}

std::set<std::string> pinned_settings(const std::set<std::string>& given, bool fixed_settings) {
  std::set<std::string> pinned = given;
  if (fixed_settings) {
    pinned.insert(runtime_setting_keys().begin(), runtime_setting_keys().end());
    pinned.insert({"texture_latency", "texture_stall_percent", "texture_stall_seed", "depth_bias_constant",
                   "depth_bias_slope"});
  } else {
    // A non-zero bias value is how a profile selects the build with the depth bias: its runtime
    // registers stay drawn, both signs of each.
    pinned.erase("depth_bias_constant");
    pinned.erase("depth_bias_slope");
  }
  return pinned;
}

const std::vector<std::string>& runtime_setting_keys() {
  static const std::vector<std::string> keys = {"depth_func", "depth_write", "depth_clear", "cull",
                                                "front_face", "traversal",   "shading",     "memory_latency",
                                                "setup_fifo_depth"};
  return keys;
}

Profile random_settings(const Profile& profile, uint64_t seed, const std::set<std::string>& pinned,
                        int max_memory_latency) {
  // A stream of its own (not the triangles'), so pinning a key does not change the triangles.
  std::mt19937_64 rng(seed ^ 0x5e7711a65ULL);
  auto uniform = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
  auto free = [&](const char* key) { return pinned.count(key) == 0; };
  Profile p = profile;
  // Every key draws whether pinned or not, so each key's value depends on the seed alone.
  const auto depth_func = DepthFunc(uniform(0, 7));
  const bool depth_write = uniform(0, 3) != 0;
  const int64_t depth_clear = uniform(0, 3) == 0 ? uniform(0, p.depth_max()) : -1;
  const auto cull = CullMode(uniform(0, 2));
  const auto front_face = FrontFace(uniform(0, 1));
  const auto traversal = Traversal(uniform(0, 1));
  const auto shading = Shading(uniform(0, 1));
  const int latency = int(uniform(1, std::max(1, std::min(8, max_memory_latency))));
  const int fifo_depth = int(uniform(0, 2) == 0 ? 1 : uniform(2, 4));  // 1 as often as not quite
  const int texture_latency = int(uniform(0, 7) == 0 ? 64 : uniform(1, 8));
  const int texture_stall_percent = int(uniform(0, 2) == 0 ? uniform(1, 60) : 0);
  const int texture_stall_seed = int(uniform(0, (int64_t(1) << 31) - 1));
  if (free("depth_func")) p.depth_func = depth_func;
  if (free("depth_write")) p.depth_write = depth_write;
  if (free("depth_clear")) p.depth_clear = depth_clear;
  if (free("cull")) p.cull = cull;
  if (free("front_face")) p.front_face = front_face;
  if (free("traversal")) p.traversal = traversal;
  if (free("shading")) p.shading = shading;
  if (free("memory_latency")) p.memory_latency = latency;
  if (free("setup_fifo_depth")) p.setup_fifo_depth = fifo_depth;
  if (p.texture_unit && free("texture_latency")) p.texture_latency = texture_latency;
  if (p.texture_unit && free("texture_stall_percent")) p.texture_stall_percent = texture_stall_percent;
  if (p.texture_unit && free("texture_stall_seed")) p.texture_stall_seed = texture_stall_seed;
  // A biased profile runs on a build with the depth bias, whose values are runtime registers: drawn,
  // a quarter of the frames unbiased and some at the constant's extremes.
  const int64_t plane_max = (int64_t(1) << p.depth_plane_bits()) - 1;
  const int64_t bias_kind = uniform(0, 7);
  const int64_t bias_constant = bias_kind == 0 ? plane_max : bias_kind == 1 ? -plane_max : uniform(-300, 300);
  const int bias_slope = int(uniform(-128, 127));
  const bool unbiased = uniform(0, 3) == 0;
  if (profile.depth_biased()) {
    if (free("depth_bias_constant")) p.depth_bias_constant = unbiased ? 0 : bias_constant;
    if (free("depth_bias_slope")) p.depth_bias_slope = unbiased ? 0 : bias_slope;
  }
  return p;
}

std::vector<CosimCase> texture_cases(const Profile& profile, const std::set<std::string>& pinned) {
  Generator g(profile, 271828);
  std::mt19937_64 rng(314159);
  auto real = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  auto free = [&](const char* key) { return pinned.count(key) == 0; };
  std::vector<CosimCase> cases;
  // Textured small and medium triangles with u, v in [-3, 3] (every wrap case: negative, inside,
  // beyond) and w spread up to 2^6, and now and then an untextured one.
  auto frame = [&](const std::string& name, TextureFilter filter, TextureWrap wrap, int log2_w, int log2_h) {
    CosimCase c{"directed texture " + name, {}, profile, {noise_texture(rng, log2_w, log2_h), filter, wrap}};
    for (int i = 0; i < 16; ++i) {
      SnappedTriangle t = i % 2 ? g.medium() : g.tiny();
      if (i % 8 != 7) {
        const double w[3] = {1.0, std::exp2(real(0.0, 6.0)), std::exp2(real(0.0, 6.0))};
        texture_with_w(rng, t, 3.0, w);
      }
      c.triangles.push_back(t);
    }
    return c;
  };
  // Both filters with both wrap modes, on textures of different shapes.
  cases.push_back(frame("nearest, repeat", TextureFilter::Nearest, TextureWrap::Repeat, 4, 3));
  cases.push_back(frame("nearest, clamp", TextureFilter::Nearest, TextureWrap::Clamp, 3, 5));
  cases.push_back(frame("bilinear, repeat", TextureFilter::Bilinear, TextureWrap::Repeat, 5, 4));
  cases.push_back(frame("bilinear, clamp", TextureFilter::Bilinear, TextureWrap::Clamp, 2, 2));
  // Triangles at the divide's limit: one vertex at w = 1, one at w = 2^14 (docs/arithmetic.md
  // section 5), u, v from a fraction of a repeat to the limits +-128.
  CosimCase ratio{"directed texture w ratio 2^14", {}, profile,
                  {noise_texture(rng, 6, 6), TextureFilter::Bilinear, TextureWrap::Repeat}};
  for (int i = 0; i < 12; ++i) {
    SnappedTriangle t = g.medium();
    double w[3] = {1.0, std::exp2(14.0), std::exp2(real(0.0, 14.0))};
    std::swap(w[0], w[i % 3]);
    texture_with_w(rng, t, i % 3 == 0 ? 127.0 : i % 3 == 1 ? 4.0 : 0.5, w);
    ratio.triangles.push_back(t);
  }
  cases.push_back(std::move(ratio));
  // Texture memory stalls at the smallest and the largest texture latency: a pattern that refuses
  // reads in about half (a quarter) of the cycles.
  for (const int latency : {1, kMaxTextureLatency}) {
    CosimCase c = frame("stalls, texture_latency " + std::to_string(latency), TextureFilter::Bilinear,
                        latency == 1 ? TextureWrap::Clamp : TextureWrap::Repeat, 4, 4);
    if (free("texture_latency")) c.profile.texture_latency = latency;
    if (free("texture_stall_percent")) c.profile.texture_stall_percent = latency == 1 ? 50 : 25;
    if (free("texture_stall_seed")) c.profile.texture_stall_seed = 1000 + latency;
    cases.push_back(std::move(c));
  }
  return cases;
}

std::vector<CosimCase> directed_cases(const Profile& profile, const std::set<std::string>& pinned) {
  Generator g(profile, 12345);
  std::vector<CosimCase> cases;
  auto add = [&](const std::string& name, auto make, int count) {
    CosimCase c{"directed " + name, {}, profile, {}};
    for (int i = 0; i < count; ++i) c.triangles.push_back(make(i));
    cases.push_back(std::move(c));
  };
  const int cx = profile.width / 2, cy = profile.height / 2;
  add("centre-on-edge ties", [&](int) { return g.centre_ties(); }, 40);
  add("huge", [&](int) { return g.huge(); }, 6);
  add("off-screen", [&](int) { return g.offscreen(); }, 12);
  add("between centres", [&](int) { return g.between_centres(); }, 8);
  add("degenerate", [&](int) { return g.degenerate(); }, 12);
  add("long rows", [&](int) { return g.long_row(); }, 8);
  // Back-to-back tiny triangles on the same pixel: a long walk whose last fragment is pixel P, then
  // a small triangle starting on P, loaded right after it while P's write is still in flight
  // (a hazard stall when L >= 2 for bbox, L >= 3 for span with its row cycle), then more on P.
  add("hazards", [&](int i) {
    const int px = std::clamp(cx + (i / 4) % 5 - 2, 21, std::max(21, profile.width - 3));
    const int py = std::clamp(cy, 21, std::max(21, profile.height - 3));
    return i % 4 == 0 ? g.ending_at(px, py) : i % 4 == 1 ? g.starting_at(px, py) : i % 4 == 2 ? g.around(px, py)
                                                                                             : g.tiny_at(px, py);
  }, 40);
  // The same triangle drawn again and again with new colours: equal depths for every depth function.
  const SnappedTriangle repeated = g.medium();
  add("repeated", [&](int) {
    SnappedTriangle t = repeated;
    for (SnappedVertex& v : t.v) v.color = g.color();
    return t;
  }, 6);
  add("mixed", [&](int) { return g.any(); }, 40);
  if (pinned.count("depth_func") == 0) {
    // Every depth function on triangles drawn twice, at the clear depth, and overlapping.
    for (int f = 0; f <= int(DepthFunc::Always); ++f) {
      Profile p = profile;
      p.depth_func = DepthFunc(f);
      CosimCase c{std::string("directed depth ") + to_string(p.depth_func), {}, p, {}};
      for (int i = 0; i < 24; ++i) {
        const SnappedTriangle t = i % 3 == 0 ? repeated : i % 3 == 1 ? g.at_clear_depth(g.medium()) : g.any();
        c.triangles.push_back(t);
        if (i % 3 == 0) c.triangles.back().v[0].color = g.color();
      }
      cases.push_back(std::move(c));
    }
  }
  return cases;
}

std::vector<CosimCase> coverage_cases(const Profile& profile, const std::set<std::string>& pinned,
                                      int max_memory_latency) {
  Generator g(profile, 54321);
  auto free = [&](const char* key) { return pinned.count(key) == 0; };
  std::vector<CosimCase> cases;
  const int64_t one = int64_t(1) << profile.subpixel_bits;
  const int64_t x_lo = -profile.width * one, x_hi = 2 * profile.width * one;
  const int64_t y_lo = -profile.height * one, y_hi = 2 * profile.height * one;
  // A triangle covering the whole screen with vertices on the guard band's limits: apex at
  // (W/2, -H), base on y = 2H from x = -W to 2W (its sides cross y = 0 at x = 0 and x = W).
  auto screen_cover = [&](bool reversed) {
    const int64_t apex_x = profile.width * one / 2;
    return reversed ? g.triangle({apex_x, y_lo, x_lo, y_hi, x_hi, y_hi}) : g.triangle({apex_x, y_lo, x_hi, y_hi, x_lo, y_hi});
  };
  // The cover walks of the hazard frames below: long enough for the setup unit to have the next
  // two records ready (the serial unit takes far longer for a record than the walker for a small
  // triangle), a triangle of that many pixels or, past half the screen, whole-screen triangles,
  // as many as that takes (with the serial setup one whole-screen walk is shorter than two setups).
  const SetupTiming timing = setup_timing(profile);
  const int64_t per_record = timing.interval > 0 ? timing.interval : timing.drawn_latency + 1;
  const int64_t needed = 2 * (timing.drawn_latency + per_record) + 64;  // cover walk, cycles
  const int64_t leg = std::min<int64_t>(std::min(profile.width, profile.height),
                                        int64_t(std::ceil(std::sqrt(2.0 * double(needed)))));
  const bool whole_screen = needed >= int64_t(profile.width) * profile.height / 2;
  const int covers = whole_screen ? int(std::min<int64_t>(8, needed / (int64_t(profile.width) * profile.height) + 1)) : 1;
  // Whole-screen triangles of each winding (one is drawn whatever the cull mode; with back culling
  // the other is culled), `covers` of each, followed by tiny triangles that fill the record FIFO
  // while the walker crosses the screen.
  auto fill = [&](const std::string& name, const Profile& p) {
    CosimCase c{"coverage " + name, {}, p, {}};
    for (const bool reversed : {false, true}) {
      for (int i = 0; i < covers; ++i) c.triangles.push_back(screen_cover(reversed));
      for (int i = 0; i < 20; ++i) c.triangles.push_back(g.tiny());
    }
    cases.push_back(std::move(c));
  };
  // With the FIFO depth free, depth 2 and depth 1: the serial unit too fills two records while the
  // walker crosses the screen `covers` times.
  Profile culling = profile;
  if (free("cull")) culling.cull = CullMode::Back;  // one of the two whole-screen triangles is culled
  if (free("setup_fifo_depth")) culling.setup_fifo_depth = 2;
  fill("guard band limits and a full record FIFO", culling);
  if (free("setup_fifo_depth")) {
    Profile p = profile;
    p.setup_fifo_depth = 1;
    fill("guard band limits and a full record FIFO of depth 1", p);
  }
  // Hazards at every memory latency the RTL is built for, with the traversals the run can use: a
  // walk ending on pixel P, then one starting on P right after it. The cover walks first give the
  // setup unit time to have both records ready, so the second walk follows the first without a
  // gap; a hazard then needs the latency to outlast the walker's load cycle, and with span its row
  // cycle too.
  const int cx = std::clamp(profile.width / 2, std::min(21, profile.width - 1), std::max(0, profile.width - 3));
  const int cy = std::clamp(profile.height / 2, std::min(21, profile.height - 1), std::max(0, profile.height - 3));
  CosimCase hazards{"", {}, profile, {}};
  // A cover triangle, a walk ending on pixel (px, cy), then two more on that pixel: one starting on
  // it and one around it; or, as a chain, one covering it alone and one starting on it (the middle
  // one's only fragment waits on the first one's write while the third one's first fragment waits
  // behind it in the z-buffer's input buffer, so the third must also wait for the middle one's
  // read: docs/cycle-model.md, "Z-buffer").
  auto group = [&](int px, bool chain) {
    for (int i = 0; i < covers; ++i)
      hazards.triangles.push_back(whole_screen ? screen_cover(false) : g.triangle({0, 0, leg * one, 0, 0, leg * one}));
    hazards.triangles.push_back(g.ending_at(px, cy));
    hazards.triangles.push_back(chain ? g.only(px, cy) : g.starting_at(px, cy));
    hazards.triangles.push_back(chain ? g.starting_at(px, cy) : g.around(px, cy));
  };
  for (int i = 0; i < 5; ++i) group(std::clamp(cx + i - 2, 0, profile.width - 1), false);
  for (int i = 0; i < 3; ++i) group(std::clamp(cx + i - 1, 0, profile.width - 1), true);
  if (free("setup_fifo_depth")) hazards.profile.setup_fifo_depth = std::max(2, profile.setup_fifo_depth);
  // Every latency the RTL is built for: at 1 and at the largest with each traversal, in between
  // with the traversals in turn.
  std::vector<int> latencies = {profile.memory_latency};
  if (free("memory_latency")) {
    latencies.clear();
    for (int latency = 1; latency <= max_memory_latency; ++latency) latencies.push_back(latency);
  }
  for (const int latency : latencies) {
    std::vector<Traversal> traversals = {profile.traversal};
    if (free("traversal"))
      traversals = latency == 1 || latency == max_memory_latency ? std::vector<Traversal>{Traversal::BBox, Traversal::Span}
                   : latency % 2 ? std::vector<Traversal>{Traversal::BBox} : std::vector<Traversal>{Traversal::Span};
    for (const Traversal traversal : traversals) {
      CosimCase c = hazards;
      c.name = std::string("coverage hazards, ") + to_string(traversal) + ", memory_latency " + std::to_string(latency);
      c.profile.traversal = traversal;
      c.profile.memory_latency = latency;
      cases.push_back(std::move(c));
    }
  }
  // Every depth function with depth_write flipped (directed_cases draws them with the profile's)
  // on a buffer cleared to mid-range, so that greater passes too.
  if (free("depth_func")) {
    const SnappedTriangle repeated = g.medium();
    for (int f = 0; f <= int(DepthFunc::Always); ++f) {
      Profile p = profile;
      p.depth_func = DepthFunc(f);
      if (free("depth_write")) p.depth_write = !profile.depth_write;
      if (free("depth_clear")) p.depth_clear = profile.depth_max() / 2;
      CosimCase c{std::string("coverage depth ") + to_string(p.depth_func) +
                      (p.depth_write ? " with depth_write" : " without depth_write"), {}, p, {}};
      for (int i = 0; i < 12; ++i)
        c.triangles.push_back(i % 3 == 0 ? repeated : i % 3 == 1 ? g.at_clear_depth(g.tiny()) : g.tiny());
      cases.push_back(std::move(c));
    }
  }
  // With the depth bias: each sign of its constant and slope factor, the slope at both extremes,
  // on triangles with depth steps.
  if (profile.depth_biased()) {
    const std::pair<int64_t, int> biases[] = {{-300, -128}, {300, 127}, {37, -9}};
    for (const auto& [constant, slope] : biases) {
      CosimCase c{"", {}, profile, {}};
      if (free("depth_bias_constant")) c.profile.depth_bias_constant = constant;
      if (free("depth_bias_slope")) c.profile.depth_bias_slope = slope;
      c.name = "coverage depth bias, constant " + std::to_string(c.profile.depth_bias_constant) + ", slope " +
               std::to_string(c.profile.depth_bias_slope) + "/16";
      for (int i = 0; i < 16; ++i) c.triangles.push_back(i % 4 == 3 ? g.tiny() : g.medium());
      cases.push_back(std::move(c));
    }
  }
  return cases;
}

CosimPlan::CosimPlan(const Profile& profile, const std::set<std::string>& pinned, int max_memory_latency,
                     uint64_t seed, int triangles, bool directed)
    : profile_(profile), pinned_(pinned), max_memory_latency_(max_memory_latency), seed_(seed), triangles_(triangles) {
  if (directed) {
    directed_ = directed_cases(profile, pinned);
    if (profile.texture_unit)
      for (CosimCase& c : texture_cases(profile, pinned)) directed_.push_back(std::move(c));
    for (CosimCase& c : coverage_cases(profile, pinned, max_memory_latency)) directed_.push_back(std::move(c));
  }
  for (const std::string& key : runtime_setting_keys())
    if (!pinned.count(key)) varied_.push_back(key);
}

CosimCase CosimPlan::frame(int64_t k) const {
  if (k < directed_count()) return directed_[size_t(k)];
  const uint64_t frame_seed = seed_ + uint64_t(k);
  CosimCase c = random_case(profile_, frame_seed, triangles_);
  if (!varied_.empty()) c.profile = random_settings(profile_, frame_seed, pinned_, max_memory_latency_);
  return c;
}

}  // namespace rastersim::rtl
