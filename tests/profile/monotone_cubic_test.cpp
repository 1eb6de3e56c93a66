#include "profile/monotone_cubic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace tread::profile {
namespace {

TEST(MonotoneCubic, PassesThroughTheKnotsAndReproducesALine) {
  const MonotoneCubic line({0.0, 0.5, 1.0, 2.0}, {1.0, 0.0, -1.0, -3.0});
  for (double x = 0.0; x <= 2.0; x += 0.01) {
    EXPECT_NEAR(line.value(x), 1.0 - 2.0 * x, 1e-12);
    EXPECT_NEAR(line.slope(x), -2.0, 1e-12);
  }
}

TEST(MonotoneCubic, NoOvershootOnStepLikeData) {
  const std::vector<double> x{0, 1, 2, 3, 4, 5};
  const std::vector<double> z{0, 0, 0, 1, 1, 1};
  const MonotoneCubic c(x, z);
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_DOUBLE_EQ(c.value(x[i]), z[i]);
  }
  for (double t = 0.0; t <= 5.0; t += 0.005) {
    EXPECT_GE(c.value(t), -1e-15);
    EXPECT_LE(c.value(t), 1.0 + 1e-15);
    EXPECT_GE(c.slope(t), -1e-15);
  }
}

TEST(MonotoneCubic, PrescribedEndSlopesAreKeptWhenCompatibleAndLimitedOtherwise) {
  const MonotoneCubic c({0.0, 1.0, 2.0}, {3.0, 2.0, 1.5}, -1.2, -0.4);
  EXPECT_NEAR(c.slope(0.0), -1.2, 1e-12);
  EXPECT_NEAR(c.slope(2.0), -0.4, 1e-12);
  // Wrong sign → 0; more than 3 × the secant → 3 × the secant (Fritsch–Carlson).
  const MonotoneCubic d({0.0, 1.0, 2.0}, {3.0, 2.0, 1.5}, 0.5, -5.0);
  EXPECT_NEAR(d.knot_slope(0), 0.0, 1e-15);
  EXPECT_NEAR(d.knot_slope(2), -1.5, 1e-12);
  EXPECT_THROW(MonotoneCubic({0.0, 0.0}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(MonotoneCubic({0.0}, {1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace tread::profile
