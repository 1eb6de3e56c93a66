// The four-lane float functions of src/mf/mf_lanes.hpp (lanes::F4, the scalar evaluate_four runs
// on) against libm in double: dense sweeps and random points over the ranges the Magic Formula
// uses, and the edges (exp near overflow and underflow, log of denormals, trig beyond the
// reduction's range and at multiples of π/2, atan and cos(atan) of huge values). Each test states
// the bound it checks (measured on x86-64 with SSE, with margin) and prints the largest error it
// found. Values go through the lanes four at a time, each lane with a different argument.
#include "mf/mf_lanes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

namespace tread::mf::lanes {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kMaxF = std::numeric_limits<float>::max();
constexpr float kMinNormal = std::numeric_limits<float>::min();
constexpr float kDenormMin = std::numeric_limits<float>::denorm_min();

F4 pack(float a, float b, float c, float d) {
  F4 r;
  r.v[0] = a;
  r.v[1] = b;
  r.v[2] = c;
  r.v[3] = d;
  return r;
}

/// f applied to xs four at a time (the last group padded with its first value).
template <typename Fn>
std::vector<float> on_lanes(Fn f, const std::vector<float>& xs) {
  std::vector<float> out(xs.size());
  for (std::size_t g = 0; g < xs.size(); g += 4) {
    F4 x(xs[g]);
    for (std::size_t k = 0; k < 4 && g + k < xs.size(); ++k) x.v[k] = xs[g + k];
    const F4 y = f(x);
    for (std::size_t k = 0; k < 4 && g + k < xs.size(); ++k) out[g + k] = y[static_cast<int>(k)];
  }
  return out;
}

/// n + 1 evenly spaced floats in [lo, hi].
std::vector<float> linear_grid(double lo, double hi, int n) {
  std::vector<float> xs;
  xs.reserve(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) xs.push_back(static_cast<float>(lo + (hi - lo) * i / n));
  return xs;
}

/// n + 1 logarithmically spaced floats in [lo, hi] (lo, hi > 0).
std::vector<float> log_grid(double lo, double hi, int n) {
  std::vector<float> xs;
  xs.reserve(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) {
    xs.push_back(static_cast<float>(lo * std::pow(hi / lo, static_cast<double>(i) / n)));
  }
  return xs;
}

/// n floats uniform in [lo, hi].
std::vector<float> random_uniform(double lo, double hi, int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<float> xs;
  for (int i = 0; i < n; ++i) xs.push_back(static_cast<float>(u(rng)));
  return xs;
}

/// n floats with uniformly random bit patterns in [lo_bits, hi_bits] (e.g. every positive finite
/// float, denormals included: each binade equally often).
std::vector<float> random_bits(std::uint32_t lo_bits, std::uint32_t hi_bits, int n,
                               std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::uint32_t> u(lo_bits, hi_bits);
  std::vector<float> xs;
  for (int i = 0; i < n; ++i) xs.push_back(std::bit_cast<float>(u(rng)));
  return xs;
}

/// One float ulp at |ref| (denormal spacing below the smallest normal).
double float_ulp(double ref) {
  int e = 0;
  std::frexp(ref, &e);  // |ref| = m·2^e, m in [0.5, 1)
  return std::max(std::ldexp(1.0, e - 24), static_cast<double>(kDenormMin));
}

struct Errors {
  double relative = 0.0;  // |got − ref| / max(|ref|, floor)
  double ulp = 0.0;       // |got − ref| / ulp(ref)
  float worst_x = 0.0f;
};

/// Errors of got[i] against ref(xs[i]) in double; every got must be finite.
template <typename R>
Errors errors(const std::vector<float>& xs, const std::vector<float>& got, R ref, double floor) {
  Errors e;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double want = ref(static_cast<double>(xs[i]));
    const double g = static_cast<double>(got[i]);
    EXPECT_TRUE(std::isfinite(g)) << "x = " << xs[i];
    const double d = std::fabs(g - want);
    const double rel = d / std::max(std::fabs(want), floor);
    if (rel > e.relative) {
      e.relative = rel;
      e.worst_x = xs[i];
    }
    e.ulp = std::max(e.ulp, d / float_ulp(want));
  }
  return e;
}

std::vector<float> concat(std::vector<float> a, const std::vector<float>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// ---- exp ------------------------------------------------------------------------------------

TEST(MfLanes, ExpRelativeErrorBelow3em7WhereTheResultIsNormal) {
  // e^x over every x with a normal float result: dense, plus random; the Magic Formula's own
  // arguments (PKX3·dFz, PTX3·dFz, y·ln x of pow) lie within |x| ≤ 30.
  const std::vector<float> xs =
      concat(concat(linear_grid(-87.3, 88.72, 2000000), linear_grid(-30.0, 30.0, 600000)),
             random_uniform(-87.3, 88.72, 400000, 11));
  const Errors e = errors(
      xs, on_lanes([](F4 x) { return exp(x); }, xs), [](double x) { return std::exp(x); }, 1e-300);
  std::printf("[ max err  ] exp %.3g relative (%.2f ulp) at x = %.9g on [-87.3, 88.72]\n",
              e.relative, e.ulp, static_cast<double>(e.worst_x));
  EXPECT_LT(e.relative, 3e-7);
  EXPECT_LT(e.ulp, 2.5);
}

TEST(MfLanes, ExpDenormalResultsWithinOneDenormalStep) {
  // −103.97 < x < −87.34: the result is denormal; its only error is the rounding to the denormal
  // grid, so it lies within one step of e^x.
  const std::vector<float> xs =
      concat(linear_grid(-103.9, -87.34, 400000), random_uniform(-103.9, -87.34, 100000, 12));
  const std::vector<float> got = on_lanes([](F4 x) { return exp(x); }, xs);
  double worst_steps = 0.0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double want = std::exp(static_cast<double>(xs[i]));
    ASSERT_TRUE(std::isfinite(got[i]) && got[i] >= 0.0f) << xs[i];
    worst_steps = std::max(worst_steps, std::fabs(static_cast<double>(got[i]) - want) /
                                            static_cast<double>(kDenormMin));
  }
  std::printf("[ max err  ] exp, denormal results: %.3g denormal steps\n", worst_steps);
  EXPECT_LE(worst_steps, 1.0);
}

TEST(MfLanes, ExpAtTheOverflowAndUnderflowEdgesIsExpf) {
  // Like expf: inf above ln(FLT_MAX) = 88.7228, denormals below −87.336, 0 below −103.97, and
  // within 2 ulp of expf (1 denormal step below the normals) where finite.
  const std::vector<float> xs = {
      88.0f,   88.7f,   88.72f,  88.7228f, 88.72283f, 88.7229f, 88.73f,     89.0f,      89.5f,
      100.0f,  1e10f,   kMaxF,   kInf,     -87.3f,    -87.33f,  -87.34f,    -87.5f,     -90.0f,
      -100.0f, -103.0f, -103.2f, -103.28f, -103.9f,   -103.98f, -104.0f,    -104.5f,    -110.0f,
      -200.0f, -1e10f,  -kMaxF,  -kInf,    0.0f,      -0.0f,    kDenormMin, -kDenormMin};
  const std::vector<float> got = on_lanes([](F4 x) { return exp(x); }, xs);
  double worst_ulp = 0.0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const float want = std::exp(xs[i]);  // expf
    if (std::isinf(want)) {
      EXPECT_TRUE(std::isinf(got[i]) && got[i] > 0.0f) << xs[i] << ": " << got[i];
    } else if (!(want > 0.0f)) {  // expf underflows to 0
      EXPECT_EQ(got[i], 0.0f) << xs[i];
    } else {
      const double ulps = std::fabs(static_cast<double>(got[i]) - static_cast<double>(want)) /
                          float_ulp(static_cast<double>(want));
      worst_ulp = std::max(worst_ulp, ulps);
      EXPECT_LE(ulps, want < kMinNormal ? 1.0 : 2.0) << xs[i] << ": " << got[i] << " vs " << want;
    }
  }
  // The named points: finite below ln(FLT_MAX), inf at 89, a denormal at −103, 0 at −110.
  const F4 r = exp(pack(88.7f, 89.0f, -103.0f, -110.0f));
  EXPECT_TRUE(std::isfinite(r[0]) && r[0] > 3.0e38f);
  EXPECT_TRUE(std::isinf(r[1]));
  EXPECT_TRUE(r[2] > 0.0f && r[2] < kMinNormal);
  EXPECT_EQ(r[3], 0.0f);
  EXPECT_EQ(exp(F4(0.0f))[0], 1.0f);
  std::printf("[ max err  ] exp at the edges: %.3g ulp of expf where finite\n", worst_ulp);
}

// ---- log ------------------------------------------------------------------------------------

TEST(MfLanes, LogWithinTwoUlpOverEveryPositiveFloat) {
  // Every binade from the smallest denormal to FLT_MAX (random bit patterns), and dense sweeps of
  // the load and pressure ratios pow() sees (1e-3 … 20) and around 1.
  const std::vector<float> xs =
      concat(concat(random_bits(1U, 0x7f7fffffU, 1000000, 21), log_grid(1e-3, 20.0, 1000000)),
             linear_grid(0.5, 2.0, 1000000));
  const Errors e = errors(
      xs, on_lanes([](F4 x) { return log(x); }, xs), [](double x) { return std::log(x); }, 1e-300);
  std::printf("[ max err  ] log %.3g relative, %.2f ulp (worst relative at x = %.9g)\n", e.relative,
              e.ulp, static_cast<double>(e.worst_x));
  EXPECT_LT(e.ulp, 2.0);
  EXPECT_LT(e.relative, 2.5e-7);
}

TEST(MfLanes, LogOfOneDenormalsPowersOfTwoAndLargeValues) {
  EXPECT_EQ(log(F4(1.0f))[0], 0.0f);
  double worst_ulp = 0.0;
  std::vector<float> xs;
  for (int k = -149; k <= 127; ++k) xs.push_back(std::ldexp(1.0f, k));  // 2^-149 … 2^127
  for (float x : {kDenormMin, 3.0f * kDenormMin, 1e-40f, 1e-39f, 1.1e-38f, kMinNormal, 1e30f, 1e38f,
                  kMaxF, 0.999999f, 1.000001f, 1.0f, 2.718281828f}) {
    xs.push_back(x);
  }
  const std::vector<float> got = on_lanes([](F4 x) { return log(x); }, xs);
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double want = std::log(static_cast<double>(xs[i]));
    const double ulps = std::fabs(static_cast<double>(got[i]) - want) / float_ulp(want);
    worst_ulp = std::max(worst_ulp, ulps);
    EXPECT_LE(ulps, 1.0) << "log " << xs[i] << " = " << got[i] << ", want " << want;
  }
  // Powers of two exactly k·ln 2 rounded (ln 2 in two parts, the mantissa part 0).
  std::printf("[ max err  ] log at powers of two, denormals, large values: %.3g ulp\n", worst_ulp);
}

// ---- pow ------------------------------------------------------------------------------------

TEST(MfLanes, PowAsExpLogRelativeErrorBelow2em6InTheMagicFormulasRange) {
  // As in mf_math_test (the scalar float path): load, pressure and deflection ratios in
  // (0, 20], exponents of My (QSY7, QSY8), the contact width's 1/3, Fz62's Q_FCY2.
  double worst = 0.0;
  for (float y : {-2.0f, -0.4f, 0.3333333f, 0.85f, 1.5f, 3.0f}) {
    const std::vector<float> xs = log_grid(1e-3, 20.0, 200000);
    const Errors e = errors(
        xs, on_lanes([y](F4 x) { return pow(x, F4(y)); }, xs),
        [y](double x) { return std::pow(x, static_cast<double>(y)); }, 1e-300);
    worst = std::max(worst, e.relative);
  }
  std::printf("[ max err  ] pow %.3g (relative)\n", worst);
  EXPECT_LT(worst, 2e-6);
}

TEST(MfLanes, PowOfRandomPositiveBasesAndExponentsPerLane) {
  // x in [1e-6, 1e6], y in [−4, 4], different in every lane: the error of exp(y·ln x) grows with
  // |y·ln x| (the rounding of the product), relative error ≤ 1.5e-7·(1 + |y ln x|) + 2 ulp.
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> lx(std::log(1e-6), std::log(1e6));
  std::uniform_real_distribution<double> uy(-4.0, 4.0);
  double worst_scaled = 0.0;
  for (int n = 0; n < 250000; ++n) {
    F4 x;
    F4 y;
    for (int k = 0; k < 4; ++k) {
      x.v[k] = static_cast<float>(std::exp(lx(rng)));
      y.v[k] = static_cast<float>(uy(rng));
    }
    const F4 r = pow(x, y);
    for (int k = 0; k < 4; ++k) {
      const double xd = static_cast<double>(x[k]);
      const double yd = static_cast<double>(y[k]);
      const double want = std::pow(xd, yd);
      const double rel = std::fabs(static_cast<double>(r[k]) - want) / want;
      worst_scaled = std::max(worst_scaled, rel / (1.0 + std::fabs(yd * std::log(xd))));
    }
  }
  std::printf("[ max err  ] pow, random: %.3g x (1 + |y ln x|) relative\n", worst_scaled);
  EXPECT_LT(worst_scaled, 1.5e-7);
  // x^0 = 1 and 1^y = 1 exactly.
  EXPECT_EQ(pow(pack(0.3f, 2.0f, 1e5f, 7.0f), F4(0.0f))[2], 1.0f);
  EXPECT_EQ(pow(F4(1.0f), pack(-3.0f, 0.5f, 2.0f, 100.0f))[3], 1.0f);
}

// ---- sqrt, abs: exact -------------------------------------------------------------------------

TEST(MfLanes, SqrtAndAbsAreExact) {
  // sqrt is correctly rounded (the vector instruction, or std::sqrt per lane): equal to sqrtf for
  // every non-negative float incl. 0, denormals and inf; abs clears the sign bit of anything.
  std::vector<float> xs = random_bits(0U, 0x7f800000U, 400000, 41);
  for (float x : {0.0f, -0.0f, kDenormMin, kMinNormal, 1.0f, 2.0f, 4.0f, kMaxF, kInf}) {
    xs.push_back(x);
  }
  const std::vector<float> got = on_lanes([](F4 x) { return sqrt(x); }, xs);
  int sqrt_mismatches = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    if (std::bit_cast<std::uint32_t>(got[i]) != std::bit_cast<std::uint32_t>(std::sqrt(xs[i]))) {
      if (++sqrt_mismatches <= 5) ADD_FAILURE() << "sqrt " << xs[i] << " = " << got[i];
    }
  }
  EXPECT_EQ(sqrt_mismatches, 0);
  EXPECT_TRUE(std::isnan(sqrt(F4(-1.0f))[0]));

  const std::vector<float> all =
      concat(random_bits(0U, 0xffffffffU, 400000, 42), {-0.0f, -kInf, -kMaxF, -kDenormMin, -1.0f});
  const std::vector<float> a = on_lanes([](F4 x) { return abs(x); }, all);
  int abs_mismatches = 0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (std::bit_cast<std::uint32_t>(a[i]) != std::bit_cast<std::uint32_t>(std::fabs(all[i]))) {
      ++abs_mismatches;
    }
  }
  EXPECT_EQ(abs_mismatches, 0);
}

// ---- sin, cos, tan ----------------------------------------------------------------------------

TEST(MfLanes, SinCosAbsoluteErrorBelow2em7UpToAFewTurnsAnd1em6UpTo32768) {
  // The Magic Formula's angles: C·atan(…) (|y| ≤ |C|·π/2), α, γ, π·Vx/VXLOW; then the whole
  // reduction range |x| ≤ 32768 (the reduction's rounding grows with |x|).
  const std::vector<float> small =
      concat(linear_grid(-10.0, 10.0, 2000000), random_uniform(-10.0, 10.0, 200000, 51));
  const std::vector<float> large = concat(linear_grid(-32768.0, 32768.0, 2000000),
                                          random_uniform(-32768.0, 32768.0, 200000, 52));
  const auto sin_ref = [](double x) { return std::sin(x); };
  const auto cos_ref = [](double x) { return std::cos(x); };
  const auto sin4 = [](F4 x) { return mf_sin(x); };
  const auto cos4 = [](F4 x) { return mf_cos(x); };
  // Absolute errors: floor 1.
  const double s_small = errors(small, on_lanes(sin4, small), sin_ref, 1.0).relative;
  const double c_small = errors(small, on_lanes(cos4, small), cos_ref, 1.0).relative;
  const double s_large = errors(large, on_lanes(sin4, large), sin_ref, 1.0).relative;
  const double c_large = errors(large, on_lanes(cos4, large), cos_ref, 1.0).relative;
  std::printf(
      "[ max err  ] sin %.3g cos %.3g on |x| <= 10; sin %.3g cos %.3g on |x| <= 32768 "
      "(absolute)\n",
      s_small, c_small, s_large, c_large);
  EXPECT_LT(std::max(s_small, c_small), 2e-7);
  EXPECT_LT(std::max(s_large, c_large), 1e-6);
}

TEST(MfLanes, SinRelativeErrorForSmallAngles) {
  // sin x ≈ x: relative accuracy down to the smallest angles (tiny slips and cambers).
  std::vector<float> xs = log_grid(1e-38, 0.5, 400000);
  const std::vector<float> neg = on_lanes([](F4 x) { return -x; }, xs);
  xs = concat(xs, neg);
  const Errors e = errors(
      xs, on_lanes([](F4 x) { return mf_sin(x); }, xs), [](double x) { return std::sin(x); },
      1e-300);
  std::printf("[ max err  ] sin, 1e-38 <= |x| <= 0.5: %.3g relative (%.2f ulp)\n", e.relative,
              e.ulp);
  EXPECT_LT(e.ulp, 2.0);
}

/// tan's error as an error of its argument: the angle between atan(got) and atan(tan x) (modulo
/// π, so that the two sides of a pole are close). Near the zeros and poles of tan its relative
/// error is that of the reduced argument, which no reduction in finite precision bounds; this
/// measure stays meaningful everywhere.
double tan_argument_error(const std::vector<float>& xs) {
  const std::vector<float> got = on_lanes([](F4 x) { return mf_tan(x); }, xs);
  const double pi = 3.14159265358979323846;
  double worst = 0.0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    EXPECT_TRUE(std::isfinite(got[i])) << xs[i];
    double d =
        std::atan(static_cast<double>(got[i])) - std::atan(std::tan(static_cast<double>(xs[i])));
    d -= pi * std::nearbyint(d / pi);
    worst = std::max(worst, std::fabs(d));
  }
  return worst;
}

TEST(MfLanes, SinCosTanAtMultiplesOfHalfPi) {
  // x = float(k·π/2), |k| ≤ 20860 (|x| ≤ 32768): the reduction's three-part π/2 gives the small
  // remainder accurately, so sin and cos stay within their absolute bound at their zeros, and tan
  // (near 0 at even k, huge at odd k) within its argument-error bound.
  std::vector<float> xs;
  for (int k = -20860; k <= 20860; ++k) {
    xs.push_back(static_cast<float>(k * 1.57079632679489661923));
  }
  const double s = errors(
                       xs, on_lanes([](F4 x) { return mf_sin(x); }, xs),
                       [](double x) { return std::sin(x); }, 1.0)
                       .relative;
  const double c = errors(
                       xs, on_lanes([](F4 x) { return mf_cos(x); }, xs),
                       [](double x) { return std::cos(x); }, 1.0)
                       .relative;
  const double t = tan_argument_error(xs);
  std::printf(
      "[ max err  ] at k*pi/2, |k| <= 20860: sin %.3g cos %.3g (absolute), tan %.3g (argument)\n",
      s, c, t);
  EXPECT_LT(std::max(s, c), 1e-6);
  EXPECT_LT(t, 1e-6);  // the rounding of k·(π/2 part 2) in the reduction: up to 2^-21 here
  // The first turns (the Magic Formula's range): relative accuracy even at the zeros of sin and
  // tan (sin(float(π)) = −8.7e-8), set by the third part of π/2 (k·5e-15).
  std::vector<float> few;
  for (int k = -8; k <= 8; ++k) few.push_back(static_cast<float>(k * 1.57079632679489661923));
  const Errors t_few = errors(
      few, on_lanes([](F4 x) { return mf_tan(x); }, few), [](double x) { return std::tan(x); },
      1e-30);
  const Errors s_few = errors(
      few, on_lanes([](F4 x) { return mf_sin(x); }, few), [](double x) { return std::sin(x); },
      1e-30);
  std::printf("[ max err  ] at k*pi/2, |k| <= 8: sin %.3g, tan %.3g (relative)\n", s_few.relative,
              t_few.relative);
  EXPECT_LT(t_few.relative, 5e-6);
  EXPECT_LT(s_few.relative, 5e-6);
}

TEST(MfLanes, TanRelativeErrorBelow1em6) {
  // α (|α| ≤ 1.5707: α* = tan α, the low-speed Vsy, turn slip): relative error; the whole
  // reduction range |x| ≤ 32768: argument error (see tan_argument_error).
  const std::vector<float> xs =
      concat(linear_grid(-1.5707, 1.5707, 2000000), random_uniform(-1.5707, 1.5707, 200000, 61));
  const Errors e = errors(
      xs, on_lanes([](F4 x) { return mf_tan(x); }, xs), [](double x) { return std::tan(x); },
      1e-30);
  const double w = tan_argument_error(concat(linear_grid(-32768.0, 32768.0, 1000000),
                                             random_uniform(-32768.0, 32768.0, 100000, 62)));
  std::printf("[ max err  ] tan %.3g relative on |x| <= 1.5707, %.3g (argument) on |x| <= 32768\n",
              e.relative, w);
  EXPECT_LT(e.relative, 1e-6);
  EXPECT_LT(w, 1e-6);
}

TEST(MfLanes, TrigBeyondTheReductionRangeIsLibmLaneByLane) {
  // |x| > 32768 (and ±inf: NaN, like libm) goes through sinf/cosf/tanf in that lane only; the
  // other lanes of the same call are the polynomials' results.
  const std::vector<float> big = concat(
      concat(random_uniform(32768.5, 1e6, 20000, 71), random_uniform(-1e30, -32769.0, 20000, 72)),
      {32768.004f, -32768.004f, 1e20f, kMaxF, -kMaxF});
  for (std::size_t i = 0; i < big.size(); ++i) {
    const float in_range = static_cast<float>(i % 97) * 0.25f - 12.0f;
    const F4 x = pack(in_range, big[i], -in_range, in_range + 1.0f);
    const F4 x_poly = pack(in_range, 0.5f, -in_range, in_range + 1.0f);
    const F4 s = mf_sin(x);
    const F4 c = mf_cos(x);
    const F4 t = mf_tan(x);
    ASSERT_EQ(s[1], std::sin(big[i])) << big[i];
    ASSERT_EQ(c[1], std::cos(big[i])) << big[i];
    ASSERT_EQ(t[1], std::tan(big[i])) << big[i];
    for (int k : {0, 2, 3}) {
      ASSERT_EQ(s[k], mf_sin(x_poly)[k]);
      ASSERT_EQ(c[k], mf_cos(x_poly)[k]);
      ASSERT_EQ(t[k], mf_tan(x_poly)[k]);
    }
  }
  const F4 inf_lanes = pack(kInf, 1.0f, -kInf, 0.0f);
  EXPECT_TRUE(std::isnan(mf_sin(inf_lanes)[0]));
  EXPECT_TRUE(std::isnan(mf_cos(inf_lanes)[2]));
  EXPECT_TRUE(std::isnan(mf_tan(inf_lanes)[0]));
  EXPECT_NEAR(mf_sin(inf_lanes)[1], std::sin(1.0f), 2e-7f);
  EXPECT_EQ(mf_sin(inf_lanes)[3], 0.0f);
  EXPECT_EQ(mf_cos(inf_lanes)[3], 1.0f);
}

// ---- atan, cos(atan) --------------------------------------------------------------------------

TEST(MfLanes, AtanAbsoluteErrorBelow2em7AndPlusMinusHalfPiForHugeAndInf) {
  const std::vector<float> xs =
      concat(concat(linear_grid(-20.0, 20.0, 2000000), linear_grid(-1e7, 1e7, 1000000)),
             random_uniform(-50.0, 50.0, 200000, 81));
  const double abs_err = errors(
                             xs, on_lanes([](F4 x) { return mf_atan(x); }, xs),
                             [](double x) { return std::atan(x); }, 1.0)
                             .relative;
  // Small arguments: relative accuracy (atan x ≈ x).
  const std::vector<float> tiny = log_grid(1e-38, 0.4, 200000);
  const Errors rel = errors(
      tiny, on_lanes([](F4 x) { return mf_atan(x); }, tiny), [](double x) { return std::atan(x); },
      1e-300);
  std::printf("[ max err  ] atan %.3g (absolute), %.3g relative on 1e-38 <= x <= 0.4\n", abs_err,
              rel.relative);
  EXPECT_LT(abs_err, 2e-7);
  EXPECT_LT(rel.relative, 5e-7);
  // Huge and infinite arguments: ±π/2.
  const float half_pi = 1.57079632679489661923f;
  const F4 h = mf_atan(pack(1e30f, -kMaxF, kInf, -kInf));
  const F4 h2 = mf_atan(pack(1e8f, -1e20f, kMaxF, 3.0e38f));
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(std::fabs(h[k]), half_pi, 2e-7f) << k;
    EXPECT_NEAR(std::fabs(h2[k]), half_pi, 2e-7f) << k;
  }
  EXPECT_GT(h[0], 0.0f);
  EXPECT_LT(h[1], 0.0f);
  EXPECT_GT(h[2], 0.0f);
  EXPECT_LT(h[3], 0.0f);
  EXPECT_EQ(mf_atan(F4(0.0f))[0], 0.0f);
}

TEST(MfLanes, CosAtanRelativeErrorBelow4em7AndLimitZeroForHugeX) {
  // cos(atan x) = 1/√(1+x²): relative error over |x| from 1e-20 to 1e19 (both signs); beyond
  // √FLT_MAX ≈ 1.8e19 x² overflows and the lanes give the limit 0, finite, within 1/|x| of the
  // true value (≤ 5.5e-20).
  std::vector<float> xs = concat(log_grid(1e-20, 1e19, 1000000), linear_grid(-50.0, 50.0, 400000));
  const std::vector<float> neg = on_lanes([](F4 x) { return -x; }, xs);
  xs = concat(xs, neg);
  xs.push_back(0.0f);
  const auto ref = [](double x) { return 1.0 / std::sqrt(1.0 + x * x); };
  const Errors e = errors(xs, on_lanes([](F4 x) { return cos_atan(x); }, xs), ref, 1e-300);
  std::printf("[ max err  ] cos_atan %.3g relative (%.2f ulp) on |x| <= 1e19\n", e.relative, e.ulp);
  EXPECT_LT(e.relative, 4e-7);

  const std::vector<float> huge = concat(log_grid(1.9e19, 3.4e38, 100000), {kMaxF, kInf});
  const std::vector<float> got = on_lanes([](F4 x) { return cos_atan(x); }, huge);
  double worst_abs = 0.0;
  for (std::size_t i = 0; i < huge.size(); ++i) {
    ASSERT_TRUE(std::isfinite(got[i])) << huge[i];
    ASSERT_GE(got[i], 0.0f) << huge[i];
    const double want = std::isinf(huge[i]) ? 0.0 : 1.0 / static_cast<double>(huge[i]);
    worst_abs = std::max(worst_abs, std::fabs(static_cast<double>(got[i]) - want));
  }
  std::printf("[ max err  ] cos_atan for |x| >= 1.9e19: %.3g absolute\n", worst_abs);
  EXPECT_LE(worst_abs, 5.5e-20);
  EXPECT_EQ(cos_atan(pack(kInf, -kInf, 0.0f, 1.0f))[0], 0.0f);
  EXPECT_EQ(cos_atan(pack(kInf, -kInf, 0.0f, 1.0f))[2], 1.0f);
}

// ---- acos: libm lane by lane --------------------------------------------------------------------

TEST(MfLanes, AcosIsLibmPerLane) {
  const F4 a = pack(-1.0f, -0.3f, 0.7f, 1.0f);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(acos(a)[k], std::acos(a[k]));
}

// ---- the Magic Formula cores ------------------------------------------------------------------

/// trig(c·atan(x − e·(x − atan x))) in double.
double core_double(float c, float x, float e, bool cosine) {
  const double xd = static_cast<double>(x);
  const double y =
      static_cast<double>(c) * std::atan(xd - static_cast<double>(e) * (xd - std::atan(xd)));
  return cosine ? std::cos(y) : std::sin(y);
}

TEST(MfLanes, CoresMatchTheScalarFloatCoresAndDouble) {
  // Random cores in the Magic Formula's ranges (C in [0.5, 2.5], E in [−3, 1], |x| ≤ 20), 1 to 8
  // per call, sin and cos mixed, every lane different: each lane against the scalar float
  // mf_cores (the same polynomials, tested in mf_math_test) and against the formula in double.
  std::mt19937_64 rng(91);
  std::uniform_real_distribution<double> uc(0.5, 2.5);
  std::uniform_real_distribution<double> ue(-3.0, 1.0);
  std::uniform_real_distribution<double> ux(-20.0, 20.0);
  std::uniform_int_distribution<int> count(1, detail::kMaxCores);
  double worst_scalar = 0.0;
  double worst_double = 0.0;
  for (int n = 0; n < 50000; ++n) {
    detail::Cores<F4> cores;
    std::array<detail::Cores<float>, 4> scalar;
    const int m = count(rng);
    for (int i = 0; i < m; ++i) {
      F4 c;
      F4 x;
      F4 e;
      for (int k = 0; k < 4; ++k) {
        c.v[k] = static_cast<float>(uc(rng));
        x.v[k] = static_cast<float>(ux(rng));
        e.v[k] = static_cast<float>(ue(rng));
      }
      const bool cosine = ((n + i) % 3) == 0;
      cores.add(c, x, e, cosine);
      for (int k = 0; k < 4; ++k) {
        scalar[static_cast<std::size_t>(k)].add(c[k], x[k], e[k], cosine);
      }
    }
    F4 out[detail::kMaxCores];
    mf_cores(cores, out);
    for (int k = 0; k < 4; ++k) {
      float want[detail::kMaxCores];
      detail::mf_cores(scalar[static_cast<std::size_t>(k)], want);
      for (int i = 0; i < m; ++i) {
        const double got = static_cast<double>(out[i][k]);
        ASSERT_TRUE(std::isfinite(got));
        worst_scalar = std::max(worst_scalar, std::fabs(got - static_cast<double>(want[i])));
        worst_double =
            std::max(worst_double, std::fabs(got - core_double(cores.c[i][k], cores.x[i][k],
                                                               cores.e[i][k], cores.cosine[i])));
      }
    }
  }
  std::printf("[ max err  ] four-lane cores: %.3g vs scalar float cores, %.3g vs double\n",
              worst_scalar, worst_double);
  EXPECT_LT(worst_scalar, 5e-7);
  EXPECT_LT(worst_double, 2e-6);
}

TEST(MfLanes, CoresWithAWideAngleInOneLaneGoThroughLibmThereOnly) {
  // C = 4e4 in lane 2 of core 1: |C·atan(…)| > 32768, libm in that lane; the other lanes and
  // cores are what they are without it.
  detail::Cores<F4> cores;
  cores.add(pack(1.6f, 1.3f, 1.1f, 2.0f), pack(3.0f, -5.0f, 0.5f, 12.0f),
            pack(-0.5f, 0.2f, 0.9f, -2.0f), false);
  cores.add(pack(1.2f, 0.9f, 4.0e4f, 1.9f), pack(-2.0f, 7.0f, 10.0f, kMaxF),
            pack(0.1f, -1.0f, 0.2f, 0.0f), true);
  F4 out[detail::kMaxCores];
  mf_cores(cores, out);
  detail::Cores<F4> narrow = cores;
  narrow.c[1].v[2] = 1.0f;
  F4 out_narrow[detail::kMaxCores];
  mf_cores(narrow, out_narrow);
  for (int i = 0; i < 2; ++i) {
    for (int k = 0; k < 4; ++k) {
      ASSERT_TRUE(std::isfinite(out[i][k])) << i << " " << k;
      EXPECT_NEAR(static_cast<double>(out[i][k]),
                  core_double(cores.c[i][k], cores.x[i][k], cores.e[i][k], cores.cosine[i]),
                  i == 1 && k == 2 ? 2e-2 : 1e-6)  // C = 4e4 magnifies atan's float rounding
          << i << " " << k;
      if (!(i == 1 && k == 2)) {
        EXPECT_EQ(out[i][k], out_narrow[i][k]) << i << " " << k;
      }
    }
  }
  // Lane 2 of core 1 is the scalar float formula: libm cos of the same float angle.
  detail::Cores<float> one;
  one.add(4.0e4f, 10.0f, 0.2f, true);
  float want[detail::kMaxCores];
  detail::mf_cores(one, want);
  EXPECT_EQ(out[1][2], want[0]);
}

// ---- Mask4, if_else, any_lane -----------------------------------------------------------------

TEST(MfLanes, MasksSelectAndCombinePerLane) {
  const F4 a = pack(1.0f, 2.0f, 3.0f, -0.0f);
  const F4 b = pack(2.0f, 2.0f, 1.0f, 0.0f);
  const Mask4 lt = a < b;
  const Mask4 le = a <= b;
  const Mask4 gt = a > b;
  const Mask4 ge = a >= b;
  const std::array<bool, 4> want_lt = {true, false, false, false};
  const std::array<bool, 4> want_le = {true, true, false, true};  // −0 ≤ 0
  for (int k = 0; k < 4; ++k) {
    const auto i = static_cast<std::size_t>(k);
    EXPECT_EQ(lt[k], want_lt[i]) << k;
    EXPECT_EQ(le[k], want_le[i]) << k;
    EXPECT_EQ(gt[k], !want_le[i]) << k;
    EXPECT_EQ(ge[k], !want_lt[i]) << k;
    EXPECT_EQ((lt && ge)[k], false);
    EXPECT_EQ((lt || ge)[k], true);
    EXPECT_EQ((!lt)[k], !want_lt[i]);
    EXPECT_EQ((le && !lt)[k], k == 1 || k == 3);  // equal lanes
    // All bits set where true, none where false.
    EXPECT_EQ(lt.m[k], want_lt[i] ? -1 : 0);
    EXPECT_EQ((!lt).m[k], want_lt[i] ? 0 : -1);
  }
  // NaN compares false in every direction.
  const F4 nan(std::numeric_limits<float>::quiet_NaN());
  EXPECT_FALSE(any_lane(nan < F4(0.0f) || nan > F4(0.0f) || nan <= nan || nan >= nan));

  // any_lane: false only for no lane set; each single lane is seen.
  EXPECT_FALSE(any_lane(Mask4{}));
  EXPECT_FALSE(any_lane(a > F4(10.0f)));
  EXPECT_TRUE(any_lane(!Mask4{}));
  for (int k = 0; k < 4; ++k) {
    F4 x(0.0f);
    x.v[k] = 1.0f;
    const Mask4 one = x > F4(0.5f);
    EXPECT_TRUE(any_lane(one)) << k;
    for (int j = 0; j < 4; ++j) EXPECT_EQ(one[j], j == k);
  }

  // if_else picks per lane, passing inf, NaN and signed zeros through untouched.
  const F4 x = pack(kInf, -0.0f, std::numeric_limits<float>::quiet_NaN(), 5.0f);
  const F4 y = pack(-1.0f, 7.0f, 8.0f, -kInf);
  const Mask4 pick = pack(1.0f, 1.0f, -1.0f, -1.0f) > F4(0.0f);
  const F4 r = if_else(pick, x, y);
  EXPECT_TRUE(std::isinf(r[0]) && r[0] > 0.0f);
  EXPECT_EQ(std::bit_cast<std::uint32_t>(r[1]), 0x80000000U);  // −0
  EXPECT_EQ(r[2], 8.0f);
  EXPECT_TRUE(std::isinf(r[3]) && r[3] < 0.0f);
  const F4 r2 = if_else(!pick, x, y);
  EXPECT_EQ(r2[0], -1.0f);
  EXPECT_EQ(r2[1], 7.0f);
  EXPECT_TRUE(std::isnan(r2[2]));
  EXPECT_EQ(r2[3], 5.0f);
}

TEST(MfLanes, MaxOfAndMinOfAreTheEvaluationsSelects) {
  // max_of(a, b) = a < b ? b : a and min_of(a, b) = b < a ? b : a, lane by lane and bit for bit,
  // as mf_evaluate.hpp's generic versions: NaN in either operand gives a, equal values (±0) a.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> special = {0.0f, -0.0f,      1.0f,   -1.0f, kInf, -kInf,
                                      nan,  kDenormMin, -kMaxF, kMaxF, 2.5f, -2.5f};
  std::vector<float> as;
  std::vector<float> bs;
  for (float a : special) {
    for (float b : special) {
      as.push_back(a);
      bs.push_back(b);
    }
  }
  const std::vector<float> ra = random_bits(0U, 0xffffffffU, 40000, 101);
  const std::vector<float> rb = random_bits(0U, 0xffffffffU, 40000, 102);
  as.insert(as.end(), ra.begin(), ra.end());
  bs.insert(bs.end(), rb.begin(), rb.end());
  int mismatches = 0;
  for (std::size_t g = 0; g + 4 <= as.size(); g += 4) {
    const F4 a = pack(as[g], as[g + 1], as[g + 2], as[g + 3]);
    const F4 b = pack(bs[g], bs[g + 1], bs[g + 2], bs[g + 3]);
    const F4 hi = max_of(a, b);
    const F4 lo = min_of(a, b);
    for (int k = 0; k < 4; ++k) {
      const float want_hi = a[k] < b[k] ? b[k] : a[k];
      const float want_lo = b[k] < a[k] ? b[k] : a[k];
      if (std::bit_cast<std::uint32_t>(hi[k]) != std::bit_cast<std::uint32_t>(want_hi) ||
          std::bit_cast<std::uint32_t>(lo[k]) != std::bit_cast<std::uint32_t>(want_lo)) {
        if (++mismatches <= 5) {
          ADD_FAILURE() << "max_of/min_of(" << a[k] << ", " << b[k] << ") = " << hi[k] << ", "
                        << lo[k];
        }
      }
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(MfLanes, ArithmeticIsPerLaneWithFloatBroadcast) {
  const F4 a = pack(1.0f, -2.0f, 3.5f, 1e30f);
  const F4 b = pack(4.0f, 0.5f, -1.0f, 1e30f);
  const F4 sum = a + b;
  const F4 diff = a - 2.0f;
  const F4 prod = a * b;
  const F4 quot = 1.0f / a;
  const F4 neg = -a;
  const F4 from_double(2.5);  // explicit from another arithmetic type
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(sum[k], a[k] + b[k]);
    EXPECT_EQ(diff[k], a[k] - 2.0f);
    EXPECT_EQ(prod[k], a[k] * b[k]);
    EXPECT_EQ(quot[k], 1.0f / a[k]);
    EXPECT_EQ(neg[k], -a[k]);
    EXPECT_EQ(from_double[k], 2.5f);
  }
  EXPECT_TRUE(std::isinf(prod[3]));
  EXPECT_EQ(F4(7)[2], 7.0f);
}

}  // namespace
}  // namespace tread::mf::lanes
