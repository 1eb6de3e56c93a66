#pragma once
// PNG plots of wheel profiles through gnuplot (gnuplot-nox; the C++ sciplot library is not packaged
// in Debian bookworm): the profile z(y), its slope tan(y), and the slopes of S1002, EPS and 1/40
// with the same flange compared over the tread (the seed's appendices 6–9).

#include <string>

#include "profile/wheel_profile.hpp"

namespace tread::profile {

/// Writes `png_path` (three panels). Throws std::runtime_error when gnuplot fails or is missing.
void plot_wheel_profile(const WheelProfile& wheel, double step_mm, const std::string& png_path);

}  // namespace tread::profile
