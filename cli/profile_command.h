// rastersim profile: the profile a set of flags and a profile file resolve to, and the core it
// needs (docs/formats.md "Profile", docs/rtl.md "The profile in the RTL").
#pragma once

#include <CLI/CLI.hpp>

#include "profile_options.h"

namespace rastersim {

struct ProfileCommandOptions {
  ProfileOptions profile;
  bool core_parameters = false;  // rastersim_core's NAME=value list instead of the JSON
  bool largest = false;          // with it: the largest run-time bounds (the co-simulation's cores)
  bool keys_markdown = false;    // docs/formats.md's key table
};

CLI::App* add_profile_command(CLI::App& app, ProfileCommandOptions& options);
int run_profile(const ProfileCommandOptions& options);

}  // namespace rastersim
