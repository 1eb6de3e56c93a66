#include "profile/rail_measures.hpp"

#include <cstddef>
#include <stdexcept>

namespace tread::profile {

RailMeasures measure_rail(const SampledProfile& p, double gauge_depth_mm) {
  const std::size_t n = p.y_mm.size();
  if (n < 2 || p.z_mm.size() != n) {
    throw std::runtime_error(p.name + ": a rail profile needs at least 2 points");
  }
  RailMeasures m{};
  std::size_t top = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (p.z_mm[i] > p.z_mm[top]) {
      top = i;
    }
  }
  m.top_y_mm = p.y_mm[top];
  m.top_z_mm = p.z_mm[top];
  m.gauge_depth_mm = gauge_depth_mm;
  const double level = m.top_z_mm - gauge_depth_mm;
  // The innermost point at or above the level: the first such point from the gauge side.
  m.gauge_point_y_mm = p.y_mm.front();
  m.reaches_gauge_depth = false;
  for (std::size_t i = 1; i < n; ++i) {
    if (p.z_mm[i] >= level && p.z_mm[i - 1] < level) {
      const double t = (p.z_mm[i] - level) / (p.z_mm[i] - p.z_mm[i - 1]);
      m.gauge_point_y_mm = p.y_mm[i] - t * (p.y_mm[i] - p.y_mm[i - 1]);
      m.reaches_gauge_depth = true;
      break;
    }
    if (p.z_mm[i - 1] >= level) {
      break;  // the profile starts above the level
    }
  }
  // The outermost point at or above the level, from the field side.
  for (std::size_t i = n - 1; i > 0; --i) {
    if (p.z_mm[i - 1] >= level && p.z_mm[i] < level) {
      const double t = (p.z_mm[i - 1] - level) / (p.z_mm[i - 1] - p.z_mm[i]);
      const double field_y = p.y_mm[i - 1] + t * (p.y_mm[i] - p.y_mm[i - 1]);
      if (m.reaches_gauge_depth) {
        m.head_width_mm = field_y - m.gauge_point_y_mm;
      }
      break;
    }
    if (p.z_mm[i] >= level) {
      break;  // the profile ends above the level
    }
  }
  return m;
}

}  // namespace tread::profile
