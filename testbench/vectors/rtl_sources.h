// The RTL sources (rtl/*.sv, rtl/*.vh) and the package tools compiled into the binary at build
// time, so that a package carries the exact Verilog it was generated against and its own checker
// (embed_files.cmake writes the definitions).
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
// The package's own tools (testbench/vectors/check_manifest.py), copied into every package.
const std::vector<EmbeddedFile>& embedded_package_tools();

}  // namespace rastersim::vectors
