// Heavy libraries as modules loaded on first use: OpenImageIO (about 250 shared libraries of
// image codecs) behind the image outputs, SystemC behind `--backend systemc`. A command that needs
// neither starts without them (docs/performance.md, "Start-up").
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rastersim {

// The image module (librastersim_images.so, cli/image_plugin.cpp).
enum class PixelType { UInt8 = 0, UInt16 = 1, Float = 2 };
// True when there is a writer for the path's extension (PNG here, the others in OpenImageIO).
bool image_format_writable(const std::string& path);
// The image encoded in memory by the writer the path's extension selects: PNG (8 or 16 bits) by
// libpng in the program (cli/png_writer.h), the rest by OpenImageIO; throws with its message.
std::vector<unsigned char> encode_image(const std::string& path, int width, int height, int channels, PixelType type,
                                        const void* pixels);

// An image file decoded as 8-bit RGB, top row first, 3 bytes a pixel (grey repeated, alpha dropped);
// `rgb` empty when the image is wider or taller than `max_size` (its pixels are not read). Throws
// with OpenImageIO's message, which names the file.
struct DecodedImage {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
};
DecodedImage decode_image_rgb8(const std::string& path, int max_size);

// A SystemC backend library: the built one (librastersim_systemc.so) when library_path is empty,
// else a module built on demand (testbench/modules.h). Its rastersim_systemc_api() table, as a
// `const rastersim::systemc::Api*` (testbench/systemc/systemc_backend.h); throws when the library's
// ABI stamp is not `abi`.
const void* systemc_api(const std::string& library_path, const std::string& abi);

}  // namespace rastersim
