// Equivalent conicity on delta r functions with known answers: a pure cone (linear delta r) and a
// cubic delta r whose wavelength follows from the energy integral (computed here independently by
// quadrature, not by integrating the equation of motion).
#include "contact/equivalent_conicity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

namespace tread::contact {
namespace {

ContactTable table_of(const std::function<double(double)>& delta_r, double y_max = 12.0,
                      double step = 0.01) {
  ContactTable t;
  t.y_first_mm = -y_max;
  t.y_step_mm = step;
  const auto n = static_cast<std::size_t>(std::lround(2.0 * y_max / step)) + 1;
  for (std::size_t i = 0; i < n; ++i) {
    const double y = -y_max + static_cast<double>(i) * step;
    t.y_mm.push_back(y);
    t.delta_r_mm.push_back(delta_r(y));
  }
  return t;
}

TEST(EquivalentConicity, LinearDeltaRGivesTheConeConicity) {
  for (const double tan_g : {0.025, 0.05, 0.15, 0.4}) {
    const ContactTable t = table_of([&](double y) { return 2.0 * tan_g * y; });
    for (const double a : {0.5, 2.0, 3.0, 8.0}) {
      const ConicityResult r = equivalent_conicity(t, a);
      EXPECT_NEAR(r.tan_gamma_e, tan_g, 1e-6 + 1e-5 * tan_g) << "tan " << tan_g << " a " << a;
      // Klingel: lambda = 2 pi sqrt(e0 r0 / tan)
      EXPECT_NEAR(r.wavelength_mm, 2.0 * std::numbers::pi * std::sqrt(750.0 * 460.0 / tan_g),
                  1e-3 * r.wavelength_mm);
      EXPECT_NEAR(linearised_conicity(t, a).tan_gamma_e, tan_g, 1e-9);
    }
  }
}

TEST(EquivalentConicity, CubicDeltaRMatchesTheEnergyIntegral) {
  const double g = 0.1;
  const double c = 0.004;  // delta r = 2 g y + c y^3
  const ContactTable t = table_of([&](double y) { return 2.0 * g * y + c * y * y * y; });
  const double k = 1.0 / (2.0 * 750.0 * 460.0);
  for (const double a : {1.0, 3.0, 6.0}) {
    // Potential V(y) = k (g y^2 + c y^4 / 4); quarter period = int_0^a dy / sqrt(2 (V(a) - V(y))),
    // with y = a sin(theta) removing the end singularity; Simpson's rule on theta.
    auto V = [&](double y) { return k * (g * y * y + 0.25 * c * y * y * y * y); };
    const int n = 20000;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double th = 0.5 * std::numbers::pi * i / n;
      const double y = a * std::sin(th);
      const double dy = a * std::cos(th);
      const double denom = std::sqrt(2.0 * (V(a) - V(y)));
      // At theta = pi/2 the integrand's limit is a / sqrt(-V''(a)... ) form: use the neighbour.
      const double f = i == n ? 0.0 : dy / denom;
      const double wgt = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      sum += wgt * f;
    }
    double quarter = sum * (0.5 * std::numbers::pi / n) / 3.0;
    // Endpoint: integrand -> a / sqrt(a V'(a)) as theta -> pi/2 (cos th / sqrt(1 - sin th)~).
    const double dVa = k * (2.0 * g * a + c * a * a * a);
    const double end_value = a / std::sqrt(a * dVa);
    quarter += end_value * (0.5 * std::numbers::pi / n) / 3.0;
    const double lambda = 4.0 * quarter;
    const double expected = 750.0 * 460.0 * std::pow(2.0 * std::numbers::pi / lambda, 2.0);
    const ConicityResult r = equivalent_conicity(t, a);
    EXPECT_NEAR(r.tan_gamma_e, expected, 2e-4 * expected) << "a = " << a;
    EXPECT_GT(r.tan_gamma_e, g);  // a hardening delta r raises the conicity with amplitude
    // The harmonic-weighted regression of 2 g y + c y^3 has slope 2 g + (3/4) c a^2.
    EXPECT_NEAR(linearised_conicity(t, a).tan_gamma_e, g + 0.375 * c * a * a, 1e-6);
  }
}

// The error of a method that has no result, or "" when it has one.
template <typename F>
std::string error_of(F&& f) {
  try {
    (void)f();
  } catch (const std::domain_error& e) {
    return e.what();
  }
  return "";
}

TEST(EquivalentConicity, SaysWhyAndAtWhichAmplitudeThereIsNoOscillation) {
  const ContactTable t = table_of([](double y) { return 0.1 * y; }, 5.0);
  for (const std::string& e : {error_of([&] { return equivalent_conicity(t, 6.0); }),
                               error_of([&] { return linearised_conicity(t, 6.0); })}) {
    EXPECT_NE(e.find("amplitude 6.000 mm"), std::string::npos) << e;
    EXPECT_NE(e.find("wider than the delta r table [-5.000, 5.000]"), std::string::npos) << e;
  }
  // A constant radius difference never restores the wheelset.
  const ContactTable flat = table_of([](double) { return 1.0; }, 5.0);
  for (const std::string& e : {error_of([&] { return equivalent_conicity(flat, 1.0); }),
                               error_of([&] { return linearised_conicity(flat, 1.0); })}) {
    EXPECT_NE(e.find("amplitude 1.000 mm"), std::string::npos) << e;
    EXPECT_NE(e.find("does not restore the wheelset"), std::string::npos) << e;
  }
  // Restoring, but centred at y = 4: an amplitude of 2 mm would leave the table at 6 mm, while
  // 0.5 mm fits.
  const ContactTable off = table_of([](double y) { return 0.2 * (y - 4.0); }, 5.0);
  for (const std::string& e : {error_of([&] { return equivalent_conicity(off, 2.0); }),
                               error_of([&] { return linearised_conicity(off, 2.0); })}) {
    EXPECT_NE(e.find("amplitude 2.000 mm"), std::string::npos) << e;
    EXPECT_NE(e.find("inside the delta r table"), std::string::npos) << e;
  }
  EXPECT_NEAR(equivalent_conicity(off, 0.5).tan_gamma_e, 0.1, 1e-9);
  EXPECT_NEAR(linearised_conicity(off, 0.5).tan_gamma_e, 0.1, 1e-9);
}

// A pair of cones with any rolling-radius offset: delta r = 2 tan(gamma) y + offset. Both methods
// give exactly the cone's tan(gamma) at every amplitude, centred where delta r = 0.
TEST(EquivalentConicity, ConePairWithARadiusOffsetGivesTheConeAtEveryAmplitude) {
  for (const double tan_g : {0.05, 0.15, 0.4}) {
    for (const double offset : {-2.0, -0.7, 0.3, 1.0}) {
      const ContactTable t = table_of([&](double y) { return 2.0 * tan_g * y + offset; });
      const double root = -offset / (2.0 * tan_g);
      for (const double a : {0.5, 1.0, 2.0, 3.0, 5.0}) {
        if (std::abs(root) + a > 11.9) {
          continue;
        }
        const ConicityResult b = equivalent_conicity(t, a);
        EXPECT_NEAR(b.tan_gamma_e, tan_g, 1e-9) << "tan " << tan_g << " offset " << offset;
        EXPECT_NEAR(b.centre_y_mm, root, 1e-9);
        EXPECT_NEAR(b.y_max_mm - b.y_min_mm, 2.0 * a, 1e-9);
        const RegressionResult c = linearised_conicity(t, a);
        EXPECT_NEAR(c.tan_gamma_e, tan_g, 1e-9);
        EXPECT_NEAR(c.centre_y_mm, root, 1e-9);
      }
    }
  }
}

// Swapping left and right turns delta r(y) into -delta r(-y): the same conicity, the centre
// mirrored. The delta r used is asymmetric and not restoring at y = 0 (it has a radius offset and
// a quadratic part), like a worn pair with different diameters.
TEST(EquivalentConicity, MirroringThePairMirrorsTheCentreAndKeepsTheConicity) {
  auto dr = [](double y) { return 0.6 + 0.15 * y + 0.02 * y * y + 0.004 * y * y * y; };
  const ContactTable t = table_of(dr);
  const ContactTable m = table_of([&](double y) { return -dr(-y); });
  for (const double a : {0.5, 1.0, 2.0, 4.0, 6.0}) {
    const ConicityResult b = equivalent_conicity(t, a);
    const ConicityResult bm = equivalent_conicity(m, a);
    EXPECT_GT(std::abs(b.centre_y_mm), 0.3) << "a = " << a;  // really off centre
    EXPECT_NEAR(bm.tan_gamma_e, b.tan_gamma_e, 1e-9 + 1e-7 * b.tan_gamma_e) << "a = " << a;
    EXPECT_NEAR(bm.centre_y_mm, -b.centre_y_mm, 1e-9) << "a = " << a;
    EXPECT_NEAR(bm.y_max_mm, -b.y_min_mm, 1e-9) << "a = " << a;
    const RegressionResult c = linearised_conicity(t, a);
    const RegressionResult cm = linearised_conicity(m, a);
    EXPECT_NEAR(cm.tan_gamma_e, c.tan_gamma_e, 1e-9) << "a = " << a;
    EXPECT_NEAR(cm.centre_y_mm, -c.centre_y_mm, 1e-9) << "a = " << a;
  }
}

// The turning points of an asymmetric delta r: V(y_min) = V(y_max) (V = integral of delta r), and
// the centre is midway between them, not at the root of delta r. Here delta r = 2 g y for y < 0
// and 2 * 4g y for y > 0 (a stiffer right side), so V = g y^2 and 4 g y^2: y_max = -y_min / 2, and
// the wavelength is the sum of the two sides' half periods (each side is a harmonic half-swing).
TEST(EquivalentConicity, TurningPointsOfAnAsymmetricDeltaRBalanceThePotential) {
  const double g = 0.1;
  const ContactTable t = table_of([&](double y) { return y < 0.0 ? 2.0 * g * y : 8.0 * g * y; });
  const double a = 3.0;
  const ConicityResult r = equivalent_conicity(t, a);
  // g y_min^2 = 4 g y_max^2 -> y_max = -y_min / 2; y_max - y_min = 2 a.
  EXPECT_NEAR(r.y_min_mm, -4.0 * a / 3.0, 1e-6);
  EXPECT_NEAR(r.y_max_mm, 2.0 * a / 3.0, 1e-6);
  EXPECT_NEAR(r.centre_y_mm, -a / 3.0, 1e-6);
  // Half period on each side: pi / omega_i with omega_i = sqrt(2 tan_i / (2 e0 r0)).
  const double k = 1.0 / (2.0 * 750.0 * 460.0);
  const double lambda =
      std::numbers::pi / std::sqrt(2.0 * g * k) + std::numbers::pi / std::sqrt(2.0 * 4.0 * g * k);
  EXPECT_NEAR(r.wavelength_mm, lambda, 1e-4 * lambda);
  // The regression centre makes the cycle mean of delta r zero instead.
  const RegressionResult c = linearised_conicity(t, a);
  double mean = 0.0;
  for (int i = 0; i < 3600; ++i) {
    mean += delta_r_at(t, c.centre_y_mm + a * std::sin(2.0 * std::numbers::pi * (i + 0.5) / 3600));
  }
  EXPECT_NEAR(mean / 3600, 0.0, 1e-9);
}

// delta r = 0 over a stretch (a flat, e.g. a worn wheel on a rail it does not steer on): inside it
// the wheelset is in neutral equilibrium, tan(gamma_e) = 0 (as EN 15302 Annex K gives for wheel I
// at small amplitudes); a motion reaching the flanks oscillates.
TEST(EquivalentConicity, ZeroDeltaRStretchIsNeutral) {
  const ContactTable t = table_of(
      [](double y) { return std::abs(y) <= 1.5 ? 0.0 : 0.8 * (y - std::copysign(1.5, y)); });
  const ConicityResult r = equivalent_conicity(t, 1.0);
  EXPECT_TRUE(r.neutral);
  EXPECT_EQ(r.tan_gamma_e, 0.0);
  EXPECT_NEAR(r.centre_y_mm, 0.0, 1e-12);
  EXPECT_EQ(linearised_conicity(t, 1.0).tan_gamma_e, 0.0);
  const ConicityResult o = equivalent_conicity(t, 2.0);
  EXPECT_FALSE(o.neutral);
  EXPECT_GT(o.tan_gamma_e, 0.01);
  EXPECT_LT(o.tan_gamma_e, 0.4);
  EXPECT_NEAR(o.centre_y_mm, 0.0, 1e-6);
}

TEST(EquivalentConicity, OffsetDeltaRIsCentredOnItsRoot) {
  // Different wheel radii shift delta r: the motion centres on the root y0.
  const double tan_g = 0.12;
  const double y0 = -1.25;
  const ContactTable t = table_of([&](double y) { return 2.0 * tan_g * (y - y0); });
  const ConicityResult r = equivalent_conicity(t, 4.0);
  EXPECT_NEAR(r.centre_y_mm, y0, 1e-9);
  EXPECT_NEAR(r.tan_gamma_e, tan_g, 1e-5 * tan_g);
  EXPECT_NEAR(linearised_conicity(t, 4.0).tan_gamma_e, tan_g, 1e-9);
  EXPECT_NEAR(linearised_conicity(t, 4.0).centre_y_mm, y0, 1e-9);
}

}  // namespace
}  // namespace tread::contact
