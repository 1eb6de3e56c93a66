// The float elementary functions of src/mf/mf_math.hpp (tread's tan and atan, x^y as exp(y ln x))
// against libm in double, over dense sweeps of the ranges the Magic Formula uses (and beyond). Each
// test states the bound it checks and prints the largest error it found.
#include "mf/mf_math.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

double dtan(double x) {
  return std::tan(x);
}
double datan(double x) {
  return std::atan(x);
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
    EXPECT_TRUE(std::isfinite(fast::tan(x))) << x;
    EXPECT_TRUE(std::isfinite(fast::atan(x))) << x;
    EXPECT_NEAR(fast::atan(x), std::atan(x), 2e-7f) << x;
  }
  // Beyond the reduction's range tan is libm's.
  EXPECT_EQ(fast::tan(1e20f), std::tan(1e20f));
  EXPECT_EQ(fast::tan(0.0f), 0.0f);
}

}  // namespace
}  // namespace tread::mf::detail
