#include "core_parameters.h"

#include <algorithm>
#include <stdexcept>

#include "widths.h"

namespace rastersim {
namespace {

enum class Fit { Equal, Bound, Guard };

struct Row {
  const char* name;
  Fit fit;
};
#define RS_ROW(name, fit) {#name, Fit::fit},
constexpr Row kRows[] = {RASTERSIM_CORE_PARAMETERS(RS_ROW)};
#undef RS_ROW

// The value of parameter `name` for the profile.
int64_t value_of(const std::string& name, const Profile& p, CoreBounds bounds) {
  const bool largest = bounds == CoreBounds::Largest;
  if (name == "WIDTH") return p.width;
  if (name == "HEIGHT") return p.height;
  if (name == "SUBPIXEL_BITS") return p.subpixel_bits;
  if (name == "Z_BITS") return p.z_bits;
  if (name == "Z_GUARD_BITS") return p.z_guard_bits;
  if (name == "MAX_MEMORY_LATENCY") return largest ? kMaxMemoryLatency : p.memory_latency;
  if (name == "MAX_SETUP_FIFO_DEPTH") return largest ? kMaxSetupFifoDepth : p.setup_fifo_depth;
  if (name == "SETUP_INTERVAL") return p.setup_interval;
  if (name == "TEXTURE") return p.texture_unit ? 1 : 0;
  if (name == "MAX_TEXTURE_LATENCY") return largest ? kMaxTextureLatency : p.texture_latency;
  // One exponent bit makes a word equal to the fixed-point one (docs/arithmetic.md section 6).
  if (name == "DEPTH_EXPONENT_BITS") return p.depth_exponent_bits >= 2 ? p.depth_exponent_bits : 0;
  if (name == "DEPTH_BIAS") return p.depth_biased() ? 1 : 0;
  if (name == "PIXEL_CENTER") return int64_t(p.pixel_center);
  if (name == "FILL_RULE") return int64_t(p.fill_rule);
  if (name == "DEPTH_ROUNDING") return int64_t(p.depth_rounding);
  if (name == "COLOR_ROUNDING") return int64_t(p.color_rounding);
  throw std::logic_error("core parameter " + name + " has no mapping from the profile");
}

const Row* row_of(const std::string& name) {
  for (const Row& r : kRows)
    if (name == r.name) return &r;
  return nullptr;
}

}  // namespace

CoreParameters core_parameters(const Profile& p, CoreBounds bounds) {
  CoreParameters out;
  for (const Row& r : kRows) out.push_back({r.name, value_of(r.name, p, bounds)});
  return out;
}

int64_t parameter_value(const CoreParameters& parameters, const std::string& name) {
  for (const CoreParameter& c : parameters)
    if (c.name == name) return c.value;
  throw std::invalid_argument("rastersim_core has no parameter " + name);
}

std::string core_parameters_text(const CoreParameters& parameters, const std::string& separator) {
  std::string out;
  for (const CoreParameter& c : parameters) out += (out.empty() ? "" : separator) + c.name + "=" + std::to_string(c.value);
  return out;
}

CoreParameters parse_core_parameters(const std::string& text) {
  CoreParameters out;
  size_t at = 0;
  while (at < text.size()) {
    const size_t end = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, end - at);
    const size_t eq = item.find('=');
    const std::string name = item.substr(0, eq);
    if (eq == std::string::npos || !row_of(name))
      throw std::invalid_argument("'" + item + "' is not NAME=value with a parameter of rastersim_core");
    size_t used = 0;
    int64_t value = 0;
    try {
      value = std::stoll(item.substr(eq + 1), &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() - eq - 1) throw std::invalid_argument("'" + item + "' has no integer value");
    out.push_back({name, value});
    at = end + 1;
  }
  return out;
}

std::string core_mismatch(const CoreParameters& built, const Profile& p) {
  for (const CoreParameter& want : core_parameters(p)) {
    const auto have = std::find_if(built.begin(), built.end(), [&](const CoreParameter& c) { return c.name == want.name; });
    if (have == built.end()) return want.name + " is not among the built core's parameters";
    const Fit fit = row_of(want.name)->fit;
    bool fits = have->value == want.value;
    if (fit == Fit::Bound) fits = have->value >= want.value;
    if (fit == Fit::Guard) {
      const auto guard = [&](int64_t g) { return g > 0 ? g : int64_t(derived_guard_bits(p.width, p.height)); };
      fits = guard(have->value) == guard(want.value);
    }
    if (!fits)
      return want.name + " is " + std::to_string(have->value) + " in this core; the profile needs " +
             (fit == Fit::Bound ? "at least " : "") + std::to_string(want.value) +
             (fit == Fit::Guard ? " (resolved guard bits differ)" : "");
  }
  return "";
}

}  // namespace rastersim
