// Hertz's elliptic contact in the core: elliptic integrals, the classic m, n coefficients, the
// textbook sphere on a plane, and two wheel-on-rail cases published with Kalker's CONTACT program
// (sources and figures in docs/contact-mechanics.md).
#include "rail/hertz_ellipse.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tread::rail {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(HertzEllipse, EllipticIntegralsMatchTheStandardLibrary) {
  for (const double k : {0.0, 1e-6, 0.01, 0.3, 0.7, 0.9, 0.99, 0.9999}) {
    const EllipticIntegrals e = elliptic_integrals(std::sqrt((1.0 - k) * (1.0 + k)));
    EXPECT_NEAR(e.k, std::comp_ellint_1(k), 1e-13 * e.k) << k;
    EXPECT_NEAR(e.e, std::comp_ellint_2(k), 1e-12) << k;
    if (k > 0.01) {
      const double direct = (std::comp_ellint_1(k) - std::comp_ellint_2(k)) / (k * k);
      EXPECT_NEAR(e.k_minus_e_over_k2, direct, 1e-12) << k;
    }
  }
  EXPECT_NEAR(elliptic_integrals(1.0).k_minus_e_over_k2, kPi / 4.0, 1e-15);
  EXPECT_NEAR(elliptic_integrals(1.0).ratio, 1.0, 1e-15);
  // Near the circle: ratio = 1 + 3/4 k^2 + ... without cancellation.
  const double k = 1e-5;
  EXPECT_NEAR(elliptic_integrals(std::sqrt(1.0 - k * k)).ratio - 1.0, 0.75 * k * k, 1e-3 * k * k);
}

double unit_c() {
  return std::cbrt(0.75);  // c^3 = 3 P / (4 E* (A + B)) with P = E* = A + B = 1
}

TEST(HertzEllipse, CoefficientsMatchTheExactSolution) {
  // m, n, and r = 2K/(pi m) (approach = r (A + B) c^2), recomputed with arbitrary-precision
  // elliptic integrals; the classic printed table (Timoshenko & Goodier) agrees to 3 digits for
  // theta >= 30 deg (up to 0.3 % in n near 70 deg, where the printed table is itself off).
  struct Row {
    double theta_deg, m, n, r;
  };
  const Row rows[] = {{10, 6.6115, 0.3110, 0.4280}, {20, 3.8160, 0.4121, 0.6038},
                      {30, 2.7306, 0.4931, 0.7263}, {45, 1.9265, 0.6038, 0.8547},
                      {60, 1.4858, 0.7171, 0.9376}, {75, 1.2020, 0.8448, 0.9847},
                      {85, 1.0609, 0.9442, 0.9983}};
  for (const Row& row : rows) {
    const double c = std::cos(row.theta_deg * kPi / 180.0);
    const Result<HertzShape<double>> s = hertz_shape(0.5 * (1.0 - c), 0.5 * (1.0 + c), 1.0);
    ASSERT_TRUE(s.ok());
    EXPECT_NEAR(s.value.a_unit_mm / unit_c(), row.m, 1e-4 * row.m + 5e-5) << row.theta_deg;
    EXPECT_NEAR(s.value.b_unit_mm / unit_c(), row.n, 1e-4 * row.n + 5e-5) << row.theta_deg;
    EXPECT_NEAR(s.value.approach_unit_mm / (unit_c() * unit_c()), row.r, 1e-4 + 5e-5)
        << row.theta_deg;
  }
}

TEST(HertzEllipse, SphereOnAPlane) {
  // a = (3 N R / (4 E*))^(1/3), p0 = 3 N / (2 pi a^2), approach a^2 / R: steel ball R = 10 mm on
  // steel, 1000 N, E = 210 GPa, nu = 0.3: a = 0.40207 mm, p0 = 2953.5 MPa, approach 0.016166 mm.
  const double e_star = contact_modulus_mpa(210000.0, 0.3, 210000.0, 0.3);
  const Result<HertzShape<double>> s = hertz_shape(0.05, 0.05, e_star);
  ASSERT_TRUE(s.ok());
  const HertzPatch<double> p = hertz_patch(s.value, 1000.0);
  EXPECT_NEAR(p.a_mm, 0.40207, 5e-5);
  EXPECT_NEAR(p.b_mm, 0.40207, 5e-5);
  EXPECT_NEAR(p.p_max_mpa, 2953.5, 0.5);
  EXPECT_NEAR(p.approach_mm, 0.016166, 5e-6);
  EXPECT_NEAR(p.approach_mm, p.a_mm * p.a_mm / 10.0, 1e-12);
}

TEST(HertzEllipse, WheelOnRailCasesOfKalkersContactProgram) {
  // CONTACT's examples (G = 82 000 N/mm^2, nu = 0.28 for both bodies):
  // tractcurv: A = 0.8e-3 /mm (R = 625 mm), B = 0.2814e-3 /mm, FN = 106.7 kN -> a = 6.304,
  //   b = 12.61 mm, approach 7.651e-2 mm, grid maximum pressure 640.7 N/mm^2.
  // fastsim:   A = 0.8464e-3, B = 0.2406e-2 /mm, FN = 82 kN -> a = 8, b = 4 mm (prescribed),
  //   approach 9.266e-2 mm, pressure 1223 N/mm^2.
  const double e = 2.0 * 82000.0 * 1.28;
  const double e_star = contact_modulus_mpa(e, 0.28, e, 0.28);
  const Result<HertzShape<double>> t = hertz_shape(0.8e-3, 0.2814e-3, e_star);
  ASSERT_TRUE(t.ok());
  const HertzPatch<double> pt = hertz_patch(t.value, 106700.0);
  EXPECT_NEAR(pt.a_mm, 6.304, 0.002);
  EXPECT_NEAR(pt.b_mm, 12.61, 0.005);
  EXPECT_NEAR(pt.approach_mm, 7.651e-2, 0.002e-2);
  EXPECT_NEAR(pt.p_max_mpa, 640.7, 0.6);  // CONTACT's maximum is at a grid point, below p0
  const HertzPatch<double> pf =
      hertz_patch(hertz_shape(0.8464e-3, 0.2406e-2, e_star).value, 82000.0);
  EXPECT_NEAR(pf.a_mm, 8.0, 0.002);
  EXPECT_NEAR(pf.b_mm, 4.0, 0.002);
  EXPECT_NEAR(pf.approach_mm, 9.266e-2, 0.002e-2);
  EXPECT_NEAR(pf.p_max_mpa, 1223.0, 1.0);
}

TEST(HertzEllipse, ScalesWithTheLoadAndInvertsTheApproach) {
  const double e_star = contact_modulus_mpa(210000.0, 0.3, 210000.0, 0.3);
  const HertzShape<double> s = hertz_shape(0.5 / 460.0, 0.5 / 300.0, e_star).value;
  const HertzPatch<double> p1 = hertz_patch(s, 10000.0);
  const HertzPatch<double> p8 = hertz_patch(s, 80000.0);
  EXPECT_NEAR(p8.a_mm / p1.a_mm, 2.0, 1e-12);
  EXPECT_NEAR(p8.approach_mm / p1.approach_mm, 4.0, 1e-12);
  EXPECT_NEAR(p8.p_max_mpa / p1.p_max_mpa, 2.0, 1e-12);
  EXPECT_NEAR(hertz_load_for_approach(s, p8.approach_mm), 80000.0, 1e-6);
  EXPECT_EQ(hertz_load_for_approach(s, -1.0), 0.0);
  // The long axis lies along the smaller curvature; swapping A and B swaps a and b.
  const HertzShape<double> t = hertz_shape(0.5 / 300.0, 0.5 / 460.0, e_star).value;
  EXPECT_NEAR(t.a_unit_mm, s.b_unit_mm, 1e-14);
  EXPECT_NEAR(t.b_unit_mm, s.a_unit_mm, 1e-14);
  EXPECT_GT(s.a_unit_mm, s.b_unit_mm);
  // float scaling of a double shape
  const HertzPatch<float> pf = hertz_patch(shape_as<float>(s), 80000.0F);
  EXPECT_NEAR(pf.a_mm, p8.a_mm, 1e-6 * p8.a_mm);
  EXPECT_NEAR(pf.p_max_mpa, p8.p_max_mpa, 1e-5 * p8.p_max_mpa);
}

TEST(HertzEllipse, FloatCubeRootIsExactToRounding) {
  // Over the loads a wheel sees and far beyond: within 2 ulp of the correctly rounded root.
  float worst = 0.0F;
  for (float x = 1e-6F; x < 3e8F; x *= 1.0137F) {
    const float want = static_cast<float>(std::cbrt(static_cast<double>(x)));
    const float got = cube_root(x);
    worst = std::max(worst, std::abs(got - want) / want);
  }
  EXPECT_LT(worst, 2.5e-7F);
  EXPECT_EQ(cube_root(0.0F), 0.0F);
  EXPECT_EQ(cube_root(-8.0F), 0.0F);
  EXPECT_EQ(cube_root(std::numeric_limits<float>::infinity()), 0.0F);
  EXPECT_EQ(cube_root(std::nanf("")), 0.0F);
  EXPECT_DOUBLE_EQ(cube_root(27.0), 3.0);
}

TEST(HertzEllipse, SlenderAndBadContacts) {
  // Very slender ellipses (flange root on a worn rail) still solve; the ratio is exact.
  for (const double ratio : {1.0 + 1e-10, 1.001, 10.0, 1e3, 1e6}) {
    const Result<HertzShape<double>> s = hertz_shape(1e-3, 1e-3 * ratio, 100000.0);
    ASSERT_TRUE(s.ok()) << ratio;
    const double kp = s.value.b_unit_mm / s.value.a_unit_mm;
    EXPECT_NEAR(elliptic_integrals(kp).ratio, ratio, 1e-9 * ratio) << ratio;
  }
  EXPECT_EQ(hertz_shape(1e-3, 1e-3 * 1e9, 1e5).status, Status::out_of_range);
  EXPECT_EQ(hertz_shape(0.0, 1e-3, 1e5).status, Status::invalid_argument);
  EXPECT_EQ(hertz_shape(1e-3, -1e-3, 1e5).status, Status::invalid_argument);
  EXPECT_EQ(hertz_shape(1e-3, std::nan(""), 1e5).status, Status::invalid_argument);
  EXPECT_EQ(hertz_shape(1e-3, 1e-3, 0.0).status, Status::invalid_argument);
  const HertzPatch<float> lifted = hertz_patch(HertzShape<float>{1.0F, 1.0F, 1.0F, 1.0F}, -5.0F);
  EXPECT_EQ(lifted.a_mm, 0.0F);
  EXPECT_EQ(lifted.p_max_mpa, 0.0F);
}

}  // namespace
}  // namespace tread::rail
