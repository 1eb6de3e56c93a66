#pragma once
// Flange measures of a wheel profile (EN 15313 style): flange height Sh (tip above the taping line
// D0), flange thickness Sd (flange back y = -70 to the flange face at 10 mm above the taping line)
// and qR (lateral distance between the flange face at 10 mm above the taping line and at 2 mm
// below the flange tip). For the constructed EN 13715 profiles (WheelProfile) the taping line is
// z = 0; for a sampled (measured, worn) profile it is the profile's own z(0).

#include <optional>

#include "profile/sampled_profile.hpp"
#include "profile/wheel_profile.hpp"

namespace tread::profile {

struct FlangeMeasures {
  double tip_y_mm;             ///< where z is highest (on the flange, y < -30)
  double height_mm;            ///< Sh: z at the tip above the taping line
  double thickness_mm;         ///< Sd: y_face(10 mm above the taping line) + 70
  double qr_mm;                ///< qR: y_face(10 mm) - y_face(2 mm below the tip)
  double face_y_at_10_mm;      ///< y_face(10 mm above the taping line)
  double face_y_below_tip_mm;  ///< y_face(2 mm below the tip)
};

/// Measures the flange of `wheel` (face points by bisection to 1e-10 mm). Throws
/// std::runtime_error if the flange face does not cross the heights.
FlangeMeasures measure_flange(const WheelProfile& wheel);

/// What `tread profile --input` measures on a sampled wheel profile.
struct SampledWheelMeasures {
  FlangeMeasures flange;
  double taping_z_mm;  ///< z(0), the reference of Sh and of the 10 mm level
  /// Hollow (tread) wear: the largest rise of z toward the field side on the tread, from the
  /// flange face at 10 mm to the end of the profile — the height of a false flange above the bottom
  /// of the hollow; 0 for a new EN 13715 profile, whose tread never rises toward the field side.
  double hollow_depth_mm;
  double hollow_bottom_y_mm;  ///< where the hollow is deepest (the face point if there is none)
  double false_flange_y_mm;   ///< the top of the rise (the face point if there is none)
  /// The outer slope's gradient (least-squares line through the points in y ∈ [38, 58], positive
  /// when falling toward the outer face), if the profile covers that range.
  std::optional<double> outer_slope;
  double outer_slope_rms_mm = 0.0;  ///< the residual of that line (0 for a straight slope)
};

/// Measures a sampled wheel profile (this project's wheel convention) by linear interpolation
/// between its points: the tip is the highest point with y < -30 (refined between the points where
/// the neighbouring segments meet in a cusp), the face points are the first crossings of the levels
/// from the tip toward the tread. Throws std::runtime_error naming the profile if it does not
/// reach the taping line y = 0 or the flange (y < -30), its highest flange point is its first point
/// (no tip), or its flange face does not cross the levels.
SampledWheelMeasures measure_wheel(const SampledProfile& wheel);

/// z at y by linear interpolation (y within the profile's range; throws std::out_of_range naming
/// the profile otherwise).
double interpolate_z(const SampledProfile& profile, double y_mm);

}  // namespace tread::profile
