// The profile's place among rastersim_core's build parameters (rtl/rastersim_core.sv): the one
// mapping from a profile to the NAME=value list a core is built with. Every consumer takes it
// from here: the verilation at build time and on demand, the SystemC core's check, hw-cost,
// vector packages and the FuseSoC core (docs/rtl.md "The profile in the RTL").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "profile.h"

namespace rastersim {

// The parameters in rastersim_core's declaration order, with how a built core must relate to the
// profile's value to run it: Equal, Bound (the core may hold more: a largest latency, a FIFO's
// size, an option the profile leaves unused) or Guard (the same resolved plane fraction bits; 0
// derives them).
#define RASTERSIM_CORE_PARAMETERS(X) \
  X(WIDTH, Equal)                    \
  X(HEIGHT, Equal)                   \
  X(SUBPIXEL_BITS, Equal)            \
  X(Z_BITS, Equal)                   \
  X(Z_GUARD_BITS, Guard)             \
  X(MAX_MEMORY_LATENCY, Bound)       \
  X(MAX_SETUP_FIFO_DEPTH, Bound)     \
  X(SETUP_INTERVAL, Equal)           \
  X(TEXTURE, Equal)                  \
  X(MAX_TEXTURE_LATENCY, Bound)      \
  X(DEPTH_EXPONENT_BITS, Equal)      \
  X(DEPTH_BIAS, Bound)               \
  X(PIXEL_CENTER, Equal)             \
  X(FILL_RULE, Equal)                \
  X(DEPTH_ROUNDING, Equal)           \
  X(COLOR_ROUNDING, Equal)

struct CoreParameter {
  std::string name;
  int64_t value;
  bool operator==(const CoreParameter& o) const { return name == o.name && value == o.value; }
};
using CoreParameters = std::vector<CoreParameter>;

enum class CoreBounds {
  Profile,  // the MAX_* parameters are the profile's own values: the smallest core (hw-cost, vectors)
  Largest,  // the largest each run-time key allows: one core runs every latency (co-simulation)
};

// The core that runs `profile`, every parameter given (a valid profile).
CoreParameters core_parameters(const Profile& profile, CoreBounds bounds = CoreBounds::Profile);

// The value of parameter `name` in the list (std::invalid_argument when it is not there).
int64_t parameter_value(const CoreParameters& parameters, const std::string& name);

// "WIDTH=640 HEIGHT=480 ..." (separator " "), or with another separator.
std::string core_parameters_text(const CoreParameters& parameters, const std::string& separator = " ");
// The inverse of core_parameters_text with separator ",": "WIDTH=640,HEIGHT=480". Names not in
// the list above or values that are not integers throw std::invalid_argument.
CoreParameters parse_core_parameters(const std::string& text);

// The parameters a verilated rastersim_core (Core: its class, which publishes each as P_<NAME>) was
// built with, in core_parameters() order.
template <class Core>
CoreParameters parameters_of() {
#define RS_PARAMETER(name, fit) {#name, int64_t(Core::P_##name)},
  return {RASTERSIM_CORE_PARAMETERS(RS_PARAMETER)};
#undef RS_PARAMETER
}

// Empty when a core built with `built` runs `profile`; else a sentence naming the first parameter
// that does not fit ("SETUP_INTERVAL is 2 in this build; the profile needs 4").
std::string core_mismatch(const CoreParameters& built, const Profile& profile);

}  // namespace rastersim
