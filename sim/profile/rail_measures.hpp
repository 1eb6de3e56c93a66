#pragma once
// What `tread profile --input` measures on a sampled rail profile (z up, gauge side at smaller y):
// the top of rail, the gauge point (the innermost point no more than 14 mm below the top) and the
// head width at that depth.

#include <optional>

#include "profile/sampled_profile.hpp"

namespace tread::profile {

struct RailMeasures {
  double top_y_mm;  ///< the highest point
  double top_z_mm;
  double gauge_depth_mm;  ///< the depth below the top used for the gauge point (14)
  /// The innermost crossing of z = top - depth on the gauge side (linear interpolation); the first
  /// point of the profile if the gauge side does not reach that depth (reaches_gauge_depth false).
  double gauge_point_y_mm;
  bool reaches_gauge_depth;
  /// From the gauge point to the field-side crossing of the same level, if the field side reaches
  /// it.
  std::optional<double> head_width_mm;
};

/// Throws std::runtime_error naming the profile for fewer than 2 points.
RailMeasures measure_rail(const SampledProfile& rail, double gauge_depth_mm = 14.0);

}  // namespace tread::profile
