#include "core_parameters.h"

#include <algorithm>
#include <stdexcept>

#include "widths.h"

namespace rastersim {

const std::vector<CoreParameterRow>& core_parameter_rows() {
  static const std::vector<CoreParameterRow> rows = [] {
    std::vector<CoreParameterRow> out;
    for (const ProfileKey& key : profile_table()) {
      if (key.place != RtlPlace::Parameter && key.place != RtlPlace::Both) continue;
      std::string name = key.rtl_name;
      if (const size_t comma = name.rfind(", "); comma != std::string::npos) name = name.substr(comma + 2);
      const auto named = std::find_if(out.begin(), out.end(), [&](const CoreParameterRow& r) { return r.name == name; });
      if (named != out.end())
        named->keys += ", " + std::string(key.key);
      else
        out.push_back({name, &key, key.key, key.place == RtlPlace::Both ? CoreFit::Bound : key.core_fit});
    }
    return out;
  }();
  return rows;
}

namespace {

const CoreParameterRow* row_of(const std::string& name) {
  for (const CoreParameterRow& r : core_parameter_rows())
    if (name == r.name) return &r;
  return nullptr;
}

int64_t value_of(const ProfileKey& key, const Profile& p, CoreBounds bounds) {
  const bool largest = bounds == CoreBounds::Largest;
  if (key.core_value) return key.core_value(p, largest);
  return key.place == RtlPlace::Both && largest ? key.max : key.get(p);
}

}  // namespace

CoreParameters core_parameters(const Profile& p, CoreBounds bounds) {
  CoreParameters out;
  for (const CoreParameterRow& r : core_parameter_rows()) out.push_back({r.name, value_of(*r.key, p, bounds)});
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
    const CoreFit fit = row_of(want.name)->fit;
    bool fits = have->value == want.value;
    if (fit == CoreFit::Bound) fits = have->value >= want.value;
    if (fit == CoreFit::Guard) {
      const auto guard = [&](int64_t g) { return g > 0 ? g : int64_t(derived_guard_bits(p.width, p.height)); };
      fits = guard(have->value) == guard(want.value);
    }
    if (!fits)
      return want.name + " is " + std::to_string(have->value) + " in this core; the profile needs " +
             (fit == CoreFit::Bound ? "at least " : "") + std::to_string(want.value) +
             (fit == CoreFit::Guard ? " (resolved guard bits differ)" : "");
  }
  return "";
}

}  // namespace rastersim
