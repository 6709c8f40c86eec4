// Texture images (docs/design/texturing.md): any image file OpenImageIO reads, as the texture
// sampler's memory (model/texture_sampler.h).
#pragma once

#include <cstdint>
#include <string>

#include "model/texture_sampler.h"

namespace rastersim {

// The largest texture file read: a 1024 x 1024 image of four 32-bit float channels, uncompressed,
// is 16 MiB.
constexpr uintmax_t kMaxTextureBytes = uintmax_t(64) << 20;

// Reads a texture (a regular file of at most kMaxTextureBytes): its width and height must be powers of two up to 2^kMaxTextureLog2 (1024);
// its pixels become 8-bit RGB (grey repeated, alpha dropped, other types converted by
// OpenImageIO), stored bottom row first, so that texel (0, 0) is the image's bottom-left pixel.
// Throws InputError naming the file and the problem.
Texture read_texture_file(const std::string& path);

}  // namespace rastersim
