// Texture images (docs/design/texturing.md): any image file OpenImageIO reads, as the texture
// sampler's memory (model/texture_sampler.h).
#pragma once

#include <string>

#include "model/texture_sampler.h"

namespace rastersim {

// Reads a texture: its width and height must be powers of two up to 2^kMaxTextureLog2 (1024);
// its pixels become 8-bit RGB (grey repeated, alpha dropped, other types converted by
// OpenImageIO), stored bottom row first, so that texel (0, 0) is the image's bottom-left pixel.
// Throws InputError naming the file and the problem.
Texture read_texture_file(const std::string& path);

}  // namespace rastersim
