#include "profile/profile_slope.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

namespace tread::profile {

std::vector<double> local_slopes(const SampledProfile& p, double half_window_mm) {
  if (!(half_window_mm >= 0.0)) {
    throw std::invalid_argument("local slope: the half-window must be >= 0 mm");
  }
  const std::size_t n = p.y_mm.size();
  if (n < 2 || p.z_mm.size() != n) {
    throw std::invalid_argument(p.name + ": a slope needs at least 2 points");
  }
  std::vector<double> out(n);
  std::size_t lo = 0;
  std::size_t hi = 0;  // one past the window
  for (std::size_t i = 0; i < n; ++i) {
    while (p.y_mm[lo] < p.y_mm[i] - half_window_mm) {
      ++lo;
    }
    hi = std::max(hi, i + 1);
    while (hi < n && p.y_mm[hi] <= p.y_mm[i] + half_window_mm) {
      ++hi;
    }
    const std::size_t a = std::min(lo, i == 0 ? 0 : i - 1);
    const std::size_t b = std::max(hi, std::min(n, i + 2));
    double sy = 0.0;
    double sz = 0.0;
    for (std::size_t j = a; j < b; ++j) {
      sy += p.y_mm[j];
      sz += p.z_mm[j];
    }
    const double count = static_cast<double>(b - a);
    const double my = sy / count;
    const double mz = sz / count;
    double syy = 0.0;
    double syz = 0.0;
    for (std::size_t j = a; j < b; ++j) {
      syy += (p.y_mm[j] - my) * (p.y_mm[j] - my);
      syz += (p.y_mm[j] - my) * (p.z_mm[j] - mz);
    }
    out[i] = syz / syy;
  }
  return out;
}

}  // namespace tread::profile
