// Q-format arithmetic: rounding to nearest, saturation with the flag, division by zero, and the
// exact results of every operation checked against 64-bit/double arithmetic on random operands.
#include "fixed/q_format.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

namespace tread::fixed {
namespace {

TEST(QFormat, ConstantsAreRoundedAtCompileTime) {
  static_assert(q<16>(1.0).raw == 65536);
  static_assert(q<16>(-1.5).raw == -98304);
  static_assert(q<30>(1.0).raw == 1073741824);
  static_assert(q<16>(1.0 / 131072.0).raw == 1);  // half a step rounds away from zero
  static_assert(q<16>(-1.0 / 131072.0).raw == -1);
  EXPECT_DOUBLE_EQ(to_double(q<29>(3.25)), 3.25);
}

TEST(QFormat, SaturationSetsTheFlagAndOnlyThen) {
  Saturation sat;
  const Q<30> big = q<30>(1.5);
  EXPECT_EQ(add(big, big, sat).raw, kRawMax);
  EXPECT_TRUE(sat.hit);
  sat = {};
  EXPECT_EQ(sub(q<30>(-1.5), big, sat).raw, kRawMin);
  EXPECT_TRUE(sat.hit);
  sat = {};
  EXPECT_EQ(neg(Q<30>{kRawMin}, sat).raw, kRawMax);
  EXPECT_TRUE(sat.hit);
  sat = {};
  EXPECT_EQ(to<28>(q<30>(1.75), sat).raw, q<28>(1.75).raw);
  EXPECT_EQ(mul<30>(big, q<30>(1.25), sat).raw, q<30>(1.875).raw);  // still inside ±2
  EXPECT_EQ(mul<30>(q<30>(1.25), q<30>(1.25), sat).raw, q<30>(1.5625).raw);
  EXPECT_FALSE(sat.hit);
  EXPECT_EQ(mul<30>(q<30>(1.5), q<30>(1.5), sat).raw, kRawMax);  // 2.25
  EXPECT_TRUE(sat.hit);
}

TEST(QFormat, DivisionByZeroAndSigns) {
  Saturation sat;
  EXPECT_EQ(div<16>(q<16>(0.0), q<16>(0.0), sat).raw, 0);
  EXPECT_FALSE(sat.hit);
  EXPECT_EQ(div<16>(q<16>(2.0), q<16>(0.0), sat).raw, kRawMax);
  EXPECT_TRUE(sat.hit);
  sat = {};
  EXPECT_EQ(div<16>(q<16>(-2.0), q<16>(0.0), sat).raw, kRawMin);
  EXPECT_TRUE(sat.hit);
  sat = {};
  EXPECT_EQ(div<16>(q<16>(1.0), q<16>(3.0), sat).raw, 21845);    // 21845.33
  EXPECT_EQ(div<16>(q<16>(-2.0), q<16>(3.0), sat).raw, -43691);  // −43690.67
  EXPECT_EQ(div<16>(q<16>(1.0), q<16>(-8.0), sat).raw, -8192);
  EXPECT_EQ(div<30>(q<16>(1.0), q<29>(3.0), sat).raw, 357913941);
  EXPECT_FALSE(sat.hit);
  EXPECT_EQ(div<30>(q<16>(4.0), q<16>(1.0), sat).raw, kRawMax);
  EXPECT_TRUE(sat.hit);
}

// Every operation equals the exactly rounded (ties up, away from zero for div) result, or the
// saturated one with the flag set.
TEST(QFormat, RandomOperandsMatchExactArithmetic) {
  std::mt19937_64 rng(20261125);
  std::uniform_int_distribution<std::int32_t> any(kRawMin, kRawMax);
  std::uniform_int_distribution<int> width(0, 31);
  const auto expect_rounded = [](long double exact, std::int32_t got, bool hit, bool ties_up) {
    if (exact > static_cast<long double>(kRawMax) + 0.5L ||
        exact < static_cast<long double>(kRawMin) - 0.5L) {
      EXPECT_TRUE(hit);
      EXPECT_EQ(got, exact > 0 ? kRawMax : kRawMin);
      return;
    }
    const long double err = static_cast<long double>(got) - exact;
    EXPECT_LE(std::fabs(static_cast<double>(err)), 0.5) << static_cast<double>(exact);
    if (ties_up && std::fabs(static_cast<double>(err)) >= 0.5) {
      EXPECT_GT(err, 0.0L);
    }
  };
  for (int i = 0; i < 200000; ++i) {
    // Operands of varied magnitude: shift a random word right by 0..31 bits.
    const std::int32_t a = any(rng) >> width(rng);
    const std::int32_t b = any(rng) >> width(rng);
    Saturation sat;
    const Q<20> m = mul<20>(Q<16>{a}, Q<24>{b}, sat);  // a·b·2^−(16+24−20)
    expect_rounded(static_cast<long double>(a) * b / 1048576.0L, m.raw, sat.hit, true);
    sat = {};
    const Q<12> s = add(Q<12>{a}, Q<12>{b}, sat);
    expect_rounded(static_cast<long double>(a) + b, s.raw, sat.hit, true);
    sat = {};
    if (b != 0) {
      const Q<18> d = div<18>(Q<16>{a}, Q<20>{b}, sat);  // a/b·2^(18+20−16)
      expect_rounded(static_cast<long double>(a) / b * 4194304.0L, d.raw, sat.hit, false);
    }
  }
}

}  // namespace
}  // namespace tread::fixed
