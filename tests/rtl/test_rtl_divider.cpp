// The divider unit alone (rtl/divider.sv, verilated as Vdivider_full and Vdivider_wrap) against
// model/fixed.h floor_div: quotient (wrapped to QUOTIENT_BITS) and remainder, and its timing
// (busy for exactly DIVIDEND_BITS cycles after start, results held afterwards).
#include <gtest/gtest.h>

#include <random>

#include "Vdivider_full.h"
#include "Vdivider_wrap.h"
#include "model/fixed.h"

namespace rastersim {
namespace {

constexpr int kDividendBits = 20, kDivisorBits = 12;

template <class V>
void check_divider(int quotient_bits) {
  VerilatedContext context;
  context.randReset(2);
  V div(&context);
  auto tick = [&] {
    div.clk = 0;
    div.eval();
    div.clk = 1;
    div.eval();
  };
  std::mt19937_64 rng(7);
  const int64_t max_dividend = (int64_t(1) << kDividendBits) - 1, max_divisor = (int64_t(1) << (kDivisorBits - 1)) - 1;
  std::vector<std::pair<int64_t, int64_t>> cases = {
      {0, 1}, {1, 1}, {-1, 1}, {7, 7}, {-7, 7}, {-6, 7}, {6, 7}, {max_dividend, 1}, {-max_dividend, 1},
      {max_dividend, max_divisor}, {-max_dividend, max_divisor}, {-1, max_divisor}, {-max_divisor, max_divisor}};
  std::uniform_int_distribution<int64_t> n(-max_dividend, max_dividend), d(1, max_divisor), small(1, 16);
  for (int i = 0; i < 3000; ++i) cases.push_back({n(rng), i % 3 ? d(rng) : small(rng)});
  for (const auto& [dividend, divisor] : cases) {
    div.start = 1;
    div.dividend_negative = dividend < 0;
    div.dividend_magnitude = uint32_t(dividend < 0 ? -dividend : dividend);
    div.divisor = uint32_t(divisor);
    tick();
    div.start = 0;
    for (int cycle = 0; cycle < kDividendBits; ++cycle) {
      div.eval();
      ASSERT_TRUE(div.busy) << "iteration " << cycle;
      tick();
    }
    div.eval();
    ASSERT_FALSE(div.busy);
    const FloorDiv expected = floor_div(dividend, divisor);
    const uint64_t mask = (uint64_t(1) << quotient_bits) - 1;
    EXPECT_EQ(uint64_t(div.quotient) & mask, uint64_t(wrap_signed(expected.quotient, quotient_bits)) & mask)
        << dividend << " / " << divisor;
    EXPECT_EQ(int64_t(div.remainder), int64_t(expected.remainder)) << dividend << " / " << divisor;
    tick();  // held while idle
    EXPECT_EQ(int64_t(div.remainder), int64_t(expected.remainder));
  }
}

TEST(RtlDivider, FloorDivisionFullQuotient) { check_divider<Vdivider_full>(20); }
TEST(RtlDivider, FloorDivisionWrappedQuotient) { check_divider<Vdivider_wrap>(9); }

}  // namespace
}  // namespace rastersim
