// Nadal's Y/Q limit against values worked out by hand and the identity tan(delta - atan(mu)).
#include "contact/nadal_limit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tread::contact {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(NadalLimit, SeventyDegreesAndMu036Is1_2) {
  // tan 70 deg = 2.747477; (2.747477 - 0.36) / (1 + 0.36 * 2.747477) = 2.387477 / 1.989092.
  EXPECT_NEAR(nadal_y_over_q(70.0 * kDeg, 0.36), 1.20028, 1e-5);
}

TEST(NadalLimit, LimitingCasesAndIdentity) {
  EXPECT_NEAR(nadal_y_over_q(70.0 * kDeg, 0.0), std::tan(70.0 * kDeg), 1e-12);  // no friction
  EXPECT_NEAR(nadal_y_over_q(60.0 * kDeg, std::tan(60.0 * kDeg)), 0.0, 1e-12);  // mu = tan delta
  for (const double d : {55.0, 65.0, 70.0, 75.0}) {
    for (const double mu : {0.1, 0.3, 0.5}) {
      EXPECT_NEAR(nadal_y_over_q(d * kDeg, mu), std::tan(d * kDeg - std::atan(mu)), 1e-12);
    }
  }
  // Higher friction lowers the limit; a steeper flange raises it.
  EXPECT_LT(nadal_y_over_q(70.0 * kDeg, 0.5), nadal_y_over_q(70.0 * kDeg, 0.3));
  EXPECT_GT(nadal_y_over_q(72.0 * kDeg, 0.3), nadal_y_over_q(70.0 * kDeg, 0.3));
  EXPECT_TRUE(std::isnan(nadal_y_over_q(95.0 * kDeg, 0.3)));
  EXPECT_TRUE(std::isnan(nadal_y_over_q(70.0 * kDeg, -0.1)));
}

}  // namespace
}  // namespace tread::contact
