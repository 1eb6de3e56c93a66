// Equivalent conicity on delta r functions with known answers: a pure cone (linear delta r) and a
// cubic delta r whose wavelength follows from the energy integral (computed here independently by
// quadrature, not by integrating the equation of motion).
#include "contact/equivalent_conicity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

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
      EXPECT_NEAR(linearised_conicity(t, a), tan_g, 1e-9);
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
    EXPECT_NEAR(linearised_conicity(t, a), g + 0.375 * c * a * a, 1e-6);
  }
}

TEST(EquivalentConicity, RejectsMotionOutsideTheTableAndNonRestoringDeltaR) {
  const ContactTable t = table_of([](double y) { return 0.1 * y; }, 5.0);
  EXPECT_THROW((void)equivalent_conicity(t, 6.0), std::domain_error);
  EXPECT_THROW((void)linearised_conicity(t, 6.0), std::domain_error);
  const ContactTable flat = table_of([](double) { return 1.0; }, 5.0);
  EXPECT_THROW((void)equivalent_conicity(flat, 1.0), std::domain_error);
}

TEST(EquivalentConicity, OffsetDeltaRIsCentredOnItsRoot) {
  // Different wheel radii shift delta r: the motion centres on the root y0.
  const double tan_g = 0.12;
  const double y0 = -1.25;
  const ContactTable t = table_of([&](double y) { return 2.0 * tan_g * (y - y0); });
  const ConicityResult r = equivalent_conicity(t, 4.0);
  EXPECT_NEAR(r.centre_y_mm, y0, 1e-9);
  EXPECT_NEAR(r.tan_gamma_e, tan_g, 1e-5 * tan_g);
  EXPECT_NEAR(linearised_conicity(t, 4.0), tan_g, 1e-9);
}

}  // namespace
}  // namespace tread::contact
