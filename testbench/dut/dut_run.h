// What a design verilated on demand behind the verification interface (testbench/dut/) exports,
// and what the program asks of it: one frame, its records back (docs/verification.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/pipeline.h"
#include "model/profile.h"
#include "model/triangle.h"
#include "testbench/dut/unit_records.h"
#include "testbench/rtl_backend.h"

namespace rastersim::dut {

struct DutRunOptions {
  // Cycles with no handshake, decision or retired fragment before the design is called stalled.
  int64_t max_idle_cycles = 200000;
  std::string wave_path;  // an FST of the frame when not empty
  // With wave_window, the FST holds only the cycles wave_from..wave_to (from the first handshake).
  bool wave_window = false;
  int64_t wave_from = 0, wave_to = 0;
};

// The library's entry point (extern "C", RASTERSIM_DUT_RUN_SYMBOL): runs one frame into `out`;
// returns false with `error` set when the design broke the interface or stalled.
using RunFunction = bool (*)(const Profile& profile, const std::vector<SnappedTriangle>& triangles,
                             const DutRunOptions& options, rtl::RtlResult& out, std::string& error);

// A library built for one unit (--unit) exports this instead: the unit's frame into `out`.
using UnitRunFunction = bool (*)(const UnitFrame& frame, const DutRunOptions& options, UnitResult& out,
                                 std::string& error);
// And the unit it was built for ("setup", "walker" or "zbuffer").
using UnitNameFunction = const char* (*)();

}  // namespace rastersim::dut

#define RASTERSIM_DUT_RUN_SYMBOL "rastersim_dut_run"
// bool (): whether the design's top has the memory port (dut_harness.h HasMemoryPort).
#define RASTERSIM_DUT_MEMORY_PORT_SYMBOL "rastersim_dut_memory_port"
#define RASTERSIM_UNIT_RUN_SYMBOL "rastersim_unit_run"
#define RASTERSIM_UNIT_NAME_SYMBOL "rastersim_unit_name"
