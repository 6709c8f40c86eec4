// The profiles verilated into this build (testbench/CMakeLists.txt, RASTERSIM_RTL_CONFIGS).
#pragma once

#include <vector>

#include "testbench/rtl_backend.h"

namespace rastersim::rtl {

struct BuiltConfiguration {
  const char* name;
  int width, height, subpixel_bits, z_bits, z_guard_bits, max_memory_latency, setup_interval;
  int texture;  // 1: built with the texture unit (profile texture_unit)
  int depth_exponent_bits, depth_bias;  // the depth word's exponent bits; 1: built with the depth bias
  RtlResult (*run)(const Profile&, const std::vector<SnappedTriangle>&, const RtlOptions&);
};

const std::vector<BuiltConfiguration>& built_configuration_table();

}  // namespace rastersim::rtl
