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
  // The exact result is num/den (den > 0), all in 64-bit integers (exact on every target).
  const auto expect_rounded = [](std::int64_t num, std::int64_t den, std::int32_t got, bool hit,
                                 bool ties_up) {
    if (hit) {
      EXPECT_TRUE(got == kRawMax || got == kRawMin);
      // Beyond the extreme by more than half a step.
      const std::int64_t beyond =
          got == kRawMax ? num - std::int64_t{kRawMax} * den : std::int64_t{kRawMin} * den - num;
      EXPECT_GT(beyond, den / 2) << num << " / " << den;
      return;
    }
    const std::int64_t diff = std::int64_t{got} * den - num;  // (got − exact)·den
    EXPECT_LE(2 * (diff < 0 ? -diff : diff), den) << num << " / " << den << " got " << got;
    if (ties_up && 2 * (diff < 0 ? -diff : diff) == den) {
      EXPECT_GT(diff, 0);
    }
  };
  for (int i = 0; i < 200000; ++i) {
    // Operands of varied magnitude: shift a random word right by 0..31 bits.
    const std::int32_t a = any(rng) >> width(rng);
    const std::int32_t b = any(rng) >> width(rng);
    Saturation sat;
    const Q<20> m = mul<20>(Q<16>{a}, Q<24>{b}, sat);  // a·b·2^−(16+24−20)
    expect_rounded(std::int64_t{a} * b, std::int64_t{1} << 20, m.raw, sat.hit, true);
    sat = {};
    const Q<12> s = add(Q<12>{a}, Q<12>{b}, sat);
    expect_rounded(std::int64_t{a} + b, 1, s.raw, sat.hit, true);
    sat = {};
    if (b != 0) {
      const Q<18> d = div<18>(Q<16>{a}, Q<20>{b}, sat);  // a/b·2^(18+20−16)
      const std::int64_t num = std::int64_t{a} * (std::int64_t{1} << 22);
      expect_rounded(b < 0 ? -num : num, b < 0 ? -std::int64_t{b} : b, d.raw, sat.hit, false);
    }
  }
}

}  // namespace
}  // namespace tread::fixed
