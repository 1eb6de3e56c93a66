// Nadal's Y/Q limit against values worked out by hand and the identity tan(delta - atan(mu)); a
// wheel's Y and Q from its contact points and the margin to the limit.
#include "rail/derailment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tread::rail {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double nadal(double delta_rad, double mu) {
  const Result<double> r = nadal_limit(delta_rad, mu);
  EXPECT_TRUE(r.ok());
  return r.value;
}

TEST(NadalLimit, SeventyDegreesAndMu036Is1_2) {
  // tan 70 deg = 2.747477; (2.747477 - 0.36) / (1 + 0.36 * 2.747477) = 2.387477 / 1.989092.
  EXPECT_NEAR(nadal(70.0 * kDeg, 0.36), 1.20028, 1e-5);
  // More hand-worked points: 60 deg / 0.3 -> 0.9424, 75 deg / 0.5 -> 1.1277, 65 deg / 0.3
  // -> 1.1224.
  EXPECT_NEAR(nadal(60.0 * kDeg, 0.3), 0.9424, 1e-4);
  EXPECT_NEAR(nadal(75.0 * kDeg, 0.5), 1.1277, 1e-4);
  EXPECT_NEAR(nadal(65.0 * kDeg, 0.3), 1.1224, 1e-4);
  EXPECT_NEAR(nadal_limit(70.0F * static_cast<float>(kDeg), 0.36F).value, 1.20028F, 1e-5F);
}

TEST(NadalLimit, LimitsAndIdentity) {
  EXPECT_NEAR(nadal(70.0 * kDeg, 0.0), std::tan(70.0 * kDeg), 1e-12);  // no friction
  EXPECT_NEAR(nadal(60.0 * kDeg, std::tan(60.0 * kDeg)), 0.0, 1e-12);  // mu = tan delta
  for (double d = 50.0; d <= 80.0; d += 5.0) {
    for (double mu = 0.1; mu <= 0.6; mu += 0.1) {
      EXPECT_NEAR(nadal(d * kDeg, mu), std::tan(d * kDeg - std::atan(mu)), 1e-12);
    }
  }
  EXPECT_LT(nadal(70.0 * kDeg, 0.5), nadal(70.0 * kDeg, 0.3));
  EXPECT_GT(nadal(72.0 * kDeg, 0.3), nadal(70.0 * kDeg, 0.3));
  EXPECT_EQ(nadal_limit(95.0 * kDeg, 0.3).status, Status::invalid_argument);
  EXPECT_EQ(nadal_limit(70.0 * kDeg, -0.1).status, Status::invalid_argument);
  EXPECT_EQ(nadal_limit(std::nan(""), 0.3).status, Status::invalid_argument);
  EXPECT_EQ(nadal_limit(70.0 * kDeg, std::nan("")).value, 0.0);
}

TEST(Derailment, ClimbingFlangeReachesNadalExactly) {
  // A flange point at 70 deg with the friction fully developed up the flange (T = mu N): the
  // wheel's Y/Q is Nadal's value, the margin zero.
  WheelYQ<double> w;
  add_contact_point(w, 50000.0, 70.0 * kDeg, 0.36 * 50000.0);
  const Result<DerailmentCheck<double>> c = derailment_check(w, 70.0 * kDeg, 0.36);
  ASSERT_TRUE(c.ok());
  EXPECT_NEAR(c.value.y_over_q, 1.20028, 1e-5);
  EXPECT_NEAR(c.value.margin, 0.0, 1e-12);
}

TEST(Derailment, TwoPointContactSumsBothPoints) {
  // Tread at 2 deg carrying most of the load, flange at 68 deg, creep forces away from the
  // flange: the quotient is the sum of both points' Y over the sum of their Q.
  WheelYQ<double> w;
  add_contact_point(w, 60000.0, 2.0 * kDeg, -3000.0);
  add_contact_point(w, 30000.0, 68.0 * kDeg, -5000.0);
  const double y = 60000.0 * std::sin(2.0 * kDeg) + 3000.0 * std::cos(2.0 * kDeg) +
                   30000.0 * std::sin(68.0 * kDeg) + 5000.0 * std::cos(68.0 * kDeg);
  const double q = 60000.0 * std::cos(2.0 * kDeg) - 3000.0 * std::sin(2.0 * kDeg) +
                   30000.0 * std::cos(68.0 * kDeg) - 5000.0 * std::sin(68.0 * kDeg);
  EXPECT_NEAR(w.y_n, y, 1e-9);
  EXPECT_NEAR(w.q_n, q, 1e-9);
  const Result<DerailmentCheck<double>> c = derailment_check(w, 68.0 * kDeg, 0.3);
  ASSERT_TRUE(c.ok());
  EXPECT_NEAR(c.value.y_over_q, y / q, 1e-12);
  EXPECT_NEAR(c.value.margin, c.value.limit - y / q, 1e-12);
  EXPECT_GT(c.value.margin, 0.0);
}

TEST(Derailment, LiftedWheelHasNoQuotient) {
  WheelYQ<float> w;
  const Result<DerailmentCheck<float>> c = derailment_check(w, 1.2F, 0.3F);
  EXPECT_EQ(c.status, Status::out_of_range);
  EXPECT_EQ(c.value.y_over_q, 0.0F);
  EXPECT_EQ(c.value.margin, c.value.limit);
  EXPECT_TRUE(std::isfinite(c.value.margin));
}

}  // namespace
}  // namespace tread::rail
