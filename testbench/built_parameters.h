// What a verilated rastersim_core was built with: its parameters, read from the P_<NAME> constants
// Verilator publishes, named by rtl/rastersim_core_parameters.vh (the build generates the list).
#pragma once

#include "model/core_parameters.h"
#include "rastersim_core_parameter_names.h"

namespace rastersim {

// Core: the verilated rastersim_core's class. In declaration order, the profile table's order.
template <class Core>
CoreParameters parameters_of() {
#define RS_PARAMETER(name) {#name, int64_t(Core::P_##name)},
  return {RASTERSIM_CORE_PARAMETER_NAMES(RS_PARAMETER)};
#undef RS_PARAMETER
}

}  // namespace rastersim
