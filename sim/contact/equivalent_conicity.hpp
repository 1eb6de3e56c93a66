#pragma once
// Equivalent conicity tan(gamma_e) from a delta r function (EN 15302), for any wheelset: equal or
// different wheels and rolling radii, delta r functions that do not pass through 0 at y = 0 or do
// not restore the wheelset near the centre.
//
// equivalent_conicity(): EN 15302:2008+A1 Annex B, integration of the nonlinear kinematic
// (Klingel) wheelset equation
//     d2y/dx2 = -delta_r(y) / (2 e0 r0).
// The equation is conservative: with V(y) = integral of delta r, (dy/dx)^2 / 2 + V(y) / (2 e0 r0)
// is constant along x. An oscillation therefore turns at two points y_min < y_max with
// V(y_min) = V(y_max) and V below that level in between. Its amplitude is (y_max - y_min) / 2 and
// its centre (y_min + y_max) / 2: for an asymmetric delta r the centre is not the root of delta r
// and the two excursions from it differ. Among the oscillations of the requested amplitude the one
// centred nearest to y = 0 is taken. The wavelength is the period integral
//     lambda = 2 * integral over (y_min, y_max) of dy / sqrt(2 (V(y_min) - V(y)) / (2 e0 r0)),
// evaluated with y = centre + amplitude * sin(theta) (which removes the end singularities) by the
// midpoint rule, and tan(gamma_e) = e0 r0 (2 pi / lambda)^2 (Klingel's formula solved for the
// conicity; e0 and r0 cancel). Where delta r is exactly 0 over a whole stretch of 2 * amplitude the
// wheelset is in neutral equilibrium there: no oscillation, lambda infinite, tan(gamma_e) = 0 (the
// value EN 15302 Annex K gives for such cases, e.g. wheel I at small amplitudes).
//
// linearised_conicity(): EN 15302:2008+A1 Annex C, linear regression of the delta r function. The
// motion is taken as harmonic, y = y_c + amplitude sin(phi); delta r is sampled at uniform phi
// (i.e. weighted by the time the motion spends at each y), the centre y_c is where the mean of
// delta r over the cycle is zero (harmonic balance of the constant part: the wheelset runs where
// the mean radius difference vanishes), and tan(gamma_e) is half the slope of the least-squares
// line through delta r over the cycle. The uniform-phi weighting is this project's reading of the
// annex (its text was not available); it reproduces the Annex K values of the EN 15302:2021 test
// cases within their windows except next to jumps of delta r (see tests/contact).
//
// Both throw std::domain_error with the amplitude and the reason when no result exists (the motion
// leaves the table, delta r does not restore the wheelset anywhere, ...).

#include <limits>

#include "contact/rigid_contact.hpp"

namespace tread::contact {

struct ConicityOptions {
  double e0_mm = 750.0;           ///< half the lateral distance between the contact points
  double r0_mm = 460.0;           ///< nominal rolling radius
  int quadrature_points = 20000;  ///< midpoint rule of the period integral (in theta)
};

/// Annex B result.
struct ConicityResult {
  double tan_gamma_e = 0.0;
  double wavelength_mm = 0.0;  ///< +inf in neutral equilibrium
  double centre_y_mm = 0.0;    ///< (y_min + y_max) / 2
  double y_min_mm = 0.0;       ///< turning points of the oscillation
  double y_max_mm = 0.0;
  bool neutral = false;  ///< delta r = 0 over the whole motion: tan(gamma_e) = 0, no oscillation
};

/// Annex C result.
struct RegressionResult {
  double tan_gamma_e = 0.0;
  double centre_y_mm = 0.0;  ///< y_c: mean of delta r over the harmonic cycle is 0
};

/// delta r is read from `table` by linear interpolation (the table's y grid must be uniform).
ConicityResult equivalent_conicity(const ContactTable& table, double amplitude_mm,
                                   const ConicityOptions& options = {});

RegressionResult linearised_conicity(const ContactTable& table, double amplitude_mm);

/// Linear interpolation of delta r in the table; throws std::domain_error outside it.
double delta_r_at(const ContactTable& table, double y_mm);

/// A table holding only y and delta r (uniform grid y_first + k step), e.g. from a tabulated
/// delta r function. Throws std::invalid_argument for fewer than 2 points or step <= 0.
ContactTable delta_r_table(double y_first_mm, double y_step_mm, const std::vector<double>& delta_r);

}  // namespace tread::contact
