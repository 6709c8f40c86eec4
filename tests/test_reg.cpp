// Reg<Bits, Signed>: the width and signedness are in the type, and a value the register cannot
// hold is refused when stored, never wrapped.
#include <gtest/gtest.h>

#include <type_traits>

#include "model/triangle_setup.h"

namespace rastersim {
namespace {

TEST(Reg, RangeFollowsWidthAndSignedness) {
  EXPECT_EQ((Reg<8>::min), -128);
  EXPECT_EQ((Reg<8>::max), 127);
  EXPECT_EQ((Reg<8, false>::min), 0);
  EXPECT_EQ((Reg<8, false>::max), 255);
  EXPECT_EQ((Reg<64>::min), INT64_MIN);
  EXPECT_EQ((Reg<64>::max), INT64_MAX);
}

TEST(Reg, StoresInRangeAndRefusesOutOfRange) {
  Reg<8> r = 127;
  EXPECT_EQ(int64_t(r), 127);
  EXPECT_THROW(r = 128, WidthOverflow);
  EXPECT_EQ(int64_t(r), 127);  // a refused store leaves the register as it was
  r = -128;
  EXPECT_THROW(r -= 1, WidthOverflow);
  EXPECT_THROW((Reg<8, false>(-1)), WidthOverflow);
  EXPECT_THROW((Reg<30, false>(int64_t(1) << 30)), WidthOverflow);
  Reg<30, false> u = (int64_t(1) << 30) - 1;
  EXPECT_THROW(u += 1, WidthOverflow);
}

TEST(Reg, SetupRecordFieldsCarryTheirFormats) {
  static_assert(std::is_same_v<decltype(EdgeSetup::start), EdgeValue>);
  static_assert(std::is_same_v<decltype(EdgeSetup::span_rem), SpanRemainder>);
  static_assert(!SpanRemainder::is_signed);
  static_assert(std::is_same_v<decltype(PlaneSetup::step_x), PlaneValue>);
  EdgeSetup e{};
  EXPECT_THROW(e.span_rem = -1, WidthOverflow);
  EXPECT_THROW(e.step_x = int64_t(1) << 40, WidthOverflow);
}

}  // namespace
}  // namespace rastersim
