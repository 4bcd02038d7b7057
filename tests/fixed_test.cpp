// The fixed-point layer: rounding and overflow at the extremes.
#include "fixed/fixed.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

#include "fixed/blend.hpp"

namespace tmu::fx {
namespace {

// --- rounding ---------------------------------------------------------------------------

TEST(FixedTest, ShiftRightRoundTiesInEveryMode) {
  // 2.5, -2.5, 3.5, -3.5 in UQ/SQ x.1 (raw = value * 2), shifted by one bit.
  struct Case {
    int64_t raw;
    int64_t floor, zero, half_up, half_even;
  };
  const Case cases[] = {
      {5, 2, 2, 3, 2},       // 2.5
      {-5, -3, -2, -2, -2},  // -2.5
      {7, 3, 3, 4, 4},       // 3.5
      {-7, -4, -3, -3, -4},  // -3.5
      {4, 2, 2, 2, 2},       // exact
      {-1, -1, 0, 0, 0},     // -0.5
      {1, 0, 0, 1, 0},       // 0.5
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.raw);
    EXPECT_EQ(shift_right_round(c.raw, 1, Round::kFloor), c.floor);
    EXPECT_EQ(shift_right_round(c.raw, 1, Round::kTowardZero), c.zero);
    EXPECT_EQ(shift_right_round(c.raw, 1, Round::kHalfUp), c.half_up);
    EXPECT_EQ(shift_right_round(c.raw, 1, Round::kHalfEven), c.half_even);
  }
}

TEST(FixedTest, ShiftRightRoundAtInt64Extremes) {
  const int64_t lo = std::numeric_limits<int64_t>::min();
  const int64_t hi = std::numeric_limits<int64_t>::max();
  EXPECT_EQ(shift_right_round(lo, 8, Round::kFloor), lo / 256);
  EXPECT_EQ(shift_right_round(hi, 8, Round::kFloor), hi / 256);
  EXPECT_EQ(shift_right_round(hi, 8, Round::kHalfUp), hi / 256 + 1);  // 0xFF remainder rounds up
  EXPECT_EQ(shift_right_round(lo, 62, Round::kHalfEven), -2);
  EXPECT_EQ(shift_right_round(123, 0, Round::kHalfUp), 123);
}

TEST(FixedTest, NarrowDropsFractionWithNamedRounding) {
  using Q8 = Fixed<SQ(8, 8)>;
  const Q8 x = Q8::from_raw(0x0180);  // 1.5
  EXPECT_EQ((narrow<SQ(8, 0)>(x, Round::kFloor, Overflow::kTrap).raw()), 1);
  EXPECT_EQ((narrow<SQ(8, 0)>(x, Round::kHalfUp, Overflow::kTrap).raw()), 2);
  EXPECT_EQ((narrow<SQ(8, 0)>(x, Round::kHalfEven, Overflow::kTrap).raw()), 2);
  const Q8 y = Q8::from_raw(-0x0180);  // -1.5
  EXPECT_EQ((narrow<SQ(8, 0)>(y, Round::kFloor, Overflow::kTrap).raw()), -2);
  EXPECT_EQ((narrow<SQ(8, 0)>(y, Round::kTowardZero, Overflow::kTrap).raw()), -1);
  EXPECT_EQ((narrow<SQ(8, 0)>(y, Round::kHalfUp, Overflow::kTrap).raw()), -1);
  EXPECT_EQ((narrow<SQ(8, 0)>(y, Round::kHalfEven, Overflow::kTrap).raw()), -2);
}

TEST(FixedTest, WideningIsExact) {
  using Q = Fixed<UQ(4, 4)>;
  const Q x = Q::from_raw(0xFF);
  EXPECT_EQ((narrow<UQ(8, 12)>(x, Round::kFloor, Overflow::kTrap).raw()), 0xFF << 8);
}

// --- overflow ---------------------------------------------------------------------------

TEST(FixedTest, FormatRangesAtTheExtremes) {
  EXPECT_EQ(SQ(16, 8).width(), 24);
  EXPECT_EQ(SQ(16, 8).min_raw(), -(1 << 23));
  EXPECT_EQ(SQ(16, 8).max_raw(), (1 << 23) - 1);
  EXPECT_EQ(UQ(0, 8).min_raw(), 0);
  EXPECT_EQ(UQ(0, 8).max_raw(), 255);
  EXPECT_EQ(SQ(1, 0).min_raw(), -1);  // a 1-bit signed value holds -1 and 0
  EXPECT_EQ(SQ(1, 0).max_raw(), 0);
  EXPECT_EQ(UQ(62, 0).max_raw(), (int64_t{1} << 62) - 1);
}

TEST(FixedTest, SaturateClampsAtBothEnds) {
  const Format s8 = SQ(8, 0);
  EXPECT_EQ(fit(128, s8, Overflow::kSaturate), 127);
  EXPECT_EQ(fit(-129, s8, Overflow::kSaturate), -128);
  EXPECT_EQ(fit(127, s8, Overflow::kSaturate), 127);
  EXPECT_EQ(fit(-128, s8, Overflow::kSaturate), -128);
  const Format u8 = UQ(8, 0);
  EXPECT_EQ(fit(-1, u8, Overflow::kSaturate), 0);
  EXPECT_EQ(fit(256, u8, Overflow::kSaturate), 255);
  EXPECT_EQ(fit(std::numeric_limits<int64_t>::max(), u8, Overflow::kSaturate), 255);
  EXPECT_EQ(fit(std::numeric_limits<int64_t>::min(), s8, Overflow::kSaturate), -128);
}

TEST(FixedTest, WrapKeepsTheLowBitsTwosComplement) {
  EXPECT_EQ(fit(128, SQ(8, 0), Overflow::kWrap), -128);
  EXPECT_EQ(fit(-129, SQ(8, 0), Overflow::kWrap), 127);
  EXPECT_EQ(fit(256, UQ(8, 0), Overflow::kWrap), 0);
  EXPECT_EQ(fit(-1, UQ(8, 0), Overflow::kWrap), 255);
  EXPECT_EQ(fit(0x1234567, UQ(12, 0), Overflow::kWrap), 0x567);
}

TEST(FixedTest, TrapThrowsOnOverflowAndOnBadRaw) {
  EXPECT_THROW(fit(256, UQ(8, 0), Overflow::kTrap), std::logic_error);
  EXPECT_THROW(Fixed<UQ(8, 0)>::from_raw(-1), std::logic_error);
  EXPECT_THROW(Fixed<SQ(8, 0)>::from_raw(128), std::logic_error);
  EXPECT_NO_THROW(Fixed<SQ(8, 0)>::from_raw(-128));
}

TEST(FixedTest, RoundingIntoSaturation) {
  // 127.5 rounds up to 128, which no longer fits SQ8.0: saturate gives 127, wrap -128.
  const Format from = SQ(9, 1);
  EXPECT_EQ(convert_raw(255, from, SQ(8, 0), Round::kHalfUp, Overflow::kSaturate), 127);
  EXPECT_EQ(convert_raw(255, from, SQ(8, 0), Round::kHalfUp, Overflow::kWrap), -128);
  EXPECT_EQ(convert_raw(255, from, SQ(8, 0), Round::kFloor, Overflow::kTrap), 127);
}

// --- conversions and exact arithmetic ---------------------------------------------------

TEST(FixedTest, FromDoubleRoundsAndSaturates) {
  using T = Fixed<SQ(16, 8)>;
  EXPECT_EQ(T::from_double(1.0).raw(), 256);
  EXPECT_EQ(T::from_double(-0.5).raw(), -128);
  EXPECT_EQ(T::from_double(1.0 / 512, Round::kHalfEven).raw(), 0);  // tie to even
  EXPECT_EQ(T::from_double(3.0 / 512, Round::kHalfEven).raw(), 2);
  EXPECT_EQ(T::from_double(1.0 / 512, Round::kHalfUp).raw(), 1);
  EXPECT_EQ(T::from_double(1e30).raw(), SQ(16, 8).max_raw());
  EXPECT_EQ(T::from_double(-1e30).raw(), SQ(16, 8).min_raw());
  EXPECT_EQ(T::from_double(std::numeric_limits<double>::quiet_NaN()).raw(), 0);
  EXPECT_DOUBLE_EQ(T::from_raw(-384).to_double(), -1.5);
}

TEST(FixedTest, BitsRoundTripThroughPorts) {
  using T = Fixed<SQ(16, 8)>;
  EXPECT_EQ(T::from_raw(-1).bits(), 0xFFFFFFu);
  EXPECT_EQ(T::from_bits(0xFFFFFF).raw(), -1);
  EXPECT_EQ(T::from_bits(0x800000).raw(), SQ(16, 8).min_raw());
  EXPECT_EQ(T::from_bits(0x7FFFFF).raw(), SQ(16, 8).max_raw());
}

TEST(FixedTest, ExactArithmeticGrowsTheFormat) {
  using U = Fixed<UQ(8, 0)>;
  using W = Fixed<UQ(0, 8)>;
  const auto s = add(U::from_raw(255), U::from_raw(255));
  EXPECT_EQ(decltype(s)::format, UQ(9, 0));
  EXPECT_EQ(s.raw(), 510);
  const auto d = sub(U::from_raw(0), U::from_raw(255));
  EXPECT_EQ(decltype(d)::format, SQ(10, 0));
  EXPECT_EQ(d.raw(), -255);
  const auto p = mul(U::from_raw(255), W::from_raw(255));
  EXPECT_EQ(decltype(p)::format, UQ(8, 8));
  EXPECT_EQ(p.raw(), 255 * 255);
  using S = Fixed<SQ(8, 4)>;
  const auto m = add(S::from_raw(-2048), U::from_raw(255));  // mixed signedness
  EXPECT_EQ(decltype(m)::format, SQ(10, 4));
  EXPECT_EQ(m.raw(), -2048 + 255 * 16);
}

// --- the blend rule ---------------------------------------------------------------------

TEST(FixedTest, BilerpHitsTheCornersExactlyAndRoundsHalfUp) {
  EXPECT_EQ(bilerp_u8(10, 20, 30, 40, 0, 0), 10u);
  EXPECT_EQ(bilerp_u8(255, 255, 255, 255, 255, 255), 255u);  // never overflows
  EXPECT_EQ(bilerp_u8(0, 0, 0, 0, 255, 255), 0u);
  EXPECT_EQ(bilerp_u8(0, 1, 0, 1, 128, 0), 1u);         // exactly 0.5 -> rounds up
  EXPECT_EQ(bilerp_u8(0, 255, 0, 255, 128, 77), 128u);  // 127.5 -> 128
  // weight 255 leaves 1/256 of the first sample: 255 * 1/256 = 0.996 -> 1
  EXPECT_EQ(bilerp_u8(255, 0, 255, 0, 255, 0), 1u);
}

}  // namespace
}  // namespace tmu::fx
