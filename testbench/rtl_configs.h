// The profiles verilated into this build (testbench/CMakeLists.txt, RASTERSIM_RTL_CONFIGS).
#pragma once

#include <string>
#include <vector>

#include "model/core_parameters.h"

#include "testbench/rtl_backend.h"

namespace rastersim::rtl {

struct BuiltConfiguration {
  std::string name;
  CoreParameters parameters;  // as verilated (the core's P_* constants)
  RtlResult (*run)(const Profile&, const std::vector<SnappedTriangle>&, const RtlOptions&);
};

const std::vector<BuiltConfiguration>& built_configuration_table();

}  // namespace rastersim::rtl
