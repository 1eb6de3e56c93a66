#pragma once
// Places a rail head given in its own upright frame (lateral x < 0 on the gauge side, z up) into
// the track frame the contact search uses: inclined toward the track centre, the gauge point
// (innermost head point from the top of rail down to `gauge_depth_mm`) at half the gauge, lateral
// measured from the running circle of the centred nominal wheelset (kTrackFrameOrigin_mm = 750 mm
// from the track centre), positive toward the field side, z up with the top of rail at 0.

#include "profile/sampled_profile.hpp"

namespace tread::contact {

/// Lateral distance of the track-frame origin from the track centre (running circle of the centred
/// nominal wheelset: back-to-back 1360 + 2 x 70 mm, halved).
inline constexpr double kTrackFrameOrigin_mm = 750.0;
/// Distance of the wheel's taping line (y = 0 of the wheel profile) from the wheel back.
inline constexpr double kTapingLineFromBack_mm = 70.0;

struct RailPlacement {
  double gauge_mm = 1435.0;
  double inclination_rad = 0.0249947916;  ///< atan(1/40); 0 = upright
  double gauge_depth_mm = 14.0;           ///< gauge point band below the top of rail
  double resample_step_mm = 0.01;         ///< step of the upper envelope in the track frame
};

struct PlacedRail {
  profile::SampledProfile track;  ///< upper envelope in the track frame (z = 0 at the top of rail)
  double gauge_point_y_mm;        ///< track-frame lateral position of the gauge point
  double gauge_point_z_mm;        ///< its height (z = -gauge_depth_mm unless the head ends higher)
};

/// Throws std::invalid_argument for a profile that is too short, not finite or whose head does not
/// reach gauge_depth_mm below its top on the gauge side.
PlacedRail place_rail(const profile::SampledProfile& upright, const RailPlacement& placement);

/// The gauge (mm) of a rail already in the track frame: 2 (kTrackFrameOrigin_mm + y_gp), with y_gp
/// the innermost point within gauge_depth_mm below its top.
double track_frame_gauge_mm(const profile::SampledProfile& track, double gauge_depth_mm = 14.0);

}  // namespace tread::contact
