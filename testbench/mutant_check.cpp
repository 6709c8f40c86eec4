// Runs the co-simulation suites against one verilated copy of the RTL with an injected bug
// (scripts/rtl-mutants.sh builds it as Vmutant) and reports the first divergence, as `cosim` does:
// with a replay and a waveform window around the divergence. Exit 0 when the bug is caught, 1 when
// every frame still agreed with the model (the harness missed it).
// Usage: mutant_check REPLAY_DIR MAX_MEMORY_LATENCY [--cosim-only | --directed-only]
//   First the frames of `rastersim cosim --count 100` on the mutant's profile, as the command line
//   that selects its build runs them (`--texture-unit true`, `--depth-bias-slope 1`: the directed
//   and coverage frames, then 100 random ones, seed 1), then, unless --cosim-only, directed and
//   random frames at each traversal with memory latencies 2 and 4. With --directed-only, the
//   directed and coverage frames alone. On a catch it writes REPLAY_DIR/mutant_replay.{tri,json}
//   and mutant_replay.{vcd,gtkw} (frame cycles around the divergence).
// Usage: mutant_check --replay PREFIX SEED
//   Runs the frame of PREFIX.tri with the profile PREFIX.json and the power-on seed alone and prints
//   its first divergence (the replay of a catch; exit 0 when it diverges).
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "Vmutant.h"
#include "Vmutant__Syms.h"
#include "model/profile.h"
#include "testbench/cosim_cases.h"
#include "testbench/rtl_harness.h"

using namespace rastersim;
using namespace rastersim::rtl;

namespace {

bool caught(const CosimCase& c, uint64_t seed, const std::string& replay_dir, const std::string& suite) {
  RtlOptions options;
  options.seed = seed;
  options.texture = c.texture;
  const RtlResult model = run_model(c.profile, c.triangles, c.texture);
  const RtlResult rtl = detail::run_verilated<Vmutant>(c.profile, c.triangles, options);
  const Divergence d = compare(model, rtl);
  if (!d.found) return false;
  const std::string prefix = replay_dir + "/mutant_replay";
  // A .tri replay carries no texture: a textured frame is not replayed alone.
  if (!c.profile.texture_unit) write_replay(prefix, c.profile, c.triangles, seed);
  // The frame again, with a waveform window around the divergence (as `cosim` writes it).
  RtlOptions wave = options;
  std::tie(wave.wave_from, wave.wave_to) = divergence_window(d, model);
  wave.wave_path = prefix + ".vcd";
  wave.wave_vcd = true;
  wave.gtkwave_save_path = gtkwave_save_path(wave.wave_path);
  wave.wave_marker = d.cycle;
  detail::run_verilated<Vmutant>(c.profile, c.triangles, wave);
  std::printf("caught by %s in %s (traversal %s, memory_latency %d):\n%s\n", suite.c_str(), c.name.c_str(),
              to_string(c.profile.traversal), c.profile.memory_latency, d.sentence.c_str());
  if (c.profile.texture_unit) std::printf("replay: none (a textured frame)\n");
  else  // rtl-mutants.sh keeps this binary in the replay folder, so the command outlives the run
    std::printf("replay: %s/mutant_check --replay %s %llu\n", replay_dir.c_str(), prefix.c_str(), (unsigned long long)seed);
  std::printf("waveform: %s.vcd frame cycles %lld..%lld, divergence cycle %lld\n", prefix.c_str(),
              (long long)wave.wave_from, (long long)wave.wave_to, (long long)d.cycle);
  return true;
}

// The replay files write_replay() made: the profile, then one triangle per line (x y z three
// times, then nine colour values), snapped as the command line snaps them.
int replay(const std::string& prefix, uint64_t seed) {
  Profile p;
  load_profile_file(p, prefix + ".json");
  std::ifstream in(prefix + ".tri");
  std::vector<SnappedTriangle> triangles;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    ScreenTriangle t;
    int rgb[9];
    for (ScreenVertex& v : t.v) fields >> v.x >> v.y >> v.z;
    for (int& c : rgb) fields >> c;
    if (!fields) {
      std::fprintf(stderr, "%s.tri: a line this program did not write: %s\n", prefix.c_str(), line.c_str());
      return 2;
    }
    for (int k = 0; k < 3; ++k) t.v[k].color = Rgb{uint8_t(rgb[3 * k]), uint8_t(rgb[3 * k + 1]), uint8_t(rgb[3 * k + 2])};
    triangles.push_back(snap(t, p));
  }
  RtlOptions options;
  options.seed = seed;
  const Divergence d = compare(run_model(p, triangles), detail::run_verilated<Vmutant>(p, triangles, options));
  std::printf("%s\n", d.found ? d.sentence.c_str() : "model and RTL agree");
  return d.found ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 4 && std::string(argv[1]) == "--replay") return replay(argv[2], std::strtoull(argv[3], nullptr, 10));
  if (argc < 3) {
    std::fprintf(stderr, "usage: mutant_check REPLAY_DIR MAX_MEMORY_LATENCY [--cosim-only]\n"
                         "       mutant_check --replay PREFIX SEED\n");
    return 2;
  }
  const std::string replay_dir = argv[1];
  const int max_latency = std::atoi(argv[2]);
  const std::string mode = argc > 3 ? argv[3] : "";
  if (!mode.empty() && mode != "--cosim-only" && mode != "--directed-only") {
    std::fprintf(stderr, "mutant_check: unknown mode %s\n", mode.c_str());
    return 2;
  }
  using Core = detail::CoreOf<Vmutant>;
  Profile p;
  p.width = int(Core::P_WIDTH);
  p.height = int(Core::P_HEIGHT);
  p.subpixel_bits = int(Core::P_SUBPIXEL_BITS);
  p.z_bits = int(Core::P_Z_BITS);
  p.setup_interval = int(Core::P_SETUP_INTERVAL);
  p.texture_unit = int(Core::P_TEXTURE) != 0;
  p.depth_exponent_bits = int(Core::P_DEPTH_EXPONENT_BITS);
  // The keys the command line that selects this build gives (its geometry and setup too, which
  // are no runtime settings): `--depth-bias-slope 1` for the bias.
  std::set<std::string> given = {"width", "height", "setup_interval"};
  if (p.texture_unit) given.insert("texture_unit");
  if (p.depth_exponent_bits != 0) given.insert("depth_exponent_bits");
  if (int(Core::P_DEPTH_BIAS) != 0) {
    p.depth_bias_slope = 16;
    given.insert("depth_bias_slope");
  }

  // As `cosim`: frame k's power-on seed is seed + k, seed 1.
  const CosimPlan plan(p, pinned_settings(given, false), max_latency, 1, 16, true);
  const bool directed_only = mode == "--directed-only";
  const int64_t frames = plan.directed_count() + (directed_only ? 0 : 100);
  const std::string suite = directed_only ? "the directed frames of cosim" : "the frames of cosim --count 100";
  for (int64_t k = 0; k < frames; ++k)
    if (caught(plan.frame(k), 1 + uint64_t(k), replay_dir, suite + " (frame " + std::to_string(k) + ")")) return 0;
  if (!mode.empty()) {
    std::printf("NOT caught by %s\n", suite.c_str());
    return 1;
  }
  for (Traversal traversal : {Traversal::BBox, Traversal::Span}) {
    for (int latency : {2, 4}) {
      p.traversal = traversal;
      p.memory_latency = latency;
      p.setup_fifo_depth = latency == 2 ? 1 : 4;  // one record at a time, and a FIFO that fills
      std::vector<CosimCase> cases = directed_cases(p);
      for (uint64_t seed = 1; seed <= 3; ++seed) cases.push_back(random_case(p, seed, 40));
      for (const CosimCase& c : cases)
        if (caught(c, 1, replay_dir, "the mutant suites")) return 0;
    }
  }
  std::printf("NOT caught: every frame agreed with the model\n");
  return 1;
}
