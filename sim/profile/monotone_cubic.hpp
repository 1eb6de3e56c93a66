#pragma once
// Shape-preserving piecewise cubic Hermite interpolation (PCHIP, Fritsch–Carlson/Fritsch–Butland):
// interior slopes are the weighted harmonic mean of the neighbouring secants (0 at a local
// extremum), so the interpolant passes through every knot and adds no wiggles between them. The end
// slopes may be prescribed (e.g. to join an arc tangentially); they are limited to keep
// monotonicity.

#include <optional>
#include <vector>

namespace tread::profile {

class MonotoneCubic {
 public:
  /// `x` strictly increasing, same size as `z`, at least 2 knots; throws std::invalid_argument.
  MonotoneCubic(std::vector<double> x, std::vector<double> z,
                std::optional<double> slope_first = std::nullopt,
                std::optional<double> slope_last = std::nullopt);

  double x_first() const { return x_.front(); }
  double x_last() const { return x_.back(); }
  /// Value and first derivative; x outside the knots is extrapolated with the end cubic.
  double value(double x) const;
  double slope(double x) const;
  double knot_slope(std::size_t i) const { return d_[i]; }

 private:
  std::size_t interval(double x) const;
  std::vector<double> x_;
  std::vector<double> z_;
  std::vector<double> d_;
};

}  // namespace tread::profile
