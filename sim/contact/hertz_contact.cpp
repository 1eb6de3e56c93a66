#include "contact/hertz_contact.hpp"

#include "contact/rigid_contact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tread::contact {

namespace {

/// Ellipse of two bodies with relative curvatures a_small <= a_large: returns (e, (K-E)/e^2).
struct Eccentricity {
  double e;
  double k_minus_e_over_e2;
};

double ratio_of(double e) {
  const double k = std::comp_ellint_1(e);
  const double ee = std::comp_ellint_2(e);
  return (ee / (1.0 - e * e) - k) / (k - ee);
}

Eccentricity solve_eccentricity(double ratio) {
  // ratio = B/A >= 1; ratio(e) rises monotonically from 1 (e = 0) to infinity (e -> 1).
  if (ratio < 1.0 + 1e-12) {
    return {0.0, std::numbers::pi / 4.0};
  }
  double lo = 0.0;
  double hi = 1.0;
  for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid > 0.0 && ratio_of(mid) < ratio) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  const double e = 0.5 * (lo + hi);
  if (e < 1e-4) {
    // Series: (K - E)/e^2 = pi/4 (1 + 3/8 e^2 + ...), avoiding the cancellation.
    return {e, std::numbers::pi / 4.0 * (1.0 + 0.375 * e * e)};
  }
  return {e, (std::comp_ellint_1(e) - std::comp_ellint_2(e)) / (e * e)};
}

double curvature(double radius_mm) {
  return 1.0 / radius_mm;
}

}  // namespace

HertzInput hertz_input_at(const WheelContact& contact, double load_n) {
  HertzInput in;
  in.load_n = load_n;
  in.wheel_rx_mm = contact.r_mm / std::cos(contact.gamma_rad);
  in.rail_rx_mm = 1e300;
  // B = (1/Ry1 + 1/Ry2)/2 = kappa/2: put the whole relative curvature on the wheel.
  in.wheel_ry_mm = 1.0 / contact.lateral_relative_curvature_per_mm;
  in.rail_ry_mm = 1e300;
  return in;
}

HertzResult hertz_contact(const HertzInput& in) {
  if (!(in.load_n > 0.0) || !(in.e1_mpa > 0.0) || !(in.e2_mpa > 0.0) || !(in.nu1 < 0.5) ||
      !(in.nu2 < 0.5)) {
    throw std::domain_error("Hertz: load and moduli must be > 0, Poisson ratios < 0.5");
  }
  HertzResult r;
  r.a_curv_per_mm = 0.5 * (curvature(in.wheel_rx_mm) + curvature(in.rail_rx_mm));
  r.b_curv_per_mm = 0.5 * (curvature(in.wheel_ry_mm) + curvature(in.rail_ry_mm));
  if (!(r.a_curv_per_mm > 0.0) || !(r.b_curv_per_mm > 0.0)) {
    throw std::domain_error(
        "Hertz: relative curvatures must be positive (conformal or non-Hertzian contact)");
  }
  r.e_star_mpa = 1.0 / ((1.0 - in.nu1 * in.nu1) / in.e1_mpa + (1.0 - in.nu2 * in.nu2) / in.e2_mpa);
  const double small = std::min(r.a_curv_per_mm, r.b_curv_per_mm);
  const double large = std::max(r.a_curv_per_mm, r.b_curv_per_mm);
  const Eccentricity ecc = solve_eccentricity(large / small);
  // The long semi-axis lies along the direction of the smaller relative curvature.
  const double long_axis = std::cbrt(3.0 * in.load_n * ecc.k_minus_e_over_e2 /
                                     (2.0 * std::numbers::pi * r.e_star_mpa * small));
  const double short_axis = long_axis * std::sqrt(1.0 - ecc.e * ecc.e);
  if (r.a_curv_per_mm <= r.b_curv_per_mm) {
    r.a_mm = long_axis;
    r.b_mm = short_axis;
  } else {
    r.a_mm = short_axis;
    r.b_mm = long_axis;
  }
  r.mean_pressure_mpa = in.load_n / (std::numbers::pi * r.a_mm * r.b_mm);
  r.max_pressure_mpa = 1.5 * r.mean_pressure_mpa;
  return r;
}

HertzCoefficients hertz_coefficients(double theta_rad) {
  // Unit problem: A + B = 1, cos(theta) = (B - A)/(A + B); identical materials with E* = 1.
  const double c = std::cos(theta_rad);
  const double a_curv = 0.5 * (1.0 - c);
  const double b_curv = 0.5 * (1.0 + c);
  const Eccentricity ecc = solve_eccentricity(b_curv / a_curv);
  // a^3 = 3 P (K-E)/(2 pi E* e^2 A) and c^3 = 3 pi P (k1+k2) / (4 (A+B)) with
  // k1 + k2 = 1/(pi E*): c^3 = 3 P / (4 E* (A+B)); take P = E* = 1.
  const double a3 = 3.0 * ecc.k_minus_e_over_e2 / (2.0 * std::numbers::pi * a_curv);
  const double c3 = 3.0 / 4.0;
  HertzCoefficients out;
  out.m = std::cbrt(a3 / c3);
  out.n = out.m * std::sqrt(1.0 - ecc.e * ecc.e);
  return out;
}

}  // namespace tread::contact
