#include "rail/contact_lookup.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

namespace tread::rail {
namespace {

// Rows at y = -12 .. 12 mm, step 0.5 (49 rows) from smooth analytic columns.
constexpr std::uint32_t kRows = 49;
double r_left_of(double y) {
  return 460.0 + 0.08 * y + 0.002 * y * y;
}
double gamma_of(double y) {
  return 0.025 + 0.001 * y;
}

struct Fixture : ::testing::Test {
  std::array<float, kRows> rl{}, rr{}, dr{}, gl{}, gr{};
  std::array<std::int32_t, kRows> qrl{}, qrr{}, qdr{}, qgl{}, qgr{};
  std::array<ContactRowF32, kRows> rows{};
  std::array<ContactRowQ, kRows> qrows{};
  ContactTableF32 table{};
  ContactTableQ qtable{};

  void SetUp() override {
    for (std::uint32_t i = 0; i < kRows; ++i) {
      const double y = -12.0 + 0.5 * i;
      rl[i] = static_cast<float>(r_left_of(y));
      rr[i] = static_cast<float>(r_left_of(-y));
      dr[i] = static_cast<float>(r_left_of(y) - r_left_of(-y));
      gl[i] = static_cast<float>(gamma_of(y));
      gr[i] = static_cast<float>(gamma_of(-y));
      qrl[i] = static_cast<std::int32_t>(std::lround(r_left_of(y) * kQLengthPerMm));
      qrr[i] = static_cast<std::int32_t>(std::lround(r_left_of(-y) * kQLengthPerMm));
      qdr[i] =
          static_cast<std::int32_t>(std::lround((r_left_of(y) - r_left_of(-y)) * kQLengthPerMm));
      qgl[i] = static_cast<std::int32_t>(std::lround(gamma_of(y) * kQAnglePerRad));
      qgr[i] = static_cast<std::int32_t>(std::lround(gamma_of(-y) * kQAnglePerRad));
    }
    for (std::uint32_t i = 0; i < kRows; ++i) {
      rows[i] = {rl[i], rr[i], dr[i], gl[i], gr[i]};
      qrows[i] = {qrl[i], qrr[i], qdr[i], qgl[i], qgr[i]};
    }
    table = {-12.0F, 0.5F, kRows, rows.data()};
    qtable = {-12 * kQYPerMm, kQYPerMm / 2, kRows, qrows.data()};
  }
};

TEST_F(Fixture, GridPointsAreExactAndBetweenIsLinear) {
  for (std::uint32_t i = 0; i < kRows; ++i) {
    const auto r = lookup(table, -12.0F + 0.5F * static_cast<float>(i));
    ASSERT_EQ(r.status, Status::ok);
    EXPECT_FLOAT_EQ(r.value.r_left_mm, rl[i]);
  }
  // Linear between rows: at a quarter of a step, 3/4·a + 1/4·b.
  const auto r = lookup(table, 1.125F);
  ASSERT_EQ(r.status, Status::ok);
  const float expected = 0.75F * rl[26] + 0.25F * rl[27];
  EXPECT_NEAR(r.value.r_left_mm, expected, 2e-5F);
  // A smooth column is reproduced within the linear-interpolation error h²/8·|f''| = 0.25/8·0.004.
  for (float y = -11.9F; y < 11.9F; y += 0.173F) {
    const auto s = lookup(table, y);
    EXPECT_NEAR(s.value.r_left_mm, r_left_of(static_cast<double>(y)), 1.25e-4 + 6e-5);
    EXPECT_NEAR(s.value.delta_r_mm, 0.16 * static_cast<double>(y), 1e-4);
  }
}

TEST_F(Fixture, OutsideTheTableIsClampedAndReported) {
  auto r = lookup(table, 20.0F);
  EXPECT_EQ(r.status, Status::out_of_range);
  EXPECT_FLOAT_EQ(r.value.r_left_mm, rl[kRows - 1]);
  r = lookup(table, -20.0F);
  EXPECT_EQ(r.status, Status::out_of_range);
  EXPECT_FLOAT_EQ(r.value.delta_r_mm, dr[0]);
  r = lookup(table, std::numeric_limits<float>::quiet_NaN());
  EXPECT_EQ(r.status, Status::out_of_range);
  EXPECT_TRUE(std::isfinite(r.value.r_left_mm));
  EXPECT_EQ(lookup(table, 12.0F).status, Status::ok);  // the last row itself is inside
}

TEST_F(Fixture, MalformedTablesAreRejected) {
  ContactTableF32 empty{};
  EXPECT_EQ(lookup(empty, 0.0F).status, Status::invalid_argument);
  ContactTableF32 one_row = table;
  one_row.count = 1;
  EXPECT_EQ(lookup(one_row, 0.0F).status, Status::invalid_argument);
  ContactTableQ qempty{};
  EXPECT_EQ(lookup(qempty, 0).status, Status::invalid_argument);
}

TEST_F(Fixture, FixedPointAgreesWithFloat) {
  for (std::int32_t y = -13'000; y <= 13'000; y += 137) {
    const auto q = lookup(qtable, y);
    const auto f = lookup(table, static_cast<float>(y) / kQYPerMm);
    EXPECT_EQ(q.status, f.status) << y;
    EXPECT_NEAR(static_cast<double>(q.value.r_left) / kQLengthPerMm, f.value.r_left_mm, 1e-4) << y;
    EXPECT_NEAR(static_cast<double>(q.value.delta_r) / kQLengthPerMm, f.value.delta_r_mm, 1e-4);
    EXPECT_NEAR(static_cast<double>(q.value.gamma_right) / kQAnglePerRad, f.value.gamma_right_rad,
                2e-6);
  }
}

TEST(RadiusLookup, InterpolatesAndClamps) {
  const std::array<float, 3> z{0.0F, 1.0F, 4.0F};
  const RadiusTableF32 t{-1.0F, 1.0F, 3, z.data()};
  EXPECT_FLOAT_EQ(lookup(t, 0.5F).value, 2.5F);
  EXPECT_EQ(lookup(t, 1.5F).status, Status::out_of_range);
  EXPECT_FLOAT_EQ(lookup(t, 1.5F).value, 4.0F);
}

}  // namespace
}  // namespace tread::rail
