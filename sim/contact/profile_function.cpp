#include "contact/profile_function.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

namespace tread::contact {

ProfileFunction::ProfileFunction(const profile::SampledProfile& profile)
    : name_(profile.name), y_mm_(profile.y_mm), z_mm_(profile.z_mm) {
  const std::string who = "profile '" + name_ + "': ";
  if (y_mm_.size() != z_mm_.size()) {
    throw std::invalid_argument(who + "y_mm and z_mm differ in size");
  }
  if (y_mm_.size() < 2) {
    throw std::invalid_argument(who + "needs at least 2 points");
  }
  for (std::size_t i = 0; i < y_mm_.size(); ++i) {
    if (!std::isfinite(y_mm_[i]) || !std::isfinite(z_mm_[i])) {
      throw std::invalid_argument(who + "point " + std::to_string(i) + " is not finite");
    }
    if (i > 0 && !(y_mm_[i] > y_mm_[i - 1])) {
      throw std::invalid_argument(who + "y is not strictly increasing at point " +
                                  std::to_string(i) + " (y = " + std::to_string(y_mm_[i]) + ")");
    }
  }
}

std::size_t ProfileFunction::segment(double y_mm) const {
  const auto it = std::upper_bound(y_mm_.begin(), y_mm_.end(), y_mm);
  if (it == y_mm_.begin()) {
    return 0;
  }
  const auto i = static_cast<std::size_t>(it - y_mm_.begin()) - 1;
  return std::min(i, y_mm_.size() - 2);
}

double ProfileFunction::z_at(double y_mm) const {
  const double y = std::clamp(y_mm, y_mm_.front(), y_mm_.back());
  const std::size_t i = segment(y);
  const double t = (y - y_mm_[i]) / (y_mm_[i + 1] - y_mm_[i]);
  return z_mm_[i] + t * (z_mm_[i + 1] - z_mm_[i]);
}

namespace {

/// The least-squares quadratic z = c0 + c1 d + c2 d^2 in d = y_k - y through samples lo..hi
/// (Cramer's rule on the normal equations); none where they are singular.
std::optional<std::array<double, 3>> local_quadratic(std::span<const double> ys,
                                                     std::span<const double> zs, std::size_t lo,
                                                     std::size_t hi, double y) {
  double m0 = 0, m1 = 0, m2 = 0, m3 = 0, m4 = 0, r0 = 0, r1 = 0, r2 = 0;
  for (std::size_t k = lo; k <= hi; ++k) {
    const double d = ys[k] - y;
    const double d2 = d * d;
    m0 += 1.0;
    m1 += d;
    m2 += d2;
    m3 += d2 * d;
    m4 += d2 * d2;
    r0 += zs[k];
    r1 += zs[k] * d;
    r2 += zs[k] * d2;
  }
  const double det = m0 * (m2 * m4 - m3 * m3) - m1 * (m1 * m4 - m3 * m2) + m2 * (m1 * m3 - m2 * m2);
  if (!(std::abs(det) > 0.0)) {
    return std::nullopt;
  }
  return std::array<double, 3>{
      (r0 * (m2 * m4 - m3 * m3) - m1 * (r1 * m4 - m3 * r2) + m2 * (r1 * m3 - m2 * r2)) / det,
      (m0 * (r1 * m4 - m3 * r2) - r0 * (m1 * m4 - m3 * m2) + m2 * (m1 * r2 - r1 * m2)) / det,
      (m0 * (m2 * r2 - r1 * m3) - m1 * (m1 * r2 - r1 * m2) + r0 * (m1 * m3 - m2 * m2)) / det};
}

struct LocalParabola {
  double slope;
  double curvature;
};

/// Least-squares parabola through samples lo..hi: the slope c1 and the second derivative 2 c2 at
/// y (exact for parabolas, symmetric window or not). With fewer than 3 samples: the chord and 0.
LocalParabola fit_parabola(std::span<const double> ys, std::span<const double> zs, std::size_t lo,
                           std::size_t hi, double y) {
  const LocalParabola chord{(zs[hi] - zs[lo]) / (ys[hi] - ys[lo]), 0.0};
  if (hi - lo + 1 < 3) {
    return chord;
  }
  const auto c = local_quadratic(ys, zs, lo, hi, y);
  if (!c) {
    return chord;
  }
  return {(*c)[1], 2.0 * (*c)[2]};
}

}  // namespace

std::pair<std::size_t, std::size_t> ProfileFunction::window(double y, double half_window_mm) const {
  const std::size_t seg = segment(y);
  std::size_t lo = seg;
  std::size_t hi = seg + 1;
  while (lo > 0 && y_mm_[lo - 1] >= y - half_window_mm) {
    --lo;
  }
  while (hi + 1 < y_mm_.size() && y_mm_[hi + 1] <= y + half_window_mm) {
    ++hi;
  }
  return {lo, hi};
}

double ProfileFunction::slope_at(double y_mm, double half_window_mm) const {
  const double y = std::clamp(y_mm, y_mm_.front(), y_mm_.back());
  const auto [lo, hi] = window(y, half_window_mm);
  return fit_parabola(y_mm_, z_mm_, lo, hi, y).slope;
}

double ProfileFunction::curvature_at(double y_mm, double half_window_mm) const {
  const double y = std::clamp(y_mm, y_mm_.front(), y_mm_.back());
  const auto [lo, hi] = window(y, half_window_mm);
  return fit_parabola(y_mm_, z_mm_, lo, hi, y).curvature;
}

profile::SampledProfile smooth_profile(const profile::SampledProfile& profile,
                                       double half_window_mm) {
  const ProfileFunction checked(profile);  // validates
  if (!(half_window_mm > 0.0)) {
    return profile;
  }
  const auto& y = profile.y_mm;
  const auto& z = profile.z_mm;
  const std::size_t n = y.size();
  profile::SampledProfile out{profile.name, y, std::vector<double>(n)};
  std::size_t lo = 0;
  std::size_t hi = 0;
  for (std::size_t i = 0; i < n; ++i) {
    while (y[lo] < y[i] - half_window_mm) {
      ++lo;
    }
    while (hi + 1 < n && y[hi + 1] <= y[i] + half_window_mm) {
      ++hi;
    }
    std::size_t a = lo;
    std::size_t b = hi;
    while (b - a + 1 < 5 && (a > 0 || b + 1 < n)) {  // at least 5 samples
      if (a > 0) {
        --a;
      }
      if (b - a + 1 < 5 && b + 1 < n) {
        ++b;
      }
    }
    if (b - a + 1 < 3) {
      out.z_mm[i] = z[i];
      continue;
    }
    // The quadratic's value at y_i.
    const auto c = local_quadratic(y, z, a, b, y[i]);
    out.z_mm[i] = c ? (*c)[0] : z[i];
  }
  return out;
}

}  // namespace tread::contact
