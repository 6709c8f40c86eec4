#include "hw_cost.h"

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "model/core_parameters.h"

namespace rastersim {
namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// FNV-1a over the RTL sources (name and content) and the synthesis script: the cache key changes
// with any edit of either.
std::string digest(const std::vector<fs::path>& sources, const std::string& script) {
  uint64_t h = 0xcbf29ce484222325ull;
  auto mix = [&](const std::string& s) {
    for (unsigned char c : s) h = (h ^ c) * 0x100000001b3ull;
  };
  for (const fs::path& p : sources) mix(p.filename().string() + "\n" + read_file(p));
  mix(script);
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

// "     SB_LUT4     1234" lines of a yosys `stat` report, by cell type; "Number of cells:" as "".
std::map<std::string, int64_t> stat_counts(const std::string& report) {
  std::map<std::string, int64_t> counts;
  std::istringstream in(report);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string first, second, third;
    words >> first >> second >> third;
    if (first == "Number" && second == "of" && third == "cells:") {
      int64_t n = 0;
      if (words >> n) counts[""] = n;  // the last module reported: the flattened top
    } else if (!first.empty() && !second.empty() && third.empty() &&
               std::all_of(second.begin(), second.end(), [](char c) { return c >= '0' && c <= '9'; })) {
      counts[first] = std::stoll(second);
    }
  }
  return counts;
}

std::string default_cache_dir() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/rastersim/hw-cost";
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/rastersim/hw-cost";
  return (fs::temp_directory_path() / "rastersim-hw-cost").string();
}

}  // namespace

std::string hardware_parameters(const Profile& p) { return core_parameters_text(core_parameters(p)); }

HardwareCost hardware_cost(const Profile& p, const std::string& rtl_dir, const std::string& cache_dir_or_empty) {
  std::vector<fs::path> sources;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(rtl_dir, ec))
    if (e.path().extension() == ".sv" || e.path().extension() == ".vh") sources.push_back(e.path());
  if (ec || sources.empty()) throw std::runtime_error("no RTL sources (.sv) in " + rtl_dir);
  std::sort(sources.begin(), sources.end());

  HardwareCost cost;
  const int64_t words = int64_t(p.width) * p.height;
  cost.memory_bits = words * (p.z_bits + 24) + 2 * ((words + 63) / 64) * 64;

  // The script, with GENERIC and ICE40 standing for the report files. synth_ice40 stops before its
  // `check` step, whose autoname pass takes longer than the whole synthesis on the full-size core.
  std::string read = "read_verilog -sv -I.";
  for (const fs::path& s : sources)
    if (s.extension() == ".sv") read += " " + s.filename().string();
  std::string chparam = "chparam";
  std::istringstream params(hardware_parameters(p));
  for (std::string kv; params >> kv;) chparam += " -set " + kv.substr(0, kv.find('=')) + " " + kv.substr(kv.find('=') + 1);
  chparam += " rastersim_core";
  const std::string script = read + "\n" + chparam + "\nsynth -flatten -top rastersim_core\ntee -q -o GENERIC stat\n" +
                             "design -reset\n" + read + "\n" + chparam +
                             "\nsynth_ice40 -top rastersim_core -run :check\ntee -q -o ICE40 stat\n";

  // The entry's name: the parameters' values in core_parameters() order (their names are in the
  // script's digest), short enough for any file system's 255-byte names.
  std::string key = "core";
  for (const CoreParameter& c : core_parameters(p)) key += "-" + std::to_string(c.value);
  key += "-" + digest(sources, script);
  const fs::path cache_dir = cache_dir_or_empty.empty() ? default_cache_dir() : cache_dir_or_empty;
  const fs::path entry = cache_dir / (key + ".stat");
  std::string generic, ice40;
  if (fs::exists(entry)) {
    const std::string both = read_file(entry);
    const size_t split = both.find("\n=== ice40 ===\n");
    if (split != std::string::npos) {
      generic = both.substr(0, split);
      ice40 = both.substr(split + 15);
      cost.from_cache = true;
    }
  }
  if (!cost.from_cache) {
    fs::create_directories(cache_dir);
    const fs::path work = cache_dir / (key + ".work");
    fs::create_directories(work);
    std::string run = script;
    for (const auto& [name, file] : {std::pair{"GENERIC", "generic.txt"}, std::pair{"ICE40", "ice40.txt"}})
      run.replace(run.find(name), std::string(name).size(), fs::absolute(work / file).string());
    std::ofstream(work / "cost.ys") << run;
    const fs::path log = work / "yosys.log";
    // Relative source names: yosys runs in rtl_dir.
    const std::string command = "cd '" + rtl_dir + "' && yosys -q -l '" + fs::absolute(log).string() + "' -s '" +
                                fs::absolute(work / "cost.ys").string() + "' > /dev/null 2>&1";
    const int status = std::system(command.c_str());
    if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) == 127)
      throw std::runtime_error("yosys is not installed (scripts/install-deps.sh installs it)");
    if (WEXITSTATUS(status) != 0)
      throw std::runtime_error("yosys failed for " + hardware_parameters(p) + "; log: " + log.string());
    generic = read_file(work / "generic.txt");
    ice40 = read_file(work / "ice40.txt");
    // Written last and renamed into place: an interrupted run leaves no entry.
    const fs::path temp = cache_dir / (key + ".stat.tmp");
    std::ofstream(temp) << generic << "\n=== ice40 ===\n" << ice40;
    fs::rename(temp, entry);
    fs::remove_all(work);
  }
  const std::map<std::string, int64_t> g = stat_counts(generic), ic = stat_counts(ice40);
  if (!g.count("") || !ic.count(""))
    throw std::runtime_error("unreadable yosys stat report for " + hardware_parameters(p) + " in " + entry.string());
  cost.cells = g.at("");
  for (const auto& [type, n] : ic) {
    if (type == "SB_LUT4") cost.ice40_luts += n;
    if (type.rfind("SB_DFF", 0) == 0) cost.ice40_ffs += n;
    if (type == "SB_CARRY") cost.ice40_carry += n;
    if (type == "SB_RAM40_4K") cost.ice40_ram += n;
  }
  return cost;
}

}  // namespace rastersim
