// The kinematic wheelset model and the hunting analysis, on cases with a closed-form answer.
#include "rig/wheelset_hunting.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "contact/klingel.hpp"

namespace tread::host {
namespace {

struct ConeRun {
  std::vector<double> t_s;
  std::vector<double> y_mm;
};

/// A wheelset on a linear delta r (a coned wheel: delta r = 2 tan(gamma) y) for `duration_s`.
ConeRun run_cone(double tan_gamma, double speed_mps, double y0_mm, double duration_s, double dt_s) {
  WheelsetHuntingParams p;
  p.speed_mps = speed_mps;
  WheelsetHunting w(p, y0_mm);
  ConeRun r;
  for (double t = 0.0; t < duration_s; t += dt_s) {
    w.step(2.0 * tan_gamma * w.y_mm(), dt_s);
    r.t_s.push_back(t + dt_s);
    r.y_mm.push_back(w.y_mm());
  }
  return r;
}

TEST(WheelsetHunting, ConedWheelHuntsAtKlingelsWavelength) {
  for (const double tan_gamma : {0.025, 0.05, 0.2}) {
    for (const double speed : {10.0, 30.0, 60.0}) {
      const double klingel_m = contact::klingel_wavelength_mm(tan_gamma, 460.0, 750.0) / 1000.0;
      const ConeRun r = run_cone(tan_gamma, speed, 4.0, 8.0 * klingel_m / speed, 1e-3);
      const HuntingAnalysis a = analyse_hunting(r.t_s, r.y_mm, speed);
      ASSERT_TRUE(a.valid);
      // Semi-implicit Euler: the frequency error is O((omega dt)^2).
      EXPECT_NEAR(a.wavelength_m / klingel_m, 1.0, 2e-4) << tan_gamma << " " << speed;
      EXPECT_NEAR(a.amplitude_mm, 4.0, 0.01 * 4.0);
      EXPECT_NEAR(a.centre_mm, 0.0, 0.01);
    }
  }
}

TEST(WheelsetHunting, SymplecticStepKeepsTheAmplitude) {
  const ConeRun r = run_cone(0.2, 60.0, 5.0, 20.0, 1e-3);  // about 140 periods
  const std::size_t n = r.y_mm.size();
  double late_max = 0.0;
  for (std::size_t i = n - n / 10; i < n; ++i) late_max = std::max(late_max, r.y_mm[i]);
  EXPECT_NEAR(late_max, 5.0, 0.05);
}

TEST(WheelsetHunting, RestoringDeltaRTurnsTheWheelsetBack) {
  WheelsetHunting w({30.0, 750.0, 460.0}, 3.0);
  w.step(0.6, 1e-3);  // left wheel larger: the wheelset yaws to the right and moves back
  EXPECT_LT(w.yaw_rad(), 0.0);
  EXPECT_LT(w.y_mm(), 3.0);
  EXPECT_NEAR(w.distance_m(), 0.03, 1e-12);
}

TEST(HuntingAnalysis, SampledSineGivesItsWavelengthAndAmplitude) {
  std::vector<double> t;
  std::vector<double> y;
  for (int i = 0; i <= 5000; ++i) {
    t.push_back(i * 1e-3);
    y.push_back(0.7 + 2.5 * std::sin(2.0 * std::numbers::pi * 3.1 * i * 1e-3 + 0.4));
  }
  const HuntingAnalysis a = analyse_hunting(t, y, 25.0);
  ASSERT_TRUE(a.valid);
  EXPECT_NEAR(a.period_s, 1.0 / 3.1, 1e-5);
  EXPECT_NEAR(a.wavelength_m, 25.0 / 3.1, 1e-3);
  EXPECT_NEAR(a.amplitude_mm, 2.5, 1e-4);
  EXPECT_NEAR(a.centre_mm, 0.7, 1e-4);
}

TEST(HuntingAnalysis, TooShortARecordIsNotValid) {
  const std::vector<double> t = {0.0, 0.1, 0.2, 0.3};
  const std::vector<double> y = {1.0, -1.0, 1.0, -1.0};
  EXPECT_FALSE(analyse_hunting(t, y, 10.0).valid);
  EXPECT_FALSE(analyse_hunting({}, {}, 10.0).valid);
}

}  // namespace
}  // namespace tread::host
