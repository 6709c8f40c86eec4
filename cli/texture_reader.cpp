#include "texture_reader.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <utility>

#include "model/input_error.h"
#include "plugins.h"

namespace rastersim {
namespace {

// log2(n) when n is a power of two up to 2^kMaxTextureLog2, else -1.
int size_log2(int n) {
  for (int k = 0; k <= kMaxTextureLog2; ++k)
    if (n == 1 << k) return k;
  return -1;
}

}  // namespace

Texture read_texture_file(const std::string& path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (std::filesystem::is_directory(status)) throw InputError(path, 0, "is a directory, not a texture image");
  // Checked before anything opens it: a FIFO would block the open, a device (/dev/zero) never ends.
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw InputError(path, 0, "is not a regular file (a device, FIFO or socket): a texture must be an image file");
  if (std::filesystem::exists(status) && std::filesystem::file_size(path, ec) > kMaxTextureBytes)
    throw InputError(path, 0, "the file is larger than " + std::to_string(kMaxTextureBytes >> 20) +
                                  " MiB, the limit of a texture (at most 1024 x 1024 texels)");
  if (!std::ifstream(path, std::ios::binary)) throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  DecodedImage image;
  try {
    image = decode_image_rgb8(path, 1 << kMaxTextureLog2);
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());  // OpenImageIO's message, which starts with the path
  }
  const int log2_width = size_log2(image.width), log2_height = size_log2(image.height);
  if (log2_width < 0 || log2_height < 0)
    throw InputError(path, 0, "the texture is " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                                  " pixels; its width and height must be powers of two up to " +
                                  std::to_string(1 << kMaxTextureLog2));
  std::vector<uint32_t> texels(size_t(image.width) * size_t(image.height));
  for (int row = 0; row < image.height; ++row)
    for (int i = 0; i < image.width; ++i) {
      const unsigned char* p = &image.rgb[3 * (size_t(row) * size_t(image.width) + size_t(i))];
      const int j = image.height - 1 - row;  // the file's first row is the texture's top
      texels[texel_address(i, j, log2_width)] = (uint32_t(p[0]) << 16) | (uint32_t(p[1]) << 8) | p[2];
    }
  return Texture(log2_width, log2_height, std::move(texels));
}

}  // namespace rastersim
