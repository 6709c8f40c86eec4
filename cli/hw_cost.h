// Hardware cost of a profile for `rastersim sweep --hw-cost`: yosys synthesizes rtl/rastersim_core
// (the pipeline; the frame memory sits behind its memory port and is counted in bits, not cells)
// with the profile's parameters, once generic (`synth -flatten`, then `stat`: cells) and once for
// iCE40 (`synth_ice40`, then `stat`: SB_LUT4 and SB_DFF* cells). MAX_MEMORY_LATENCY is the
// profile's memory_latency: the in-flight ring is sized for the latency the profile runs at.
// Results are cached per parameter set and RTL source content (a file per key in the cache folder),
// so that a sweep synthesizes each distinct hardware profile once.
#pragma once

#include <cstdint>
#include <string>

#include "model/profile.h"

namespace rastersim {

struct HardwareCost {
  int64_t cells = 0;        // generic yosys cells after synth -flatten
  int64_t ice40_luts = 0;   // SB_LUT4
  int64_t ice40_ffs = 0;    // SB_DFF*
  int64_t ice40_carry = 0;  // SB_CARRY
  int64_t ice40_ram = 0;    // SB_RAM40_4K
  int64_t memory_bits = 0;  // the frame memory behind the port: W H (z_bits + 24) + written bits
  bool from_cache = false;
};

// The parameters that change the synthesized core, as "WIDTH=640 HEIGHT=480 ...".
std::string hardware_parameters(const Profile& profile);

// Synthesizes (or reads from `cache_dir`) the cost of `profile`'s core from the sources in
// `rtl_dir`. Throws std::runtime_error when yosys is missing or fails (the message says which and
// where its log is).
HardwareCost hardware_cost(const Profile& profile, const std::string& rtl_dir, const std::string& cache_dir);

}  // namespace rastersim
