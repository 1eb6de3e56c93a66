// src/node/contact_table_channel_fixed.hpp: the fixed-point contact channel on a generated pair's
// integer table gives the float channel's radii and angles within the integer table's resolution
// (0.1 µm, 1 µrad, y rounded to 1 µm), with the same clamping flag; the integer conversions round
// half away from zero and saturate.
#include "node/contact_table_channel_fixed.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "lut/tread_lut.hpp"
#include "node/contact_table_channel.hpp"

namespace tread::node {
namespace {

using fixed::Fixed64;

TEST(ContactTableChannelFixed, FollowsTheFloatChannelOverTheTableAndBeyond) {
  ASSERT_FALSE(lut::contact_pairs().empty());
  const lut::ContactPairTable& pair = lut::contact_pairs()[0];
  const ContactTableChannel f(pair.f32);
  const ContactTableChannelFixed x(pair.q);
  int clamped = 0;
  for (int k = -700; k <= 700; ++k) {
    const double y_mm = 0.0173 * k;  // beyond ±12 mm on both sides
    proto::WheelsetInput in;
    in.lateral_mm = static_cast<float>(y_mm);
    proto::WheelsetInputFixed inx;
    inx.lateral_mm = Fixed64::from_double(y_mm);
    const ContactResult want = f.evaluate(in);
    const ContactResultFixed got = x.evaluate(inx);
    EXPECT_EQ(got.clamped, want.clamped) << y_mm;
    clamped += got.clamped ? 1 : 0;
    // The integer table's resolution (and the float table's rounding), plus what the outputs
    // change over the 1 µm the displacement is rounded to (steep near the flange).
    in.lateral_mm = static_cast<float>(y_mm - 1e-3);
    const ContactResult lo = f.evaluate(in);
    in.lateral_mm = static_cast<float>(y_mm + 1e-3);
    const ContactResult hi = f.evaluate(in);
    const auto near = [](Fixed64 g, double w, double a, double b, double resolution) {
      return std::fabs(g.to_double() - w) <= resolution + std::fabs(b - a);
    };
    EXPECT_TRUE(near(got.r_left_mm, want.r_left_mm, lo.r_left_mm, hi.r_left_mm, 1e-4)) << y_mm;
    EXPECT_TRUE(near(got.r_right_mm, want.r_right_mm, lo.r_right_mm, hi.r_right_mm, 1e-4)) << y_mm;
    EXPECT_TRUE(near(got.delta_r_mm, want.delta_r_mm, lo.delta_r_mm, hi.delta_r_mm, 1e-4)) << y_mm;
    EXPECT_TRUE(
        near(got.gamma_left_rad, want.gamma_left_rad, lo.gamma_left_rad, hi.gamma_left_rad, 2e-6))
        << y_mm;
    EXPECT_TRUE(near(got.gamma_right_rad, want.gamma_right_rad, lo.gamma_right_rad,
                     hi.gamma_right_rad, 2e-6))
        << y_mm;
  }
  EXPECT_GT(clamped, 0);
}

TEST(ContactTableChannelFixed, ConversionsRoundHalfAwayFromZeroAndSaturate) {
  using C = ContactTableChannelFixed;
  EXPECT_EQ(C::to_table_y(Fixed64(1.0)), 1000);
  EXPECT_EQ(C::to_table_y(Fixed64(0.0005)), 1);
  EXPECT_EQ(C::to_table_y(Fixed64(-0.0005)), -1);
  EXPECT_EQ(C::to_table_y(Fixed64(-0.00049)), 0);
  EXPECT_EQ(C::to_table_y(Fixed64(-12.3456)), -12346);
  EXPECT_EQ(C::to_table_y(Fixed64(2000000000.0)), INT32_MAX);
  EXPECT_EQ(C::to_table_y(Fixed64(-2000000000.0)), INT32_MIN);
  EXPECT_EQ(C::from_units(5, 10), Fixed64(0.5));
  EXPECT_EQ(C::from_units(-5, 10), Fixed64(-0.5));
  EXPECT_EQ(C::from_units(INT32_MIN, 1).raw(), std::int64_t{INT32_MIN} * (std::int64_t{1} << 32));
  EXPECT_NEAR(C::from_units(4601234, rail::kQLengthPerMm).to_double(), 460.1234, 1e-9);
  // An invalid displacement (the fixed-point NaN) gives zeros, flagged.
  const ContactTableChannelFixed x(lut::contact_pairs()[0].q);
  proto::WheelsetInputFixed in;
  in.lateral_mm = Fixed64::invalid();
  const ContactResultFixed r = x.evaluate(in);
  EXPECT_TRUE(r.clamped);
  EXPECT_EQ(r.r_left_mm, Fixed64(0.0));
}

}  // namespace
}  // namespace tread::node
