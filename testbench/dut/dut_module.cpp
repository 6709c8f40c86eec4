// A design verilated on demand (CMakeLists.txt beside): its verilated top (class Vrastersim_dut)
// driven by dut_harness.h, or by unit_dut_harness.h when it is built for one unit
// (RASTERSIM_DUT_UNIT_SETUP, _WALKER or _ZBUFFER), exported with the ABI stamp of the program's records.
#include "Vrastersim_dut.h"
#include "testbench/modules.h"

#if defined(RASTERSIM_DUT_UNIT_SETUP) || defined(RASTERSIM_DUT_UNIT_WALKER) || defined(RASTERSIM_DUT_UNIT_ZBUFFER)
#include "model/widths.h"
#include "testbench/dut/unit_dut_harness.h"
#include "testbench/setup_record.h"

extern "C" __attribute__((visibility("default"))) bool rastersim_unit_run(const rastersim::dut::UnitFrame& frame,
                                                                          const rastersim::dut::DutRunOptions& options,
                                                                          rastersim::dut::UnitResult& out,
                                                                          std::string& error) {
  using namespace rastersim;
  try {
#if defined(RASTERSIM_DUT_UNIT_SETUP)
    out = dut::run_setup<Vrastersim_dut>(frame, options);
#elif defined(RASTERSIM_DUT_UNIT_WALKER)
    // Each record's auxiliary word: rastersim's packed record (setup_record.h).
    const rtl::RecordLayout layout(derive_widths(frame.profile), true);
    std::vector<std::vector<uint32_t>> aux;
    for (const SetupResult& r : frame.records) aux.push_back(layout.pack(r));
    out = dut::run_walker<Vrastersim_dut>(frame, aux, options);
#else
    out = dut::run_zbuffer<Vrastersim_dut>(frame, options);
#endif
    return true;
  } catch (const std::exception& e) {
    error = e.what();
    return false;
  }
}

extern "C" __attribute__((visibility("default"))) const char* rastersim_unit_name() {
#if defined(RASTERSIM_DUT_UNIT_SETUP)
  return "setup";
#elif defined(RASTERSIM_DUT_UNIT_WALKER)
  return "walker";
#else
  return "zbuffer";
#endif
}
#else
#include "testbench/dut/dut_harness.h"

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

extern "C" __attribute__((visibility("default"))) bool rastersim_dut_memory_port() {
  return rastersim::dut::HasMemoryPort<Vrastersim_dut>::value;
}
#endif

extern "C" __attribute__((visibility("default"))) const char* rastersim_module_abi() {
  static const std::string stamp = rastersim::modules::abi_stamp();
  return stamp.c_str();
}
