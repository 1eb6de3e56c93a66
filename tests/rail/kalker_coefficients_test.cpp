// Kalker's linear creep coefficients: the published table at its own points, the interpolation
// between them, and cross-checks whose numbers come from outside this repository (sources in
// docs/contact-mechanics.md).
#include "rail/kalker_coefficients.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace tread::rail {
namespace {

constexpr double kNu[3] = {0.0, 0.25, 0.5};

double coefficient(const KalkerCoefficients<double>& c, int k) {
  const double v[4] = {c.c11, c.c22, c.c23, c.c33};
  return v[k];
}

double g_of(int row) {
  return 0.1 * (row + 1);
}

TEST(KalkerCoefficients, ReproduceThePublishedTableAtItsPoints) {
  // Kalker 1990, table E.3, e.g. a/b = 0.5: C11 = 2.88 / 3.62 / 4.83 at nu = 0 / 0.25 / 0.5.
  for (const bool a_block : {true, false}) {
    for (int row = 0; row < 10; ++row) {
      for (int j = 0; j < 3; ++j) {
        const KalkerCoefficients<double> want = kalker_table_entry(a_block, row, j);
        const double g = g_of(row);
        const KalkerCoefficients<double> got = kalker_coefficients(a_block ? g : 1.0 / g, kNu[j]);
        for (int k = 0; k < 4; ++k) {
          EXPECT_NEAR(coefficient(got, k), coefficient(want, k), 1e-6 * coefficient(want, k))
              << (a_block ? "a/b " : "b/a ") << g << " nu " << kNu[j] << " C" << k;
        }
        EXPECT_FALSE(got.extrapolated);
      }
    }
  }
  const KalkerCoefficients<double> e = kalker_table_entry(true, 4, 1);
  EXPECT_NEAR(e.c11, 3.62, 1e-6);
  EXPECT_NEAR(e.c22, 3.01, 1e-6);
  EXPECT_NEAR(e.c23, 0.929, 1e-6);
  const KalkerCoefficients<double> f = kalker_table_entry(false, 0, 2);  // b/a = 0.1, nu = 0.5
  EXPECT_NEAR(f.c11, 12.9, 1e-5);
  EXPECT_NEAR(f.c22, 16.0, 1e-5);
  EXPECT_NEAR(f.c23, 18.0, 1e-5);
}

TEST(KalkerCoefficients, TableObeysTheTheory) {
  // nu = 0: C11 = C22 on every row (the longitudinal and lateral problems coincide); the row
  // g = 1 is shared by both blocks; C22 at a/b -> 0 tends to pi^2/4 = 2.467.
  for (const bool a_block : {true, false}) {
    for (int row = 0; row < 10; ++row) {
      const KalkerCoefficients<double> c = kalker_table_entry(a_block, row, 0);
      EXPECT_DOUBLE_EQ(c.c11, c.c22);
    }
  }
  for (int j = 0; j < 3; ++j) {
    const KalkerCoefficients<double> a = kalker_table_entry(true, 9, j);
    const KalkerCoefficients<double> b = kalker_table_entry(false, 9, j);
    EXPECT_EQ(a.c11, b.c11);
    EXPECT_EQ(a.c23, b.c23);
    EXPECT_EQ(a.c33, b.c33);
  }
  EXPECT_NEAR(kalker_table_entry(true, 0, 1).c22, std::numbers::pi * std::numbers::pi / 4.0, 0.06);
}

/// The interpolation's estimate of the middle row from the rows at g0 and g2 = g0 + 0.2.
double leave_one_out(bool a_block, int row, int j, int k) {
  const double p = kalker_interpolation_power(a_block, k);
  const double g0 = g_of(row - 1);
  const double g1 = g_of(row);
  const double g2 = g_of(row + 1);
  const double lo = coefficient(kalker_table_entry(a_block, row - 1, j), k) * std::pow(g0, p);
  const double hi = coefficient(kalker_table_entry(a_block, row + 1, j), k) * std::pow(g2, p);
  return 0.5 * (lo + hi) / std::pow(g1, p);
}

TEST(KalkerCoefficients, InterpolationErrorBetweenTablePoints) {
  // Leave every inner row out and interpolate it from its neighbours 0.2 apart with the scheme
  // the code uses: the error of linear interpolation grows with the square of the spacing, so at
  // the table's own spacing of 0.1 it is about a quarter of this. Printed for
  // docs/contact-mechanics.md; plain linear interpolation in g misses by up to 46 % (C23 of the
  // b/a block) on the same test.
  double worst[4] = {0, 0, 0, 0};
  for (const bool a_block : {true, false}) {
    for (int row = 1; row < 9; ++row) {
      for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 4; ++k) {
          const double want = coefficient(kalker_table_entry(a_block, row, j), k);
          worst[k] = std::max(worst[k], std::abs(leave_one_out(a_block, row, j, k) / want - 1.0));
        }
      }
    }
  }
  std::printf(
      "leave-one-out (spacing 0.2) worst relative error: C11 %.4f C22 %.4f C23 %.4f "
      "C33 %.4f\n",
      worst[0], worst[1], worst[2], worst[3]);
  for (const double w : worst) {
    EXPECT_LT(w, 0.02);
  }
  // The code's midpoints are that interpolation at the table's spacing.
  for (const bool a_block : {true, false}) {
    for (int row = 0; row < 9; ++row) {
      const double g = 0.5 * (g_of(row) + g_of(row + 1));
      const KalkerCoefficients<double> c = kalker_coefficients(a_block ? g : 1.0 / g, 0.0);
      for (int k = 0; k < 4; ++k) {
        const double p = kalker_interpolation_power(a_block, k);
        const double lo =
            coefficient(kalker_table_entry(a_block, row, 0), k) * std::pow(g_of(row), p);
        const double hi =
            coefficient(kalker_table_entry(a_block, row + 1, 0), k) * std::pow(g_of(row + 1), p);
        EXPECT_NEAR(coefficient(c, k), 0.5 * (lo + hi) / std::pow(g, p), 1e-6 * coefficient(c, k));
      }
    }
  }
}

TEST(KalkerCoefficients, PoissonInterpolationMatchesContactFlexibility) {
  // Kalker's CONTACT (examples/tractcurv, a/b = 0.5, nu = 0.28, G = 82 000 N/mm^2, a = 6.304 mm)
  // prints the FASTSIM flexibility L1 = 8 a / (3 G C11) = 0.5491e-4 mm^3/N: C11 = 3.7335 by the
  // parabola through 1/C; a linear blend in nu would give 3.765 and 0.5446e-4.
  const KalkerCoefficients<double> c = kalker_coefficients(0.5, 0.28);
  EXPECT_NEAR(c.c11, 3.7335, 5e-4);
  EXPECT_NEAR(8.0 * 6.304 / (3.0 * 82000.0 * c.c11), 0.5491e-4, 0.00005e-4);
  EXPECT_NEAR(c.c22, 3.0256, 5e-4);
  EXPECT_NEAR(c.c23, 0.9435, 5e-4);
  const KalkerCoefficients<double> d = kalker_coefficients(2.0, 0.28);  // b/a = 0.5
  EXPECT_NEAR(d.c11, 5.2037, 5e-4);
  EXPECT_NEAR(d.c22, 4.9715, 5e-4);
  EXPECT_NEAR(d.c23, 2.6566, 5e-4);
}

TEST(KalkerCoefficients, AgreeWithAnIndependentTableAtNuPointThree) {
  // A separately published table for nu = 0.3 (whose columns are 0.8 x (nu = 0.25) + 0.2 x
  // (nu = 0.5), a linear blend): our parabola in 1/C differs from a linear blend by < 2 % (C11 at
  // a/b = 0.5: 1.3 %).
  struct Point {
    double a_over_b;
    double c11, c22, c23, c33;
  };
  const Point points[] = {{0.5, 3.862, 3.036, 0.9572, 1.988},
                          {1.0, 4.336, 3.732, 1.502, 1.184},
                          {2.0, 5.302, 5.032, 2.688, 0.7852}};
  for (const Point& p : points) {
    const KalkerCoefficients<double> c = kalker_coefficients(p.a_over_b, 0.3);
    EXPECT_NEAR(c.c11, p.c11, 0.02 * p.c11) << p.a_over_b;
    EXPECT_NEAR(c.c22, p.c22, 0.02 * p.c22) << p.a_over_b;
    EXPECT_NEAR(c.c23, p.c23, 0.02 * p.c23) << p.a_over_b;
    EXPECT_NEAR(c.c33, p.c33, 0.02 * p.c33) << p.a_over_b;
  }
}

TEST(KalkerCoefficients, SlenderEllipsesFollowTheAsymptotesContinuously) {
  for (const double nu : {0.0, 0.28, 0.5}) {
    for (const double at : {0.1, 10.0}) {
      const KalkerCoefficients<double> edge = kalker_coefficients(at, nu);
      const KalkerCoefficients<double> just =
          kalker_coefficients(at < 1 ? at * 0.999 : at / 0.999, nu);
      EXPECT_NEAR(just.c11, edge.c11, 0.002 * edge.c11);
      EXPECT_NEAR(just.c23, edge.c23, 0.005 * edge.c23);
      EXPECT_TRUE(just.extrapolated);
    }
    // a/b -> 0: C11 -> pi^2 / (4 (1 - nu)) and C22 -> pi^2 / 4, to within the table's own
    // distance from the asymptote at 0.1 (a few per cent).
    const KalkerCoefficients<double> thin = kalker_coefficients(1e-3, nu);
    EXPECT_NEAR(thin.c22, std::numbers::pi * std::numbers::pi / 4.0, 0.03 * 2.467);
    // a/b -> infinity: the coefficients grow without bound (like 1/(g ln(1/g))).
    const KalkerCoefficients<double> wide = kalker_coefficients(100.0, nu);
    EXPECT_GT(wide.c11, 50.0);
    EXPECT_GT(wide.c22, 50.0);
  }
}

TEST(KalkerCoefficients, FloatAgreesAndBadInputIsContained) {
  for (const double r : {0.05, 0.13, 0.5, 1.0, 1.7, 4.2, 20.0}) {
    const KalkerCoefficients<double> d = kalker_coefficients(r, 0.28);
    const KalkerCoefficients<float> f = kalker_coefficients(static_cast<float>(r), 0.28F);
    EXPECT_NEAR(f.c11, d.c11, 1e-5 * d.c11);
    EXPECT_NEAR(f.c22, d.c22, 1e-5 * d.c22);
    EXPECT_NEAR(f.c23, d.c23, 1e-5 * d.c23);
    EXPECT_NEAR(f.c33, d.c33, 1e-5 * d.c33);
  }
  const KalkerCoefficients<float> bad = kalker_coefficients(std::nanf(""), 0.3F);
  EXPECT_TRUE(bad.extrapolated);
  EXPECT_TRUE(std::isfinite(bad.c11) && std::isfinite(bad.c33));
  const KalkerCoefficients<float> huge = kalker_coefficients(1e30F, 2.0F);
  EXPECT_TRUE(std::isfinite(huge.c11) && std::isfinite(huge.c23) && std::isfinite(huge.c33));
  const KalkerCoefficients<float> tiny = kalker_coefficients(0.0F, -1.0F);
  EXPECT_TRUE(std::isfinite(tiny.c11) && std::isfinite(tiny.c23) && std::isfinite(tiny.c33));
}

}  // namespace
}  // namespace tread::rail
