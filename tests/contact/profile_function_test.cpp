// ProfileFunction: interpolation, least-squares slopes, input checks, and the smoothing that keeps
// parabolas exactly while averaging out noise.
#include "contact/profile_function.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace tread::contact {
namespace {

profile::SampledProfile parabola(double step) {
  profile::SampledProfile p{"parabola", {}, {}};
  for (double y = -10.0; y <= 10.0 + 1e-9; y += step) {
    p.y_mm.push_back(y);
    p.z_mm.push_back(0.02 * y * y - 0.1 * y + 1.0);
  }
  return p;
}

TEST(ProfileFunction, InterpolatesAndClamps) {
  const ProfileFunction f(profile::SampledProfile{"line", {0.0, 1.0, 3.0}, {0.0, 2.0, 0.0}});
  EXPECT_DOUBLE_EQ(f.z_at(0.5), 1.0);
  EXPECT_DOUBLE_EQ(f.z_at(2.0), 1.0);
  EXPECT_DOUBLE_EQ(f.z_at(-5.0), 0.0);  // clamped
  EXPECT_DOUBLE_EQ(f.z_at(9.0), 0.0);
  EXPECT_EQ(f.segment(3.0), 1u);
}

TEST(ProfileFunction, SlopeOfAParabola) {
  const ProfileFunction f(parabola(0.01));
  for (const double y : {-5.0, 0.0, 2.5, 7.0}) {
    // A symmetric least-squares window gives the exact derivative of a parabola.
    EXPECT_NEAR(f.slope_at(y, 0.05), 0.04 * y - 0.1, 1e-9) << y;
    EXPECT_NEAR(f.curvature_at(y, 0.5), 0.04, 1e-9) << y;
  }
}

TEST(ProfileFunction, RejectsBadInput) {
  EXPECT_THROW(ProfileFunction(profile::SampledProfile{"a", {0.0}, {0.0}}), std::invalid_argument);
  EXPECT_THROW(ProfileFunction(profile::SampledProfile{"b", {0.0, 1.0}, {0.0}}),
               std::invalid_argument);
  EXPECT_THROW(ProfileFunction(profile::SampledProfile{"c", {0.0, 1.0, 0.5}, {0.0, 0.0, 0.0}}),
               std::invalid_argument);
  EXPECT_THROW(ProfileFunction(profile::SampledProfile{"d", {0.0, 1.0}, {0.0, std::nan("")}}),
               std::invalid_argument);
}

TEST(ProfileFunction, SmoothingKeepsParabolasAndAveragesNoise) {
  const auto p = parabola(0.05);
  const auto s = smooth_profile(p, 0.5);
  for (std::size_t i = 0; i < p.y_mm.size(); ++i) {
    EXPECT_NEAR(s.z_mm[i], p.z_mm[i], 1e-10);
  }
  auto noisy = p;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (double& z : noisy.z_mm) {
    z += noise(rng);
  }
  const auto smoothed = smooth_profile(noisy, 1.0);
  double raw2 = 0.0;
  double smooth2 = 0.0;
  for (std::size_t i = 0; i < p.y_mm.size(); ++i) {
    raw2 += std::pow(noisy.z_mm[i] - p.z_mm[i], 2);
    smooth2 += std::pow(smoothed.z_mm[i] - p.z_mm[i], 2);
  }
  EXPECT_LT(smooth2, 0.1 * raw2);
  EXPECT_EQ(smooth_profile(p, 0.0).z_mm, p.z_mm);
}

}  // namespace
}  // namespace tread::contact
