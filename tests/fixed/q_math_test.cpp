// The fixed-point elementary functions against double precision: the error bounds documented in
// src/fixed/q_math.hpp hold over dense grids, the formats' extremes and 10^6 random arguments.
// The worst errors found are printed.
#include "fixed/q_math.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>

namespace tread::fixed {
namespace {

constexpr double kStep30 = 1.0 / 1073741824.0;

struct Worst {
  double error = 0.0;
  double at = 0.0;
  void update(double e, double x) {
    if (std::fabs(e) > error) {
      error = std::fabs(e);
      at = x;
    }
  }
};

template <int F>
void check_atan(std::int32_t raw, Worst& worst) {
  const Q<F> x{raw};
  const double exact = std::atan(to_double(x));
  worst.update(to_double(atan(x)) - exact, to_double(x));
}

TEST(QMath, AtanWithin4e9OverEveryFormatsRange) {
  Worst worst;
  std::mt19937 rng(1);
  std::uniform_int_distribution<std::int32_t> any(kRawMin, kRawMax);
  for (int i = 0; i < 1000000; ++i) {
    const std::int32_t raw = any(rng) >> (i % 32);
    check_atan<16>(raw, worst);
    check_atan<30>(raw, worst);
    check_atan<24>(raw, worst);
  }
  for (std::int32_t raw : {kRawMin, kRawMin + 1, -1, 0, 1, kRawMax}) {
    check_atan<16>(raw, worst);
    check_atan<30>(raw, worst);
    check_atan<0>(raw, worst);
  }
  for (double x = -4.0; x <= 4.0; x += 1.0 / 4096.0) {  // around the reduction points 0.414, 1
    Saturation sat;
    check_atan<28>(from_double<28>(x, sat).raw, worst);
  }
  std::printf("atan: worst |error| %.3g rad at x = %.9g\n", worst.error, worst.at);
  EXPECT_LE(worst.error, 4e-9);
}

TEST(QMath, SinCosWithin4e9ForEveryAngleOfTheFormat) {
  Worst ws;
  Worst wc;
  std::mt19937 rng(2);
  std::uniform_int_distribution<std::int32_t> any(kRawMin, kRawMax);
  const auto check = [&](Angle a) {
    Unit s;
    Unit c;
    sin_cos(a, s, c);
    const double x = to_double(a);
    ws.update(to_double(s) - std::sin(x), x);
    wc.update(to_double(c) - std::cos(x), x);
  };
  for (int i = 0; i < 1000000; ++i) {
    check(Angle{any(rng) >> (i % 8)});
  }
  for (double x = -4.0; x < 4.0; x += 1.0 / 8192.0) {
    Saturation sat;
    check(from_double<29>(x, sat));
  }
  check(Angle{kRawMin});
  check(Angle{kRawMax});
  std::printf("sin: worst |error| %.3g at %.9g; cos: %.3g at %.9g\n", ws.error, ws.at, wc.error,
              wc.at);
  EXPECT_LE(ws.error, 4e-9);
  EXPECT_LE(wc.error, 4e-9);
  // Other input formats: Q15.16 angles of up to ±32768 rad (a few thousand turns).
  Worst wide;
  for (int i = 0; i < 200000; ++i) {
    const Q<16> a{any(rng)};
    wide.update(to_double(sin(a)) - std::sin(to_double(a)), to_double(a));
  }
  std::printf("sin of Q15.16 angles: worst |error| %.3g at %.9g\n", wide.error, wide.at);
  EXPECT_LE(wide.error, 4e-9);
}

TEST(QMath, ExpRelativeErrorBelow1em8PlusOneStep) {
  Worst worst;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-20.0, 10.0);
  for (int i = 0; i < 1000000; ++i) {
    Saturation sat;
    const Q<24> x = from_double<24>(u(rng), sat);
    const double exact = std::exp(to_double(x));
    const Q<16> y = exp<16>(x, sat);
    if (exact >= 32767.0) {
      EXPECT_TRUE(sat.hit) << to_double(x);
      continue;
    }
    EXPECT_FALSE(sat.hit) << to_double(x);
    const double bound = 1e-8 * exact + 1.0 / 65536.0;
    worst.update((to_double(y) - exact) / bound, to_double(x));
    // Q1.30 output for arguments ≤ 0.69
    if (to_double(x) < 0.69) {
      const Q<30> z = exp<30>(x, sat);
      EXPECT_LE(std::fabs(to_double(z) - exact), 1e-8 * exact + kStep30) << to_double(x);
    }
  }
  std::printf("exp: worst error %.3g of the bound at x = %.9g\n", worst.error, worst.at);
  EXPECT_LE(worst.error, 1.0);
  Saturation sat;
  EXPECT_EQ(exp<16>(q<16>(-30.0), sat).raw, 0);
  EXPECT_EQ(exp<16>(q<16>(0.0), sat).raw, 65536);
  EXPECT_FALSE(sat.hit);
  EXPECT_EQ(exp<16>(q<16>(11.0), sat).raw, kRawMax);
  EXPECT_TRUE(sat.hit);
}

TEST(QMath, LogWithin1em8PlusOneStepAndDomainErrors) {
  Worst worst;
  std::mt19937 rng(4);
  std::uniform_int_distribution<std::int32_t> positive(1, kRawMax);
  for (int i = 0; i < 1000000; ++i) {
    const std::int32_t raw = std::max(1, positive(rng) >> (i % 31));
    Saturation sat;
    const Q<16> x{raw};
    const double exact = std::log(to_double(x));
    const Q<27> l = log<27>(x, sat);
    EXPECT_FALSE(sat.hit);
    worst.update((to_double(l) - exact) / (1e-8 + 1.0 / 134217728.0), to_double(x));
    const double ln30 = std::log(to_double(Q<30>{raw}));  // x < 2: ln x < 0.69
    const Q<30> l30 = log<30>(Q<30>{raw}, sat);
    if (ln30 > -1.99) {
      EXPECT_LE(std::fabs(to_double(l30) - ln30), 1e-8 + kStep30);
      EXPECT_FALSE(sat.hit);
    } else if (ln30 < -2.01) {
      EXPECT_TRUE(sat.hit);  // beyond Q1.30
    }
  }
  std::printf("log: worst error %.3g of the bound at x = %.9g\n", worst.error, worst.at);
  EXPECT_LE(worst.error, 1.0);
  Saturation sat;
  EXPECT_EQ(log<16>(q<16>(0.0), sat).raw, 0);
  EXPECT_TRUE(sat.hit);
  sat = {};
  EXPECT_EQ(log<16>(q<16>(-1.0), sat).raw, 0);
  EXPECT_TRUE(sat.hit);
}

TEST(QMath, PowRelativeErrorWithinItsBound) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> ux(0.05, 4.0);
  std::uniform_real_distribution<double> uy(-3.0, 3.0);
  double worst = 0.0;
  for (int i = 0; i < 300000; ++i) {
    Saturation sat;
    const Q<24> x = from_double<24>(ux(rng), sat);
    const Q<24> y = from_double<24>(uy(rng), sat);
    const double lx = std::log(to_double(x));
    const double exact = std::exp(to_double(y) * lx);
    if (exact > 60.0) continue;
    const Q<24> p = pow<24>(x, y, sat);
    EXPECT_FALSE(sat.hit);
    const double bound =
        (std::fabs(to_double(y) * lx) * 2e-9 + 1e-8) * exact + 1.0 / 16777216.0 + 1.5e-8 * exact;
    worst = std::max(worst, std::fabs(to_double(p) - exact) / bound);
  }
  std::printf("pow: worst error %.3g of the bound\n", worst);
  EXPECT_LE(worst, 1.0);
}

TEST(QMath, SqrtIsExactlyRoundedDown) {
  std::mt19937 rng(6);
  std::uniform_int_distribution<std::int32_t> positive(0, kRawMax);
  for (int i = 0; i < 300000; ++i) {
    const std::int32_t raw = positive(rng) >> (i % 31);
    Saturation sat;
    const Q<16> r = sqrt(Q<16>{raw}, sat);
    const std::uint64_t v = static_cast<std::uint64_t>(raw) << 16;
    const std::uint64_t s = static_cast<std::uint64_t>(r.raw);
    EXPECT_LE(s * s, v);
    EXPECT_GT((s + 1) * (s + 1), v);
    EXPECT_FALSE(sat.hit);
  }
  Saturation sat;
  EXPECT_EQ(sqrt(Q<30>{kRawMax}, sat).raw, 1518500249);  // √(2 − 2^−30) in Q30
  EXPECT_EQ(sqrt(q<16>(-1.0), sat).raw, 0);
  EXPECT_TRUE(sat.hit);
}

TEST(QMath, TanSaturatesAtTheQuarterTurn) {
  Saturation sat;
  EXPECT_NEAR(to_double(tan<24>(q<29>(1.0), sat)), std::tan(1.0), 1e-7);
  EXPECT_NEAR(to_double(tan<24>(q<29>(-0.3), sat)), std::tan(-0.3), 1e-7);
  EXPECT_FALSE(sat.hit);
  (void)tan<24>(q<29>(1.5707963), sat);  // tan ≈ 3.7e6: beyond Q7.24
  EXPECT_TRUE(sat.hit);
}

}  // namespace
}  // namespace tread::fixed
