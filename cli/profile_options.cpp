#include "profile_options.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/input_error.h"

namespace rastersim {
namespace {

std::string flag_name(const std::string& key) {
  std::string name = key;
  std::replace(name.begin(), name.end(), '_', '-');
  return "--" + name;
}

}  // namespace

void add_profile_options(CLI::App& app, ProfileOptions& options) {
  app.add_option("--profile", options.profile_file, "hardware profile JSON file (flags override its keys)")
      ->type_name("FILE")
      ->group("Profile");
  std::string presets;
  for (const ConventionPreset& p : convention_presets()) presets += (presets.empty() ? "" : ", ") + std::string(p.name);
  app.add_option("--conventions", options.conventions,
                 "a named set of conventions (docs/arithmetic.md section 7), applied before the flags: " + presets)
      ->type_name("NAME")
      ->group("Profile");
  for (const ProfileKey& row : profile_table())
    options.flags[row.key] = app.add_option(flag_name(row.key), options.flag_values[row.key], key_help(row))
                                 ->type_name("VALUE")
                                 ->group("Profile");
}

Profile resolve_profile(const ProfileOptions& options) {
  Profile profile;
  if (!options.profile_file.empty()) load_profile_file(profile, options.profile_file);
  std::vector<std::string> errors;
  if (!options.conventions.empty()) {
    const ConventionPreset* preset = find_convention_preset(options.conventions);
    if (!preset) {
      std::string names;
      for (const ConventionPreset& p : convention_presets()) names += (names.empty() ? "" : ", ") + std::string(p.name);
      throw InputError("--conventions: '" + options.conventions + "' is not a preset; the presets are " + names);
    }
    for (const auto& [key, value] : preset->keys) set_profile_key(profile, key, value);
  }
  for (const std::string& key : profile_keys()) {
    auto flag = options.flags.find(key);
    if (flag == options.flags.end() || flag->second->count() == 0) continue;
    const std::string error = set_profile_key(profile, key, options.flag_values.at(key));
    if (!error.empty()) errors.push_back(flag_name(key) + ": " + error);
  }
  // A flag that failed to parse left its key unchanged, so validate() reports only other problems.
  for (const std::string& e : validate(profile)) errors.push_back(e);
  if (!errors.empty()) {
    std::string message = "bad hardware profile:";
    for (const std::string& e : errors) message += "\n  " + e;
    throw InputError(message);
  }
  return profile;
}

std::set<std::string> given_profile_keys(const ProfileOptions& options) {
  std::set<std::string> keys;
  for (const auto& [key, flag] : options.flags)
    if (flag->count() > 0) keys.insert(key);
  if (const ConventionPreset* preset = find_convention_preset(options.conventions))
    for (const auto& [key, value] : preset->keys) keys.insert(key);
  if (!options.profile_file.empty()) {
    std::ifstream in(options.profile_file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    const nlohmann::json doc = nlohmann::json::parse(text.str(), nullptr, false);
    if (doc.is_object())
      for (auto it = doc.begin(); it != doc.end(); ++it) keys.insert(it.key());
  }
  return keys;
}

}  // namespace rastersim
