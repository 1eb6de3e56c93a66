#pragma once
// A synthetic worn wheel: an EN 13715 profile with a thinned flange and a hollow-worn tread, made
// by a documented procedure (for tests and the README's example; it is not a measurement).
//
// On a grid y_min … y_max at step_mm (as WheelProfile::sample), with z_n the nominal profile:
// 1. Flange thinning: the face is moved toward the flange back by δ(y) = thinning × w(y), w = 1
//    for y <= thinning_full_to_y_mm, 0 for y >= thinning_zero_from_y_mm, smoothstep between;
//    z = min(z_n(y), z_n(y + δ(y))). The flange back is unchanged, the tip becomes a cusp of the
//    two tip arcs (as EN 13715's thin flanges), the tread beyond the taper is unchanged.
// 2. Hollow wear: z -= hollow_depth × cos²(π (y - c) / (2 half_width)) for |y - c| < half_width.
// 3. Measurement-like noise: z += noise × (2u - 1), u uniform in [0, 1] from std::minstd_rand
//    seeded with noise_seed (u = (x - 1) / (2³¹ - 3), reproducible on every platform).
// 4. z rounded to 1e-6 mm.

#include <cstdint>

#include "profile/sampled_profile.hpp"
#include "profile/wheel_profile.hpp"

namespace tread::profile {

struct SyntheticWear {
  double flange_thinning_mm = 0.0;
  double thinning_full_to_y_mm = -36.0;
  double thinning_zero_from_y_mm = -26.0;
  double hollow_depth_mm = 0.0;
  double hollow_centre_y_mm = 5.0;
  double hollow_half_width_mm = 25.0;
  double noise_mm = 0.0;
  std::uint32_t noise_seed = 13;
};

/// The worn profile (named "<nominal name> synthetic wear"). Throws std::invalid_argument for a
/// non-positive step, a negative thinning/depth/noise or a taper whose ends are not increasing.
SampledProfile apply_synthetic_wear(const WheelProfile& nominal, const SyntheticWear& wear,
                                    double step_mm);

}  // namespace tread::profile
