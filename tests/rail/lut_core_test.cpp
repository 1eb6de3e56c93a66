// The flashed tables as an ECU sees them (runs in the cross builds too): present, finite, in range.
#include "lut/tread_lut.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tread {
namespace {

TEST(LutCore, EveryTableIsWellFormedAndFinite) {
  ASSERT_GE(lut::profiles().size(), 1U);
  ASSERT_GE(lut::contact_pairs().size(), 1U);
  for (const lut::ProfileTable& t : lut::profiles()) {
    ASSERT_GE(t.f32.count, 2U);
    EXPECT_EQ(t.f32.count, t.q.count);
    for (std::uint32_t i = 0; i < t.f32.count; ++i) {
      ASSERT_TRUE(std::isfinite(t.f32.z_mm[i]));
      // Float and fixed point hold the same value to their resolution.
      EXPECT_NEAR(static_cast<double>(t.f32.z_mm[i]), t.q.z[i] / 10'000.0, 1e-4);
    }
  }
  for (const lut::ContactPairTable& t : lut::contact_pairs()) {
    for (float y = -12.0F; y <= 12.0F; y += 0.37F) {
      const auto r = rail::lookup(t.f32, y);
      EXPECT_EQ(r.status, Status::ok);
      EXPECT_NEAR(static_cast<double>(r.value.r_left_mm - r.value.r_right_mm),
                  static_cast<double>(r.value.delta_r_mm), 1e-3);
      EXPECT_GT(r.value.r_left_mm, 400.0F);
    }
    // Symmetric pair: delta_r is odd in y.
    const auto plus = rail::lookup(t.f32, 3.0F);
    const auto minus = rail::lookup(t.f32, -3.0F);
    EXPECT_NEAR(static_cast<double>(plus.value.delta_r_mm),
                -static_cast<double>(minus.value.delta_r_mm), 1e-3);
  }
}

}  // namespace
}  // namespace tread
