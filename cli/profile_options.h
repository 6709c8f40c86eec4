// The hardware-profile options shared by the subcommands: --profile FILE and one flag per profile
// key (`--subpixel-bits` for subpixel_bits). The file is applied first, then the flags.
#pragma once

#include <map>
#include <set>
#include <string>

#include <CLI/CLI.hpp>

#include "model/profile.h"

namespace rastersim {

struct ProfileOptions {
  std::string profile_file;
  std::string conventions;  // a preset's name (convention_presets()), or empty
  std::map<std::string, std::string> flag_values;  // by profile key
  std::map<std::string, CLI::Option*> flags;       // by profile key
};

void add_profile_options(CLI::App& app, ProfileOptions& options);

// A check for unsigned 64-bit options (seeds): a decimal number 0..2^64-1 without leading zeros.
// Without it CLI11 takes -1 and larger numbers as 2^64-1, and 010 as octal.
inline std::string unsigned_64_text(const std::string& value) {
  const std::string max = "18446744073709551615";
  const bool digits = !value.empty() && value.find_first_not_of("0123456789") == std::string::npos &&
                      (value == "0" || value[0] != '0');
  if (digits && (value.size() < max.size() || (value.size() == max.size() && value <= max))) return "";
  return "'" + value + "' is not a decimal number in 0.." + max;
}

// Defaults, then the profile file, then the flags given (in profile_keys() order), then
// validate(). Throws InputError with every problem found, one a line.
Profile resolve_profile(const ProfileOptions& options);

// The keys the user set: the flags given and the keys of the profile file (call after
// resolve_profile, which has checked the file).
std::set<std::string> given_profile_keys(const ProfileOptions& options);

}  // namespace rastersim
