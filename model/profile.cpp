#include "profile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <type_traits>
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
const char* const kPixelCenterNames[] = {"half", "corner"};
const char* const kFillRuleNames[] = {"top_left", "top_right", "bottom_left", "bottom_right"};
const char* const kVertexSnapNames[] = {"nearest", "nearest_even", "floor", "toward_zero"};
const char* const kRoundingNames[] = {"nearest", "truncate"};

// A slope factor held in sixteenths, as a decimal (exact: 1/16 has a finite decimal).
std::string slope_text(int sixteenths) {
  std::ostringstream out;
  out << sixteenths / 16.0;
  return out.str();
}

std::string choices(const std::vector<const char*>& names) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + std::string(names[i]);
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
const char* to_string(PixelCenter v) { return kPixelCenterNames[int(v)]; }
const char* to_string(FillRule v) { return kFillRuleNames[int(v)]; }
const char* to_string(VertexSnap v) { return kVertexSnapNames[int(v)]; }
const char* to_string(Rounding v) { return kRoundingNames[int(v)]; }
std::optional<DepthFunc> parse_depth_func(const std::string& s) { return parse_enum<DepthFunc>(s, kDepthFuncNames); }
std::optional<CullMode> parse_cull(const std::string& s) { return parse_enum<CullMode>(s, kCullNames); }
std::optional<FrontFace> parse_front_face(const std::string& s) { return parse_enum<FrontFace>(s, kFrontFaceNames); }
std::optional<Traversal> parse_traversal(const std::string& s) { return parse_enum<Traversal>(s, kTraversalNames); }
std::optional<Shading> parse_shading(const std::string& s) { return parse_enum<Shading>(s, kShadingNames); }
std::optional<DepthBuffer> parse_depth_buffer(const std::string& s) {
  return parse_enum<DepthBuffer>(s, kDepthBufferNames);
}

namespace {

// Accessors for a row, from the member they read and write.
template <auto Member>
int64_t get_member(const Profile& p) {
  return int64_t(p.*Member);
}
template <auto Member>
void set_member(Profile& p, int64_t v) {
  using T = std::remove_reference_t<decltype(p.*Member)>;
  p.*Member = T(v);
}
#define RS_MEMBER(name) &get_member<&Profile::name>, &set_member<&Profile::name>

std::vector<const char*> names_of(const char* const* names, size_t n) { return {names, names + n}; }
#define RS_CHOICES(array) names_of(array, std::size(array))

int64_t written_depth_clear(const Profile& p) { return p.depth_clear_value(); }
// One exponent bit makes a word equal to the fixed-point one (docs/arithmetic.md section 6).
int64_t core_depth_exponent_bits(const Profile& p, bool) { return p.depth_exponent_bits >= 2 ? p.depth_exponent_bits : 0; }
int64_t core_depth_bias(const Profile& p, bool) { return p.depth_biased() ? 1 : 0; }

const std::vector<ProfileKey> kTable = {
    {"width", KeyType::Integer, 1, 4096, nullptr, 0, {}, nullptr, "screen width in pixels",
     RtlPlace::Parameter, "WIDTH", RS_MEMBER(width)},
    {"height", KeyType::Integer, 1, 4096, nullptr, 0, {}, nullptr, "screen height in pixels",
     RtlPlace::Parameter, "HEIGHT", RS_MEMBER(height)},
    {"subpixel_bits", KeyType::Integer, 1, 8, nullptr, 0, {}, nullptr, "S: vertex fraction bits",
     RtlPlace::Parameter, "SUBPIXEL_BITS", RS_MEMBER(subpixel_bits)},
    {"z_bits", KeyType::Integer, 16, 32, nullptr, 0, {}, nullptr, "N: depth buffer word",
     RtlPlace::Parameter, "Z_BITS", RS_MEMBER(z_bits)},
    {"z_guard_bits", KeyType::Integer, 0, 24, "auto", 0, {}, "`auto` or 1..24",
     "F: plane register fraction bits; `auto` derives the proven minimum ([arithmetic.md](arithmetic.md))",
     RtlPlace::Parameter, "Z_GUARD_BITS", RS_MEMBER(z_guard_bits), nullptr, nullptr, CoreFit::Guard},
    {"depth_func", KeyType::Choice, 0, 7, nullptr, 0, RS_CHOICES(kDepthFuncNames), nullptr, "depth test",
     RtlPlace::Port, "cfg_depth_func", RS_MEMBER(depth_func)},
    {"depth_write", KeyType::Boolean, 0, 1, nullptr, 0, {}, nullptr, "write depth on pass",
     RtlPlace::Port, "cfg_depth_write", RS_MEMBER(depth_write)},
    {"depth_clear", KeyType::Integer, -1, INT64_MAX, "max", -1, {}, "0..2^N-1 or `max`",
     "depth buffer clear value; `max` is 2^N-1, or 0 with `depth_buffer` `inverse_w` (an input of rastersim_top's "
     "on-chip memory)",
     RtlPlace::Port, "cfg_depth_clear", RS_MEMBER(depth_clear), &written_depth_clear},
    {"depth_buffer", KeyType::Choice, 0, 1, nullptr, 0, RS_CHOICES(kDepthBufferNames), nullptr,
     "what the 3D front end puts in the depth plane: the projected z, or `near / w` (a 1/w buffer: needs "
     "`depth_func` greater or gequal and a perspective camera; [arithmetic.md](arithmetic.md) section 6)",
     RtlPlace::None, "", RS_MEMBER(depth_buffer)},
    {"depth_exponent_bits", KeyType::Integer, 0, 4, nullptr, 0, {}, nullptr,
     "Ne: 0 a fixed-point depth word; 1..4 an unsigned floating-point word of N bits with Ne exponent bits, the "
     "depth plane then `N - Ne + 2^Ne - 1` bits (at most 32; [arithmetic.md](arithmetic.md) section 6). A build "
     "option of the RTL",
     RtlPlace::Parameter, "DEPTH_EXPONENT_BITS", RS_MEMBER(depth_exponent_bits), nullptr, &core_depth_exponent_bits},
    {"depth_bias_constant", KeyType::Integer, INT64_MIN, INT64_MAX, nullptr, 0, {},
     "integer, \\|c\\| < 2^plane bits", "depth bias in depth plane LSBs",
     RtlPlace::Both, "cfg_depth_bias_constant, DEPTH_BIAS", RS_MEMBER(depth_bias_constant), nullptr, &core_depth_bias},
    {"depth_bias_slope", KeyType::Sixteenths, -128, 127, nullptr, 0, {}, "-8..7.9375, a multiple of 1/16",
     "depth bias per LSB of the triangle's largest depth step per pixel (polygon offset's factor). A bias is a "
     "build option of the RTL; both values are run-time inputs",
     RtlPlace::Both, "cfg_depth_bias_slope, DEPTH_BIAS", RS_MEMBER(depth_bias_slope), nullptr, &core_depth_bias},
    {"cull", KeyType::Choice, 0, 2, nullptr, 0, RS_CHOICES(kCullNames), nullptr, "face culling",
     RtlPlace::Port, "cfg_cull", RS_MEMBER(cull)},
    {"front_face", KeyType::Choice, 0, 1, nullptr, 0, RS_CHOICES(kFrontFaceNames), nullptr,
     "front-face winding as seen on screen", RtlPlace::Port, "cfg_front_face", RS_MEMBER(front_face)},
    {"traversal", KeyType::Choice, 0, 1, nullptr, 0, RS_CHOICES(kTraversalNames), nullptr,
     "walker strategy: the whole bounding box, or edge-bounded rows ([cycle-model.md](cycle-model.md))",
     RtlPlace::Port, "cfg_traversal", RS_MEMBER(traversal)},
    {"shading", KeyType::Choice, 0, 1, nullptr, 0, RS_CHOICES(kShadingNames), nullptr, "colour interpolation",
     RtlPlace::Port, "cfg_shading", RS_MEMBER(shading)},
    {"memory_latency", KeyType::Integer, 1, kMaxMemoryLatency, nullptr, 0, {}, nullptr, "z-buffer read latency in cycles",
     RtlPlace::Both, "cfg_memory_latency, MAX_MEMORY_LATENCY", RS_MEMBER(memory_latency)},
    {"memory_stall_percent", KeyType::Integer, 0, 90, nullptr, 0, {}, nullptr,
     "memory back-pressure: share of cycles refusing reads (backends model and systemc, `rastersim_core` vector "
     "packages, `cosim --dut` memory port; not `rastersim_top`: rtl, cosim; [cycle-model.md](cycle-model.md))",
     RtlPlace::None, "", RS_MEMBER(memory_stall_percent)},
    {"memory_stall_seed", KeyType::Integer, 0, INT32_MAX, nullptr, 0, {}, nullptr, "seed of the stall pattern",
     RtlPlace::None, "", RS_MEMBER(memory_stall_seed)},
    {"setup_fifo_depth", KeyType::Integer, 1, kMaxSetupFifoDepth, nullptr, 0, {}, nullptr,
     "setup records on their way to the walker: the record FIFO between setup and walker "
     "([cycle-model.md](cycle-model.md))",
     RtlPlace::Both, "cfg_setup_fifo_depth, MAX_SETUP_FIFO_DEPTH", RS_MEMBER(setup_fifo_depth)},
    {"setup_interval", KeyType::Integer, 0, kMaxSetupInterval, nullptr, 0, {}, "0, 2..64",
     "the setup unit: 0 = serial (one shared datapath, the smallest unit, about 1,500 cycles per drawn triangle); "
     "I = pipelined, a triangle accepted every I cycles at best ([cycle-model.md](cycle-model.md))",
     RtlPlace::Parameter, "SETUP_INTERVAL", RS_MEMBER(setup_interval)},
    {"texture_unit", KeyType::Boolean, 0, 1, nullptr, 0, {}, nullptr,
     "the texture unit between walker and z-buffer, a build option of the RTL ([cycle-model.md](cycle-model.md), "
     "\"Texture unit\"); without it texture coordinates are ignored",
     RtlPlace::Parameter, "TEXTURE", RS_MEMBER(texture_unit)},
    {"perspective", KeyType::Boolean, 0, 1, nullptr, 0, {}, nullptr,
     "perspective-correct texture coordinates; false interpolates them affinely ([arithmetic.md](arithmetic.md) "
     "section 5)",
     RtlPlace::None, "", RS_MEMBER(perspective)},
    {"texture_latency", KeyType::Integer, 1, kMaxTextureLatency, nullptr, 0, {}, nullptr, "texture memory read latency in cycles",
     RtlPlace::Both, "cfg_texture_latency, MAX_TEXTURE_LATENCY", RS_MEMBER(texture_latency)},
    {"texture_stall_percent", KeyType::Integer, 0, 90, nullptr, 0, {}, nullptr,
     "texture memory back-pressure: share of cycles refusing reads", RtlPlace::None, "",
     RS_MEMBER(texture_stall_percent)},
    {"texture_stall_seed", KeyType::Integer, 0, INT32_MAX, nullptr, 0, {}, nullptr, "seed of its stall pattern",
     RtlPlace::None, "", RS_MEMBER(texture_stall_seed)},
    {"pixel_center", KeyType::Choice, 0, 1, nullptr, 0, RS_CHOICES(kPixelCenterNames), nullptr,
     "where a pixel is sampled: its centre (i + 1/2, j + 1/2) or its corner (i, j) "
     "([arithmetic.md](arithmetic.md) section 7)",
     RtlPlace::Parameter, "PIXEL_CENTER", RS_MEMBER(pixel_center)},
    {"fill_rule", KeyType::Choice, 0, 3, nullptr, 0, RS_CHOICES(kFillRuleNames), nullptr,
     "which edges own a sample that lies exactly on them ([arithmetic.md](arithmetic.md) section 7)", RtlPlace::Parameter,
     "FILL_RULE", RS_MEMBER(fill_rule)},
    {"vertex_snap", KeyType::Choice, 0, 3, nullptr, 0, RS_CHOICES(kVertexSnapNames), nullptr,
     "how vertex x and y become subpixels: round half up, round half to even, floor, toward zero "
     "([arithmetic.md](arithmetic.md) section 7; the host's work: the RTL takes snapped words)",
     RtlPlace::None, "", RS_MEMBER(vertex_snap)},
    {"depth_rounding", KeyType::Choice, 0, 1, nullptr, 0, RS_CHOICES(kRoundingNames), nullptr,
     "the depth plane's output: rounded to nearest or truncated ([arithmetic.md](arithmetic.md) section 7)",
     RtlPlace::Parameter, "DEPTH_ROUNDING", RS_MEMBER(depth_rounding)},
    {"color_rounding", KeyType::Choice, 0, 1, nullptr, 0, RS_CHOICES(kRoundingNames), nullptr,
     "the colour planes' outputs: rounded to nearest or truncated ([arithmetic.md](arithmetic.md) section 7)",
     RtlPlace::Parameter, "COLOR_ROUNDING", RS_MEMBER(color_rounding)},
};
#undef RS_MEMBER
#undef RS_CHOICES

std::string bound_text(int64_t v) { return v == INT32_MAX ? "2^31-1" : std::to_string(v); }

// The values column when the row does not give one.
std::string values_text(const ProfileKey& row) {
  if (row.values) return row.values;
  switch (row.type) {
    case KeyType::Boolean: return "true / false";
    case KeyType::Choice: {
      std::string out;
      for (const char* c : row.choices) out += (out.empty() ? "" : " ") + std::string(c);
      return out;
    }
    default: return bound_text(row.min) + ".." + bound_text(row.max);
  }
}

// Markdown made plain for a terminal: "[a.md](a.md)" becomes "docs/a.md", backticks and the
// table's escapes go.
std::string plain(const std::string& markdown) {
  std::string out;
  for (size_t i = 0; i < markdown.size(); ++i) {
    const char c = markdown[i];
    if (c == '`' || (c == '\\' && i + 1 < markdown.size() && markdown[i + 1] == '|')) continue;
    if (c == '[') {
      const size_t close = markdown.find("](", i);
      const size_t end = close == std::string::npos ? close : markdown.find(')', close);
      if (end != std::string::npos) {
        out += "docs/" + markdown.substr(close + 2, end - close - 2);
        i = end;
        continue;
      }
    }
    out += c;
  }
  return out;
}

}  // namespace

const std::vector<ProfileKey>& profile_table() { return kTable; }

const ProfileKey* find_profile_key(const std::string& key) {
  for (const ProfileKey& row : kTable)
    if (key == row.key) return &row;
  return nullptr;
}

const std::vector<std::string>& profile_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> out;
    for (const ProfileKey& row : kTable) out.push_back(row.key);
    return out;
  }();
  return keys;
}

std::string key_value_text(const ProfileKey& row, int64_t value) {
  if (row.word && value == row.word_value) return row.word;
  switch (row.type) {
    case KeyType::Boolean: return value ? "true" : "false";
    case KeyType::Choice: return value >= 0 && size_t(value) < row.choices.size() ? row.choices[size_t(value)] : "?";
    case KeyType::Sixteenths: return slope_text(int(value));
    default: return std::to_string(value);
  }
}

std::string key_help(const ProfileKey& row) {
  return plain(row.meaning) + "; " + plain(values_text(row)) + " (default " + key_value_text(row, row.get(Profile{})) +
         ")";
}

std::string profile_table_markdown() {
  std::string out = "| key | values | default | in the RTL | meaning |\n|---|---|---|---|---|\n";
  for (const ProfileKey& row : kTable) {
    const std::string def = key_value_text(row, row.get(Profile{}));
    std::string rtl;
    for (const char* at = row.rtl_name; *at;) {  // "cfg_x, X" -> "`cfg_x`, `X`"
      const char* end = std::strchr(at, ',');
      const std::string name(at, end ? end : at + std::strlen(at));
      rtl += (rtl.empty() ? "`" : ", `") + name + "`";
      at = end ? end + 2 : at + name.size();
    }
    out += "| `" + std::string(row.key) + "` | " + values_text(row) + " | " +
           (row.word && def == row.word ? "`" + def + "`" : def) + " | " + (rtl.empty() ? "-" : rtl) + " | " +
           row.meaning + " |\n";
  }
  return out;
}

std::vector<std::string> validate(const Profile& p) {
  std::vector<std::string> errors;
  for (const ProfileKey& row : kTable) {
    const int64_t v = row.get(p);
    if (v >= row.min && v <= row.max) continue;
    if (row.type == KeyType::Sixteenths)
      errors.push_back(std::string(row.key) + " is " + slope_text(int(v)) + "; it must be in " + values_text(row));
    else
      errors.push_back(std::string(row.key) + " is " + std::to_string(v) + "; it must be in " + bound_text(row.min) +
                       ".." + bound_text(row.max));
  }
  // The rules that tie a key to another, or leave a gap in its range.
  if (p.setup_interval > 0 && p.setup_interval < kMinSetupInterval)
    errors.push_back("setup_interval is " + std::to_string(p.setup_interval) + "; it must be 0 or in " +
                     std::to_string(kMinSetupInterval) + ".." + std::to_string(kMaxSetupInterval));
  if (p.z_bits >= 16 && p.z_bits <= 32 && p.depth_clear >= 0 && p.depth_clear > int64_t(p.depth_max()))
    errors.push_back("depth_clear is " + std::to_string(p.depth_clear) + "; it must be in 0.." +
                     std::to_string(p.depth_max()) + " for z_bits " + std::to_string(p.z_bits));
  if (p.z_bits >= 16 && p.z_bits <= 32 && p.depth_exponent_bits >= 1 && p.depth_exponent_bits <= 4 &&
      p.depth_plane_bits() > 32)
    errors.push_back("depth_exponent_bits " + std::to_string(p.depth_exponent_bits) + " with z_bits " +
                     std::to_string(p.z_bits) + " makes a depth plane of " + std::to_string(p.depth_plane_bits()) +
                     " bits; it must be at most 32");
  else if (p.z_bits >= 16 && p.z_bits <= 32 && p.depth_exponent_bits >= 0 && p.depth_exponent_bits <= 4) {
    const int64_t limit = (int64_t(1) << p.depth_plane_bits()) - 1;
    if (p.depth_bias_constant < -limit || p.depth_bias_constant > limit)
      errors.push_back("depth_bias_constant is " + std::to_string(p.depth_bias_constant) + "; it must be in " +
                       std::to_string(-limit) + ".." + std::to_string(limit));
  }
  if (p.depth_buffer == DepthBuffer::InverseW && (p.depth_func == DepthFunc::Less || p.depth_func == DepthFunc::LEqual))
    errors.push_back(std::string("depth_func is ") + to_string(p.depth_func) +
                     "; a 1/w buffer (depth_buffer inverse_w) keeps the nearer fragment with greater or gequal");
  return errors;
}

std::string set_profile_key(Profile& p, const std::string& key, const std::string& value) {
  const ProfileKey* row = find_profile_key(key);
  if (!row) return "unknown profile key '" + key + "'";
  int64_t n = 0;
  switch (row->type) {
    case KeyType::Boolean: {
      bool b = false;
      if (!parse_bool(value, b)) return key + " takes true or false, not '" + value + "'";
      row->set(p, b);
      return "";
    }
    case KeyType::Choice:
      for (size_t i = 0; i < row->choices.size(); ++i)
        if (value == row->choices[i]) return row->set(p, int64_t(i)), "";
      return key + " is '" + value + "'; it must be one of " + choices(row->choices);
    case KeyType::Sixteenths: {
      char* end = nullptr;
      const double number = value.empty() ? 0 : std::strtod(value.c_str(), &end);
      if (value.empty() || *end != '\0' || !std::isfinite(number)) return key + " takes a number, not '" + value + "'";
      const double sixteenths = number * 16;
      if (sixteenths < -1e6 || sixteenths > 1e6 || sixteenths != std::floor(sixteenths))
        return key + " is " + value + "; it must be " + values_text(*row);
      row->set(p, int64_t(sixteenths));
      return "";
    }
    case KeyType::Integer: break;
  }
  if (row->word && value == row->word) return row->set(p, row->word_value), "";
  const bool wide = row->min < INT32_MIN || row->max > INT32_MAX;
  // Digits beyond 64 bits, or beyond 32 for a key whose range fits them, are out of range, not a non-integer.
  const size_t sign = !value.empty() && (value[0] == '-' || value[0] == '+') ? 1 : 0;
  const bool digits = value.size() > sign && value.find_first_not_of("0123456789", sign) == std::string::npos;
  const bool parsed = parse_int(value, n);
  if (digits && (!parsed || (!wide && (n < INT32_MIN || n > INT32_MAX))))
    return key + " is '" + value + "'; it must be " + plain(values_text(*row));
  if (!parsed)
    return key + " takes an integer" + (row->word ? " or '" + std::string(row->word) + "'" : "") + ", not '" + value + "'";
  // A number that spells the word's value is out of range (0 is how z_guard_bits holds 'auto').
  if (row->word && (n == row->word_value || n < row->min))
    return key + " is '" + value + "'; it must be " + plain(values_text(*row));
  row->set(p, n);
  return "";
}

void load_profile_file(Profile& profile, const std::string& path) {
  load_profile_text(profile, read_text_file(path, "a profile file", kMaxProfileBytes), path);
}

void load_profile_text(Profile& profile, const std::string& text, const std::string& file_name) {
  const nlohmann::json doc = parse_json_document(text, file_name);
  if (!doc.is_object()) throw InputError(file_name, 1, "a profile must be a JSON object");
  const JsonLines lines(text);
  // JSON types as docs/formats.md gives them: numbers for the integer keys (and a word where the
  // key has one), true/false for the booleans, strings for the choices.
  auto type_error = [](const ProfileKey& row, const nlohmann::json& v) -> std::string {
    const bool is_integer = v.is_number_integer() || v.is_number_unsigned();
    const std::string key = row.key;
    switch (row.type) {
      case KeyType::Integer:
        if (row.word) return is_integer || v.is_string() ? "" : key + " must be a JSON integer or \"" + row.word + "\", not " + v.dump();
        return is_integer ? "" : key + " must be a JSON integer, not " + v.dump();
      case KeyType::Sixteenths: return v.is_number() ? "" : key + " must be a JSON number, not " + v.dump();
      case KeyType::Boolean: return v.is_boolean() ? "" : key + " must be true or false, not " + v.dump();
      case KeyType::Choice: break;
    }
    return v.is_string() ? "" : key + " must be a JSON string, not " + v.dump();
  };
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    const std::string pointer = JsonLines::child("", it.key());
    const int line = lines.line(pointer);
    std::string value;
    if (it->is_string()) value = it->get<std::string>();
    else if (it->is_boolean()) value = it->get<bool>() ? "true" : "false";
    else if (it->is_number_unsigned()) value = std::to_string(it->get<uint64_t>());  // above INT64_MAX too
    else if (it->is_number_integer()) value = std::to_string(it->get<int64_t>());
    else if (it->is_number_float()) value = it->dump();
    else throw InputError(file_name, line, "profile key '" + it.key() + "' must be a string, integer or boolean");
    std::string error = set_profile_key(profile, it.key(), value);
    if (error.empty() && (it->is_string() || it->is_boolean() || it->is_number()))
      if (const ProfileKey* row = find_profile_key(it.key())) error = type_error(*row, *it);
    if (!error.empty()) throw InputError(file_name, line, error);
  }
  // Ranges (and depth_clear against z_bits) at the line of the key each error names.
  for (const std::string& error : validate(profile)) {
    const std::string key = error.substr(0, error.find(' '));
    if (doc.contains(key)) throw InputError(file_name, lines.line(JsonLines::child("", key)), error);
  }
}

const std::vector<ConventionPreset>& convention_presets() {
  static const std::vector<ConventionPreset> presets = {
      {"rastersim", "rastersim's own", {{"pixel_center", "half"}, {"fill_rule", "top_left"}}},
      {"d3d9", "Direct3D 9: pixel centres at integer coordinates, the top-left rule",
       {{"pixel_center", "corner"}, {"fill_rule", "top_left"}}},
      {"d3d10", "Direct3D 10 to 12: pixel centres at half-integer coordinates, the top-left rule, 8 subpixel bits",
       {{"pixel_center", "half"}, {"fill_rule", "top_left"}, {"subpixel_bits", "8"}}},
  };
  return presets;
}

const ConventionPreset* find_convention_preset(const std::string& name) {
  for (const ConventionPreset& p : convention_presets())
    if (name == p.name) return &p;
  return nullptr;
}

std::string conventions_text(const Profile& p) {
  const Profile defaults;
  std::string out;
  for (const char* key : {"pixel_center", "fill_rule", "vertex_snap", "depth_rounding", "color_rounding"}) {
    const ProfileKey& row = *find_profile_key(key);
    if (row.get(p) != row.get(defaults)) out += (out.empty() ? "" : ", ") + std::string(key) + " " + key_value_text(row, row.get(p));
  }
  return out;
}

std::string profile_to_json(const Profile& p, int indent) {
  nlohmann::ordered_json j;
  for (const ProfileKey& row : kTable) {
    const int64_t v = row.written ? row.written(p) : row.get(p);
    nlohmann::ordered_json& out = j[row.key];
    if (row.word && v == row.word_value) out = row.word;
    else if (row.type == KeyType::Boolean) out = v != 0;
    else if (row.type == KeyType::Choice) out = key_value_text(row, v);
    else if (row.type == KeyType::Sixteenths) out = double(v) / 16.0;  // exact: a multiple of 1/16
    else out = v;
  }
  return j.dump(indent);
}

}  // namespace rastersim
