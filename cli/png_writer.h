// PNG images written with libpng, in the program itself: `-o x.png` needs no OpenImageIO (whose
// codecs take hundreds of milliseconds to load; docs/performance.md, "Start-up").
#pragma once

#include <string>
#include <vector>

namespace rastersim {

// The image as PNG bytes: 1 to 4 channels (grey, grey + alpha, RGB, RGBA) of 8 or 16 bits, rows
// top first, samples in machine order. Throws std::runtime_error with libpng's message.
std::vector<unsigned char> encode_png(int width, int height, int channels, int bits, const void* pixels);

}  // namespace rastersim
