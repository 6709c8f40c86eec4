#include "cosim_command.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <iostream>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>

#include "model/input_error.h"
#include "model/text_file.h"
#include "outputs.h"
#include "parallel.h"
#ifdef RASTERSIM_HAVE_RTL
#include "backend.h"
#include "testbench/cosim_cases.h"
#include "testbench/cosim_coverage.h"
#include "testbench/dut_backend.h"
#include "testbench/functional_compare.h"
#include "testbench/rtl_backend.h"
#include "testbench/unit_compare.h"
#include "testbench/waveform.h"
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
  if (p.depth_exponent_bits >= 2) s << " Ne=" << p.depth_exponent_bits;
  if (const std::string conventions = conventions_text(p); !conventions.empty()) s << " (" << conventions << ")";
  return s.str();
}

[[maybe_unused]] std::string settings_summary(const Profile& p) {
  std::ostringstream s;
  s << to_string(p.traversal) << ", " << to_string(p.shading) << ", depth " << to_string(p.depth_func)
    << (p.depth_write ? "" : " no-write") << ", clear " << p.depth_clear_value() << ", cull " << to_string(p.cull)
    << " " << to_string(p.front_face) << ", latency " << p.memory_latency << ", setup FIFO " << p.setup_fifo_depth;
  return s.str();
}

// One <testsuite> of the frames this shard ran: any JUnit consumer merges shards by concatenation.
[[maybe_unused]] std::string junit_xml(const std::vector<FrameResult>& frames, const Profile& profile, const CosimOptions& o) {
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

#ifdef RASTERSIM_HAVE_RTL
// The coverage table: a line per bin with its hits in total and the frames that hit it.
void print_coverage(std::ostream& out, const std::vector<rtl::CoverageBin>& bins, const rtl::CoverageCounts& hits,
                    const rtl::CoverageCounts& frames) {
  out << "functional coverage (hits, frames):\n";
  for (size_t b = 0; b < bins.size(); ++b) {
    char line[160];
    if (bins[b].reachable)
      std::snprintf(line, sizeof line, "  %-32s %12lld %7lld%s", bins[b].name.c_str(), (long long)hits[b],
                    (long long)frames[b], hits[b] == 0 ? "  NOT HIT" : "");
    else
      std::snprintf(line, sizeof line, "  %-32s %12s %7s  unreachable: ", bins[b].name.c_str(), "-", "-");
    out << line << (bins[b].reachable ? "" : bins[b].unreachable) << "\n";
  }
}

nlohmann::ordered_json coverage_json(const std::vector<rtl::CoverageBin>& bins, const rtl::CoverageCounts& hits,
                                     const rtl::CoverageCounts& frames,
                                     const std::vector<std::pair<int64_t, rtl::CoverageCounts>>& per_frame,
                                     const std::vector<std::string>& holes, bool gated) {
  nlohmann::ordered_json j;
  j["gated"] = gated;
  j["holes"] = holes;
  j["bins"] = nlohmann::ordered_json::array();
  for (size_t b = 0; b < bins.size(); ++b) {
    nlohmann::ordered_json bin = {{"name", bins[b].name},       {"description", bins[b].description},
                                  {"reachable", bins[b].reachable}, {"hits", hits[b]},
                                  {"frames", frames[b]}};
    if (!bins[b].reachable) bin["unreachable"] = bins[b].unreachable;
    j["bins"].push_back(bin);
  }
  // Per frame, only the bins it hit.
  j["frames"] = nlohmann::ordered_json::array();
  for (const auto& [k, counts] : per_frame) {
    nlohmann::ordered_json f = {{"frame", k}, {"hits", nlohmann::ordered_json::object()}};
    for (size_t b = 0; b < bins.size(); ++b)
      if (counts[b] > 0) f["hits"][bins[b].name] = counts[b];
    j["frames"].push_back(f);
  }
  return j;
}
#endif

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
      ->type_name("S")
      ->check(unsigned_64_text);
  cmd->add_option("--compare", o.compare,
                  "what must agree: cycle (every event at the model's cycle; the default for rastersim's RTL), stream "
                  "(decisions and fragments in order, any timing; the default with --dut), triangle (triangles in "
                  "order, each one's fragments as a set) or frame (the final buffers); docs/verification.md")
      ->type_name("MODE");
  cmd->add_option("--dut", o.dut,
                  "check a design of your own behind the verification interface instead of rastersim's RTL: a .f "
                  "file list or a folder of .sv/.v files, verilated on demand into the module cache "
                  "(docs/verification.md)")
      ->type_name("LIST|DIR");
  cmd->add_option("--unit", o.unit,
                  "with --dut: the design is one unit behind that unit's interface, checked against the model's "
                  "twin: setup (triangles in, decisions and setup records out), walker (setup records in, fragments "
                  "out) or zbuffer (fragments in, depth-test results and the final buffers out); docs/verification.md")
      ->check([](const std::string& v) {
        return v.empty() ? std::string("an empty name is not setup, walker or zbuffer") : std::string();
      })
      ->type_name("UNIT");
  cmd->add_option("--top", o.top, "with --dut: the design's top module")->type_name("NAME");
  cmd->add_option("-G", o.generics,
                  "with --dut: a parameter of the top, NAME=value (repeatable; WIDTH, HEIGHT, SUBPIXEL_BITS and "
                  "Z_BITS come from the profile)")
      ->type_name("NAME=value");
  cmd->add_option("--tolerance", o.tolerance,
                  "depth=N,color=M: functional modes accept a fragment's depth and colour (and the buffer words) "
                  "within N and M LSBs of the model's; coverage stays exact")
      ->type_name("LIST");
  cmd->add_option("--triangles", o.triangles, "triangles per random frame (default " + std::to_string(o.triangles) + ")")
      ->type_name("K");
  cmd->add_flag_callback("--no-directed", [&o] { o.directed = false; }, "skip the directed frames");
  cmd->add_flag("--fixed-settings", o.fixed_settings,
                "random frames keep the profile's runtime settings (by default each frame draws depth_func, "
                "depth_write, depth_clear, cull, front_face, traversal, shading, memory_latency and setup_fifo_depth, except the keys "
                "set by a flag or the profile file; with the texture unit also its latency and stall pattern, and with the "
                "depth bias its constant and slope factor, given or not)");
  cmd->add_option("--shard", o.shard, "run only frames k with k mod N = K - 1 (1 <= K <= N); the union of shards 1/N .. N/N is the whole run")
      ->type_name("K/N");
  cmd->add_option("--junit", o.junit_out, "write the frames' results as JUnit XML")->type_name("FILE");
  cmd->add_flag("--keep-going", o.keep_going, "run every frame even after a divergence");
  cmd->add_option("--replay-dir", o.replay_dir,
                  "folder for the replay files of a divergence (default the working folder)")->type_name("DIR");
  cmd->add_option("--coverage", o.coverage_out,
                  "write the functional coverage (bins, reachability, hits in total and per frame) as JSON")
      ->type_name("FILE");
  cmd->add_flag_callback("--no-coverage-gate", [&o] { o.coverage_gate = false; },
                         "exit 0 even when a reachable coverage bin stays at zero (a whole run exits 1 by default)");
  cmd->add_option("--jobs", o.jobs,
                  "frames run in parallel, each on its own model and RTL (the report is the same as with 1; default 1)")
      ->type_name("N");
  cmd->add_option("--threads", o.threads,
                  "threads per frame: 2 runs the frame's model (the expected trace) on a thread of its own while the "
                  "RTL or the design runs (the report is the same as with 1; default 1; with --jobs J, J x 2 threads)")
      ->type_name("N");
  cmd->add_option("--frame", o.frame, "run only frame K (as numbered in reports: the directed frames from 0, then the random ones)")
      ->check([](const std::string& v) {
        return unsigned_64_text(v).empty() ? std::string() : "'" + v + "' is not a frame number (0 or more)";
      })
      ->type_name("K");
  cmd->add_option("--export", o.export_dir,
                  "write the frames (all, a shard's, or --frame K) as replay files into DIR instead of running them: "
                  "frame-K.tri, frame-K.json (its profile) and frame-K.txt (its power-on seed and replay command)")
      ->type_name("DIR");
  add_wave_options(*cmd, o.wave, "the last frame run: ");
  add_profile_options(*cmd, o.profile);
  return cmd;
}

#ifdef RASTERSIM_HAVE_RTL
namespace {

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// In a functional mode the coverage JSON also holds the differences' histograms: "compare" with the
// mode and, per attribute, each difference (design - model) and how often it occurred.
nlohmann::ordered_json with_distributions(nlohmann::ordered_json j, verify::CompareMode mode,
                                          const verify::ErrorDistribution& depth,
                                          const verify::ErrorDistribution& color) {
  if (mode == verify::CompareMode::Cycle) return j;
  nlohmann::ordered_json compare;
  compare["mode"] = verify::to_string(mode);
  for (const auto& [name, d] : {std::pair<const char*, const verify::ErrorDistribution*>{"depth_error", &depth},
                                {"color_error", &color}}) {
    nlohmann::ordered_json histogram = nlohmann::ordered_json::object();
    for (const auto& [error, count] : d->counts) histogram[std::to_string(error)] = count;
    compare[name] = histogram;
  }
  j["compare"] = compare;
  return j;
}

// A failing frame's waveform: this many cycles either side of the mismatch.
constexpr int64_t kWaveAround = 32;

// A failing frame's replay waveform at <prefix>.fst: `rerun` runs the frame again with the options
// given and returns the cycle its numbering starts from (a design's first handshake, a unit's 0);
// with `at` >= 0 the FST holds the cycles around `at` and <prefix>.fst.gtkw marks it, else (a stall) the
// frame up to the stall. `who` names the cycle in the message ("design", "unit").
void add_failure_waveform(std::string& message, const std::string& prefix, int64_t at, const char* who,
                          const std::string& replay, const std::function<int64_t(const dut::DutRunOptions&)>& rerun) {
  if (!prefix.empty() && at >= 0)
    message += std::string("; the ") + who + "'s cycle " + std::to_string(at) + ", marked in " + rtl::gtkwave_save_path(prefix + ".fst");
  message += "; replay: " + replay;
  if (prefix.empty()) return;
  dut::DutRunOptions wave;
  wave.wave_path = prefix + ".fst";
  wave.wave_window = at >= 0;
  wave.wave_from = at - kWaveAround, wave.wave_to = at + kWaveAround;
  int64_t origin = 0;
  try {
    origin = rerun(wave);
  } catch (const std::runtime_error&) {  // the stall is reported already; the waveform ends at it
  }
  message += "; waveform: " + wave.wave_path;
  if (at >= 0) {
    const int64_t edge = 2 * (origin + at) + 9;  // the mismatch cycle's rising edge, after reset's 8 half cycles
    rtl::WaveView view;
    view.start = edge - 2 * kWaveAround - 1, view.end = edge + 2 * kWaveAround;
    view.primary_marker = edge;
    view.markers = {{"window_start", view.start}, {"mismatch", edge}, {"window_end", view.end}};
    rtl::write_design_gtkwave_save(wave.wave_path, wave.wave_path, rtl::gtkwave_save_path(wave.wave_path), view);
  }
}

// One frame of a user's design: the model's run, the design's, their comparison by mode. On a
// mismatch with a replay prefix, the frame again with a waveform at <prefix>.fst.
struct DesignFrame {
  rtl::RtlResult model;
  verify::FunctionalReport report;
  int64_t design_cycles = 0;  // the design's frame, from its first handshake (0 when it stalled)
  bool passed = false;
  std::string message;
};
// With `waveform.wave_path`, the frame's waveform (--wave: FST or VCD, its window in cycles from the
// first handshake) and its GTKWave save file.
DesignFrame design_frame(const dut::Design& design, const rtl::CosimCase& c, const std::string& prefix,
                         verify::CompareMode mode, const verify::Tolerance& tolerance, const std::string& replay,
                         const rtl::RtlOptions& waveform) {
  DesignFrame d;
  // With waveform.model_beside the model runs while the design does (std::async's future joins on
  // every path out).
  std::future<rtl::RtlResult> model;
  if (waveform.model_beside)
    model = std::async(std::launch::async, [&] { return rtl::run_model(c.profile, c.triangles, c.texture); });
  else
    d.model = rtl::run_model(c.profile, c.triangles, c.texture);
  dut::DutRunOptions run_options;
  const std::string fst_path = waveform.wave_vcd ? waveform.wave_fst_scratch : waveform.wave_path;
  if (!waveform.wave_path.empty()) {
    run_options.wave_path = fst_path;
    run_options.wave_window = waveform.wave_from >= 0 || waveform.wave_to >= 0;
    run_options.wave_from = std::max<int64_t>(0, waveform.wave_from);
    run_options.wave_to = waveform.wave_to >= 0 ? waveform.wave_to : std::numeric_limits<int64_t>::max();
  }
  int64_t at = -1;  // the mismatch's cycle in the design, -1 for a stall
  int64_t wave_start = 0;
  try {
    const rtl::RtlResult result = design.run(c.profile, c.triangles, run_options);
    if (model.valid()) d.model = model.get();
    d.design_cycles = result.stats.cycles;
    // FST times: reset's 4 cycles, then cycle k's rising edge at 2 (first handshake + k) + 9.
    wave_start = run_options.wave_window ? 2 * (result.first_handshake + run_options.wave_from) + 8 : 0;
    d.report = verify::compare(c.profile, d.model, result, mode, tolerance);
    d.passed = d.report.passed();
    d.message = d.passed ? "" : d.report.summary();
    if (!d.passed) at = verify::design_cycle(d.report.mismatches.front(), result);
  } catch (const std::runtime_error& e) {
    d.message = e.what();
  }
  if (model.valid()) d.model = model.get();  // a design that stalled or failed: the coverage still needs it
  if (!waveform.wave_path.empty()) {  // a stalled frame's waveform ends at the stall
    rtl::WaveView view;
    view.start = wave_start;
    if (run_options.wave_window) view.markers = {{"window_start", wave_start}};
    rtl::write_design_gtkwave_save(fst_path, waveform.wave_name, waveform.gtkwave_save_path, view);
    if (waveform.wave_vcd) rtl::fst_to_vcd(fst_path, waveform.wave_path);
  }
  if (d.passed) return d;
  add_failure_waveform(d.message, prefix, at, "design", replay, [&](const dut::DutRunOptions& wave) {
    return design.run(c.profile, c.triangles, wave).first_handshake;
  });
  return d;
}

// One frame of a unit: the model's run, the unit's inputs from it, the unit's run, their comparison.
DesignFrame unit_design_frame(const dut::Design& design, dut::Unit unit, const rtl::CosimCase& c, uint64_t seed,
                              const std::string& prefix, verify::CompareMode mode, const verify::Tolerance& tolerance,
                              const std::string& replay) {
  DesignFrame d;
  d.model = rtl::run_model(c.profile, c.triangles, c.texture);
  const dut::UnitFrame frame = verify::unit_frame(unit, c.profile, c.triangles, d.model, seed);
  int64_t at = -1;  // the mismatch's cycle in the unit, -1 for a stall
  try {
    const dut::UnitResult result = design.run_unit(frame);
    d.report = verify::compare_unit(frame, d.model, result, mode, tolerance);
    d.passed = d.report.passed();
    d.message = d.passed ? "" : d.report.summary();
    if (!d.passed) at = verify::unit_design_cycle(d.report.mismatches.front(), frame, result);
  } catch (const std::runtime_error& e) {
    d.message = e.what();
  }
  if (d.passed) return d;
  add_failure_waveform(d.message, prefix, at, "unit", replay, [&](const dut::DutRunOptions& wave) {
    design.run_unit(frame, wave);
    return int64_t(0);  // a unit's cycles count from the first after reset
  });
  return d;
}

}  // namespace
#endif

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
  const bool with_dut = !o.dut.empty();
  const std::string compare = !o.compare.empty() ? o.compare : with_dut ? "stream" : "cycle";
  const std::optional<verify::CompareMode> mode = verify::parse_compare_mode(compare);
  if (!mode) throw InputError("--compare '" + o.compare + "' is not cycle, stream, triangle or frame");
  if (with_dut == o.top.empty()) throw InputError(with_dut ? "--dut needs --top NAME" : "--top and -G go with --dut");
  std::optional<dut::Unit> unit;
  if (!o.unit.empty()) {
    if (!with_dut) throw InputError("--unit checks a unit of your own: it goes with --dut LIST|DIR --top NAME");
    unit = dut::parse_unit(o.unit);
    if (!unit) throw InputError("--unit '" + o.unit + "' is not setup, walker or zbuffer");
    if (const std::string error = verify::unit_mode_error(*unit, *mode); !error.empty()) throw InputError(error);
    if (*unit != dut::Unit::Walker && !o.tolerance.empty())
      throw InputError("--tolerance applies to the walker's fragments; --unit " + o.unit + " compares every bit");
  }
  if (!with_dut && !o.generics.empty()) throw InputError("--top and -G go with --dut");
  verify::Tolerance tolerance;
  if (const std::string error = verify::parse_tolerance(o.tolerance, tolerance); !error.empty()) throw InputError(error);
  if (*mode == verify::CompareMode::Cycle && !o.tolerance.empty())
    throw InputError("--tolerance applies to --compare stream, triangle or frame; cycle compares every bit");
  // A folder that must exist: "is not a folder" when the name is a file.
  const auto require_folder = [](const std::string& option, const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return;
    throw InputError(option + ": '" + path + "' " +
                     (std::filesystem::exists(std::filesystem::symlink_status(path, ec)) ? "is not a folder" : "does not exist"));
  };
  require_folder("--replay-dir", o.replay_dir);
  if (!o.export_dir.empty()) require_folder("--export", o.export_dir);
  if (o.frame < -1) throw InputError("--frame " + std::to_string(o.frame) + " is not a frame number (0 or more)");
  if (o.frame >= 0 && shard.count > 1) throw InputError("--frame and --shard choose frames both: give one");
  if (!o.export_dir.empty() && (!o.junit_out.empty() || !o.wave.path.empty() || !o.coverage_out.empty()))
    throw InputError("--export writes the frames without running them: --junit, --wave and --coverage need a run");
  if (!o.export_dir.empty() && profile.texture_unit)
    throw InputError("--export writes .tri replays, which carry no texture: with the texture unit, rerun a frame "
                     "with --frame");
  if (o.jobs < 1 || o.jobs > 256) throw InputError("--jobs " + std::to_string(o.jobs) + " is outside 1..256");
  // The traced model is one walk in order (every fragment, record and cycle), so a frame's model
  // side is one thread: a second thread runs it beside the RTL, and more would have nothing to do.
  if (o.threads < 1 || o.threads > 2)
    throw InputError("--threads " + std::to_string(o.threads) +
                     " is outside 1..2: a frame's model side is one traced run, beside the RTL's with 2");
  if (unit && !o.wave.path.empty())
    throw InputError("--wave with --unit: a failing frame's waveform goes to --replay-dir");
  modules::DutDesign files;
  if (with_dut) {
    if (const std::string problem = dut::interface_error(profile); !problem.empty()) throw InputError(problem);
    files = dut::read_design(o.dut, o.top);
  }
  // Every output is checked before anything is built: none may be an input (the profile, the
  // design's file list or one of its sources).
  OutputFiles outputs;
  outputs.protect(o.profile.profile_file);
  if (with_dut && std::filesystem::is_regular_file(o.dut)) outputs.protect(o.dut);
  for (const std::string& source : files.files) outputs.protect(source);
  const std::string junit_temp = o.junit_out.empty() ? "" : outputs.add(o.junit_out, "--junit");
  const WaveFiles wave = add_waveform(outputs, o.wave);
  const std::string coverage_temp = o.coverage_out.empty() ? "" : outputs.add(o.coverage_out, "--coverage");

  std::unique_ptr<dut::Design> design;
  if (with_dut) {
    files.parameters = unit ? dut::unit_parameters(*unit, profile, o.generics) : dut::design_parameters(profile, o.generics);
    files.unit = unit ? dut::to_string(*unit) : "";
    design = std::make_unique<dut::Design>(design_library(files), unit);
    if (!unit && !design->has_memory_port() && profile.memory_stall_percent > 0)
      throw InputError("memory_stall_percent " + std::to_string(profile.memory_stall_percent) + ": " + o.top +
                       " keeps its buffers (it has the read-back port, not the memory port), so no memory refuses "
                       "its reads; give 0, or a design with the memory port (docs/verification.md)");
  } else {
    ensure_rtl_configuration(profile);  // verilated on demand when the build lacks it
    const std::string problem = rtl::configuration_error(profile);
    if (!problem.empty()) throw InputError(problem);
  }
  std::set<std::string> pinned = rtl::pinned_settings(given_profile_keys(o.profile), o.fixed_settings);
  // A design is told only the settings on the interface's cfg_* ports; the others are the model's
  // micro-architecture, which cycle mode needs equal to the design's.
  if (with_dut) pinned.insert({"traversal", "memory_latency", "setup_fifo_depth"});
  const int max_latency = with_dut ? kMaxMemoryLatency : rtl::built_max_memory_latency(profile);
  const rtl::CosimPlan plan(profile, pinned, max_latency, o.seed, o.triangles, o.directed);
  const std::vector<std::string>& varied = plan.varied();
  const std::vector<rtl::CoverageBin> bins = rtl::coverage_bins(profile, pinned, max_latency);
  rtl::CoverageCounts total_hits(bins.size(), 0), frames_hit(bins.size(), 0);
  std::vector<std::pair<int64_t, rtl::CoverageCounts>> frame_hits;

  const int64_t directed = plan.directed_count();
  const bool tty = isatty(STDERR_FILENO) != 0;
  const int64_t total = directed + o.count;
  if (o.frame >= total)
    throw InputError("--frame " + std::to_string(o.frame) + ": this run has frames 0.." + std::to_string(total - 1) +
                     " (" + std::to_string(directed) + " directed, then --count " + std::to_string(o.count) + " random)");
  // The frames this invocation takes: one, a shard's, or all.
  const int64_t first = o.frame >= 0 ? o.frame : shard.index, step = o.frame >= 0 ? total : shard.count;
  const int64_t in_shard = o.frame >= 0 ? 1 : total / shard.count + (shard.index < total % shard.count ? 1 : 0);
  if (!o.export_dir.empty()) {
    for (int64_t k = first; k < total; k += step)
      for (const char* extension : {".tri", ".json", ".txt"})
        outputs.refuse_input((std::filesystem::path(o.export_dir) / ("frame-" + std::to_string(k) + extension)).string(),
                             "--export");
    for (int64_t k = first; k < total; k += step) {
      const rtl::CosimCase c = plan.frame(k);
      const std::string prefix = (std::filesystem::path(o.export_dir) / ("frame-" + std::to_string(k))).string();
      const std::string command = rtl::write_replay(prefix, c.profile, c.triangles, o.seed + uint64_t(k));
      std::ofstream seeds(prefix + ".txt", std::ios::binary);
      seeds << "frame " << k << ": " << c.name << "\npower-on seed " << o.seed + uint64_t(k) << "\nreplay: " << command
            << "\n";
      if (!seeds.flush()) throw std::runtime_error("cannot write " + prefix + ".txt");
      std::cout << "frame " << k << ": " << command << "\n";
    }
    return 0;
  }
  std::vector<FrameResult> results;
  int64_t passed = 0, failed = 0, directed_run = 0;
  // With the JUnit XML or the coverage on standard output, the report goes to standard error.
  std::ostream& info = outputs.writes_stdout() ? std::cerr : std::cout;

  // One frame through the model and the RTL; `outputs`: with the waveform and, on a divergence,
  // the replay files and the waveform window.
  struct Outcome {
    int64_t k = 0;
    std::string name;
    size_t triangles = 0;
    double seconds = 0;
    bool passed = true;
    std::string message;
    rtl::CoverageCounts hits;
    int64_t cycles = 0;
    verify::ErrorDistribution depth_error, color_error;  // functional modes
  };
  // A design's frame is replayed by this command with --frame K.
  std::string replay_command;
  if (design) {
    const auto quoted = [](const std::string& word) {
      return word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=.,/:") ==
                     std::string::npos
                 ? word
                 : "'" + replace_all(word, "'", "'\\''") + "'";
    };
    replay_command = "rastersim cosim " + (unit ? "--unit " + o.unit + " " : std::string()) + "--dut " +
                     quoted(std::filesystem::absolute(o.dut).string()) + " --top " + o.top;
    for (const std::string& g : o.generics) replay_command += " -G " + quoted(g);
    replay_command += " --compare " + compare;
    if (!o.tolerance.empty()) replay_command += " --tolerance " + quoted(o.tolerance);
    for (const ProfileKey& row : profile_table())
      if (given_profile_keys(o.profile).count(row.key)) {
        std::string flag = row.key;
        std::replace(flag.begin(), flag.end(), '_', '-');
        replay_command += " --" + flag + " " + quoted(key_value_text(row, row.get(profile)));
      }
    replay_command += " --seed " + std::to_string(o.seed) + " --triangles " + std::to_string(o.triangles) +
                      " --count " + std::to_string(o.count) + (o.directed ? "" : " --no-directed") +
                      (o.fixed_settings ? " --fixed-settings" : "");
  }
  auto run_frame = [&](int64_t k, bool with_outputs) {
    rtl::CosimCase c = plan.frame(k);
    if (!varied.empty() || k < directed) c.name += " (" + settings_summary(c.profile) + ")";
    rtl::RtlOptions options;
    options.seed = o.seed + uint64_t(k);
    options.texture = c.texture;
    options.model_beside = o.threads > 1;
    if (with_outputs) set_wave_fields(options, wave, o.wave);
    const std::string prefix =
        with_outputs ? (std::filesystem::path(o.replay_dir) / ("rastersim-replay-" + std::to_string(k))).string() : "";
    const auto start = std::chrono::steady_clock::now();
    Outcome out;
    if (design) {
      const std::string replay = replay_command + " --frame " + std::to_string(k);
      DesignFrame d = unit ? unit_design_frame(*design, *unit, c, options.seed, with_outputs ? prefix : "", *mode,
                                               tolerance, replay)
                           : design_frame(*design, c, with_outputs ? prefix : "", *mode, tolerance, replay, options);
      out.k = k;
      out.name = c.name;
      out.triangles = c.triangles.size();
      out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      out.passed = d.passed;
      out.message = d.message;
      out.depth_error = d.report.depth_error;
      out.color_error = d.report.color_error;
      out.hits = rtl::frame_coverage(c.profile, c.triangles, d.model, max_latency, c.texture);
      out.cycles = unit ? d.model.stats.cycles : d.design_cycles;  // --wave's window is in the design's cycles
      return out;
    }
    const rtl::CosimReport report = rtl::cosim(c.profile, c.triangles, options, prefix);
    out.k = k;
    out.name = c.name;
    out.triangles = c.triangles.size();
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.passed = report.passed;
    out.message = report.passed ? "" : report.message();
    if (*mode != verify::CompareMode::Cycle) {
      // A functional mode: what the mode does not compare (cycles, order) may differ.
      const verify::FunctionalReport functional = verify::compare(c.profile, report.model, report.rtl, *mode, tolerance);
      out.passed = functional.passed() && report.rtl.finished;
      out.message = !report.rtl.finished ? report.rtl.note
                    : out.passed         ? ""
                                         : functional.summary() + (report.message().empty() || report.passed ? "" : "; " + report.message());
      out.depth_error = functional.depth_error;
      out.color_error = functional.color_error;
    }
    // What a frame's stimulus reached, from the model's run of it.
    out.hits = rtl::frame_coverage(c.profile, c.triangles, report.model, max_latency, c.texture);
    out.cycles = report.model.stats.cycles;
    return out;
  };
  std::vector<int64_t> frames;
  for (int64_t k = first; k < total; k += step) frames.push_back(k);
  std::vector<Outcome> outcomes(frames.size());
  std::mutex progress_mutex;
  int64_t done = 0, failures = 0;
  auto progress = [&](const std::string& name) {
    if (!tty) return;
    std::lock_guard<std::mutex> lock(progress_mutex);
    std::fprintf(stderr, "\rcosim: %lld / %lld frames, %lld failed (%s)\033[K", (long long)done, (long long)in_shard,
                 (long long)failures, name.c_str());
  };
  size_t kept = frames.size();  // outcomes[0, kept) are the frames the run reports
  if (o.jobs == 1) {
    for (size_t i = 0; i < frames.size(); ++i) {
      progress("frame " + std::to_string(frames[i]));
      outcomes[i] = run_frame(frames[i], true);
      ++done;
      if (!outcomes[i].passed) {
        ++failures;
        if (!o.keep_going) {
          kept = i + 1;
          break;
        }
      }
    }
  } else {
    // Frames in parallel, each on its own verilated model; the report is the same as one job's:
    // frames in order, and without --keep-going none after the first divergence.
    std::atomic<size_t> first_failure{frames.size()};
    parallel_for(
        o.jobs, frames.size(),
        [&](size_t i) {
          outcomes[i] = run_frame(frames[i], false);
          {
            std::lock_guard<std::mutex> lock(progress_mutex);
            ++done;
            if (!outcomes[i].passed) {
              ++failures;
              if (!o.keep_going && i < first_failure) first_failure = i;
            }
          }
          progress(outcomes[i].name);
        },
        [&] { return first_failure.load(); });
    if (!o.keep_going && first_failure < frames.size()) kept = first_failure + 1;
    // The files a frame leaves, as one job leaves them: a divergence's replay and waveform window,
    // and the last frame's waveform.
    for (size_t i = 0; i < kept; ++i)
      if (!outcomes[i].passed || (i + 1 == kept && !wave.wave_temp.empty())) outcomes[i] = run_frame(frames[i], true);
  }
  int64_t last_cycles = 0;
  verify::ErrorDistribution depth_error, color_error;
  for (size_t i = 0; i < kept; ++i) {
    Outcome& f = outcomes[i];
    directed_run += f.k < directed;
    for (const auto& [e, n] : f.depth_error.counts) depth_error.counts[e] += n;
    for (const auto& [e, n] : f.color_error.counts) color_error.counts[e] += n;
    results.push_back(FrameResult{f.k, f.name, f.seconds, f.passed, f.message});
    last_cycles = f.cycles;
    for (size_t b = 0; b < bins.size(); ++b) total_hits[b] += f.hits[b], frames_hit[b] += f.hits[b] > 0;
    if (!o.coverage_out.empty()) frame_hits.emplace_back(f.k, std::move(f.hits));
    if (f.passed) {
      ++passed;
      continue;
    }
    ++failed;
    if (tty) std::fprintf(stderr, "\r\033[K");
    info << "frame " << f.k << " (" << f.name << ", " << f.triangles << " triangles, power-on seed "
         << o.seed + uint64_t(f.k) << "): " << f.message << "\n";
  }
  if (tty) std::fprintf(stderr, "\r\033[K");
  const std::vector<std::string> holes = rtl::coverage_holes(bins, total_hits);
  // A shard's frames, or one frame, are a part of the run: only a whole run is held to every
  // reachable bin.
  const bool gated = o.coverage_gate && shard.count == 1 && o.frame < 0;
  if (!junit_temp.empty()) write_text_file(junit_temp, o.junit_out, junit_xml(results, profile, o));
  if (!coverage_temp.empty())
    write_text_file(coverage_temp, o.coverage_out,
                    with_distributions(coverage_json(bins, total_hits, frames_hit, frame_hits, holes, gated), *mode,
                                       depth_error, color_error)
                            .dump(2) +
                        "\n");
  // The last frame's waveform is kept whether it passed or not: it is what a divergence is debugged with.
  if (!wave.wave_temp.empty() && passed + failed > 0) check_waveform_written(wave, o.wave, last_cycles);
  if (!junit_temp.empty() || !coverage_temp.empty() || (!wave.wave_temp.empty() && passed + failed > 0)) outputs.commit();
  print_coverage(info, bins, total_hits, frames_hit);
  info << "profile " << profile_summary(profile) << ", " << settings_summary(profile) << "; shard " << o.shard
       << ": " << directed_run << " directed and " << (passed + failed - directed_run) << " random frames of "
       << o.triangles << " triangles";
  if (!varied.empty()) {
    info << "; random frames draw";
    for (const std::string& key : varied) info << " " << key;
  }
  if (profile.texture_unit)
    info << "; with the texture unit, random frames draw textured triangles, a texture, its filter and wrap mode,"
         << " texture_latency and the texture memory's stall pattern";
  if (profile.depth_biased())
    info << (o.fixed_settings ? "; with the depth bias, its constant and slope factor stay the profile's"
                              : "; with the depth bias, random frames draw its constant and slope factor, each of either "
                                "sign, given or not");
  info << "\n";
  if (!holes.empty()) {
    info << "coverage: " << holes.size() << " reachable bin" << (holes.size() == 1 ? "" : "s") << " not hit:";
    for (const std::string& h : holes) info << " " << h;
    info << (gated ? "" : o.frame >= 0 ? " (one frame: not gated)" : shard.count > 1 ? " (a shard: not gated)" : " (--no-coverage-gate)") << "\n";
  }
  if (*mode != verify::CompareMode::Cycle)
    info << "compare " << compare << ": depth error (design - model) " << depth_error.summary()
         << "; colour error per channel " << color_error.summary() << "\n";
  info << passed << " passed, " << failed << " failed\n";
  return failed == 0 && (holes.empty() || !gated) ? 0 : 1;
#endif
}

CLI::App* add_junit_merge_command(CLI::App& app, JunitMergeOptions& o) {
  CLI::App* cmd = app.add_subcommand("junit-merge", "merge the JUnit files of a sharded cosim run into one");
  cmd->add_option("-o,--output", o.out, "the merged JUnit XML")->required()->type_name("FILE");
  cmd->add_option("inputs", o.inputs, "the shards' JUnit files (cosim --junit)")->required()->type_name("IN...");
  return cmd;
}

int run_junit_merge(const JunitMergeOptions& o) {
  // A number attribute of an opening tag: name="value".
  auto attribute = [](const std::string& tag, const std::string& name, const std::string& file) {
    const std::string key = " " + name + "=\"";
    const size_t at = tag.find(key);
    if (at == std::string::npos) throw InputError(file, 0, "a <testsuite> without " + name);
    const std::string text = tag.substr(at + key.size(), tag.find('"', at + key.size()) - at - key.size());
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !(value >= 0))
      throw InputError(file, 0, "a <testsuite> whose " + name + " is '" + text + "', not a number");
    return value;
  };
  // A property of a testsuite block: <property name="NAME" value="..."/>.
  auto property = [](const std::string& block, const std::string& name, const std::string& file) {
    const std::string key = "<property name=\"" + name + "\" value=\"";
    const size_t at = block.find(key);
    if (at == std::string::npos) throw InputError(file, 0, "a <testsuite> without the property " + name);
    return block.substr(at + key.size(), block.find('"', at + key.size()) - at - key.size());
  };
  std::string suites;
  double tests = 0, failures = 0, time = 0;
  std::set<std::string> frames;
  // The run every shard must belong to (its profile, seed, count, triangles, shard count) and the
  // shards seen.
  std::string run, run_file;
  std::set<int64_t> shards;
  int64_t shard_count = 0;
  for (const std::string& file : o.inputs) {
    const std::string xml = read_text_file(file, "junit-merge", size_t(1) << 30);
    if (xml.find("<testsuite name=\"rastersim.cosim.") == std::string::npos)
      throw InputError(file, 0, "not a JUnit file of rastersim cosim (no rastersim.cosim testsuite)");
    for (size_t at = xml.find("<testsuite "); at != std::string::npos; at = xml.find("<testsuite ", at + 1)) {
      const size_t end = xml.find("</testsuite>", at);
      const size_t tag_end = xml.find('>', at);
      if (end == std::string::npos || tag_end == std::string::npos)
        throw InputError(file, 0, "a <testsuite> that does not end");
      const std::string tag = xml.substr(at, tag_end - at);
      tests += attribute(tag, "tests", file);
      failures += attribute(tag, "failures", file);
      time += attribute(tag, "time", file);
      const std::string block = xml.substr(at, end + 12 - at);
      const std::string name_key = "<testcase classname=\"rastersim.cosim\" name=\"";
      for (size_t c = block.find(name_key); c != std::string::npos; c = block.find(name_key, c + 1)) {
        const size_t begin = c + name_key.size();
        const std::string name = block.substr(begin, block.find('"', begin) - begin);
        if (!frames.insert(name).second)
          throw InputError(file, 0, "'" + name + "' is in another input too: shards of one run do not overlap");
      }
      std::string this_run;
      for (const char* name : {"profile", "seed", "count", "triangles"})
        this_run += std::string(name) + " " + property(block, name, file) + ", ";
      const std::string shard_text = property(block, "shard", file);
      const size_t slash = shard_text.find('/');
      const int64_t k = std::atoll(shard_text.substr(0, slash).c_str());
      const int64_t n = slash == std::string::npos ? 0 : std::atoll(shard_text.substr(slash + 1).c_str());
      if (k < 1 || k > n) throw InputError(file, 0, "a <testsuite> whose shard is '" + shard_text + "', not K/N");
      this_run += std::to_string(n) + " shards";
      if (run.empty()) run = this_run, run_file = file, shard_count = n;
      else if (this_run != run)
        throw InputError(file, 0, "a shard of another run (" + this_run + ") than " + run_file + "'s (" + run + ")");
      if (!shards.insert(k).second)
        throw InputError(file, 0, "shard " + shard_text + " is in another input too");
      suites += "  " + block + "\n";
    }
  }
  if (int64_t(shards.size()) != shard_count) {
    std::string missing;
    for (int64_t k = 1; k <= shard_count; ++k)
      if (!shards.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k) + "/" + std::to_string(shard_count);
    throw InputError("junit-merge: the inputs are not a whole run: shard" + std::string(shard_count - shards.size() > 1 ? "s " : " ") +
                     missing + " missing");
  }
  OutputFiles outputs;
  for (const std::string& file : o.inputs) outputs.protect(file);  // -o naming an input is refused
  const std::string temp = outputs.add(o.out, "--output");
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites tests=\"" << int64_t(tests) << "\" failures=\""
    << int64_t(failures) << "\" time=\"" << time << "\">\n"
    << suites << "</testsuites>\n";
  write_text_file(temp, o.out, x.str());
  outputs.commit();
  std::ostream& info = outputs.writes_stdout() ? std::cerr : std::cout;
  info << "merged " << o.inputs.size() << " files: " << int64_t(tests) << " frames, " << int64_t(failures)
       << " failed\n";
  return failures == 0 ? 0 : 1;
}

}  // namespace rastersim
