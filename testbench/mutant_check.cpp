// Runs the co-simulation suites against one verilated copy of the RTL with an injected bug
// (scripts/rtl-mutants.sh builds it as Vmutant) and reports the first divergence. Exit 0 when the
// bug is caught, 1 when every frame still agreed with the model (the harness missed it).
#include <cstdio>
#include <string>

#include "Vmutant.h"
#include "Vmutant__Syms.h"
#include "testbench/cosim_cases.h"
#include "testbench/rtl_harness.h"

using namespace rastersim;
using namespace rastersim::rtl;

int main(int argc, char** argv) {
  const std::string replay_dir = argc > 1 ? argv[1] : "/tmp";
  using Core = detail::CoreOf<Vmutant>;
  Profile p;
  p.width = int(Core::P_WIDTH);
  p.height = int(Core::P_HEIGHT);
  p.subpixel_bits = int(Core::P_SUBPIXEL_BITS);
  p.z_bits = int(Core::P_Z_BITS);
  p.setup_interval = int(Core::P_SETUP_INTERVAL);
  for (Traversal traversal : {Traversal::BBox, Traversal::Span}) {
    for (int latency : {2, 4}) {
      p.traversal = traversal;
      p.memory_latency = latency;
      p.setup_fifo_depth = latency == 2 ? 1 : 4;  // one record at a time, and a FIFO that fills
      std::vector<CosimCase> cases = directed_cases(p);
      for (uint64_t seed = 1; seed <= 3; ++seed) cases.push_back(random_case(p, seed, 40));
      for (const CosimCase& c : cases) {
        const RtlResult model = run_model(p, c.triangles);
        const RtlResult rtl = detail::run_verilated<Vmutant>(p, c.triangles, RtlOptions{});
        const Divergence d = compare(model, rtl);
        if (d.found) {
          const std::string command = write_replay(replay_dir + "/mutant_replay", p, c.triangles);
          std::printf("caught in %s (traversal %s, memory_latency %d): %s\nreplay: %s\n", c.name.c_str(),
                      to_string(traversal), latency, d.sentence.c_str(), command.c_str());
          return 0;
        }
      }
    }
  }
  std::printf("NOT caught: every frame agreed with the model\n");
  return 1;
}
