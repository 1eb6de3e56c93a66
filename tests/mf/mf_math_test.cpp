// The float elementary functions of src/mf/mf_math.hpp against libm in double, over dense sweeps
// of the ranges the Magic Formula uses (and beyond, where the functions fall back to libm). Each
// test states the bound it checks and prints the largest error it found.
#include "mf/mf_math.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace tread::mf::detail {
namespace {

/// Largest |f(x) − ref(x)| / max(|ref(x)|, floor) over n + 1 evenly spaced x in [lo, hi].
template <typename F, typename R>
double max_error(F f, R ref, double lo, double hi, int n, double floor) {
  double worst = 0.0;
  for (int i = 0; i <= n; ++i) {
    const float x = static_cast<float>(lo + (hi - lo) * i / n);
    const double got = static_cast<double>(f(x));
    const double want = ref(static_cast<double>(x));
    const double err = std::fabs(got - want) / std::max(std::fabs(want), floor);
    EXPECT_TRUE(std::isfinite(got)) << "x = " << x;
    if (err > worst) worst = err;
  }
  return worst;
}

double dsin(double x) {
  return std::sin(x);
}
double dcos(double x) {
  return std::cos(x);
}
double dtan(double x) {
  return std::tan(x);
}
double datan(double x) {
  return std::atan(x);
}
double dexp(double x) {
  return std::exp(x);
}
double dlog(double x) {
  return std::log(x);
}

TEST(MfMath, SinCosAbsoluteErrorBelow2em7) {
  // |x| ≤ 2π: the Magic Formula's arguments (C·atan(...), γ, α); up to 1000: any file.
  for (double range : {6.3, 100.0, 1000.0}) {
    const double es =
        max_error([](float x) { return fast::sin(x); }, dsin, -range, range, 1000000, 1.0);
    const double ec =
        max_error([](float x) { return fast::cos(x); }, dcos, -range, range, 1000000, 1.0);
    std::printf("[ max err  ] |x| <= %g: sin %.3g, cos %.3g (absolute)\n", range, es, ec);
    // The float argument itself is exact; libm in double is the reference.
    EXPECT_LT(es, range < 10.0 ? 2e-7 : 1e-6);
    EXPECT_LT(ec, range < 10.0 ? 2e-7 : 1e-6);
  }
}

TEST(MfMath, TanRelativeErrorBelow1em6) {
  const double e =
      max_error([](float x) { return fast::tan(x); }, dtan, -1.5707, 1.5707, 1000000, 1e-30);
  std::printf("[ max err  ] |x| <= 1.5707: tan %.3g (relative)\n", e);
  EXPECT_LT(e, 1e-6);
}

TEST(MfMath, AtanAbsoluteErrorBelow2em7) {
  const double e1 =
      max_error([](float x) { return fast::atan(x); }, datan, -20.0, 20.0, 1000000, 1.0);
  const double e2 =
      max_error([](float x) { return fast::atan(x); }, datan, -1e7, 1e7, 1000000, 1.0);
  std::printf("[ max err  ] atan %.3g on |x| <= 20, %.3g on |x| <= 1e7 (absolute)\n", e1, e2);
  EXPECT_LT(e1, 2e-7);
  EXPECT_LT(e2, 2e-7);
}

TEST(MfMath, ExpRelativeErrorBelow3em7) {
  const double e =
      max_error([](float x) { return fast::exp(x); }, dexp, -86.9, 86.9, 1000000, 1e-300);
  std::printf("[ max err  ] |x| <= 86.9: exp %.3g (relative)\n", e);
  EXPECT_LT(e, 3e-7);
}

TEST(MfMath, LogAbsoluteErrorBelow2em7) {
  const double e1 = max_error([](float x) { return fast::log(x); }, dlog, 1e-3, 10.0, 1000000, 1.0);
  const double e2 = max_error([](float x) { return fast::log(x); }, dlog, 10.0, 1e30, 1000000, 1.0);
  std::printf("[ max err  ] log %.3g on [1e-3, 10], %.3g relative on [10, 1e30]\n", e1, e2);
  EXPECT_LT(e1, 2e-7);
  EXPECT_LT(e2, 2e-7);
}

TEST(MfMath, PowAsExpLogRelativeErrorBelow2em6) {
  // Load and pressure ratios of My: x in (0, 20], exponents of a few units.
  double worst = 0.0;
  for (float y : {-2.0f, -0.4f, 0.3333333f, 0.85f, 1.5f, 3.0f}) {
    const double e = max_error([y](float x) { return mf_pow(x, y); },
                               [y](double x) { return std::pow(x, static_cast<double>(y)); }, 1e-3,
                               20.0, 200000, 1e-300);
    worst = std::max(worst, e);
  }
  std::printf("[ max err  ] pow %.3g (relative)\n", worst);
  EXPECT_LT(worst, 2e-6);
}

TEST(MfMath, OutsideTheFastRangesStillFinite) {
  constexpr float kMax = std::numeric_limits<float>::max();
  for (float x : {1e5f, -1e5f, 1e20f, -1e20f, kMax, -kMax, 1e-30f, -1e-30f, 0.0f, -0.0f,
                  std::numeric_limits<float>::denorm_min()}) {
    EXPECT_TRUE(std::isfinite(fast::sin(x))) << x;
    EXPECT_TRUE(std::isfinite(fast::cos(x))) << x;
    EXPECT_TRUE(std::isfinite(fast::atan(x))) << x;
    EXPECT_NEAR(fast::sin(x), std::sin(x), 2e-7f) << x;
    EXPECT_NEAR(fast::cos(x), std::cos(x), 2e-7f) << x;
  }
  EXPECT_EQ(fast::exp(100.0f), std::exp(100.0f));
  EXPECT_EQ(fast::exp(-100.0f), std::exp(-100.0f));
  EXPECT_EQ(fast::log(1e-40f), std::log(1e-40f));
  EXPECT_EQ(fast::log(1.0f), 0.0f);
  EXPECT_EQ(fast::exp(0.0f), 1.0f);
}

}  // namespace
}  // namespace tread::mf::detail
