// Verilated modules built on demand (docs/debugging.md "Any profile on the RTL backends"): a
// profile this build has no verilated RTL or SystemC core for is verilated once into a per-user
// cache, keyed by the sources' digest and the parameters, and loaded from there by later runs.
#pragma once

#include <functional>
#include <string>

#include "model/pipeline.h"
#include "model/profile.h"
#include "model/triangle.h"
#include "testbench/rtl_backend.h"

namespace rastersim::modules {

enum class Kind { Rtl, Systemc };

// The parameters a module is verilated with (rastersim_core's, as a RASTERSIM_RTL_CONFIGS entry).
struct Geometry {
  int width = 0, height = 0, subpixel_bits = 0, z_bits = 0, z_guard_bits = 0;
  int max_memory_latency = 0, setup_interval = 0;
  int texture = 0;  // 1: with the texture unit (profile texture_unit)
  int depth_exponent_bits = 0, depth_bias = 0;  // the depth word (profile's, 0 for 1) and 1: the depth bias
};

// The module that runs `profile`: its geometry, z_guard_bits as the profile gives it (0: derived),
// memory latency up to 64 (or the profile's, when larger), its setup_interval, texture unit, depth
// word and depth bias (when the profile has one).
Geometry geometry_for(const Profile& profile);

// The cache: $RASTERSIM_CACHE_DIR, else $XDG_CACHE_HOME/rastersim, else $HOME/.cache/rastersim.
std::string cache_root();

// The shared library of the module, from the cache; verilated and compiled into it first when
// missing, reporting progress line by line. Two processes asking for the same module at once build
// it once (a lock per entry; the finished entry appears by one rename). Throws std::runtime_error
// naming the build log when the build fails.
using Progress = std::function<void(const std::string& line)>;
std::string module_library(Kind kind, const Geometry& geometry, const Progress& progress);

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
