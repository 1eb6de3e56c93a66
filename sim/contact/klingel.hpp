#pragma once
// Klingel's kinematic hunting wavelength of a free wheelset (1883):
//     lambda = 2 pi sqrt(e0 r0 / tan(gamma_e)),
// e0 = half the lateral distance between the contact points, r0 = nominal rolling radius,
// tan(gamma_e) = equivalent conicity. And its inverse (tan(gamma_e) from a wavelength), which is
// how EN 15302 Annex B turns the integrated wavelength into the conicity.

#include <cmath>
#include <numbers>

namespace tread::contact {

/// lambda (mm); NaN unless tan_gamma_e, e0 and r0 are > 0.
inline double klingel_wavelength_mm(double tan_gamma_e, double r0_mm, double e0_mm = 750.0) {
  if (!(tan_gamma_e > 0.0) || !(r0_mm > 0.0) || !(e0_mm > 0.0)) {
    return std::nan("");
  }
  return 2.0 * std::numbers::pi * std::sqrt(e0_mm * r0_mm / tan_gamma_e);
}

/// tan(gamma_e) from the wavelength (mm); NaN unless all arguments are > 0.
inline double klingel_conicity(double wavelength_mm, double r0_mm, double e0_mm = 750.0) {
  if (!(wavelength_mm > 0.0) || !(r0_mm > 0.0) || !(e0_mm > 0.0)) {
    return std::nan("");
  }
  const double w = 2.0 * std::numbers::pi / wavelength_mm;
  return e0_mm * r0_mm * w * w;
}

}  // namespace tread::contact
