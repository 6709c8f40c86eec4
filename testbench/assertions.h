// Assertions in a verilated design (Verilator --assert; rastersim's own: rtl/rastersim_assert.vh).
// A failing assertion prints the simulator's message, which names its scope; with fatal-on-error
// off the context records the failure instead of aborting the program, and the harness ends the
// frame as failed in that cycle.
#pragma once

#include <verilated.h>

#include <cstdint>
#include <string>

namespace rastersim::rtl {

inline void record_assertion_failures(VerilatedContext& context) { context.fatalOnError(false); }

inline bool assertion_failed(const VerilatedContext& context) { return context.gotError(); }

inline std::string assertion_failure_note(int64_t cycle) {
  return "an assertion failed in cycle " + std::to_string(cycle) + " (the simulator's message names it)";
}

}  // namespace rastersim::rtl
