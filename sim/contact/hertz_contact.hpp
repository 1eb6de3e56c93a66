#pragma once
// Hertz contact ellipse for a wheel on a rail: semi-axes and pressures from the wheel load and the
// principal radii of both bodies at the contact point, by the standard elliptic-integral solution
// (Hertz 1882; Johnson, Contact Mechanics, §4.2): with the relative curvatures
//     A = (1/Rx1 + 1/Rx2) / 2  (rolling direction x),  B = (1/Ry1 + 1/Ry2) / 2  (lateral y),
// the ellipse eccentricity e solves  B/A = (E(e)/(1 - e^2) - K(e)) / (K(e) - E(e))  (for B >= A;
// axes swapped otherwise), and  a^3 = 3 P (K - E) / (2 pi E* e^2 A),  b = a sqrt(1 - e^2), where
// K, E are the complete elliptic integrals of modulus e and 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2.
// Mean pressure P / (pi a b), maximum 3/2 of it. The solution itself is the core's
// (rail/hertz_ellipse.hpp); this is the host's interface with radii and materials.
//
// The seed's eq. 1-2 (square root of 3Q(1-nu^2)/(E (1/rd + 1/rk))) are not Hertz's result: the
// semi-axes go with the cube root of the load and depend on all four curvatures; eq. 3 is the
// auxiliary angle of the classic Hertz coefficient tables (cos theta = (B - A)/(B + A)).

namespace tread::contact {

struct HertzInput {
  double load_n = 0.0;         ///< normal load P
  double wheel_rx_mm = 460.0;  ///< wheel rolling radius
  double wheel_ry_mm = 1e300;  ///< wheel profile radius (lateral); < 0 concave; huge = straight
  double rail_rx_mm = 1e300;   ///< rail longitudinal radius (straight track: huge)
  double rail_ry_mm = 300.0;   ///< rail head profile radius (lateral); < 0 concave
  double e1_mpa = 210000.0;    ///< wheel Young's modulus
  double nu1 = 0.3;            ///< wheel Poisson ratio
  double e2_mpa = 210000.0;    ///< rail
  double nu2 = 0.3;
};

struct HertzResult {
  double a_mm = 0.0;  ///< semi-axis in the rolling direction (x)
  double b_mm = 0.0;  ///< semi-axis lateral (y)
  double mean_pressure_mpa = 0.0;
  double max_pressure_mpa = 0.0;
  double approach_mm = 0.0;    ///< mutual approach of the two bodies
  double a_curv_per_mm = 0.0;  ///< A
  double b_curv_per_mm = 0.0;  ///< B
  double e_star_mpa = 0.0;     ///< contact modulus E*
};

struct WheelContact;

/// Hertz input at a contact point of the rigid search: the wheel's radius in the contact plane
/// r / cos(gamma) along the rail (straight track), the lateral relative curvature of both profiles
/// (given as the wheel's lateral radius, the rail's lateral radius set to a straight line).
HertzInput hertz_input_at(const WheelContact& contact, double load_n);

/// Throws std::domain_error when A or B is not positive (conformal or non-Hertzian contact) or
/// the load/material values are not positive.
HertzResult hertz_contact(const HertzInput& input);

/// Hertz coefficients m, n of the classic tables: a = m c, b = n c with
/// c = (3 pi P (k1 + k2) / (4 (A + B)))^(1/3), k = (1 - nu^2) / (pi E); for the long axis m >= n.
/// theta_rad = acos(|B - A| / (A + B)).
struct HertzCoefficients {
  double m = 1.0;
  double n = 1.0;
};
HertzCoefficients hertz_coefficients(double theta_rad);

}  // namespace tread::contact
