#include "cosim_command.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "model/input_error.h"
#include "outputs.h"
#ifdef RASTERSIM_HAVE_RTL
#include "testbench/cosim_cases.h"
#include "testbench/rtl_backend.h"
#endif

namespace rastersim {
namespace {

struct Shard {
  int64_t index = 0, count = 1;  // this run takes frames k with k % count == index
};

Shard parse_shard(const std::string& text) {
  Shard s;
  long long k = 0, n = 0;
  char slash = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%lld %c %lld %c", &k, &slash, &n, &extra) != 3 || slash != '/' || n < 1 || k < 1 ||
      k > n)
    throw InputError("--shard: '" + text + "' is not K/N with 1 <= K <= N (for example 2/8)");
  s.index = k - 1;
  s.count = n;
  return s;
}

std::string xml_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') ? ' ' : c;
    }
  }
  return out;
}

struct FrameResult {
  int64_t index;
  std::string name;
  double seconds;
  bool passed;
  std::string failure;  // the divergence paragraph
};

std::string profile_summary(const Profile& p) {
  std::ostringstream s;
  s << p.width << "x" << p.height << " S=" << p.subpixel_bits << " N=" << p.z_bits;
  return s.str();
}

std::string settings_summary(const Profile& p) {
  std::ostringstream s;
  s << to_string(p.traversal) << ", " << to_string(p.shading) << ", depth " << to_string(p.depth_func)
    << (p.depth_write ? "" : " no-write") << ", clear " << p.depth_clear_value() << ", cull " << to_string(p.cull)
    << " " << to_string(p.front_face) << ", latency " << p.memory_latency << ", setup FIFO " << p.setup_fifo_depth;
  return s.str();
}

// One <testsuite> of the frames this shard ran: any JUnit consumer merges shards by concatenation.
std::string junit_xml(const std::vector<FrameResult>& frames, const Profile& profile, const CosimOptions& o) {
  int64_t failures = 0;
  double total = 0;
  for (const FrameResult& f : frames) failures += !f.passed, total += f.seconds;
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<testsuites tests=\"" << frames.size() << "\" failures=\"" << failures << "\" time=\"" << total << "\">\n"
    << "  <testsuite name=\"rastersim.cosim." << xml_escape(profile_summary(profile)) << ".shard" << o.shard
    << "\" tests=\"" << frames.size() << "\" failures=\"" << failures << "\" errors=\"0\" skipped=\"0\" time=\""
    << total << "\">\n"
    << "    <properties>\n"
    << "      <property name=\"profile\" value=\"" << xml_escape(profile_summary(profile)) << "\"/>\n"
    << "      <property name=\"seed\" value=\"" << o.seed << "\"/>\n"
    << "      <property name=\"count\" value=\"" << o.count << "\"/>\n"
    << "      <property name=\"triangles\" value=\"" << o.triangles << "\"/>\n"
    << "      <property name=\"shard\" value=\"" << xml_escape(o.shard) << "\"/>\n"
    << "    </properties>\n";
  for (const FrameResult& f : frames) {
    x << "    <testcase classname=\"rastersim.cosim\" name=\"frame " << f.index << ": " << xml_escape(f.name)
      << "\" time=\"" << f.seconds << "\"";
    if (f.passed) {
      x << "/>\n";
    } else {
      x << ">\n      <failure type=\"divergence\" message=\"" << xml_escape(f.failure) << "\">"
        << xml_escape(f.failure) << "</failure>\n    </testcase>\n";
    }
  }
  x << "  </testsuite>\n</testsuites>\n";
  return x.str();
}

}  // namespace

CLI::App* add_cosim_command(CLI::App& app, CosimOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "cosim", "directed and random frames through the model and the RTL in lockstep, compared at every transaction");
  // The defaults in the help text are those of CosimOptions.
  cmd->add_option("--count", o.count,
                  "random frames to run after the directed ones (default " + std::to_string(o.count) + ")")
      ->type_name("N");
  cmd->add_option("--seed", o.seed,
                  "frame k draws its triangles, settings and the RTL's power-on state from seed + k (default " +
                      std::to_string(o.seed) + ")")
      ->type_name("S");
  cmd->add_option("--triangles", o.triangles, "triangles per random frame (default " + std::to_string(o.triangles) + ")")
      ->type_name("K");
  cmd->add_flag_callback("--no-directed", [&o] { o.directed = false; }, "skip the directed frames");
  cmd->add_flag("--fixed-settings", o.fixed_settings,
                "random frames keep the profile's runtime settings (by default each frame draws depth_func, "
                "depth_write, depth_clear, cull, front_face, traversal, shading, memory_latency and setup_fifo_depth, except the keys "
                "set by a flag or the profile file)");
  cmd->add_option("--shard", o.shard, "run only frames k with k mod N = K - 1 (1 <= K <= N); the union of shards 1/N .. N/N is the whole run")
      ->type_name("K/N");
  cmd->add_option("--junit", o.junit_out, "write the frames' results as JUnit XML")->type_name("FILE");
  cmd->add_flag("--keep-going", o.keep_going, "run every frame even after a divergence");
  cmd->add_option("--replay-dir", o.replay_dir,
                  "folder for the replay files of a divergence (default the working folder)")->type_name("DIR");
  cmd->add_option("--fst", o.fst_out, "write the RTL waveform of every frame (the last one run remains)")
      ->type_name("FILE");
  add_profile_options(*cmd, o.profile);
  return cmd;
}

int run_cosim(const CosimOptions& o) {
  const Profile profile = resolve_profile(o.profile);
  // Frame indices must not overflow (a huge count once ran nothing and passed).
  constexpr int64_t kMaxCount = 1000000000;
  if (o.count < 0 || o.count > kMaxCount)
    throw InputError("--count " + std::to_string(o.count) + " is outside 0.." + std::to_string(kMaxCount) +
                     " (random frames; split a longer run with --shard and several seeds)");
  if (o.triangles < 1 || o.triangles > 100000) throw InputError("--triangles must be in 1..100000");
  const Shard shard = parse_shard(o.shard);
#ifndef RASTERSIM_HAVE_RTL
  (void)profile;
  (void)shard;
  throw InputError("cosim needs the RTL backend, which is not built in this binary (install Verilator and rebuild)");
#else
  const std::string problem = rtl::configuration_error(profile);
  if (!problem.empty()) throw InputError(problem);
  if (!std::filesystem::is_directory(o.replay_dir))
    throw InputError("--replay-dir: folder '" + o.replay_dir + "' does not exist");
  OutputFiles outputs;
  const std::string junit_temp = o.junit_out.empty() ? "" : outputs.add(o.junit_out, "--junit");
  const std::string fst_temp = o.fst_out.empty() ? "" : add_waveform(outputs, o.fst_out);

  const std::set<std::string> pinned =
      o.fixed_settings ? std::set<std::string>(rtl::runtime_setting_keys().begin(), rtl::runtime_setting_keys().end())
                       : given_profile_keys(o.profile);
  std::vector<std::string> varied;
  for (const std::string& key : rtl::runtime_setting_keys())
    if (!pinned.count(key)) varied.push_back(key);
  const int max_latency = rtl::built_max_memory_latency(profile);

  std::vector<rtl::CosimCase> cases;
  if (o.directed) cases = rtl::directed_cases(profile, pinned);
  const int64_t directed = int64_t(cases.size());
  const bool tty = isatty(STDERR_FILENO) != 0;
  const int64_t total = directed + o.count;
  const int64_t in_shard = total / shard.count + (shard.index < total % shard.count ? 1 : 0);
  std::vector<FrameResult> results;
  int64_t passed = 0, failed = 0, directed_run = 0;
  // With the JUnit XML on standard output (`--junit -`), the report goes to standard error.
  std::ostream& info = outputs.writes_stdout() ? std::cerr : std::cout;
  for (int64_t k = shard.index; k < total; k += shard.count) {
    const uint64_t frame_seed = o.seed + uint64_t(k);
    rtl::CosimCase c;
    if (k < directed) {
      c = cases[size_t(k)];
      ++directed_run;
    } else {
      c = rtl::random_case(profile, frame_seed, o.triangles);
      if (!varied.empty()) c.profile = rtl::random_settings(profile, frame_seed, pinned, max_latency);
    }
    if (!varied.empty() || k < directed) c.name += " (" + settings_summary(c.profile) + ")";
    if (tty)
      std::fprintf(stderr, "\rcosim: %lld / %lld frames, %lld failed (%s)\033[K", (long long)(passed + failed),
                   (long long)in_shard, (long long)failed, c.name.c_str());
    rtl::RtlOptions options;
    options.seed = frame_seed;
    options.fst_path = fst_temp;
    const std::string prefix = (std::filesystem::path(o.replay_dir) / ("rastersim-replay-" + std::to_string(k))).string();
    const auto start = std::chrono::steady_clock::now();
    const rtl::CosimReport report = rtl::cosim(c.profile, c.triangles, options, prefix);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    results.push_back(FrameResult{k, c.name, seconds, report.passed, report.passed ? "" : report.message()});
    if (report.passed) {
      ++passed;
      continue;
    }
    ++failed;
    if (tty) std::fprintf(stderr, "\r\033[K");
    info << "frame " << k << " (" << c.name << ", " << c.triangles.size() << " triangles, power-on seed "
              << frame_seed << "): " << report.message() << "\n";
    if (!o.keep_going) break;
  }
  if (tty) std::fprintf(stderr, "\r\033[K");
  if (!junit_temp.empty()) write_text_file(junit_temp, o.junit_out, junit_xml(results, profile, o));
  // The last frame's waveform is kept whether it passed or not: it is what a divergence is debugged with.
  if (!fst_temp.empty() && passed + failed > 0) check_waveform_written(fst_temp, o.fst_out);
  if (!junit_temp.empty() || (!fst_temp.empty() && passed + failed > 0)) outputs.commit();
  info << "profile " << profile_summary(profile) << ", " << settings_summary(profile) << "; shard " << o.shard
       << ": " << directed_run << " directed and " << (passed + failed - directed_run) << " random frames of "
       << o.triangles << " triangles";
  if (!varied.empty()) {
    info << "; random frames draw";
    for (const std::string& key : varied) info << " " << key;
  }
  info << "\n" << passed << " passed, " << failed << " failed\n";
  return failed == 0 ? 0 : 1;
#endif
}

}  // namespace rastersim
