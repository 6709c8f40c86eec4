// The texture sampler (model/texture_sampler.h) against references written from the rules of
// docs/design/texturing.md with other arithmetic: texel coordinates as doubles (exact: at most 28
// significant bits), floor and modulo instead of shifts and masks, exact quotients for the blend
// and the modulation.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>

#include "model/texture_sampler.h"

namespace rastersim {
namespace {

int64_t place_reference(int64_t index, int size, TextureWrap wrap) {
  if (wrap == TextureWrap::Repeat) return ((index % size) + size) % size;
  return std::min<int64_t>(std::max<int64_t>(index, 0), size - 1);
}

AxisTexels axis_reference(int32_t coord, int log2_size, TextureFilter filter, TextureWrap wrap) {
  const int size = 1 << log2_size;
  const double texels = std::ldexp(double(coord), log2_size - kUvFracBits);  // coord in texels
  AxisTexels t;
  if (filter == TextureFilter::Nearest) {
    t.first = t.second = int(place_reference(int64_t(std::floor(texels)), size, wrap));
    return t;
  }
  const double centred = texels - 0.5;  // texel centres at k + 1/2
  const double below = std::floor(centred);
  t.first = int(place_reference(int64_t(below), size, wrap));
  t.second = int(place_reference(int64_t(below) + 1, size, wrap));
  t.weight = int(std::floor((centred - below) * (1 << kWeightBits)));
  return t;
}

const TextureFilter kFilters[] = {TextureFilter::Nearest, TextureFilter::Bilinear};
const TextureWrap kWraps[] = {TextureWrap::Repeat, TextureWrap::Clamp};

void expect_axis(int32_t coord, int log2_size) {
  for (TextureFilter filter : kFilters)
    for (TextureWrap wrap : kWraps) {
      const AxisTexels got = axis_texels(coord, log2_size, filter, wrap);
      const AxisTexels want = axis_reference(coord, log2_size, filter, wrap);
      ASSERT_EQ(got.first, want.first) << "coord " << coord << " size 2^" << log2_size;
      ASSERT_EQ(got.second, want.second) << "coord " << coord << " size 2^" << log2_size;
      ASSERT_EQ(got.weight, want.weight) << "coord " << coord << " size 2^" << log2_size;
    }
}

TEST(TextureSampler, AxisTexelsMatchTheRulesOnRandomCoordinates) {
  std::mt19937 rng(17);
  const int32_t lo = -(int32_t(1) << (kUvBits - 1)), hi = (int32_t(1) << (kUvBits - 1)) - 1;
  std::uniform_int_distribution<int32_t> any(lo, hi);
  std::uniform_int_distribution<int32_t> near_one(-(3 << kUvFracBits), 3 << kUvFracBits);
  for (int n = 0; n < 200000; ++n) {
    const int log2_size = n % (kMaxTextureLog2 + 1);
    expect_axis(n % 2 ? any(rng) : near_one(rng), log2_size);
  }
  for (int log2_size = 0; log2_size <= kMaxTextureLog2; ++log2_size) expect_axis(lo, log2_size), expect_axis(hi, log2_size);
}

TEST(TextureSampler, AxisTexelsMatchTheRulesAroundEveryTexelEdgeAndCentre) {
  for (int log2_size = 0; log2_size <= kMaxTextureLog2; ++log2_size) {
    const int32_t texel = int32_t(1) << (kUvFracBits - log2_size);
    for (int32_t k = -2 * (1 << log2_size); k <= 2 * (1 << log2_size); ++k)
      for (int32_t at : {k * texel, k * texel + texel / 2})
        for (int32_t delta = -1; delta <= 1; ++delta) expect_axis(at + delta, log2_size);
  }
}

TEST(TextureSampler, BilinearAtATexelCentreReadsThatTexelAlone) {
  // (k + 1/2) / size is texel k's centre: weight 0 on the next texel, so the blend is texel k.
  for (int log2_size = 0; log2_size <= kMaxTextureLog2; ++log2_size)
    for (int k = 0; k < (1 << log2_size); ++k) {
      const int32_t centre = (2 * k + 1) << (kUvFracBits - log2_size - 1);
      const AxisTexels t = axis_texels(centre, log2_size, TextureFilter::Bilinear, TextureWrap::Repeat);
      EXPECT_EQ(t.first, k);
      EXPECT_EQ(t.weight, 0);
      EXPECT_EQ(axis_texels(centre, log2_size, TextureFilter::Nearest, TextureWrap::Repeat).first, k);
    }
}

TEST(TextureSampler, BlendMatchesTheExactWeightedSumRoundedHalfUp) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> channel(0, 255), weight(0, (1 << kWeightBits) - 1);
  for (int n = 0; n < 300000; ++n) {
    const int a = channel(rng), b = channel(rng), c = channel(rng), d = channel(rng);
    const int wx = weight(rng), wy = weight(rng);
    // sum / 65536 rounded half up: floor((2 sum + 65536) / 131072), in 64-bit integers.
    const int64_t sum = (int64_t(a) * (256 - wx) + int64_t(b) * wx) * (256 - wy) +
                        (int64_t(c) * (256 - wx) + int64_t(d) * wx) * wy;
    ASSERT_EQ(blend_channel(a, b, c, d, wx, wy), int((2 * sum + 65536) / 131072))
        << a << " " << b << " " << c << " " << d << " at " << wx << " " << wy;
  }
  // Equal texels blend to themselves at every weight.
  for (int value : {0, 1, 128, 254, 255})
    for (int wx = 0; wx < 256; ++wx)
      for (int wy = 0; wy < 256; ++wy) ASSERT_EQ(blend_channel(value, value, value, value, wx, wy), value);
}

TEST(TextureSampler, ModulationIsTheRoundedProductOnEveryPair) {
  for (int t = 0; t < 256; ++t)
    for (int g = 0; g < 256; ++g)
      ASSERT_EQ(modulate_channel(t, g), (2 * t * g + 255) / 510) << t << " x " << g;  // round(t g / 255), half up
}

TEST(TextureSampler, RowZeroIsTheBottomOfTheTexture) {
  // 2 x 2 texels; memory word j 2 + i holds texel (i, j), j counted from the bottom.
  const Texture texture(1, 1, {0x000001, 0x000002, 0x000003, 0x000004});
  auto at = [&](double u, double v) {
    const Rgb c = texture.sample(int32_t(u * (1 << kUvFracBits)), int32_t(v * (1 << kUvFracBits)),
                                 TextureFilter::Nearest, TextureWrap::Clamp);
    return int(c.b);
  };
  EXPECT_EQ(at(0.25, 0.25), 1);  // bottom left
  EXPECT_EQ(at(0.75, 0.25), 2);  // bottom right
  EXPECT_EQ(at(0.25, 0.75), 3);  // top left
  EXPECT_EQ(at(0.75, 0.75), 4);  // top right
}

// The worked example of docs/design/texturing.md, numbers computed by hand there.
TEST(TextureSampler, WorkedExample) {
  std::ifstream in(RASTERSIM_SOURCE_DIR "/docs/design/texturing.md");
  ASSERT_TRUE(in);
  std::map<std::string, std::string> keys;
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (!inside && line == "```example-texel") inside = true;
    else if (inside && line == "```") break;
    else if (inside && line.find(" = ") != std::string::npos)
      keys[line.substr(0, line.find(" = "))] = line.substr(line.find(" = ") + 3);
  }
  ASSERT_EQ(keys.size(), 12u) << "the example-texel block";
  int log2_width = 0, log2_height = 0;
  std::istringstream(keys["log2 size"]) >> log2_width >> log2_height;
  const int32_t u = std::stoi(keys["u"]), v = std::stoi(keys["v"]);
  auto axes = [&](TextureFilter filter, TextureWrap wrap) {
    const AxisTexels x = axis_texels(u, log2_width, filter, wrap), y = axis_texels(v, log2_height, filter, wrap);
    std::ostringstream s;
    if (filter == TextureFilter::Nearest) s << x.first << " " << y.first;
    else s << x.first << " " << x.second << " " << x.weight << " / " << y.first << " " << y.second << " " << y.weight;
    return s.str();
  };
  EXPECT_EQ(axes(TextureFilter::Nearest, TextureWrap::Repeat), keys["nearest repeat"]);
  EXPECT_EQ(axes(TextureFilter::Nearest, TextureWrap::Clamp), keys["nearest clamp"]);
  EXPECT_EQ(axes(TextureFilter::Bilinear, TextureWrap::Repeat), keys["bilinear repeat"]);
  EXPECT_EQ(axes(TextureFilter::Bilinear, TextureWrap::Clamp), keys["bilinear clamp"]);
  int a, b, c, d, wx, wy, texel, shade;
  std::istringstream(keys["blend texels"]) >> a >> b >> c >> d;
  std::istringstream(keys["blend weights"]) >> wx >> wy;
  EXPECT_EQ(std::to_string(blend_channel(a, b, c, d, wx, wy)), keys["blend"]);
  std::istringstream(keys["modulate"]) >> texel >> shade;
  EXPECT_EQ(std::to_string(modulate_channel(texel, shade)), keys["modulated"]);
}

}  // namespace
}  // namespace rastersim
