#pragma once
// The plot of `tread profile --input`: a profile read from a file, its local slope and, for a
// wheel, its nominal EN 13715 profile and the difference measured - nominal (in the file's frame,
// no vertical alignment: wear shows as negative values where the taping line is not worn).

#include <string>
#include <vector>

#include "profile/sampled_profile.hpp"
#include "profile/wheel_profile.hpp"

namespace tread::profile {

/// Writes a PNG (or SVG, by the extension) through gnuplot. `slopes` has the profile's size;
/// `nominal` may be null (rails, or a wheel without one). Throws std::runtime_error if gnuplot
/// fails or a file cannot be written.
void plot_measured_profile(const SampledProfile& measured, const std::vector<double>& slopes,
                           const WheelProfile* nominal, const std::string& title,
                           const std::string& png_path);

}  // namespace tread::profile
