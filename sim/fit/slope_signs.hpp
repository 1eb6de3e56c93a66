#pragma once
// The signs a fitted tyre's curves have at the origin in ISO-W axes (the axes of every fit):
// dFx/dκ > 0 (driving slip drives), dFy/dα < 0 (the contact patch moving towards +y is pulled
// back) and dMz/dα > 0 (a positive pneumatic trail). A fit with the other sign is a mirror image
// of a tyre: the data's slip or force was written in another sign convention, which the fit
// cannot tell from a real tyre. Host side.

#include <string>
#include <vector>

namespace tread::fit {

enum class SlopeOf { fx_kappa, fy_alpha, mz_alpha };

/// One slope of a fit: its load (N) and value (N, N/rad or N m/rad).
struct LoadSlope {
  double fz_n = 0.0;
  double slope = 0.0;
};

/// Empty if every slope has its ISO-W sign (0 or NaN included); otherwise one warning naming the
/// slope, the loads and values of the wrong ones and the conventions that explain them.
std::string slope_sign_doubt(SlopeOf which, const std::vector<LoadSlope>& slopes);

}  // namespace tread::fit
