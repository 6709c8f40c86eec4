#include "testbench/systemc/systemc_backend.h"

#include <cstdlib>
#include <stdexcept>

#include <verilated.h>

#include "testbench/modules.h"
#include "testbench/systemc/rastersim_system.h"

namespace rastersim::systemc {
namespace {

// Built on the first frame and never destroyed: SystemC modules outlive the simulation.
RastersimSystem& system(const SystemcOptions& options) {
  static RastersimSystem* instance = nullptr;
  if (!instance) {
    // The SystemC kernel prints its banner on stdout unless told not to.
    setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
    Verilated::fatalOnError(false);  // a failed assertion ends the frame (monitor), not the program
    Verilated::randReset(2);
    Verilated::randSeed(int(options.seed % 2147483647u) + 1);
    instance = new RastersimSystem("rastersim", options.fifo_depth);
  }
  return *instance;
}

}  // namespace

Profile built_geometry() { return RastersimSystem::built_geometry(); }

std::string built_configuration() { return RastersimSystem::built_configuration(); }

std::string configuration_error(const Profile& p) { return RastersimSystem::configuration_error(p); }

std::string geometry_error(const Profile& p) { return RastersimSystem::geometry_error(p); }

rtl::RtlResult run_systemc(const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                           const SystemcOptions& options) {
  return system(options).run_frame(profile, triangles, options.max_cycles, options.texture);
}

int64_t simulated_cycles() { return system(SystemcOptions{}).simulated_cycles(); }

}  // namespace rastersim::systemc

const rastersim::systemc::Api* rastersim_systemc_api() {
  static const rastersim::systemc::Api api = {&rastersim::systemc::configuration_error,
                                              &rastersim::systemc::geometry_error, &rastersim::systemc::run_systemc};
  return &api;
}

const char* rastersim_module_abi() {
  static const std::string stamp = rastersim::modules::abi_stamp();
  return stamp.c_str();
}

// libsystemc.so calls sc_main from its own main(); rastersim has its own main and never calls it,
// but the symbol must exist for the link. Programs with their own sc_main override this one.
RASTERSIM_SYSTEMC_API int sc_main(int, char*[]) { return 1; }
