#pragma once
// The local slope of a sampled profile: at each point the gradient of the least-squares line
// through the points within a lateral half-window (at least the point and its neighbours), which
// tames the noise of measured points that a two-point difference would amplify.

#include <vector>

#include "profile/sampled_profile.hpp"

namespace tread::profile {

/// dz/dy at every point of `profile` (same size). `half_window_mm` >= 0; with 0 each point uses
/// its neighbours only (a central difference inside, one-sided at the ends). Throws
/// std::invalid_argument for a negative window or fewer than 2 points.
std::vector<double> local_slopes(const SampledProfile& profile, double half_window_mm);

}  // namespace tread::profile
