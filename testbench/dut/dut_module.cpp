// A design verilated on demand (CMakeLists.txt beside): its verilated top (class Vrastersim_dut)
// driven by dut_harness.h, exported with the ABI stamp of the program's records.
#include "Vrastersim_dut.h"
#include "testbench/dut/dut_harness.h"
#include "testbench/modules.h"

extern "C" __attribute__((visibility("default"))) bool rastersim_dut_run(
    const rastersim::Profile& profile, const std::vector<rastersim::SnappedTriangle>& triangles,
    const rastersim::dut::DutRunOptions& options, rastersim::rtl::RtlResult& out, std::string& error) {
  try {
    out = rastersim::dut::run<Vrastersim_dut>(profile, triangles, options);
    return true;
  } catch (const std::exception& e) {
    error = e.what();
    return false;
  }
}

extern "C" __attribute__((visibility("default"))) const char* rastersim_module_abi() {
  static const std::string stamp = rastersim::modules::abi_stamp();
  return stamp.c_str();
}
