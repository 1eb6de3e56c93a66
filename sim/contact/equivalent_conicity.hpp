#pragma once
// Equivalent conicity tan(gamma_e) from a delta r function (EN 15302).
//
// equivalent_conicity(): the Annex B method. The kinematic (Klingel) wheelset equation with the
// nonlinear delta r function,
//     d2y/dx2 = -delta_r(y) / (2 e0 r0),
// is integrated over distance from y = y_c + amplitude, dy/dx = 0 (y_c: the root of delta r nearest
// 0, the centre of the motion); the wavelength lambda is the distance between the first and third
// zero crossing of y - y_c; then tan(gamma_e) = e0 r0 (2 pi / lambda)^2 (Klingel's formula solved
// for the conicity; e0 and r0 cancel, they only set the length scale).
//
// linearised_conicity(): the linear-regression value for comparison (EN 15302 Annex C, "linear
// regression of the delta r function"): the slope of the least-squares line through delta r over
// -amplitude..+amplitude about y_c, halved (delta r ~ 2 tan(gamma) y). y is sampled as a harmonic
// motion y = y_c + amplitude sin(phi) at uniform phi, i.e. weighted by the time a harmonic
// oscillation spends at each y. That weighting is this project's reading of the method (the
// standard's text was not available); a uniform weighting gives somewhat larger values where delta
// r steepens toward the amplitude.

#include "contact/rigid_contact.hpp"

namespace tread::contact {

struct ConicityOptions {
  double e0_mm = 750.0;  ///< half the lateral distance between the contact points
  double r0_mm = 460.0;  ///< nominal rolling radius
  double step_mm = 2.0;  ///< RK4 step in travelled distance
};

struct ConicityResult {
  double tan_gamma_e = 0.0;
  double wavelength_mm = 0.0;
  double centre_y_mm = 0.0;  ///< root of delta r the motion is centred on
};

/// delta r is read from `table` by linear interpolation. Throws std::domain_error when the motion
/// leaves the table, delta r has no root, or it does not oscillate (no restoring delta r).
ConicityResult equivalent_conicity(const ContactTable& table, double amplitude_mm,
                                   const ConicityOptions& options = {});

/// See above; throws std::domain_error when centre +- amplitude leaves the table.
double linearised_conicity(const ContactTable& table, double amplitude_mm);

/// Linear interpolation of delta r in the table; throws std::domain_error outside it.
double delta_r_at(const ContactTable& table, double y_mm);

}  // namespace tread::contact
