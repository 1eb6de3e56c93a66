#include "contact/rail_placement.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace tread::contact {

namespace {

/// Innermost (smallest y) point of the polyline within [top - depth, top]; returns {y, z}.
std::pair<double, double> innermost_in_band(const std::string& name, const std::vector<double>& y,
                                            const std::vector<double>& z, double depth_mm) {
  const double top = *std::max_element(z.begin(), z.end());
  const double floor_z = top - depth_mm;
  double best_y = std::numeric_limits<double>::infinity();
  double best_z = top;
  bool reaches = false;
  auto consider = [&](double py, double pz) {
    if (py < best_y) {
      best_y = py;
      best_z = pz;
    }
  };
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (z[i] >= floor_z) {
      consider(y[i], z[i]);
    } else {
      reaches = true;
    }
    if (i + 1 < y.size()) {
      // Crossing of the band floor inside the segment.
      const double z0 = z[i] - floor_z;
      const double z1 = z[i + 1] - floor_z;
      if ((z0 < 0.0 && z1 > 0.0) || (z0 > 0.0 && z1 < 0.0)) {
        const double t = z0 / (z0 - z1);
        consider(y[i] + t * (y[i + 1] - y[i]), floor_z);
        reaches = true;
      }
    }
  }
  if (!reaches) {
    throw std::invalid_argument("rail profile '" + name + "' does not reach " +
                                std::to_string(depth_mm) + " mm below its top: no gauge point");
  }
  return {best_y, best_z};
}

}  // namespace

PlacedRail place_rail(const profile::SampledProfile& upright, const RailPlacement& placement) {
  const std::size_t n = upright.y_mm.size();
  if (n < 2 || upright.z_mm.size() != n) {
    throw std::invalid_argument("rail profile '" + upright.name + "': needs >= 2 (y, z) points");
  }
  const double c = std::cos(placement.inclination_rad);
  const double s = std::sin(placement.inclination_rad);
  std::vector<double> x(n);
  std::vector<double> z(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double y0 = upright.y_mm[i];
    const double z0 = upright.z_mm[i];
    if (!std::isfinite(y0) || !std::isfinite(z0)) {
      throw std::invalid_argument("rail profile '" + upright.name + "': point " +
                                  std::to_string(i) + " is not finite");
    }
    // Counter-clockwise in (x right = field side, z up): the top leans toward the track centre.
    x[i] = c * y0 - s * z0;
    z[i] = s * y0 + c * z0;
  }
  const auto [gp_x, gp_z] = innermost_in_band(upright.name, x, z, placement.gauge_depth_mm);
  const double top = *std::max_element(z.begin(), z.end());
  const double shift = (0.5 * placement.gauge_mm - kTrackFrameOrigin_mm) - gp_x;

  // Upper envelope on a uniform grid (the rotated polyline need not be a function of x).
  const double h = placement.resample_step_mm;
  const double x_lo = *std::min_element(x.begin(), x.end());
  const double x_hi = *std::max_element(x.begin(), x.end());
  const auto m = static_cast<std::size_t>(std::floor((x_hi - x_lo) / h)) + 1;
  std::vector<double> env(m, -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double xa = std::min(x[i], x[i + 1]);
    const double xb = std::max(x[i], x[i + 1]);
    const auto k0 = static_cast<std::size_t>(std::ceil((xa - x_lo) / h - 1e-9));
    for (std::size_t k = k0; k < m; ++k) {
      const double xk = x_lo + static_cast<double>(k) * h;
      if (xk > xb + 1e-12) {
        break;
      }
      const double dx = x[i + 1] - x[i];
      const double t = std::abs(dx) < 1e-15 ? 0.0 : std::clamp((xk - x[i]) / dx, 0.0, 1.0);
      env[k] = std::max(env[k], z[i] + t * (z[i + 1] - z[i]));
    }
  }
  PlacedRail out;
  out.track.name = upright.name;
  for (std::size_t k = 0; k < m; ++k) {
    if (std::isfinite(env[k])) {
      out.track.y_mm.push_back(x_lo + static_cast<double>(k) * h + shift);
      out.track.z_mm.push_back(env[k] - top);
    }
  }
  out.gauge_point_y_mm = gp_x + shift;
  out.gauge_point_z_mm = gp_z - top;
  return out;
}

double track_frame_gauge_mm(const profile::SampledProfile& track, double gauge_depth_mm) {
  const auto [gp_y, gp_z] = innermost_in_band(track.name, track.y_mm, track.z_mm, gauge_depth_mm);
  (void)gp_z;
  return 2.0 * (kTrackFrameOrigin_mm + gp_y);
}

}  // namespace tread::contact
