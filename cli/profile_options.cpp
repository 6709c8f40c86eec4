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

// What each key means and takes, for --help. A key the model adds later still gets a flag.
std::string key_help(const std::string& key) {
  static const std::map<std::string, std::string> help = {
      {"width", "screen width in pixels, 1..4096"},
      {"height", "screen height in pixels, 1..4096"},
      {"subpixel_bits", "S, fraction bits of snapped vertex coordinates, 1..8"},
      {"z_bits", "N, depth buffer bits, 16..32"},
      {"z_guard_bits", "fraction bits of the depth plane registers, 1..24, or auto (derived)"},
      {"depth_func", "never, less, equal, lequal, greater, notequal, gequal or always"},
      {"depth_write", "write depth on a pass: true or false"},
      {"depth_clear", "depth buffer clear value, 0..2^N-1, or max (0 with depth_buffer inverse_w)"},
      {"depth_buffer", "what the 3D front end puts in the depth plane: z, or inverse_w (near / w; depth_func greater)"},
      {"depth_exponent_bits", "0 (fixed-point depth word) or 1..4 (a floating-point word with that many exponent bits)"},
      {"depth_bias_constant", "depth bias in depth plane LSBs (integer)"},
      {"depth_bias_slope", "depth bias per LSB of the triangle's largest depth step per pixel, -8..7.9375 in 1/16"},
      {"cull", "none, back or front"},
      {"front_face", "winding of front faces as seen on the screen: ccw or cw"},
      {"traversal", "walker strategy: bbox (whole bounding box) or span (edge-bounded rows)"},
      {"shading", "flat or gouraud"},
      {"memory_latency", "z-buffer read latency in cycles, 1..64"},
      {"memory_stall_percent", "z-buffer memory back-pressure: share of cycles refusing reads, 0..90 (0 on chip)"},
      {"memory_stall_seed", "seed of the memory's stall pattern, 0..2^31-1"},
      {"setup_fifo_depth", "setup records on their way to the walker (the record FIFO's depth), 1..16"},
      {"setup_interval", "setup initiation interval: 0 (serial, the smallest unit) or 2..64 (pipelined, a triangle every I cycles)"},
      {"texture_unit", "the texture unit between walker and z-buffer: true or false (texture coordinates ignored)"},
      {"perspective", "perspective-correct texture coordinates: true, or false (affine)"},
      {"texture_latency", "texture memory read latency in cycles, 1..64"},
      {"texture_stall_percent", "texture memory back-pressure: share of cycles refusing reads, 0..90"},
      {"texture_stall_seed", "seed of the texture memory's stall pattern, 0..2^31-1"},
  };
  auto it = help.find(key);
  return it == help.end() ? "profile key " + key : it->second;
}

}  // namespace

void add_profile_options(CLI::App& app, ProfileOptions& options) {
  app.add_option("--profile", options.profile_file, "hardware profile JSON file (flags override its keys)")
      ->type_name("FILE")
      ->group("Profile");
  const nlohmann::json defaults = nlohmann::json::parse(profile_to_json(Profile{}));
  for (const std::string& key : profile_keys()) {
    std::string default_text;
    if (defaults.contains(key))
      default_text = defaults[key].is_string() ? defaults[key].get<std::string>() : defaults[key].dump();
    const std::string description = key_help(key) + (default_text.empty() ? "" : " (default " + default_text + ")");
    options.flags[key] = app.add_option(flag_name(key), options.flag_values[key], description)
                             ->type_name("VALUE")
                             ->group("Profile");
  }
}

Profile resolve_profile(const ProfileOptions& options) {
  Profile profile;
  if (!options.profile_file.empty()) load_profile_file(profile, options.profile_file);
  std::vector<std::string> errors;
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
