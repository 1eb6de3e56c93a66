#pragma once
// Flange measures of a wheel profile (EN 15313 style): flange height (tip above D0), flange
// thickness (flange back y = -70 to the flange face at z = +10 mm) and qR (lateral distance between
// the flange face at z = +10 mm and at 2 mm below the flange tip).

#include "profile/wheel_profile.hpp"

namespace tread::profile {

struct FlangeMeasures {
  double tip_y_mm;             ///< where z is highest
  double height_mm;            ///< z at the tip
  double thickness_mm;         ///< y_face(z = 10) + 70
  double qr_mm;                ///< y_face(z = 10) - y_face(z = height - 2)
  double face_y_at_10_mm;      ///< y_face(z = 10)
  double face_y_below_tip_mm;  ///< y_face(z = height - 2)
};

/// Measures the flange of `wheel` (face points by bisection to 1e-10 mm). Throws
/// std::runtime_error if the flange face does not cross the heights.
FlangeMeasures measure_flange(const WheelProfile& wheel);

}  // namespace tread::profile
