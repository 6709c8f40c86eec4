// Texture sampler: from a fragment's perspective-divided texture coordinate to its texel
// addresses, bilinear weights, filtered texel and the texel modulated by the Gouraud colour
// (docs/design/texturing.md, "The sampler"). The first unit of the texturing pipeline; the planes
// of u/w, v/w and 1/w and the per-fragment divide that feed it come next.
//
// Texture space: (0, 0) is the bottom-left corner of the texture and (1, 1) its top-right one. A
// texture of 2^lw x 2^lh texels holds texel (i, j) (column i from the left, row j from the bottom)
// at word j 2^lw + i of its memory: row 0 is the image file's last row.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "triangle.h"

namespace rastersim {

// A texture coordinate as the perspective divide delivers it: s8.20 (28-bit two's complement,
// 20 fraction bits), in units of the texture, so |u| < 128 (repeats of the texture).
constexpr int kUvFracBits = 20;
constexpr int kUvBits = 28;
// Textures are 2^lw x 2^lh texels with 0 <= lw, lh <= kMaxTextureLog2.
constexpr int kMaxTextureLog2 = 10;
// Bilinear weights: unsigned 0.8, the fraction of the second texel of a pair.
constexpr int kWeightBits = 8;
static_assert(kUvFracBits - kMaxTextureLog2 >= kWeightBits, "a texel's fraction must hold a weight");

enum class TextureFilter { Nearest, Bilinear };
enum class TextureWrap { Repeat, Clamp };

// The texels one axis reads: `first` and `second` (columns or rows, already wrapped or clamped)
// and the weight of `second` in 1/2^kWeightBits. Nearest reads one texel: second == first,
// weight 0.
struct AxisTexels {
  int first = 0, second = 0;
  int weight = 0;
};

// One axis of the lookup: `coord` an s8.20 coordinate, the texture 2^log2_size texels along it.
// The coordinate in texels is coord 2^log2_size, with T = kUvFracBits - log2_size fraction bits.
// Nearest: texel floor(coord 2^log2_size). Bilinear: the texel centres on either side, i0 =
// floor(c - 1/2) and i0 + 1, with the weight of i0 + 1 the fraction of c - 1/2 truncated to
// kWeightBits. Repeat takes a texel index modulo 2^log2_size, clamp limits it to [0, 2^log2_size - 1].
inline AxisTexels axis_texels(int32_t coord, int log2_size, TextureFilter filter, TextureWrap wrap) {
  const int fraction_bits = kUvFracBits - log2_size;
  const int32_t last = (int32_t(1) << log2_size) - 1;
  auto place = [&](int32_t index) {
    if (wrap == TextureWrap::Repeat) return int(index & last);
    return int(index < 0 ? 0 : (index > last ? last : index));
  };
  AxisTexels t;
  if (filter == TextureFilter::Nearest) {
    t.first = t.second = place(coord >> fraction_bits);  // arithmetic shift: floor
    return t;
  }
  const int32_t centred = coord - (int32_t(1) << (fraction_bits - 1));
  const int32_t index = centred >> fraction_bits;
  t.first = place(index);
  t.second = place(index + 1);
  t.weight = int((centred & ((int32_t(1) << fraction_bits) - 1)) >> (fraction_bits - kWeightBits));
  return t;
}

// Word of texel (i, j) in the texture's memory.
inline uint32_t texel_address(int i, int j, int log2_width) { return (uint32_t(j) << log2_width) | uint32_t(i); }

// Bilinear blend of one 8-bit channel: a, b the lower row's texels (first, second column), c, d
// the upper row's; wx, wy the weights of the second column and row. Exact: the weighted sum in
// 1/2^16, rounded half up.
inline int blend_channel(int a, int b, int c, int d, int wx, int wy) {
  constexpr int one = 1 << kWeightBits;
  const int lower = a * (one - wx) + b * wx;
  const int upper = c * (one - wx) + d * wx;
  return (lower * (one - wy) + upper * wy + (1 << (2 * kWeightBits - 1))) >> (2 * kWeightBits);
}

// A texel channel times a Gouraud channel, both 0..255 meaning 0..1: round(t g / 255), half up,
// without a divider (x + (x >> 8)) >> 8 with x = t g + 128 (tests/test_texture_sampler.cpp checks
// all 65,536 pairs).
inline int modulate_channel(int texel, int shade) {
  const int x = texel * shade + 128;
  return (x + (x >> 8)) >> 8;
}

// A texture in the sampler's memory layout (bottom row first), 0xRRGGBB per texel.
class Texture {
 public:
  Texture(int log2_width, int log2_height, std::vector<uint32_t> texels)
      : log2_width_(log2_width), log2_height_(log2_height), texels_(std::move(texels)) {}

  int log2_width() const { return log2_width_; }
  int log2_height() const { return log2_height_; }
  uint32_t texel(int i, int j) const { return texels_[texel_address(i, j, log2_width_)]; }

  // The filtered texel at (u, v), s8.20 each.
  Rgb sample(int32_t u, int32_t v, TextureFilter filter, TextureWrap wrap) const {
    const AxisTexels x = axis_texels(u, log2_width_, filter, wrap);
    const AxisTexels y = axis_texels(v, log2_height_, filter, wrap);
    const uint32_t t[4] = {texel(x.first, y.first), texel(x.second, y.first), texel(x.first, y.second),
                           texel(x.second, y.second)};
    auto channel = [&](int shift) {
      return uint8_t(blend_channel(int(t[0] >> shift) & 255, int(t[1] >> shift) & 255, int(t[2] >> shift) & 255,
                                   int(t[3] >> shift) & 255, x.weight, y.weight));
    };
    return Rgb{channel(16), channel(8), channel(0)};
  }

 private:
  int log2_width_, log2_height_;
  std::vector<uint32_t> texels_;
};

// The fragment's colour: the filtered texel modulated by its Gouraud colour, channel by channel.
inline Rgb modulate(const Rgb& texel, const Rgb& shade) {
  return Rgb{uint8_t(modulate_channel(texel.r, shade.r)), uint8_t(modulate_channel(texel.g, shade.g)),
             uint8_t(modulate_channel(texel.b, shade.b))};
}

}  // namespace rastersim
