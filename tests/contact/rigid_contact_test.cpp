// Rigid contact search on synthetic profiles whose answer is known in closed form, and against an
// independent brute-force search on a profile pair with a contact jump.
#include "contact/rigid_contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace tread::contact {
namespace {

constexpr double kCrownRadius = 300.0;
constexpr double kCrownCentre = 2.0;  // track frame

/// Rail head in the track frame: a circular crown of radius 300 centred at y = 2, top at z = 0,
/// with a sharp gauge corner at y = -26 and a steep (tan 3) gauge face below it.
profile::SampledProfile crown_rail(double step = 0.01) {
  auto crown = [](double y) {
    const double d = y - kCrownCentre;
    return std::sqrt(kCrownRadius * kCrownRadius - d * d) - kCrownRadius;
  };
  profile::SampledProfile p{"crown", {}, {}};
  for (double y = -35.0; y <= 35.0 + 1e-9; y += step) {
    p.y_mm.push_back(y);
    p.z_mm.push_back(y >= -26.0 ? crown(y) : crown(-26.0) - 3.0 * (-26.0 - y));
  }
  return p;
}

/// Conical wheel z = -tan_g * y (radius grows toward the flange side, y < 0).
profile::SampledProfile cone_wheel(double tan_g, double step = 0.01) {
  profile::SampledProfile p{"cone", {}, {}};
  for (double y = -60.0; y <= 60.0 + 1e-9; y += step) {
    p.y_mm.push_back(y);
    p.z_mm.push_back(-tan_g * y);
  }
  return p;
}

TEST(RigidContact, ConeOnCrownGivesTwiceTheConicityTimesY) {
  const double tan_g = 0.05;
  const auto wheel = cone_wheel(tan_g);
  const RigidContact contact(wheel, wheel, crown_rail(), WheelsetSetup{1360.0, 460.0, 460.0});
  // The crown's slope equals the cone's where sin(theta) = -sin(gamma): fixed on the rail.
  const double y_rail = kCrownCentre - kCrownRadius * std::sin(std::atan(tan_g));
  for (double y = -8.0; y <= 8.0; y += 0.5) {
    const ContactState c = contact.at(y);
    EXPECT_NEAR(c.delta_r_mm(), 2.0 * tan_g * y, 1e-6) << "y = " << y;
    EXPECT_NEAR(c.left.gamma_rad, std::atan(tan_g), 1e-9);
    EXPECT_NEAR(c.right.gamma_rad, std::atan(tan_g), 1e-9);
    EXPECT_NEAR(c.left.y_rail_mm, y_rail, 0.01);
    EXPECT_NEAR(c.right.y_rail_mm, y_rail, 0.01);
    // The wheel moves by y toward the left rail: the left contact moves toward its flange.
    EXPECT_NEAR(c.left.y_wheel_mm, y_rail - y, 0.01);
    EXPECT_NEAR(c.right.y_wheel_mm, y_rail + y, 0.01);
    EXPECT_NEAR(c.left.r_mm, 460.0 - tan_g * c.left.y_wheel_mm, 1e-6);
    // A straight cone on a R300 crown: the relative curvature in the contact plane is 1/300.
    EXPECT_NEAR(c.left.lateral_relative_curvature_per_mm, 1.0 / kCrownRadius, 1e-7);
    EXPECT_NEAR(c.right.lateral_relative_curvature_per_mm, 1.0 / kCrownRadius, 1e-7);
  }
}

TEST(RigidContact, DifferentRadiiAndBackToBackShiftTheContact) {
  const double tan_g = 0.025;
  const auto wheel = cone_wheel(tan_g);
  // b2b 1356: each wheel's taping line sits 2 mm further in, so its contact is 2 mm further out.
  const RigidContact contact(wheel, wheel, crown_rail(), WheelsetSetup{1356.0, 461.0, 459.5});
  const double y_rail = kCrownCentre - kCrownRadius * std::sin(std::atan(tan_g));
  const ContactState c = contact.at(0.0);
  EXPECT_NEAR(c.left.y_wheel_mm, y_rail + 2.0, 0.01);
  EXPECT_NEAR(c.right.y_wheel_mm, y_rail + 2.0, 0.01);
  EXPECT_NEAR(c.delta_r_mm(), 1.5, 1e-6);
  EXPECT_NEAR(c.left.r_mm, 461.0 - tan_g * (y_rail + 2.0), 1e-4);
}

/// A cone (1:40) with a steep straight flange (tan 1.5) from y = -30: the contact jumps from the
/// tread to the flange at one displacement.
profile::SampledProfile cone_with_flange() {
  profile::SampledProfile p{"flanged", {}, {}};
  for (double y = -45.0; y <= 50.0 + 1e-9; y += 0.02) {
    p.y_mm.push_back(y);
    p.z_mm.push_back(y > -30.0 ? -0.025 * y : 0.75 + 1.5 * (-30.0 - y));
  }
  return p;
}

/// Independent reference: the vertical-gap minimum on a uniform 0.0005 mm grid.
double brute_force_r(const profile::SampledProfile& w, const profile::SampledProfile& r,
                     double shift) {
  auto interp = [](const profile::SampledProfile& p, double y) {
    const auto it = std::upper_bound(p.y_mm.begin(), p.y_mm.end(), y);
    const auto i = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(
        it - p.y_mm.begin() - 1, 0, static_cast<std::ptrdiff_t>(p.y_mm.size()) - 2));
    const double t = (y - p.y_mm[i]) / (p.y_mm[i + 1] - p.y_mm[i]);
    return p.z_mm[i] + t * (p.z_mm[i + 1] - p.z_mm[i]);
  };
  const double lo = std::max(r.y_mm.front(), w.y_mm.front() + shift);
  const double hi = std::min(r.y_mm.back(), w.y_mm.back() + shift);
  double best = -1e300;
  double best_s = lo;
  for (double s = lo; s <= hi; s += 0.0005) {
    const double f = interp(w, s - shift) + interp(r, s);
    if (f > best) {
      best = f;
      best_s = s;
    }
  }
  return 460.0 + interp(w, best_s - shift);
}

TEST(RigidContact, FindsTheGlobalMinimumAcrossAJump) {
  const auto wheel = cone_with_flange();
  const auto rail = crown_rail(0.03);
  SearchSettings no_refine;
  no_refine.refine_half_window_mm = 0.0;
  const RigidContact contact(wheel, wheel, rail, WheelsetSetup{}, no_refine);
  bool saw_tread = false;
  bool saw_flange = false;
  bool saw_two_point = false;
  for (double y = 0.0; y <= 10.0; y += 0.2) {
    const ContactState c = contact.at(y);
    EXPECT_NEAR(c.left.r_mm, brute_force_r(wheel, rail, y), 2e-3) << "y = " << y;
    EXPECT_NEAR(c.right.r_mm, brute_force_r(wheel, rail, -y), 2e-3) << "y = " << y;
    saw_tread = saw_tread || c.left.y_wheel_mm > -30.0;
    saw_flange = saw_flange || c.left.y_wheel_mm < -30.0;
    saw_two_point = saw_two_point || c.left.second_gap_mm < 0.15;
  }
  EXPECT_TRUE(saw_tread);
  EXPECT_TRUE(saw_flange);
  EXPECT_TRUE(saw_two_point);
  // Flange contact: the flange slope is the contact angle.
  EXPECT_NEAR(contact.at(10.0).left.gamma_rad, std::atan(1.5), 1e-6);
}

TEST(RigidContact, NoisyMeasuredProfileStaysCloseToTheSmoothOne) {
  const double tan_g = 0.05;
  auto noisy = cone_wheel(tan_g);
  std::mt19937 rng(42);
  std::normal_distribution<double> noise(0.0, 0.002);  // 2 um measurement noise
  for (double& z : noisy.z_mm) {
    z += noise(rng);
  }
  const auto smoothed = smooth_profile(noisy, 1.0);
  const RigidContact contact(smoothed, smoothed, crown_rail(), WheelsetSetup{});
  for (double y = -6.0; y <= 6.0; y += 1.0) {
    const ContactState c = contact.at(y);
    EXPECT_NEAR(c.delta_r_mm(), 2.0 * tan_g * y, 0.03) << "y = " << y;
    EXPECT_NEAR(std::tan(c.left.gamma_rad), tan_g, 0.02) << "y = " << y;
  }
}

TEST(RigidContact, TableIsAUniformGrid) {
  const auto wheel = cone_wheel(0.05);
  const ContactTable t =
      contact_table(wheel, wheel, crown_rail(), WheelsetSetup{}, -12.0, 12.0, 0.1);
  ASSERT_EQ(t.y_mm.size(), 241u);
  EXPECT_DOUBLE_EQ(t.y_mm.front(), -12.0);
  EXPECT_NEAR(t.y_mm.back(), 12.0, 1e-9);
  for (std::size_t k = 0; k < t.y_mm.size(); ++k) {
    EXPECT_NEAR(t.delta_r_mm[k], t.r_left_mm[k] - t.r_right_mm[k], 1e-12);
  }
  EXPECT_EQ(t.gamma_left_rad.size(), 241u);
  EXPECT_EQ(t.at_profile_end.size(), 241u);
  EXPECT_NEAR(t.delta_r_mm[120], 0.0, 1e-12);  // y = 0 of a symmetric pair
}

TEST(RigidContact, RejectsBadProfilesAndNoOverlap) {
  profile::SampledProfile bad{"bad", {0.0, 1.0, 1.0}, {0.0, 0.0, 0.0}};
  EXPECT_THROW(RigidContact(bad, bad, crown_rail(), WheelsetSetup{}), std::invalid_argument);
  const auto wheel = cone_wheel(0.05);
  const RigidContact contact(wheel, wheel, crown_rail(), WheelsetSetup{});
  EXPECT_THROW((void)contact.at(200.0), std::domain_error);
}

}  // namespace
}  // namespace tread::contact
