#include "profile/synthetic_wear.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>
#include <stdexcept>

namespace tread::profile {

SampledProfile apply_synthetic_wear(const WheelProfile& nominal, const SyntheticWear& wear,
                                    double step_mm) {
  if (!(wear.flange_thinning_mm >= 0.0) || !(wear.hollow_depth_mm >= 0.0) ||
      !(wear.noise_mm >= 0.0) || !(wear.hollow_half_width_mm > 0.0)) {
    throw std::invalid_argument(
        "synthetic wear: thinning, hollow depth and noise must be >= 0, the half-width > 0");
  }
  if (!(wear.thinning_zero_from_y_mm > wear.thinning_full_to_y_mm)) {
    throw std::invalid_argument("synthetic wear: the thinning taper must end after it starts");
  }
  SampledProfile out = nominal.sample(step_mm);
  out.name = nominal.name() + " synthetic wear";
  std::minstd_rand rng(wear.noise_seed);
  for (std::size_t i = 0; i < out.y_mm.size(); ++i) {
    const double y = out.y_mm[i];
    double z = out.z_mm[i];
    if (wear.flange_thinning_mm > 0.0) {
      const double t = std::clamp((y - wear.thinning_full_to_y_mm) /
                                      (wear.thinning_zero_from_y_mm - wear.thinning_full_to_y_mm),
                                  0.0, 1.0);
      const double w = 1.0 - t * t * (3.0 - 2.0 * t);
      const double shifted = std::min(y + wear.flange_thinning_mm * w, nominal.y_max_mm());
      z = std::min(z, nominal.at(shifted).z_mm);
    }
    const double u = (y - wear.hollow_centre_y_mm) / wear.hollow_half_width_mm;
    if (std::fabs(u) < 1.0) {
      const double c = std::cos(0.5 * std::numbers::pi * u);
      z -= wear.hollow_depth_mm * c * c;
    }
    if (wear.noise_mm > 0.0) {
      const double r = static_cast<double>(rng() - 1U) / 2147483645.0;
      z += wear.noise_mm * (2.0 * r - 1.0);
    }
    out.z_mm[i] = std::round(z * 1e6) / 1e6;
  }
  return out;
}

}  // namespace tread::profile
