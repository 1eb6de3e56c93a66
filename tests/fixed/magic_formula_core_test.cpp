// The fixed-point Magic Formula core against double evaluation of the same (quantised) inputs, over
// the formats' ranges: |x| up to 32767 (log-spread), C in (0, 8), E in (−127, 1].
#include "fixed/magic_formula_core.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace tread::fixed {
namespace {

double reference(double x, double c, double e, bool cosine) {
  const double a = c * std::atan(x - e * (x - std::atan(x)));
  return cosine ? std::cos(a) : std::sin(a);
}

TEST(MagicFormulaCore, WithinItsBoundOverTheFormats) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> log_mag(-8.0, std::log(32767.0));
  std::uniform_real_distribution<double> uc(0.0, 7.99);
  std::uniform_real_distribution<double> ue(-127.0, 1.0);
  std::bernoulli_distribution coin;
  double worst = 0.0;
  double worst_abs = 0.0;
  for (int i = 0; i < 500000; ++i) {
    Saturation sat;
    const double xs = (coin(rng) ? 1.0 : -1.0) * std::exp(log_mag(rng));
    const Slip16 x = from_double<16>(xs, sat);
    // Typical shapes half of the time: C in (0, 2.5), E in (−3, 1].
    const bool typical = coin(rng);
    const ShapeC c = from_double<28>(typical ? uc(rng) / 3.2 : uc(rng), sat);
    const CurveE e = from_double<24>(typical ? std::max(-3.0, ue(rng) / 40.0) : ue(rng), sat);
    ASSERT_FALSE(sat.hit);
    const bool cosine = coin(rng);
    const double want = reference(to_double(x), to_double(c), to_double(e), cosine);
    const double got = to_double(magic_formula_core(x, c, e, cosine));
    const double bound = 1e-8 * (1.0 + to_double(c) * (1.0 + std::fabs(to_double(e))));
    worst = std::max(worst, std::fabs(got - want) / bound);
    if (typical) worst_abs = std::max(worst_abs, std::fabs(got - want));
  }
  std::printf("core: worst error %.3g of the bound; typical shapes: worst |error| %.3g\n", worst,
              worst_abs);
  EXPECT_LE(worst, 1.0);
  EXPECT_LE(worst_abs, 2e-8);
}

TEST(MagicFormulaCore, ExtremesOfTheArgument) {
  // x at the format's ends, E = 1 (u = atan x) and E very negative (u far beyond the format).
  for (const double xs : {-32768.0, 32767.99998, 1e-4, -1e-4, 0.0}) {
    for (const double es : {1.0, 0.0, -127.0}) {
      for (const double cs : {1.3, 2.0, 7.5}) {
        Saturation sat;
        const Slip16 x = from_double<16>(xs, sat);
        const ShapeC c = from_double<28>(cs, sat);
        const CurveE e = from_double<24>(es, sat);
        for (const bool cosine : {false, true}) {
          EXPECT_NEAR(to_double(magic_formula_core(x, c, e, cosine)),
                      reference(to_double(x), to_double(c), to_double(e), cosine), 2e-8)
              << xs << ' ' << es << ' ' << cs << ' ' << cosine;
        }
      }
    }
  }
}

}  // namespace
}  // namespace tread::fixed
