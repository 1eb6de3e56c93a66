#pragma once
// A sampled profile z(y) as a continuous function: piecewise-linear values, slopes from a local
// least-squares line (robust against the noise of measured and worn profiles) and a check of the
// samples. The contact search works on these.

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "profile/sampled_profile.hpp"

namespace tread::contact {

class ProfileFunction {
 public:
  /// Takes the samples of `profile`; throws std::invalid_argument (naming the profile) when there
  /// are fewer than 2 points, sizes differ, a value is not finite or y is not strictly increasing.
  explicit ProfileFunction(const profile::SampledProfile& profile);

  const std::string& name() const { return name_; }
  double y_min_mm() const { return y_mm_.front(); }
  double y_max_mm() const { return y_mm_.back(); }
  std::span<const double> y_mm() const { return y_mm_; }
  std::span<const double> z_mm() const { return z_mm_; }

  /// Linear interpolation; y is clamped into [y_min, y_max].
  double z_at(double y_mm) const;

  /// Slope dz/dy at y from a least-squares parabola through the samples within ±half_window_mm of
  /// y (at least the two neighbouring samples; the chord if fewer than 3); y is clamped.
  double slope_at(double y_mm, double half_window_mm) const;

  /// Second derivative d2z/dy2 at y from the same least-squares parabola (0 with fewer than 3
  /// samples in the window).
  double curvature_at(double y_mm, double half_window_mm) const;

  /// Index i of the segment [y_i, y_i+1] holding y (clamped).
  std::size_t segment(double y_mm) const;

 private:
  std::pair<std::size_t, std::size_t> window(double y, double half_window_mm) const;
  std::string name_;
  std::vector<double> y_mm_;
  std::vector<double> z_mm_;
};

/// Local quadratic least-squares smoothing (uniform weights within +-half_window_mm, at least 5
/// samples): straight lines and parabolas are kept exactly, measurement noise is averaged out. For
/// measured or worn profiles before the contact search; half_window_mm <= 0 returns the input.
profile::SampledProfile smooth_profile(const profile::SampledProfile& profile,
                                       double half_window_mm);

}  // namespace tread::contact
