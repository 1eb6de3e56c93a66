// The generated tables against the double definitions they were generated from.
#include "lut/tread_lut.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "contact/contact_setup.hpp"
#include "lut/lut_generator.hpp"
#include "profile/wheel_profile.hpp"
#include "runtime/node_runtime.hpp"

namespace tread {
namespace {

TEST(Lut, RadiusTablesInterpolateWithinOneMicrometre) {
  ASSERT_FALSE(lut::profiles().empty());
  std::mt19937 rng(5);
  for (const lut::ProfileTable& t : lut::profiles()) {
    const profile::WheelProfile wheel(contact::parse_wheel_spec(t.spec));
    EXPECT_EQ(wheel.name(), t.name);
    const float y_last = t.f32.y_first_mm + t.f32.y_step_mm * static_cast<float>(t.f32.count - 1U);
    std::uniform_real_distribution<double> y_dist(t.f32.y_first_mm, y_last);
    double worst_f32_um = 0.0;
    double worst_q_um = 0.0;
    for (int k = 0; k < 20000; ++k) {
      const double y = y_dist(rng);
      const double exact = wheel.at(y).z_mm;
      const Result<float> f = rail::lookup(t.f32, static_cast<float>(y));
      ASSERT_EQ(f.status, Status::ok) << t.name << " y " << y;
      // The float table is looked up at float(y): compare with the definition there.
      const double exact_f = wheel.at(static_cast<double>(static_cast<float>(y))).z_mm;
      worst_f32_um = std::max(worst_f32_um, std::abs(static_cast<double>(f.value) - exact_f) * 1e3);
      const auto yq = static_cast<std::int32_t>(std::lround(y * rail::kQYPerMm));
      const Result<std::int32_t> q = rail::lookup(t.q, yq);
      ASSERT_EQ(q.status, Status::ok);
      const double exact_q = wheel.at(static_cast<double>(yq) / rail::kQYPerMm).z_mm;
      worst_q_um = std::max(
          worst_q_um, std::abs(static_cast<double>(q.value) / rail::kQLengthPerMm - exact_q) * 1e3);
      static_cast<void>(exact);
    }
    EXPECT_LE(worst_f32_um, 1.0) << t.name;
    EXPECT_LE(worst_q_um, 1.0) << t.name;  // plus at most 0.1 µm of fixed-point rounding
    EXPECT_LE(static_cast<double>(t.max_error_um), 1.0);
    RecordProperty(std::string(t.spec), std::to_string(worst_f32_um) + " um");
  }
}

TEST(Lut, ContactTablesEqualTheContactSearchAtTheirRows) {
  ASSERT_FALSE(lut::contact_pairs().empty());
  for (const lut::ContactPairTable& t : lut::contact_pairs()) {
    const contact::RigidContact contact =
        contact::build_contact(host::parse_wheelset_profile(t.name));
    for (std::uint32_t i = 0; i < t.f32.count; i += 7) {
      const double y =
          static_cast<double>(t.f32.y_first_mm) + i * static_cast<double>(t.f32.y_step_mm);
      const contact::ContactState s = contact.at(y);
      const Result<rail::ContactSample> f = rail::lookup(t.f32, static_cast<float>(y));
      ASSERT_EQ(f.status, Status::ok);
      EXPECT_NEAR(f.value.delta_r_mm, s.delta_r_mm(), 1e-4) << t.name << " y " << y;
      EXPECT_NEAR(f.value.r_left_mm, s.left.r_mm, 1e-4);
      EXPECT_NEAR(f.value.gamma_right_rad, s.right.gamma_rad, 1e-6);
      const Result<rail::ContactSampleQ> q =
          rail::lookup(t.q, static_cast<std::int32_t>(std::lround(y * rail::kQYPerMm)));
      EXPECT_NEAR(q.value.delta_r / static_cast<double>(rail::kQLengthPerMm), s.delta_r_mm(), 1e-4);
    }
    EXPECT_EQ(rail::lookup(t.f32, 40.0F).status, Status::out_of_range);
  }
}

}  // namespace
}  // namespace tread
