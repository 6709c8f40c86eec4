// The profile's place among rastersim_core's build parameters (rtl/rastersim_core_parameters.vh): the one
// mapping from a profile to the NAME=value list a core is built with. Every consumer takes it
// from here: the verilation at build time and on demand, the SystemC core's check, hw-cost,
// vector packages and the FuseSoC core (docs/rtl.md "The profile in the RTL").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "profile.h"

namespace rastersim {

struct CoreParameter {
  std::string name;
  int64_t value;
  bool operator==(const CoreParameter& o) const { return name == o.name && value == o.value; }
};
using CoreParameters = std::vector<CoreParameter>;

// rastersim_core's parameters as the profile table gives them: the name (the last of a row's
// rtl_name), the first row naming it, which maps it, the keys of every row naming it
// ("depth_bias_constant, depth_bias_slope" for DEPTH_BIAS) and its fit.
struct CoreParameterRow {
  std::string name;
  const ProfileKey* key;
  std::string keys;
  CoreFit fit;
};
const std::vector<CoreParameterRow>& core_parameter_rows();

enum class CoreBounds {
  Profile,  // the MAX_* parameters are the profile's own values: the smallest core (hw-cost, vectors)
  Largest,  // the largest each run-time key allows: one core runs every latency (co-simulation)
};

// The core that runs `profile`, every parameter given (a valid profile): one per Parameter and
// Both row of the profile table, in its order, which is rastersim_core's declaration order
// (rtl/rastersim_core_parameters.vh; a test holds the two equal).
CoreParameters core_parameters(const Profile& profile, CoreBounds bounds = CoreBounds::Profile);

// The value of parameter `name` in the list (std::invalid_argument when it is not there).
int64_t parameter_value(const CoreParameters& parameters, const std::string& name);

// "WIDTH=640 HEIGHT=480 ..." (separator " "), or with another separator.
std::string core_parameters_text(const CoreParameters& parameters, const std::string& separator = " ");
// The inverse of core_parameters_text with separator ",": "WIDTH=640,HEIGHT=480". Names that are
// not rastersim_core's parameters or values that are not integers throw std::invalid_argument.
CoreParameters parse_core_parameters(const std::string& text);

// Empty when a core built with `built` runs `profile`; else a sentence naming the first parameter
// that does not fit ("SETUP_INTERVAL is 2 in this build; the profile needs 4").
std::string core_mismatch(const CoreParameters& built, const Profile& profile);

}  // namespace rastersim
