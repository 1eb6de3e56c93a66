#pragma once
// Nadal's flange-climb limit (1896): a flange with contact angle delta and friction coefficient mu
// starts to climb when the lateral/vertical wheel force ratio reaches
//     Y/Q = (tan(delta) - mu) / (1 + mu tan(delta))  ( = tan(delta - atan(mu)) ).
// E.g. delta = 70 deg, mu = 0.36: 1.200 (the value behind the usual Y/Q < 1.2 limit).

#include <cmath>

namespace tread::contact {

/// NaN for delta outside (0, 90 deg) or mu < 0.
inline double nadal_y_over_q(double flange_angle_rad, double mu) {
  constexpr double kHalfPi = 1.5707963267948966;
  if (!(flange_angle_rad > 0.0 && flange_angle_rad < kHalfPi) || !(mu >= 0.0)) {
    return std::nan("");
  }
  const double t = std::tan(flange_angle_rad);
  return (t - mu) / (1.0 + mu * t);
}

}  // namespace tread::contact
