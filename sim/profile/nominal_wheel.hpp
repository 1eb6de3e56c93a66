#pragma once
// The nominal EN 13715 profile a measured wheel is compared with: the family, h, e, outer slope and
// width given by the user, the rest taken from the measures — h and e on the standard's grid (h:
// the largest of 28/30/32 not above Sh + 0.2, since tread wear only raises Sh and a thin flange's
// cusp lowers it by up to 0.17 mm; e: Sd to the nearest 0.5 mm within 28.5 … 32.5), the outer slope
// from the measured one (1:15 if within 0.015 % of it, else the nearest 0.1 % within 6.7 … 15 %),
// the width from the profile's end (140 if it reaches y = 67.5, else 135). The family is S1002
// unless given; "auto" picks the family whose profile is closest to the measured one (least RMS z
// difference over the points in y ∈ [-25, 25]; tread wear can mislead it).

#include <string>

#include "profile/sampled_profile.hpp"
#include "profile/wheel_measures.hpp"
#include "profile/wheel_profile.hpp"

namespace tread::profile {

struct NominalChoice {
  WheelParameters parameters;
  std::string how;  ///< what was given and what was derived, for the output
};

/// `spec`: empty (S1002, the rest derived), "auto" (everything derived), or "S1002"/"EPS"/"1/40"
/// optionally followed by
/// ":h=..,e=..,slope=..,width=..,chamfer=.." (keys given are used, the others derived). Throws
/// std::invalid_argument for a malformed spec or parameters outside the standard.
NominalChoice choose_nominal(const std::string& spec, const SampledProfile& measured,
                             const SampledWheelMeasures& measures);

}  // namespace tread::profile
