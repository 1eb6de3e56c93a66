#include "profile/profile_table.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>
#include <stdexcept>
#include <string>

namespace tread::profile {

int step_decimals(double step_mm) {
  for (int d = 1; d < 6; ++d) {
    const double scaled = step_mm * std::pow(10.0, d);
    if (std::fabs(scaled - std::round(scaled)) < 1e-6) {
      return d;
    }
  }
  return 6;
}

std::vector<double> descending_grid(const WheelProfile& wheel, double step_mm) {
  if (!(step_mm > 0.0)) {
    throw std::invalid_argument("step must be positive");
  }
  const double snap = std::pow(10.0, step_decimals(step_mm));
  std::vector<double> ys;
  const auto n =
      static_cast<std::size_t>(std::floor((wheel.y_max_mm() - wheel.y_min_mm()) / step_mm + 1e-9));
  for (std::size_t i = 0; i <= n; ++i) {
    ys.push_back(std::round((wheel.y_max_mm() - static_cast<double>(i) * step_mm) * snap) / snap);
  }
  if (ys.back() > wheel.y_min_mm() + 1e-9) {
    ys.push_back(wheel.y_min_mm());
  }
  return ys;
}

namespace {

std::string fixed5(double v) {
  if (std::isinf(v)) {
    return v > 0.0 ? "inf" : "-inf";
  }
  if (std::fabs(v) < 5e-6) {
    v = 0.0;  // no "-0.00000"
  }
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.5f", v);
  return buffer;
}

}  // namespace

void write_profile_table(std::ostream& out, const WheelProfile& wheel, double step_mm) {
  const WheelParameters& p = wheel.parameters();
  const int decimals = step_decimals(step_mm);
  out << "profile " << to_string(p.family) << "\n\n"
      << "e = " << p.flange_thickness_mm << " mm h = " << p.flange_height_mm << " mm outer slope "
      << to_string(p.outer_slope) << (p.outer_slope.uic_1in15 ? "" : " %") << " width "
      << p.width_mm << " mm" << (p.chamfer ? "" : " no chamfer") << "\n\n"
      << "y [mm]\tz [mm]\ttan\n";
  for (const double y : descending_grid(wheel, step_mm)) {
    const ProfileValue v = wheel.at(y);
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, y);
    out << buffer << '\t' << fixed5(v.z_mm) << '\t' << fixed5(v.tan) << '\n';
  }
}

}  // namespace tread::profile
