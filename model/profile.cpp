#include "profile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "input_error.h"
#include "text_file.h"
#include "json_lines.h"

namespace rastersim {
namespace {

template <typename E, size_t N>
std::optional<E> parse_enum(const std::string& s, const char* const (&names)[N]) {
  for (size_t i = 0; i < N; ++i)
    if (s == names[i]) return E(i);
  return std::nullopt;
}

const char* const kDepthFuncNames[] = {"never", "less", "equal", "lequal",
                                       "greater", "notequal", "gequal", "always"};
const char* const kCullNames[] = {"none", "back", "front"};
const char* const kFrontFaceNames[] = {"ccw", "cw"};
const char* const kTraversalNames[] = {"bbox", "span"};
const char* const kShadingNames[] = {"flat", "gouraud"};
const char* const kDepthBufferNames[] = {"z", "inverse_w"};

// A slope factor held in sixteenths, as a decimal (exact: 1/16 has a finite decimal).
std::string slope_text(int sixteenths) {
  std::ostringstream out;
  out << sixteenths / 16.0;
  return out.str();
}

template <size_t N>
std::string choices(const char* const (&names)[N]) {
  std::string out;
  for (size_t i = 0; i < N; ++i) out += (i ? ", " : "") + std::string(names[i]);
  return out;
}

// Strict integer parse: the whole text must be a base-10 integer.
bool parse_int(const std::string& text, int64_t& out) {
  if (text.empty()) return false;
  size_t pos = 0;
  try {
    out = std::stoll(text, &pos, 10);
  } catch (...) {
    return false;
  }
  return pos == text.size();
}

bool parse_bool(const std::string& text, bool& out) {
  if (text == "true" || text == "on" || text == "1") return out = true, true;
  if (text == "false" || text == "off" || text == "0") return out = false, true;
  return false;
}

}  // namespace

const char* to_string(DepthFunc v) { return kDepthFuncNames[int(v)]; }
const char* to_string(CullMode v) { return kCullNames[int(v)]; }
const char* to_string(FrontFace v) { return kFrontFaceNames[int(v)]; }
const char* to_string(Traversal v) { return kTraversalNames[int(v)]; }
const char* to_string(Shading v) { return kShadingNames[int(v)]; }
const char* to_string(DepthBuffer v) { return kDepthBufferNames[int(v)]; }
std::optional<DepthFunc> parse_depth_func(const std::string& s) { return parse_enum<DepthFunc>(s, kDepthFuncNames); }
std::optional<CullMode> parse_cull(const std::string& s) { return parse_enum<CullMode>(s, kCullNames); }
std::optional<FrontFace> parse_front_face(const std::string& s) { return parse_enum<FrontFace>(s, kFrontFaceNames); }
std::optional<Traversal> parse_traversal(const std::string& s) { return parse_enum<Traversal>(s, kTraversalNames); }
std::optional<Shading> parse_shading(const std::string& s) { return parse_enum<Shading>(s, kShadingNames); }
std::optional<DepthBuffer> parse_depth_buffer(const std::string& s) {
  return parse_enum<DepthBuffer>(s, kDepthBufferNames);
}

const std::vector<std::string>& profile_keys() {
  static const std::vector<std::string> keys = {
      "width", "height", "subpixel_bits", "z_bits", "z_guard_bits", "depth_func", "depth_write",
      "depth_clear", "depth_buffer", "depth_exponent_bits", "depth_bias_constant", "depth_bias_slope", "cull",
      "front_face", "traversal", "shading", "memory_latency", "memory_stall_percent", "memory_stall_seed",
      "setup_fifo_depth", "setup_interval", "texture_unit", "perspective", "texture_latency",
      "texture_stall_percent", "texture_stall_seed"};
  return keys;
}

std::vector<std::string> validate(const Profile& p) {
  std::vector<std::string> errors;
  auto range = [&](const char* key, int64_t v, int64_t lo, int64_t hi) {
    if (v < lo || v > hi)
      errors.push_back(std::string(key) + " is " + std::to_string(v) + "; it must be in " +
                       std::to_string(lo) + ".." + std::to_string(hi));
  };
  range("width", p.width, 1, 4096);
  range("height", p.height, 1, 4096);
  range("subpixel_bits", p.subpixel_bits, 1, 8);
  range("z_bits", p.z_bits, 16, 32);
  range("z_guard_bits", p.z_guard_bits, 0, 24);
  range("memory_latency", p.memory_latency, 1, 64);
  range("memory_stall_percent", p.memory_stall_percent, 0, 90);
  range("memory_stall_seed", p.memory_stall_seed, 0, INT32_MAX);
  range("setup_fifo_depth", p.setup_fifo_depth, 1, kMaxSetupFifoDepth);
  if (p.setup_interval != 0) range("setup_interval", p.setup_interval, kMinSetupInterval, kMaxSetupInterval);
  range("texture_latency", p.texture_latency, 1, 64);
  range("texture_stall_percent", p.texture_stall_percent, 0, 90);
  range("texture_stall_seed", p.texture_stall_seed, 0, INT32_MAX);
  if (p.z_bits >= 16 && p.z_bits <= 32 && p.depth_clear >= 0 && p.depth_clear > int64_t(p.depth_max()))
    errors.push_back("depth_clear is " + std::to_string(p.depth_clear) + "; it must be in 0.." +
                     std::to_string(p.depth_max()) + " for z_bits " + std::to_string(p.z_bits));
  if (p.depth_clear < -1) errors.push_back("depth_clear must not be negative");
  range("depth_exponent_bits", p.depth_exponent_bits, 0, 4);
  if (p.z_bits >= 16 && p.z_bits <= 32 && p.depth_exponent_bits >= 1 && p.depth_exponent_bits <= 4 &&
      p.depth_plane_bits() > 32)
    errors.push_back("depth_exponent_bits " + std::to_string(p.depth_exponent_bits) + " with z_bits " +
                     std::to_string(p.z_bits) + " makes a depth plane of " + std::to_string(p.depth_plane_bits()) +
                     " bits; it must be at most 32");
  else if (p.z_bits >= 16 && p.z_bits <= 32 && p.depth_exponent_bits >= 0 && p.depth_exponent_bits <= 4) {
    const int64_t limit = (int64_t(1) << p.depth_plane_bits()) - 1;
    range("depth_bias_constant", p.depth_bias_constant, -limit, limit);
  }
  if (p.depth_bias_slope < -128 || p.depth_bias_slope > 127)
    errors.push_back("depth_bias_slope is " + slope_text(p.depth_bias_slope) + "; it must be in -8..7.9375");
  if (p.depth_buffer == DepthBuffer::InverseW && (p.depth_func == DepthFunc::Less || p.depth_func == DepthFunc::LEqual))
    errors.push_back(std::string("depth_func is ") + to_string(p.depth_func) +
                     "; a 1/w buffer (depth_buffer inverse_w) keeps the nearer fragment with greater or gequal");
  return errors;
}

std::string set_profile_key(Profile& p, const std::string& key, const std::string& value) {
  int64_t n = 0;
  auto integer = [&](int& field) -> std::string {
    if (!parse_int(value, n) || n < INT32_MIN || n > INT32_MAX)
      return key + " takes an integer, not '" + value + "'";
    field = int(n);
    return "";
  };
  auto enumeration = [&](auto parsed, auto& field, const std::string& allowed) -> std::string {
    if (!parsed) return key + " is '" + value + "'; it must be one of " + allowed;
    field = *parsed;
    return "";
  };
  if (key == "width") return integer(p.width);
  if (key == "height") return integer(p.height);
  if (key == "subpixel_bits") return integer(p.subpixel_bits);
  if (key == "z_bits") return integer(p.z_bits);
  if (key == "z_guard_bits") {
    if (value == "auto") return p.z_guard_bits = 0, "";
    // 0 is how the profile holds 'auto'; written as a number it is out of range.
    if (parse_int(value, n) && n == 0) return "z_guard_bits is 0; it must be in 1..24, or auto";
    return integer(p.z_guard_bits);
  }
  if (key == "memory_latency") return integer(p.memory_latency);
  if (key == "memory_stall_percent") return integer(p.memory_stall_percent);
  if (key == "memory_stall_seed") return integer(p.memory_stall_seed);
  if (key == "setup_fifo_depth") return integer(p.setup_fifo_depth);
  if (key == "setup_interval") return integer(p.setup_interval);
  if (key == "depth_clear") {
    if (value == "max") return p.depth_clear = -1, "";
    if (!parse_int(value, n) || n < 0) return key + " takes a non-negative integer or 'max', not '" + value + "'";
    p.depth_clear = n;
    return "";
  }
  auto boolean = [&](bool& field) -> std::string {
    if (!parse_bool(value, field)) return key + " takes true or false, not '" + value + "'";
    return "";
  };
  if (key == "depth_write") return boolean(p.depth_write);
  if (key == "texture_unit") return boolean(p.texture_unit);
  if (key == "depth_exponent_bits") return integer(p.depth_exponent_bits);
  if (key == "depth_bias_constant") {
    if (!parse_int(value, n)) return key + " takes an integer, not '" + value + "'";
    p.depth_bias_constant = n;
    return "";
  }
  if (key == "depth_bias_slope") {
    // A decimal number: exactly a multiple of 1/16 (s4.4).
    char* end = nullptr;
    const double slope = value.empty() ? 0 : std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || !std::isfinite(slope))
      return key + " takes a number, not '" + value + "'";
    const double sixteenths = slope * 16;
    if (sixteenths < -1e6 || sixteenths > 1e6 || sixteenths != std::floor(sixteenths))
      return key + " is " + value + "; it must be a multiple of 1/16 (0.0625) in -8..7.9375";
    p.depth_bias_slope = int(sixteenths);
    return "";
  }
  if (key == "perspective") return boolean(p.perspective);
  if (key == "texture_latency") return integer(p.texture_latency);
  if (key == "texture_stall_percent") return integer(p.texture_stall_percent);
  if (key == "texture_stall_seed") return integer(p.texture_stall_seed);
  if (key == "depth_func") return enumeration(parse_depth_func(value), p.depth_func, choices(kDepthFuncNames));
  if (key == "cull") return enumeration(parse_cull(value), p.cull, choices(kCullNames));
  if (key == "front_face") return enumeration(parse_front_face(value), p.front_face, choices(kFrontFaceNames));
  if (key == "traversal") return enumeration(parse_traversal(value), p.traversal, choices(kTraversalNames));
  if (key == "shading") return enumeration(parse_shading(value), p.shading, choices(kShadingNames));
  if (key == "depth_buffer")
    return enumeration(parse_depth_buffer(value), p.depth_buffer, choices(kDepthBufferNames));
  return "unknown profile key '" + key + "'";
}

void load_profile_file(Profile& profile, const std::string& path) {
  load_profile_text(profile, read_text_file(path, "a profile file", kMaxProfileBytes), path);
}

void load_profile_text(Profile& profile, const std::string& text, const std::string& file_name) {
  const nlohmann::json doc = parse_json_document(text, file_name);
  if (!doc.is_object()) throw InputError(file_name, 1, "a profile must be a JSON object");
  const JsonLines lines(text);
  // JSON types as docs/formats.md gives them: numbers for the integer keys (z_guard_bits also
  // "auto", depth_clear also "max"), true/false for depth_write, strings for the others.
  auto type_error = [](const std::string& key, const nlohmann::json& v) -> std::string {
    static const std::set<std::string> integers = {"width", "height", "subpixel_bits", "z_bits", "memory_latency",
                                                   "memory_stall_percent", "memory_stall_seed", "setup_fifo_depth",
                                                   "setup_interval", "texture_latency", "texture_stall_percent",
                                                   "texture_stall_seed", "depth_exponent_bits",
                                                   "depth_bias_constant"};
    const bool is_integer = v.is_number_integer() || v.is_number_unsigned();
    if (integers.count(key)) return is_integer ? "" : key + " must be a JSON integer, not " + v.dump();
    if (key == "z_guard_bits" || key == "depth_clear") {
      const char* word = key == "z_guard_bits" ? "\"auto\"" : "\"max\"";
      return is_integer || v.is_string() ? "" : key + " must be a JSON integer or " + word + ", not " + v.dump();
    }
    if (key == "depth_bias_slope") return v.is_number() ? "" : key + " must be a JSON number, not " + v.dump();
    if (key == "depth_write" || key == "texture_unit" || key == "perspective")
      return v.is_boolean() ? "" : key + " must be true or false, not " + v.dump();
    return v.is_string() ? "" : key + " must be a JSON string, not " + v.dump();
  };
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    const std::string pointer = JsonLines::child("", it.key());
    const int line = lines.line(pointer);
    if (const int again = lines.repeated_line(pointer))
      throw InputError(file_name, again, "profile key '" + it.key() + "' is given twice (first on line " +
                                             std::to_string(line) + ")");
    std::string value;
    if (it->is_string()) value = it->get<std::string>();
    else if (it->is_boolean()) value = it->get<bool>() ? "true" : "false";
    else if (it->is_number_unsigned()) value = std::to_string(it->get<uint64_t>());  // above INT64_MAX too
    else if (it->is_number_integer()) value = std::to_string(it->get<int64_t>());
    else if (it->is_number_float()) value = it->dump();
    else throw InputError(file_name, line, "profile key '" + it.key() + "' must be a string, integer or boolean");
    std::string error = set_profile_key(profile, it.key(), value);
    if (error.empty() && (it->is_string() || it->is_boolean() || it->is_number()) &&
        std::count(profile_keys().begin(), profile_keys().end(), it.key()))
      error = type_error(it.key(), *it);
    if (!error.empty()) throw InputError(file_name, line, error);
  }
  // Ranges (and depth_clear against z_bits) at the line of the key each error names.
  for (const std::string& error : validate(profile)) {
    const std::string key = error.substr(0, error.find(' '));
    if (doc.contains(key)) throw InputError(file_name, lines.line(JsonLines::child("", key)), error);
  }
}

std::string profile_to_json(const Profile& p, int indent) {
  nlohmann::ordered_json j;
  j["width"] = p.width;
  j["height"] = p.height;
  j["subpixel_bits"] = p.subpixel_bits;
  j["z_bits"] = p.z_bits;
  if (p.z_guard_bits > 0) j["z_guard_bits"] = p.z_guard_bits;
  else j["z_guard_bits"] = "auto";
  j["depth_func"] = to_string(p.depth_func);
  j["depth_write"] = p.depth_write;
  j["depth_clear"] = p.depth_clear_value();
  j["depth_buffer"] = to_string(p.depth_buffer);
  j["depth_exponent_bits"] = p.depth_exponent_bits;
  j["depth_bias_constant"] = p.depth_bias_constant;
  j["depth_bias_slope"] = p.depth_bias_slope / 16.0;  // exact: a multiple of 1/16
  j["cull"] = to_string(p.cull);
  j["front_face"] = to_string(p.front_face);
  j["traversal"] = to_string(p.traversal);
  j["shading"] = to_string(p.shading);
  j["memory_latency"] = p.memory_latency;
  j["memory_stall_percent"] = p.memory_stall_percent;
  j["memory_stall_seed"] = p.memory_stall_seed;
  j["setup_fifo_depth"] = p.setup_fifo_depth;
  j["setup_interval"] = p.setup_interval;
  j["texture_unit"] = p.texture_unit;
  j["perspective"] = p.perspective;
  j["texture_latency"] = p.texture_latency;
  j["texture_stall_percent"] = p.texture_stall_percent;
  j["texture_stall_seed"] = p.texture_stall_seed;
  return j.dump(indent);
}

}  // namespace rastersim
