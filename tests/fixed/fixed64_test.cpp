// Fixed64 (Q31.32): exact + and −, × rounded to nearest, ÷ within its documented steps, invalid
// values like NaN (overflow, division by zero, domains, propagation, comparisons), and the
// elementary functions within their error bounds against double over 10^5–10^6 arguments.
#include "fixed/fixed64.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>

namespace tread::fixed {
namespace {

constexpr double kStep = 1.0 / 4294967296.0;

Fixed64 fx(double v) {
  return Fixed64::from_double(v);
}
double dbl(Fixed64 v) {
  return v.to_double();
}

TEST(Fixed64, ConstantsAndConversions) {
  static_assert(Fixed64(1.0).raw() == Fixed64::kOneRaw);
  static_assert(Fixed64(-0.5).raw() == -(Fixed64::kOneRaw / 2));
  static_assert((Fixed64(1.5) * Fixed64(2.0)).raw() == 3 * Fixed64::kOneRaw);
  EXPECT_EQ(fx(1e-10).raw(), 0);
  EXPECT_EQ(fx(2e-10).raw(), 1);
  EXPECT_FALSE(fx(std::nan("")).valid());
  EXPECT_FALSE(fx(3e9).valid());
  EXPECT_TRUE(std::isnan(Fixed64::invalid().to_double()));
}

TEST(Fixed64, ProductsAreRoundedToNearestAndDivisionWithinTwoSteps) {
#ifndef __SIZEOF_INT128__
  GTEST_SKIP() << "the exact reference needs a 128-bit integer type, which this target's compiler "
                  "lacks (32-bit Arm); the same integer code is checked on x86-64 and aarch64";
#else
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<std::int64_t> any(std::numeric_limits<std::int64_t>::min() + 1,
                                                  std::numeric_limits<std::int64_t>::max());
  std::uniform_int_distribution<int> width(0, 63);
  for (int i = 0; i < 300000; ++i) {
    const Fixed64 a = Fixed64::from_raw(any(rng) >> width(rng));
    const Fixed64 b = Fixed64::from_raw(any(rng) >> width(rng));
    const __int128 exact = static_cast<__int128>(a.raw()) * b.raw();
    const __int128 rounded = (exact + (static_cast<__int128>(1) << 31)) >> 32;
    const Fixed64 p = a * b;
    if (rounded > std::numeric_limits<std::int64_t>::max() ||
        rounded <= std::numeric_limits<std::int64_t>::min()) {
      EXPECT_FALSE(p.valid());
    } else {
      ASSERT_TRUE(p.valid());
      EXPECT_EQ(p.raw(), static_cast<std::int64_t>(rounded));
    }
    if (b.raw() == 0) continue;
    const long double q = static_cast<long double>(a.raw()) / b.raw() * 4294967296.0L;
    const Fixed64 d = a / b;
    if (std::fabs(static_cast<double>(q)) >= 9.2233720368547e18) {
      EXPECT_FALSE(d.valid());
    } else if (std::fabs(static_cast<double>(q)) < 9.2e18) {
      ASSERT_TRUE(d.valid()) << a.raw() << " / " << b.raw();
      const long double err = static_cast<long double>(d.raw()) - q;
      const bool exact_rounding = std::llabs(b.raw()) <= 0xFFFFFFFFLL;
      EXPECT_LE(std::fabs(static_cast<double>(err)), exact_rounding ? 0.5 + 1e-6 : 2.0)
          << a.raw() << " / " << b.raw();
    }
  }
#endif
}

TEST(Fixed64, InvalidBehavesLikeNaN) {
  const Fixed64 big(2e9);
  const Fixed64 bad = big + big;
  EXPECT_FALSE(bad.valid());
  EXPECT_FALSE((big * big).valid());
  EXPECT_FALSE((Fixed64(1.0) / Fixed64(0.0)).valid());
  EXPECT_FALSE((Fixed64(0.0) / Fixed64(0.0)).valid());
  EXPECT_FALSE((bad * Fixed64(0.0)).valid());  // like NaN·0
  EXPECT_FALSE((bad - bad).valid());
  EXPECT_FALSE(bad < Fixed64(0.0));
  EXPECT_FALSE(bad > Fixed64(0.0));
  EXPECT_FALSE(bad <= bad);
  EXPECT_FALSE(bad == bad);
  EXPECT_TRUE(bad != bad);
  EXPECT_FALSE(isfinite(bad));
  EXPECT_FALSE(sqrt(Fixed64(-1.0)).valid());
  EXPECT_FALSE(log(Fixed64(0.0)).valid());
  EXPECT_FALSE(acos(Fixed64(1.0001)).valid());
  EXPECT_FALSE(exp(Fixed64(21.5)).valid());
  EXPECT_TRUE(exp(Fixed64(21.48)).valid());
  EXPECT_EQ(exp(Fixed64(-40.0)).raw(), 0);
  EXPECT_FALSE(pow(Fixed64(-2.0), Fixed64(0.5)).valid());
  EXPECT_EQ(pow(Fixed64(0.0), Fixed64(0.5)).raw(), 0);
  EXPECT_EQ(pow(Fixed64(0.0), Fixed64(0.0)).raw(), Fixed64::kOneRaw);
  for (Fixed64 (*f)(Fixed64) : {&abs, &sqrt, &exp, &log, &sin, &cos, &tan, &atan, &acos}) {
    EXPECT_FALSE(f(bad).valid());
  }
}

struct Worst {
  double error = 0.0;
  double at = 0.0;
  void update(double e, double x) {
    if (!(std::fabs(e) <= error)) {
      error = std::fabs(e);
      at = x;
    }
  }
};

TEST(Fixed64, ElementaryFunctionsWithinTheirBounds) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> log_mag(std::log(1e-9), std::log(2e9));
  std::uniform_real_distribution<double> angle(-60.0, 60.0);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> expo(-30.0, 21.4);
  std::bernoulli_distribution coin;
  Worst w_atan, w_sin, w_cos, w_tan, w_exp, w_log, w_sqrt, w_pow, w_acos;
  for (int i = 0; i < 400000; ++i) {
    const Fixed64 x = fx((coin(rng) ? 1.0 : -1.0) * std::exp(log_mag(rng)));
    const double xd = dbl(x);
    w_atan.update(dbl(atan(x)) - std::atan(xd), xd);
    const Fixed64 ax = abs(x);
    w_log.update(dbl(log(ax)) - std::log(dbl(ax)), dbl(ax));
    w_sqrt.update((dbl(sqrt(ax)) - std::sqrt(dbl(ax))) / (std::sqrt(dbl(ax)) * 1e-9 + kStep),
                  dbl(ax));
    const Fixed64 a = fx(angle(rng));
    w_sin.update(dbl(sin(a)) - std::sin(dbl(a)), dbl(a));
    w_cos.update(dbl(cos(a)) - std::cos(dbl(a)), dbl(a));
    const double t = std::tan(dbl(a));
    if (std::fabs(t) < 100.0) w_tan.update((dbl(tan(a)) - t) / (1.0 + t * t), dbl(a));
    const Fixed64 e = fx(expo(rng));
    const double ed = std::exp(dbl(e));
    w_exp.update((dbl(exp(e)) - ed) / (1e-8 * ed + kStep), dbl(e));
    const Fixed64 u = fx(unit(rng));
    w_acos.update(dbl(acos(u)) - std::acos(dbl(u)), dbl(u));
    const Fixed64 px = fx(std::exp(unit(rng) * 3.0));
    const Fixed64 py = fx(unit(rng) * 3.0);
    const double pd = std::pow(dbl(px), dbl(py));
    w_pow.update((dbl(pow(px, py)) - pd) / (5e-8 * pd + kStep), dbl(px));
  }
  std::printf(
      "worst: atan %.3g, sin %.3g, cos %.3g, tan %.3g·(1+tan²), exp %.3g of (1e-8 rel + 1 step), "
      "log %.3g, sqrt "
      "%.3g of (1e-9 rel + 1 step), pow %.3g of (5e-8 rel + 1 step), acos %.3g\n",
      w_atan.error, w_sin.error, w_cos.error, w_tan.error, w_exp.error, w_log.error, w_sqrt.error,
      w_pow.error, w_acos.error);
  EXPECT_LE(w_atan.error, 4e-9) << w_atan.at;
  EXPECT_LE(w_sin.error, 4e-9) << w_sin.at;
  EXPECT_LE(w_cos.error, 4e-9) << w_cos.at;
  EXPECT_LE(w_tan.error, 8e-9) << w_tan.at;
  EXPECT_LE(w_exp.error, 1.0) << w_exp.at;
  EXPECT_LE(w_log.error, 4e-9) << w_log.at;
  EXPECT_LE(w_sqrt.error, 1.0) << w_sqrt.at;
  EXPECT_LE(w_pow.error, 1.0) << w_pow.at;
  EXPECT_LE(w_acos.error, 2e-8) << w_acos.at;
}

}  // namespace
}  // namespace tread::fixed
