#include "rig/wheelset_hunting.hpp"

#include <algorithm>
#include <cstddef>

namespace tread::host {

void WheelsetHunting::step(double delta_r_mm, double dt_s) {
  const double v = params_.speed_mps;
  // psi' = -V dr / (2 e0 r0): dr / (e0 r0) in 1/mm, times 1000 for 1/m.
  yaw_rad_ -= dt_s * v * delta_r_mm / (2.0 * params_.e0_mm * params_.r0_mm) * 1000.0;
  y_mm_ += dt_s * v * yaw_rad_ * 1000.0;
  distance_m_ += dt_s * v;
}

HuntingAnalysis analyse_hunting(std::span<const double> t_s, std::span<const double> y_mm,
                                double speed_mps) {
  HuntingAnalysis a;
  const std::size_t n = std::min(t_s.size(), y_mm.size());
  if (n < 3) {
    return a;
  }
  const auto [lo, hi] = std::minmax_element(y_mm.begin(), y_mm.begin() + static_cast<long>(n));
  a.centre_mm = 0.5 * (*hi + *lo);
  a.amplitude_mm = 0.5 * (*hi - *lo);
  double first = 0.0;
  double last = 0.0;
  int crossings = 0;
  for (std::size_t i = 1; i < n; ++i) {
    const double y0 = y_mm[i - 1] - a.centre_mm;
    const double y1 = y_mm[i] - a.centre_mm;
    if (y0 < 0.0 && y1 >= 0.0) {
      const double t = t_s[i - 1] + (t_s[i] - t_s[i - 1]) * (-y0) / (y1 - y0);
      if (crossings == 0) {
        first = t;
      }
      last = t;
      ++crossings;
    }
  }
  a.periods = crossings - 1;
  if (a.periods >= 2) {
    a.valid = true;
    a.period_s = (last - first) / a.periods;
    a.wavelength_m = a.period_s * speed_mps;
  }
  return a;
}

}  // namespace tread::host
