// The float elementary functions of src/mf/mf_math.hpp (tread's tan and atan, x^y as exp(y ln x))
// against libm in double, over dense sweeps of the ranges the Magic Formula uses (and beyond). Each
// test states the bound it checks and prints the largest error it found.
#include "mf/mf_math.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
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

// The four-lane float functions behind mf_cores: fast::atan4 (same bound as fast::atan) over
// |x| ≤ 1e7, fast::sin_cos4 over the whole range it is used on, |y| ≤ kTrigMax.
TEST(MfMath, FourLaneAtanAbsoluteErrorBelow2em7) {
  double worst = 0.0;
  for (double hi : {20.0, 1e7}) {
    const int n = 400000;
    for (int i = 0; i <= n; i += 4) {
      fast::F4 x;
      for (int lane = 0; lane < 4; ++lane) {
        x[lane] = static_cast<float>(-hi + 2.0 * hi * (i + lane) / n);
      }
      const fast::F4 got = fast::atan4(x);
      for (int lane = 0; lane < 4; ++lane) {
        const double err =
            std::fabs(static_cast<double>(got[lane]) - std::atan(static_cast<double>(x[lane])));
        worst = std::max(worst, err);
      }
    }
  }
  std::printf("[ max err  ] atan4 %.3g (absolute)\n", worst);
  EXPECT_LT(worst, 2e-7);
}

TEST(MfMath, FourLaneSinCosAbsoluteErrorBelow2em7UpToAFewTurnsAnd1em6Beyond) {
  // The reduction's rounding grows with |y| (k·π/2 in three parts): a few turns, as the Magic
  // Formula's C·atan(...) gives (|y| ≤ |C|·π/2), stay at the polynomials' error.
  double worst_small = 0.0;
  double worst_large = 0.0;
  for (double hi : {10.0, static_cast<double>(fast::kTrigMax)}) {
    const int n = 1000000;
    for (int i = 0; i <= n; i += 4) {
      fast::F4 y;
      for (int lane = 0; lane < 4; ++lane) {
        y[lane] = static_cast<float>(-hi + 2.0 * hi * (i + lane) / n);
      }
      const fast::F4 s = fast::sin_cos4(y, fast::I4{});
      const fast::F4 c = fast::sin_cos4(y, fast::I4{} + 1);
      for (int lane = 0; lane < 4; ++lane) {
        const double yd = static_cast<double>(y[lane]);
        const double err = std::max(std::fabs(static_cast<double>(s[lane]) - std::sin(yd)),
                                    std::fabs(static_cast<double>(c[lane]) - std::cos(yd)));
        (hi <= 10.0 ? worst_small : worst_large) =
            std::max(hi <= 10.0 ? worst_small : worst_large, err);
      }
    }
  }
  std::printf("[ max err  ] sin/cos four lanes %.3g on |y| <= 10, %.3g on |y| <= %g (absolute)\n",
              worst_small, worst_large, static_cast<double>(fast::kTrigMax));
  EXPECT_LT(worst_small, 2e-7);
  EXPECT_LT(worst_large, 1e-6);
}

// The core itself against the same formula in scalar float (fast::atan, libm sin/cos) for the
// Magic Formula's ranges: C in [0.5, 2.5], E in [−3, 1], |x| ≤ 20, sin and cos lanes mixed.
TEST(MfMath, FourLaneCoreMatchesTheScalarFloatFormulaWithin5em7) {
  double worst = 0.0;
  std::uint32_t state = 2024U;
  const auto uniform = [&state](double lo, double hi) {
    state = state * 1664525U + 1013904223U;
    return lo + (hi - lo) * static_cast<double>(state >> 8U) / 16777216.0;
  };
  for (int n = 0; n < 200000; ++n) {
    Cores<float> cores;
    for (int lane = 0; lane < 4; ++lane) {
      cores.add(static_cast<float>(uniform(0.5, 2.5)), static_cast<float>(uniform(-20.0, 20.0)),
                static_cast<float>(uniform(-3.0, 1.0)), (n + lane) % 2 == 0);
    }
    float out[kMaxCores];
    mf_cores(cores, out);
    for (int lane = 0; lane < 4; ++lane) {
      const float x = cores.x[lane];
      const float y = cores.c[lane] * fast::atan(x - cores.e[lane] * (x - fast::atan(x)));
      const float want = cores.cosine[lane] ? std::cos(y) : std::sin(y);
      worst = std::max(worst, static_cast<double>(std::fabs(out[lane] - want)));
    }
  }
  std::printf("[ max err  ] four-lane core vs scalar float %.3g (absolute)\n", worst);
  EXPECT_LT(worst, 5e-7);
}

TEST(MfMath, FourLaneCoreMatchesTheScalarFormulaLaneByLane) {
  // Fewer than four lanes, huge angles (libm fallback), infinite and huge x: each lane is what the
  // scalar float functions give within the four-lane error, and finite wherever they are.
  Cores<float> cores;
  cores.add(1.6f, 3.0f, -0.5f, false);
  cores.add(4.0e4f, 10.0f, 0.2f, true);  // |C·atan| > kTrigMax: libm
  cores.add(1.3f, std::numeric_limits<float>::max(), 0.0f, false);
  float out[kMaxCores];
  mf_cores(cores, out);
  for (int lane = 0; lane < 3; ++lane) {
    const float x = cores.x[lane];
    const float y = cores.c[lane] * fast::atan(x - cores.e[lane] * (x - fast::atan(x)));
    const float want = cores.cosine[lane] ? std::cos(y) : std::sin(y);
    EXPECT_TRUE(std::isfinite(out[lane])) << lane;
    EXPECT_NEAR(out[lane], want, 5e-6f) << lane;
  }
  EXPECT_EQ(out[3], out[0]);  // unused slot of a pass of four: the group's first core again
  EXPECT_EQ(out[4], 0.0f);    // unused group
}

// double's cores run stage by stage over all cores (every inner atan, then every outer atan, then
// every sin/cos): each must still be exactly the formula as written, to the bit, for every count
// of cores and any mix of sin and cos, NaN and infinities included.
TEST(MfMath, DoubleCoresAreTheFormulaBitForBit) {
  std::uint64_t state = 2026U;
  const auto uniform = [&state](double lo, double hi) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * static_cast<double>(state >> 11U) / 9007199254740992.0;
  };
  const double specials[] = {0.0,
                             -0.0,
                             1e300,
                             -1e300,
                             std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::quiet_NaN(),
                             5e-324,
                             -std::numeric_limits<double>::infinity()};
  long compared = 0;
  for (int n = 0; n < 100000; ++n) {
    Cores<double> cores;
    const int count = 1 + n % kMaxCores;
    for (int k = 0; k < count; ++k) {
      double x = uniform(-50.0, 50.0);
      if ((n + k) % 97 == 0) x = specials[static_cast<std::size_t>(n / 97 + k) % 8];
      cores.add(uniform(0.5, 2.5), x, uniform(-3.0, 1.0), uniform(0.0, 1.0) < 0.5);
    }
    double out[kMaxCores];
    mf_cores(cores, out);
    for (int k = 0; k < count; ++k) {
      const double x = cores.x[k];
      const double y = cores.c[k] * std::atan(x - cores.e[k] * (x - std::atan(x)));
      const double want = cores.cosine[k] ? std::cos(y) : std::sin(y);
      if (std::isnan(want)) {
        EXPECT_TRUE(std::isnan(out[k])) << n << ' ' << k;
      } else {
        EXPECT_EQ(std::bit_cast<std::uint64_t>(out[k]), std::bit_cast<std::uint64_t>(want))
            << n << ' ' << k << ": x " << x;
      }
      ++compared;
    }
  }
  EXPECT_EQ(compared, 100000L / kMaxCores * (kMaxCores * (kMaxCores + 1) / 2));
}

}  // namespace
}  // namespace tread::mf::detail
