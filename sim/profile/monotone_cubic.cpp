#include "profile/monotone_cubic.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace tread::profile {

namespace {

/// Fritsch–Carlson limit of an end slope against the adjacent secant.
double limit_end_slope(double d, double secant) {
  if (!(d * secant > 0.0)) {  // opposite sign, or a flat secant
    return 0.0;
  }
  if (std::fabs(d) > 3.0 * std::fabs(secant)) {
    return 3.0 * secant;
  }
  return d;
}

}  // namespace

MonotoneCubic::MonotoneCubic(std::vector<double> x, std::vector<double> z,
                             std::optional<double> slope_first, std::optional<double> slope_last)
    : x_(std::move(x)), z_(std::move(z)) {
  const std::size_t n = x_.size();
  if (n < 2 || z_.size() != n) {
    throw std::invalid_argument("MonotoneCubic: need at least 2 knots and equal sizes");
  }
  for (std::size_t i = 1; i < n; ++i) {
    if (!(x_[i] > x_[i - 1])) {
      throw std::invalid_argument("MonotoneCubic: x must be strictly increasing");
    }
  }
  std::vector<double> h(n - 1);
  std::vector<double> delta(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    h[i] = x_[i + 1] - x_[i];
    delta[i] = (z_[i + 1] - z_[i]) / h[i];
  }
  d_.assign(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (delta[i - 1] * delta[i] > 0.0) {
      const double w1 = 2.0 * h[i] + h[i - 1];
      const double w2 = h[i] + 2.0 * h[i - 1];
      d_[i] = (w1 + w2) / (w1 / delta[i - 1] + w2 / delta[i]);
    }
  }
  // One-sided three-point end slopes (as MATLAB/SciPy pchip) unless prescribed.
  const auto end_slope = [](double h0, double h1, double del0, double del1) {
    if (h1 <= 0.0) {
      return del0;
    }
    return ((2.0 * h0 + h1) * del0 - h0 * del1) / (h0 + h1);
  };
  if (n == 2) {
    d_[0] = slope_first.value_or(delta[0]);
    d_[1] = slope_last.value_or(delta[0]);
  } else {
    d_[0] = slope_first.value_or(end_slope(h[0], h[1], delta[0], delta[1]));
    d_[n - 1] = slope_last.value_or(end_slope(h[n - 2], h[n - 3], delta[n - 2], delta[n - 3]));
  }
  d_[0] = limit_end_slope(d_[0], delta[0]);
  d_[n - 1] = limit_end_slope(d_[n - 1], delta[n - 2]);
}

std::size_t MonotoneCubic::interval(double x) const {
  const auto it = std::upper_bound(x_.begin() + 1, x_.end() - 1, x);
  return static_cast<std::size_t>(it - x_.begin()) - 1;
}

double MonotoneCubic::value(double x) const {
  const std::size_t i = interval(x);
  const double h = x_[i + 1] - x_[i];
  const double t = (x - x_[i]) / h;
  const double t2 = t * t;
  const double t3 = t2 * t;
  return (2.0 * t3 - 3.0 * t2 + 1.0) * z_[i] + (t3 - 2.0 * t2 + t) * h * d_[i] +
         (-2.0 * t3 + 3.0 * t2) * z_[i + 1] + (t3 - t2) * h * d_[i + 1];
}

double MonotoneCubic::slope(double x) const {
  const std::size_t i = interval(x);
  const double h = x_[i + 1] - x_[i];
  const double t = (x - x_[i]) / h;
  const double t2 = t * t;
  return (6.0 * t2 - 6.0 * t) / h * z_[i] + (3.0 * t2 - 4.0 * t + 1.0) * d_[i] +
         (-6.0 * t2 + 6.0 * t) / h * z_[i + 1] + (3.0 * t2 - 2.0 * t) * d_[i + 1];
}

}  // namespace tread::profile
