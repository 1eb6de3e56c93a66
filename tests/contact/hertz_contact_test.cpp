// Hertz ellipse: the circular limit (closed form), the classic coefficient table (Timoshenko &
// Goodier, Theory of Elasticity, §140: m, n against theta), scaling laws and symmetry.
#include "contact/hertz_contact.hpp"

#include "contact/rigid_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tread::contact {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(HertzContact, CrossedEqualCylindersGiveTheCircularContact) {
  // Wheel as a cylinder of radius 460 crossing a rail crown of radius 460: A = B = 1/920, the
  // contact of a sphere of radius 460 on a plane: a = (3 P R / (4 E*))^(1/3).
  HertzInput in;
  in.load_n = 100000.0;
  in.wheel_rx_mm = 460.0;
  in.rail_ry_mm = 460.0;
  const HertzResult r = hertz_contact(in);
  const double e_star = 210000.0 / (2.0 * (1.0 - 0.09));
  const double a = std::cbrt(3.0 * 100000.0 * 460.0 / (4.0 * e_star));
  EXPECT_NEAR(r.e_star_mpa, e_star, 1e-9);
  EXPECT_NEAR(r.a_mm, a, 1e-9 * a);
  EXPECT_NEAR(r.b_mm, a, 1e-9 * a);
  EXPECT_NEAR(r.max_pressure_mpa, 3.0 * 100000.0 / (2.0 * std::numbers::pi * a * a), 1e-6);
  EXPECT_NEAR(r.mean_pressure_mpa, r.max_pressure_mpa / 1.5, 1e-9);
}

struct TableRow {
  double theta_deg;
  double m;
  double n;
};

TEST(HertzContact, CoefficientsMatchTheClassicTable) {
  // Timoshenko & Goodier, Theory of Elasticity (3rd ed.), §140, table of m and n (3 decimals).
  const TableRow rows[] = {{30, 2.731, 0.493}, {40, 2.136, 0.567}, {50, 1.754, 0.641},
                           {60, 1.486, 0.717}, {70, 1.284, 0.802}, {80, 1.128, 0.893},
                           {90, 1.000, 1.000}};
  for (const TableRow& row : rows) {
    const HertzCoefficients c = hertz_coefficients(row.theta_deg * kDeg);
    EXPECT_NEAR(c.m, row.m, 0.002 * row.m + 0.0005) << "theta " << row.theta_deg;
    EXPECT_NEAR(c.n, row.n, 0.002 * row.n + 0.0005) << "theta " << row.theta_deg;
  }
}

TEST(HertzContact, WheelOnRailEllipseAgreesWithTheCoefficients) {
  // S1002-like tread (cone, lateral radius infinite) on a 60E1 crown (R300), 460 mm wheel.
  HertzInput in;
  in.load_n = 110000.0;
  const HertzResult r = hertz_contact(in);
  const double a_curv = 0.5 / 460.0;
  const double b_curv = 0.5 / 300.0;
  EXPECT_NEAR(r.a_curv_per_mm, a_curv, 1e-15);
  EXPECT_NEAR(r.b_curv_per_mm, b_curv, 1e-15);
  const HertzCoefficients c = hertz_coefficients(std::acos((b_curv - a_curv) / (a_curv + b_curv)));
  const double scale = std::cbrt(3.0 * in.load_n / (4.0 * r.e_star_mpa * (a_curv + b_curv)));
  EXPECT_NEAR(r.a_mm, c.m * scale, 1e-9);  // the long axis runs along the rail (A < B)
  EXPECT_NEAR(r.b_mm, c.n * scale, 1e-9);
  EXPECT_GT(r.a_mm, r.b_mm);
  // Plausibility against the seed's "a = 6-8 mm, b = 4.5-5.5 mm, p = 1000-1500 MPa".
  EXPECT_GT(r.a_mm, 5.0);
  EXPECT_LT(r.a_mm, 9.0);
  EXPECT_GT(r.b_mm, 3.5);
  EXPECT_LT(r.b_mm, 6.5);
}

TEST(HertzContact, ScalesWithTheCubeRootOfTheLoadAndSwapsWithTheCurvatures) {
  HertzInput in;
  in.load_n = 50000.0;
  const HertzResult r1 = hertz_contact(in);
  in.load_n = 400000.0;  // x 8
  const HertzResult r8 = hertz_contact(in);
  EXPECT_NEAR(r8.a_mm, 2.0 * r1.a_mm, 1e-9);
  EXPECT_NEAR(r8.b_mm, 2.0 * r1.b_mm, 1e-9);
  EXPECT_NEAR(r8.max_pressure_mpa, 2.0 * r1.max_pressure_mpa, 1e-6);
  HertzInput swapped;
  swapped.load_n = 50000.0;
  swapped.wheel_rx_mm = 1e300;
  swapped.wheel_ry_mm = 460.0;
  swapped.rail_rx_mm = 300.0;
  swapped.rail_ry_mm = 1e300;
  const HertzResult rs = hertz_contact(swapped);
  EXPECT_NEAR(rs.a_mm, r1.b_mm, 1e-9);
  EXPECT_NEAR(rs.b_mm, r1.a_mm, 1e-9);
}

TEST(HertzContact, ConcaveWheelRadiusAndConformalLimit) {
  HertzInput in;
  in.load_n = 100000.0;
  in.wheel_ry_mm = -500.0;  // hollow worn tread, still Hertzian with a R300 crown
  const HertzResult r = hertz_contact(in);
  EXPECT_NEAR(r.b_curv_per_mm, 0.5 * (1.0 / 300.0 - 1.0 / 500.0), 1e-15);
  in.wheel_ry_mm = -300.0;  // fully conformal laterally
  EXPECT_THROW((void)hertz_contact(in), std::domain_error);
  in.wheel_ry_mm = 1e300;
  in.load_n = 0.0;
  EXPECT_THROW((void)hertz_contact(in), std::domain_error);
}

TEST(HertzContact, InputAtARigidContactPoint) {
  // A tread contact at gamma = 0 with relative lateral curvature 1/300 is the cone-on-R300 case.
  WheelContact c;
  c.r_mm = 460.0;
  c.gamma_rad = 0.0;
  c.lateral_relative_curvature_per_mm = 1.0 / 300.0;
  HertzInput reference;
  reference.load_n = 90000.0;
  const HertzResult expected = hertz_contact(reference);
  const HertzResult got = hertz_contact(hertz_input_at(c, 90000.0));
  EXPECT_NEAR(got.a_mm, expected.a_mm, 1e-9);
  EXPECT_NEAR(got.b_mm, expected.b_mm, 1e-9);
  // On a 70 degree flange the wheel's radius in the contact plane is r / cos(gamma).
  c.gamma_rad = 70.0 * kDeg;
  EXPECT_NEAR(hertz_input_at(c, 1.0).wheel_rx_mm, 460.0 / std::cos(70.0 * kDeg), 1e-9);
  c.lateral_relative_curvature_per_mm = -0.001;  // conformal
  EXPECT_THROW((void)hertz_contact(hertz_input_at(c, 1000.0)), std::domain_error);
}

}  // namespace
}  // namespace tread::contact
