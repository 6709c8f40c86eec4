// The SystemC backend (`rastersim render --backend systemc`): frames through the SystemC system
// model (rastersim_system.h: the verilated rastersim_core, a command FIFO and the z-buffer memory
// model with latency and stall pattern). Built as a shared library whose Verilator runtime (built
// for SystemC) stays private, so that a program can also link the plain verilated RTL
// (testbench/rtl_backend.h). One system is elaborated per process, on the first frame.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/profile.h"
#include "model/texture_unit.h"
#include "model/triangle.h"
#include "testbench/rtl_backend.h"

#define RASTERSIM_SYSTEMC_API __attribute__((visibility("default")))

namespace rastersim::systemc {

struct SystemcOptions {
  uint64_t seed = 1;       // random power-on state of the core (the first frame of the process only)
  int64_t max_cycles = 0;  // 0: a generous bound from the triangles' bounding boxes
  int fifo_depth = 16;     // command FIFO entries (the first frame of the process only)
  TextureBinding texture;  // what the texture unit samples (profiles with texture_unit)
};

// The geometry the SystemC core was verilated for (width, height, subpixel_bits, z_bits,
// z_guard_bits; the other keys at their defaults).
RASTERSIM_SYSTEMC_API Profile built_geometry();

// The profile the SystemC core was verilated for, as "WxH subpixel_bits .. z_bits .. memory_latency 1..L".
RASTERSIM_SYSTEMC_API std::string built_configuration();

// Empty when the SystemC system can run `profile` (a valid profile: see validate()); otherwise a
// sentence saying why.
RASTERSIM_SYSTEMC_API std::string configuration_error(const Profile& profile);

// The part of configuration_error() a SystemC core verilated for the profile would not have
// (geometry, memory latency, setup_interval): the program builds such a core on demand (modules.h).
RASTERSIM_SYSTEMC_API std::string geometry_error(const Profile& profile);

// Runs one frame. Throws std::invalid_argument with configuration_error() for a profile it cannot
// run. Fragments, triangle records, setup records, counters and final memories as run_rtl returns them.
RASTERSIM_SYSTEMC_API rtl::RtlResult run_systemc(const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                                                 const SystemcOptions& options = {});

// Clock cycles simulated by this process's system so far (resets and clears included), for speed figures.
RASTERSIM_SYSTEMC_API int64_t simulated_cycles();

// The functions above as one table, for a program that loads this library with dlopen (rastersim
// does, so that its commands start without SystemC unless they run it).
struct Api {
  std::string (*configuration_error)(const Profile& profile);
  std::string (*geometry_error)(const Profile& profile);
  rtl::RtlResult (*run_systemc)(const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                                const SystemcOptions& options);
};

}  // namespace rastersim::systemc

extern "C" RASTERSIM_SYSTEMC_API const rastersim::systemc::Api* rastersim_systemc_api();
// The library's records' stamp (modules.h abi_stamp), checked by the program before it uses the API.
extern "C" RASTERSIM_SYSTEMC_API const char* rastersim_module_abi();
