// The RTL sources (rtl/*.sv, rtl/*.vh) compiled into the binary at build time, so that a package
// can carry the exact Verilog it was generated against (embed_files.cmake writes the definition).
#pragma once

#include <cstddef>
#include <vector>

namespace rastersim::vectors {

struct EmbeddedFile {
  const char* name;  // file name inside rtl/
  const unsigned char* data;
  size_t size;
};

// In name order.
const std::vector<EmbeddedFile>& embedded_rtl();

}  // namespace rastersim::vectors
