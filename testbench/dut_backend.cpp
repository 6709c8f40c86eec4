#include "testbench/dut_backend.h"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "model/input_error.h"
#include "model/widths.h"
#include "testbench/setup_record.h"

namespace fs = std::filesystem;

namespace rastersim::dut {
namespace {

constexpr int kMaxListDepth = 16;  // nested -F lists: deeper is a loop

void read_list(const fs::path& list, modules::DutDesign& design, int depth) {
  if (depth > kMaxListDepth) throw InputError(list.string(), 1, "file lists nest more than 16 deep (a loop?)");
  std::ifstream in(list);
  if (!in) throw InputError(list.string() + ": cannot read the file list");
  const fs::path base = list.parent_path();
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    for (const char* comment : {"//", "#"})
      if (const size_t at = line.find(comment); at != std::string::npos) line.erase(at);
    std::istringstream words(line);
    for (std::string word; words >> word;) {
      const auto resolve = [&](const std::string& p) { return fs::absolute(base / p).lexically_normal(); };
      if (word.rfind("+incdir+", 0) == 0) {
        const fs::path dir = resolve(word.substr(8));
        if (!fs::is_directory(dir)) throw InputError(list.string(), line_number, "include folder " + dir.string() + " does not exist");
        design.include_dirs.push_back(dir.string());
      } else if (word == "-F" || word == "-f") {
        std::string nested;
        if (!(words >> nested)) throw InputError(list.string(), line_number, word + " names no file list");
        read_list(resolve(nested), design, depth + 1);
      } else if (word[0] == '-' || word[0] == '+') {
        throw InputError(list.string(), line_number,
                         "'" + word + "' is not a source file, +incdir+DIR, -F LIST or -f LIST");
      } else {
        const fs::path file = resolve(word);
        if (!fs::is_regular_file(file)) throw InputError(list.string(), line_number, "source file " + file.string() + " does not exist");
        design.files.push_back(file.string());
      }
    }
  }
}

}  // namespace

modules::DutDesign read_design(const std::string& list_or_folder, const std::string& top) {
  modules::DutDesign design;
  design.top = top;
  if (top.empty() || !std::all_of(top.begin(), top.end(), [](char c) { return std::isalnum(uint8_t(c)) || c == '_'; }))
    throw InputError("--top '" + top + "' is not a module name");
  const fs::path path = fs::absolute(list_or_folder).lexically_normal();
  if (fs::is_directory(path)) {
    for (const fs::directory_entry& e : fs::directory_iterator(path))
      if (e.is_regular_file() && (e.path().extension() == ".sv" || e.path().extension() == ".v"))
        design.files.push_back(e.path().string());
    std::sort(design.files.begin(), design.files.end());
    design.include_dirs.push_back(path.string());
    if (design.files.empty()) throw InputError("--dut: folder " + path.string() + " holds no .sv or .v file");
  } else if (fs::is_regular_file(path)) {
    read_list(path, design, 0);
    if (design.files.empty()) throw InputError(path.string() + ": the file list names no source file");
  } else {
    throw InputError("--dut: " + path.string() + " is neither a file list nor a folder");
  }
  return design;
}

std::vector<std::string> design_parameters(const Profile& p, const std::vector<std::string>& options) {
  std::vector<std::pair<std::string, std::string>> out = {{"WIDTH", std::to_string(p.width)},
                                                          {"HEIGHT", std::to_string(p.height)},
                                                          {"SUBPIXEL_BITS", std::to_string(p.subpixel_bits)},
                                                          {"Z_BITS", std::to_string(p.z_bits)}};
  for (const std::string& option : options) {
    const size_t eq = option.find('=');
    const std::string name = option.substr(0, eq);
    if (eq == std::string::npos || name.empty() || eq + 1 == option.size() ||
        !std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(uint8_t(c)) || c == '_'; }) ||
        option.find_first_of(" \t;'\"$`\\") != std::string::npos)
      throw InputError("-G '" + option + "' is not NAME=value");
    auto it = std::find_if(out.begin(), out.end(), [&](const auto& kv) { return kv.first == name; });
    if (it != out.end()) it->second = option.substr(eq + 1);
    else out.emplace_back(name, option.substr(eq + 1));
  }
  std::vector<std::string> list;
  for (const auto& [name, value] : out) list.push_back(name + "=" + value);
  return list;
}

std::vector<std::string> unit_parameters(Unit unit, const Profile& p, const std::vector<std::string>& options) {
  const Widths w = derive_widths(p);
  std::vector<std::string> given = {"FRACTION_BITS=" + std::to_string(w.guard_bits)};
  if (unit == Unit::Walker) given.push_back("AUX_BITS=" + std::to_string(rtl::RecordLayout(w, true).bits()));
  given.insert(given.end(), options.begin(), options.end());
  return design_parameters(p, given);
}

std::optional<Unit> parse_unit(const std::string& text) {
  for (Unit u : {Unit::Setup, Unit::Walker, Unit::Zbuffer})
    if (text == to_string(u)) return u;
  return std::nullopt;
}

std::string interface_error(const Profile& p) {
  if (p.texture_unit) return "texture_unit: the verification interface carries no texture coordinates";
  if (p.depth_exponent_bits >= 2) return "depth_exponent_bits: the verification interface carries the fixed-point depth word";
  if (p.depth_biased()) return "a depth bias: the verification interface has no bias inputs";
  return "";
}

Design::Design(const std::string& library_path, std::optional<Unit> unit) {
  void* handle = dlopen(library_path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw std::runtime_error(std::string("cannot load the design's module: ") + dlerror());
  const auto abi = reinterpret_cast<const char* (*)()>(dlsym(handle, RASTERSIM_MODULE_ABI_SYMBOL));
  if (unit) {
    run_unit_ = reinterpret_cast<UnitRunFunction>(dlsym(handle, RASTERSIM_UNIT_RUN_SYMBOL));
    const auto name = reinterpret_cast<UnitNameFunction>(dlsym(handle, RASTERSIM_UNIT_NAME_SYMBOL));
    if (!abi || !run_unit_ || !name || std::string(name()) != to_string(*unit))
      throw std::runtime_error(library_path + " is not a module of rastersim for the " + to_string(*unit) + " unit");
  } else {
    run_ = reinterpret_cast<RunFunction>(dlsym(handle, RASTERSIM_DUT_RUN_SYMBOL));
    const auto memory_port = reinterpret_cast<bool (*)()>(dlsym(handle, RASTERSIM_DUT_MEMORY_PORT_SYMBOL));
    if (!abi || !run_ || !memory_port) throw std::runtime_error(library_path + " is not a design module of rastersim");
    memory_port_ = memory_port();
  }
  if (abi() != modules::abi_stamp())
    throw std::runtime_error(library_path + " was built against other records than this program");
}

rtl::RtlResult Design::run(const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                           const DutRunOptions& options) const {
  rtl::RtlResult out;
  std::string error;
  if (!run_(profile, triangles, options, out, error)) throw std::runtime_error(error);
  return out;
}

UnitResult Design::run_unit(const UnitFrame& frame, const DutRunOptions& options) const {
  UnitResult out;
  std::string error;
  if (!run_unit_(frame, options, out, error)) throw std::runtime_error(error);
  return out;
}

}  // namespace rastersim::dut
