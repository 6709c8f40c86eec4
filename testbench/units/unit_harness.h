// Helpers for the unit-level tests (tests/units/): one verilated RTL unit alone, clocked from the
// test, its ports written and read field by field.
#pragma once

#include <verilated.h>

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <type_traits>

#include "model/profile.h"
#include "testbench/assertions.h"
#include "testbench/core_ports.h"

namespace rastersim::units {

using rtl::field_bits;

// The number of triangles (fragments, for the z-buffer) a test runs: its default, or
// RASTERSIM_UNIT_COUNT when set (the `long` label's million-triangle runs).
inline int64_t unit_count(int64_t fallback) {
  const char* text = std::getenv("RASTERSIM_UNIT_COUNT");
  return text != nullptr && *text != '\0' ? std::strtoll(text, nullptr, 10) : fallback;
}

// A unit's build profile (its runtime settings are the test's).
inline Profile unit_profile(int width, int height, int subpixel_bits, int z_bits, int z_guard_bits, int setup_interval) {
  Profile p;
  p.width = width;
  p.height = height;
  p.subpixel_bits = subpixel_bits;
  p.z_bits = z_bits;
  p.z_guard_bits = z_guard_bits;
  p.setup_interval = setup_interval;
  return p;
}

// Writes `value` into bits [lo, lo + width) of a verilated port (an integer or a VlWide).
template <class Port>
void put_bits(Port& port, int lo, int width, uint64_t value) {
  if constexpr (std::is_integral_v<Port>) {
    const uint64_t mask = (width >= 64 ? ~uint64_t(0) : (uint64_t(1) << width) - 1) << lo;
    port = Port((uint64_t(port) & ~mask) | ((value << lo) & mask));
  } else {
    for (int i = 0; i < width; ++i) {
      const int bit = lo + i;
      const uint32_t one = 1u << (bit % 32);
      if ((value >> i) & 1u) port[bit / 32] |= one;
      else port[bit / 32] &= ~one;
    }
  }
}

// One verilated unit with a clock: `tick()` is a rising edge after the inputs were set and the
// outputs of the cycle read (`settle()` evaluates the cycle's combinational outputs first).
template <class V>
class Unit {
 public:
  explicit Unit(uint64_t seed) : context_(std::make_unique<VerilatedContext>()) {
    rtl::record_assertion_failures(*context_);
    context_->randReset(2);  // registers without a reset start random: the unit must not read them
    context_->randSeed(int(seed % 2147483647u) + 1);
    top_ = std::make_unique<V>(context_.get(), "unit");
    top_->clk = 0;
    top_->eval();
  }
  ~Unit() { top_->final(); }
  V& operator*() { return *top_; }
  V* operator->() { return top_.get(); }
  void settle() {
    top_->clk = 0;
    top_->eval();
  }
  void tick() {
    top_->clk = 1;
    top_->eval();
    top_->clk = 0;
    top_->eval();
    if (rtl::assertion_failed(*context_)) throw std::runtime_error(rtl::assertion_failure_note(cycle_));
    ++cycle_;
  }

 private:
  std::unique_ptr<VerilatedContext> context_;
  std::unique_ptr<V> top_;
  int64_t cycle_ = 0;  // rising edges since construction
};

}  // namespace rastersim::units
