// Verilated modules built on demand (docs/debugging.md "Any profile on the RTL backends"): a
// profile this build has no verilated RTL or SystemC core for is verilated once into a per-user
// cache, keyed by the sources' digest and the parameters, and loaded from there by later runs.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "model/core_parameters.h"
#include "model/pipeline.h"
#include "model/profile.h"
#include "model/triangle.h"
#include "testbench/rtl_backend.h"

namespace rastersim::modules {

enum class Kind { Rtl, Systemc };

// The cache: $RASTERSIM_CACHE_DIR, else $XDG_CACHE_HOME/rastersim, else $HOME/.cache/rastersim.
std::string cache_root();

// The shared library of the module, from the cache; verilated and compiled into it first when
// missing, reporting progress line by line. Two processes asking for the same module at once build
// it once (a lock per entry; the finished entry appears by one rename). Throws std::runtime_error
// naming the build log when the build fails.
using Progress = std::function<void(const std::string& line)>;
// The module that runs `profile`: rastersim_core's parameters with the largest run-time bounds, so
// that one module runs every memory and texture latency and record FIFO depth.
CoreParameters module_parameters(const Profile& profile);
std::string module_library(Kind kind, const Profile& profile, const Progress& progress);

// A user's design behind the verification interface (docs/verification.md), verilated on demand
// with testbench/dut/ around it: its files in order, include folders, top module and -G options
// (NAME=value); `unit` names the unit-level interface it has instead (setup, walker, zbuffer).
struct DutDesign {
  std::vector<std::string> files, include_dirs;
  std::string top;
  std::vector<std::string> parameters;
  std::string unit;
};
// Its shared library (librastersim_dut.so) from the cache, built first when missing; the cache key
// holds the files' contents, so an edited design is built again.
std::string dut_library(const DutDesign& design, const Progress& progress);

// The records a module passes across the library boundary, as their sizes: a module compiled
// against other headers than the program is refused instead of misread.
inline std::string abi_stamp() {
  return "rastersim-module-1 profile " + std::to_string(sizeof(Profile)) + " triangle " +
         std::to_string(sizeof(SnappedTriangle)) + " fragment " + std::to_string(sizeof(Fragment)) + " record " +
         std::to_string(sizeof(TriangleRecord)) + " setup " + std::to_string(sizeof(SetupResult)) + " stats " +
         std::to_string(sizeof(FrameStats)) + " options " + std::to_string(sizeof(rtl::RtlOptions)) + " result " +
         std::to_string(sizeof(rtl::RtlResult));
}

}  // namespace rastersim::modules

// Every module exports its stamp under this name.
#define RASTERSIM_MODULE_ABI_SYMBOL "rastersim_module_abi"
