// Texture images (cli/texture_reader.h): written here with OpenImageIO in formats and channel
// counts a user has, read back as the sampler's memory (bottom row first), and every refusal an
// InputError naming the file.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli_test_support.h"
#include "model/input_error.h"
#include "texture_reader.h"

namespace rastersim {
namespace {

using cli_test::ScratchDir;
namespace fs = std::filesystem;

template <class T>
void write_image(const fs::path& path, int width, int height, int channels, OIIO::TypeDesc type,
                 const std::vector<T>& pixels) {
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out) << OIIO::geterror();
  ASSERT_TRUE(out->open(path.string(), OIIO::ImageSpec(width, height, channels, type)));
  ASSERT_TRUE(out->write_image(type, pixels.data()));
  ASSERT_TRUE(out->close());
}

// The InputError message of reading `path`, or "no error".
std::string error_of(const fs::path& path) {
  try {
    read_texture_file(path.string());
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(TextureReader, TheFilesLastRowIsRowZero) {
  ScratchDir dir;
  // 4 x 2 pixels, top row first as the file stores them: pixel (x, row) = (x, row, 7).
  std::vector<unsigned char> pixels;
  for (int row = 0; row < 2; ++row)
    for (int x = 0; x < 4; ++x) pixels.insert(pixels.end(), {(unsigned char)x, (unsigned char)row, 7});
  write_image(dir.path("t.png"), 4, 2, 3, OIIO::TypeDesc::UINT8, pixels);
  const Texture t = read_texture_file(dir.path("t.png").string());
  EXPECT_EQ(t.log2_width(), 2);
  EXPECT_EQ(t.log2_height(), 1);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) EXPECT_EQ(t.texel(i, j), (uint32_t(i) << 16) | (uint32_t(1 - j) << 8) | 7u) << i << "," << j;
  // Texture coordinate (0, 0) is the image's bottom-left corner: the file's last row, first pixel.
  const Rgb corner = t.sample(0, 0, TextureFilter::Nearest, TextureWrap::Clamp);
  EXPECT_EQ(corner, (Rgb{0, 1, 7}));
}

TEST(TextureReader, GreyIsRepeatedAlphaDroppedAndSixteenBitsConverted) {
  ScratchDir dir;
  write_image(dir.path("grey.png"), 2, 1, 1, OIIO::TypeDesc::UINT8, std::vector<unsigned char>{10, 250});
  const Texture grey = read_texture_file(dir.path("grey.png").string());
  EXPECT_EQ(grey.texel(0, 0), 0x0a0a0au);
  EXPECT_EQ(grey.texel(1, 0), 0xfafafau);
  write_image(dir.path("alpha.png"), 1, 1, 4, OIIO::TypeDesc::UINT8, std::vector<unsigned char>{1, 2, 3, 0});
  EXPECT_EQ(read_texture_file(dir.path("alpha.png").string()).texel(0, 0), 0x010203u);
  // 16 bits: v / 257 exactly for these (0x8080 = 128 x 257).
  write_image(dir.path("deep.png"), 1, 2, 3, OIIO::TypeDesc::UINT16,
              std::vector<uint16_t>{0xffff, 0x8080, 0, 0, 257, 0xffff});
  const Texture deep = read_texture_file(dir.path("deep.png").string());
  EXPECT_EQ(deep.texel(0, 1), 0xff8000u);  // the file's first row is the top (j = 1)
  EXPECT_EQ(deep.texel(0, 0), 0x0001ffu);
}

TEST(TextureReader, RefusalsNameTheFileAndTheProblem) {
  ScratchDir dir;
  write_image(dir.path("three.png"), 3, 4, 3, OIIO::TypeDesc::UINT8, std::vector<unsigned char>(3 * 4 * 3));
  write_image(dir.path("wide.png"), 2048, 1, 3, OIIO::TypeDesc::UINT8, std::vector<unsigned char>(2048 * 3));
  dir.write("text.png", "this is not a PNG\n");
  fs::create_directory(dir.path("folder.png"));
  // Endless or blocking inputs end at once (a link to /dev/zero spun until killed).
  fs::create_symlink("/dev/zero", dir.path("zero.png"));
  ASSERT_EQ(mkfifo(dir.path("fifo.png").c_str(), 0600), 0);
  dir.write("huge.png", "");
  fs::resize_file(dir.path("huge.png"), kMaxTextureBytes + 1);  // sparse: no disk used
  const std::string powers = "its width and height must be powers of two up to 1024";
  struct Case {
    std::string file, problem;
  };
  for (const Case& c : {Case{"three.png", "the texture is 3 x 4 pixels; " + powers},
                        Case{"wide.png", "the texture is 2048 x 1 pixels; " + powers},
                        Case{"missing.png", "cannot open: No such file or directory"},
                        Case{"folder.png", "is a directory, not a texture image"}, Case{"text.png", ""},
                        Case{"zero.png", "is not a regular file"}, Case{"fifo.png", "is not a regular file"},
                        Case{"huge.png", "the file is larger than 64 MiB"}}) {
    const std::string path = dir.path(c.file).string();
    const std::string message = error_of(path);
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(c.problem), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace rastersim
