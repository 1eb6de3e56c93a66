#include "contact/hertz_contact.hpp"

#include "contact/rigid_contact.hpp"
#include "rail/hertz_ellipse.hpp"

#include <cmath>
#include <stdexcept>

namespace tread::contact {

namespace {

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
  r.e_star_mpa = rail::contact_modulus_mpa(in.e1_mpa, in.nu1, in.e2_mpa, in.nu2);
  const Result<rail::HertzShape<double>> shape =
      rail::hertz_shape(r.a_curv_per_mm, r.b_curv_per_mm, r.e_star_mpa);
  if (shape.status == Status::invalid_argument) {
    throw std::domain_error("Hertz: contact modulus not positive or curvatures not finite");
  }
  const rail::HertzPatch<double> patch = rail::hertz_patch(shape.value, in.load_n);
  r.a_mm = patch.a_mm;
  r.b_mm = patch.b_mm;
  r.approach_mm = patch.approach_mm;
  r.mean_pressure_mpa = patch.p_mean_mpa;
  r.max_pressure_mpa = patch.p_max_mpa;
  return r;
}

HertzCoefficients hertz_coefficients(double theta_rad) {
  // Unit problem: A + B = 1, cos(theta) = (B - A)/(A + B), E* = 1, P = 1; then
  // c^3 = 3 pi P (k1 + k2) / (4 (A + B)) with k1 + k2 = 1/(pi E*) is 3/4.
  const double c = std::cos(theta_rad);
  const Result<rail::HertzShape<double>> shape =
      rail::hertz_shape(0.5 * (1.0 - c), 0.5 * (1.0 + c), 1.0);
  const double unit = std::cbrt(0.75);
  HertzCoefficients out;
  out.m = shape.value.a_unit_mm / unit;
  out.n = shape.value.b_unit_mm / unit;
  return out;
}

}  // namespace tread::contact
