// Runs the co-simulation suites against one verilated copy of the RTL with an injected bug
// (scripts/rtl-mutants.sh builds it as Vmutant) and reports the first divergence. Exit 0 when the
// bug is caught, 1 when every frame still agreed with the model (the harness missed it).
// Usage: mutant_check REPLAY_DIR MAX_MEMORY_LATENCY [--cosim-only]
// First the frames of `rastersim cosim --count 100` on the mutant's profile (the directed and
// coverage frames, then 100 random ones, seed 1), then, unless --cosim-only, directed and random
// frames at each traversal with memory latencies 2 and 4.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "Vmutant.h"
#include "Vmutant__Syms.h"
#include "testbench/cosim_cases.h"
#include "testbench/rtl_harness.h"

using namespace rastersim;
using namespace rastersim::rtl;

namespace {

bool caught(const CosimCase& c, const std::string& replay_dir, const std::string& suite) {
  const RtlResult model = run_model(c.profile, c.triangles);
  const RtlResult rtl = detail::run_verilated<Vmutant>(c.profile, c.triangles, RtlOptions{});
  const Divergence d = compare(model, rtl);
  if (!d.found) return false;
  const std::string command = write_replay(replay_dir + "/mutant_replay", c.profile, c.triangles);
  std::printf("caught by %s in %s (traversal %s, memory_latency %d): %s\nreplay: %s\n", suite.c_str(),
              c.name.c_str(), to_string(c.profile.traversal), c.profile.memory_latency, d.sentence.c_str(),
              command.c_str());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: mutant_check REPLAY_DIR MAX_MEMORY_LATENCY [--cosim-only]\n");
    return 2;
  }
  const std::string replay_dir = argv[1];
  const int max_latency = std::atoi(argv[2]);
  const bool cosim_only = argc > 3 && std::string(argv[3]) == "--cosim-only";
  using Core = detail::CoreOf<Vmutant>;
  Profile p;
  p.width = int(Core::P_WIDTH);
  p.height = int(Core::P_HEIGHT);
  p.subpixel_bits = int(Core::P_SUBPIXEL_BITS);
  p.z_bits = int(Core::P_Z_BITS);
  p.setup_interval = int(Core::P_SETUP_INTERVAL);

  const CosimPlan plan(p, {}, max_latency, 1, 16, true);
  for (int64_t k = 0; k < plan.directed_count() + 100; ++k)
    if (caught(plan.frame(k), replay_dir, "the frames of cosim --count 100 (frame " + std::to_string(k) + ")"))
      return 0;
  if (cosim_only) {
    std::printf("NOT caught by the frames of cosim --count 100\n");
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
        if (caught(c, replay_dir, "the mutant suites")) return 0;
    }
  }
  std::printf("NOT caught: every frame agreed with the model\n");
  return 1;
}
