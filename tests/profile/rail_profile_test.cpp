#include "profile/rail_profile.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "golden_path.hpp"
#include "profile/profile_csv.hpp"
#include "profile/simpack_profile.hpp"

namespace tread::profile {
namespace {

TEST(RailProfile, UprightHeadsAreSymmetricContinuousAndTangent) {
  for (const RailSection section : {RailSection::k60E1, RailSection::k54E1}) {
    const RailProfile rail(section, RailInclination::kNone);
    EXPECT_NEAR(rail.top_y_mm(), 0.0, 1e-12);
    EXPECT_NEAR(rail.top_z_mm(), 0.0, 1e-12);
    EXPECT_NEAR(rail.y_min_mm(), -rail.y_max_mm(), 1e-9);
    double worst_jump = 0.0;
    double worst_kink = 0.0;
    for (double y = rail.y_min_mm(); y <= rail.y_max_mm(); y += 0.01) {
      EXPECT_NEAR(rail.at(y).z_mm, rail.at(-y).z_mm, 1e-9) << y;
      // Left and right limits just around any y: continuity and a continuous slope.
      const double e = 1e-7;
      if (y - e > rail.y_min_mm() && y + e < rail.y_max_mm()) {
        const ProfileValue l = rail.at(y - e);
        const ProfileValue r = rail.at(y + e);
        worst_jump = std::max(worst_jump, std::fabs(r.z_mm - l.z_mm - e * (l.tan + r.tan)));
        worst_kink = std::max(worst_kink, std::fabs(std::atan(r.tan) - std::atan(l.tan)));
      }
    }
    EXPECT_LT(worst_jump, 1e-6) << to_string(section);
    EXPECT_LT(worst_kink, 1e-5) << to_string(section);
  }
}

TEST(RailProfile, HeadDimensionsOfDefinitions) {
  // DEFINITIONS.md §3: 60E1 chord widths 20.456 / 52.053 (EN 13674-1), R13 end at
  // (±35.999811, -14.299958), gauge point of the upright rail at |x| = 35.981.
  const RailProfile r60(RailSection::k60E1, RailInclination::kNone);
  EXPECT_NEAR(r60.at(10.228).z_mm, -0.174404, 2e-6);
  EXPECT_NEAR(r60.at(26.0265).z_mm, -2.302524, 2e-5);
  EXPECT_NEAR(r60.at(35.999811).z_mm, -14.299958, 3e-5);  // slope 20 × y rounded to 5e-7
  EXPECT_NEAR(r60.gauge_point_y_mm(14.0), -35.981, 5e-4);
  const RailProfile r54(RailSection::k54E1, RailInclination::kNone);
  EXPECT_NEAR(r54.at(10.012).z_mm, -0.167113, 2e-6);
  EXPECT_NEAR(r54.at(24.8635).z_mm, -2.064868, 2e-5);
  EXPECT_NEAR(r54.at(35.000058).z_mm, -14.100052, 3e-5);
}

TEST(RailProfile, InclinationMovesTheTopTowardTheFieldSide) {
  const RailProfile r40(RailSection::k60E1, RailInclination::k1in40);
  EXPECT_NEAR(r40.top_y_mm(), 300.0 * std::sin(std::atan(1.0 / 40.0)), 1e-9);  // 7.5 mm
  const RailProfile r20(RailSection::k60E1, RailInclination::k1in20);
  // At 1:20 the top leaves the R300 crown (±1.95°) and sits on the field-side R80.
  EXPECT_GT(r20.top_y_mm(), 10.0);
  EXPECT_LT(r20.top_y_mm(), 15.0);
  // 1:20: the gauge face turns vertical at the end of the R13 corner, where z(y) ends.
  EXPECT_GT(r20.at(r20.y_min_mm()).tan, 1e4);
}

TEST(RailProfile, TrackFramePlacesTheGaugePoint) {
  for (const RailInclination inc :
       {RailInclination::kNone, RailInclination::k1in20, RailInclination::k1in40}) {
    for (const double gauge : {1435.0, 1437.0}) {
      const RailProfile rail(RailSection::k60E1, inc, {gauge, 750.0, 14.0});
      EXPECT_NEAR(rail.top_z_mm(), 0.0, 1e-12);
      EXPECT_NEAR(rail.gauge_point_y_mm(14.0), gauge / 2.0 - 750.0, 1e-9);
      EXPECT_NEAR(rail.at(rail.gauge_point_y_mm(14.0)).z_mm, -14.0, 1e-9);
    }
  }
}

TEST(RailProfileGolden, En15302RailAIs60E1InclinedOneInTwenty) {
  const auto path = testing::test_data("rail/en15302/RailA.csv");
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const SampledProfile a = read_profile_csv(path);
  // EN 15302 conditions: gauge 1435.16 mm, b2b 1360 (running circles ±750).
  const RailProfile rail(RailSection::k60E1, RailInclination::k1in20, {1435.16, 750.0, 14.0});
  const double top_a = *std::max_element(a.z_mm.begin(), a.z_mm.end());
  double worst = 0.0;
  double worst_y = 0.0;
  double sum2 = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.y_mm.size(); ++i) {
    const double y = a.y_mm[i];
    if (y < rail.y_min_mm() || y > rail.y_max_mm()) {
      continue;
    }
    // Distance normal to the profile (|dz| cos γ): near the vertical gauge face a vertical
    // difference means nothing.
    const ProfileValue v = rail.at(y);
    const double d = std::fabs((v.z_mm + top_a) - a.z_mm[i]) / std::sqrt(1.0 + v.tan * v.tan);
    sum2 += d * d;
    ++n;
    if (d > worst) {
      worst = d;
      worst_y = y;
    }
  }
  ASSERT_GT(n, 7000u);
  const double rms = std::sqrt(sum2 / static_cast<double>(n));
  // Stated tolerance: 0.05 mm normal to the profile over the head, rms 0.025 mm. Rail A is not
  // exactly 60E1 turned by atan(1/20): its gauge-side R80 centre sits where a 1:19.6 turn puts it,
  // its field-side R80 centre where a 1:52 turn would (centres of Annex I.7); the worst deviation
  // (0.039 mm) is on the field-side shoulder, the gauge side stays within 0.032 mm.
  EXPECT_LT(worst, 0.05);
  EXPECT_LT(rms, 0.025);
  std::printf("Rail A vs 60E1 1:20: %zu points, worst %.4f mm at y = %.3f, rms %.4f mm\n", n, worst,
              worst_y, rms);
  // The gauge point of Rail A itself (14 mm below its top) is where the placement puts ours.
  double gp_a = 0.0;
  for (std::size_t i = 0; i < a.y_mm.size(); ++i) {
    if (a.z_mm[i] >= top_a - 14.0) {
      gp_a = a.y_mm[i];
      break;
    }
  }
  EXPECT_NEAR(gp_a, rail.gauge_point_y_mm(14.0), 0.011);
  std::printf("gauge point: Rail A %.3f, 60E1 placed %.4f mm\n", gp_a, rail.gauge_point_y_mm(14.0));
}

struct Deviation {
  double worst_mm;
  double rms_mm;
};

/// A measured rail head given in any frame (z up) against `rail`: aligned only by the top of rail
/// and the gauge point (14 mm below it, interpolated), no fitting; distances normal to `rail`,
/// over the head down to 16 mm below the top.
Deviation head_deviation(const SampledProfile& m, const RailProfile& rail) {
  const double top = *std::max_element(m.z_mm.begin(), m.z_mm.end());
  double gp = 0.0;
  for (std::size_t i = 1; i < m.y_mm.size(); ++i) {
    if (m.z_mm[i] >= top - 14.0) {
      const double t = (top - 14.0 - m.z_mm[i - 1]) / (m.z_mm[i] - m.z_mm[i - 1]);
      gp = m.y_mm[i - 1] + t * (m.y_mm[i] - m.y_mm[i - 1]);
      break;
    }
  }
  const double shift = rail.gauge_point_y_mm(14.0) - gp;
  double worst = 0.0;
  double sum2 = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < m.y_mm.size(); ++i) {
    const double y = m.y_mm[i] + shift;
    if (y < rail.y_min_mm() || y > rail.y_max_mm() || m.z_mm[i] < top - 16.0) {
      continue;
    }
    const ProfileValue v = rail.at(y);
    const double d =
        std::fabs(v.z_mm - rail.top_z_mm() - (m.z_mm[i] - top)) / std::sqrt(1.0 + v.tan * v.tan);
    worst = std::max(worst, d);
    sum2 += d * d;
    ++n;
  }
  EXPECT_GT(n, 250u);
  return {worst, std::sqrt(sum2 / static_cast<double>(n))};
}

TEST(RailProfileGolden, ManchesterBenchmarkRailIs60E1InclinedOneInForty) {
  const auto path = testing::test_data("rail/manchester_benchmark/MBench_UIC60_v3.prr");
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const SampledProfile m = read_simpack_profile(path).profile;
  const Deviation d40 = head_deviation(m, RailProfile(RailSection::k60E1, RailInclination::k1in40));
  const Deviation d20 = head_deviation(m, RailProfile(RailSection::k60E1, RailInclination::k1in20));
  const Deviation d0 = head_deviation(m, RailProfile(RailSection::k60E1, RailInclination::kNone));
  // Stated tolerance: 0.05 mm normal to the head, rms 0.03 mm (the benchmark rail is a measured-
  // style spline of UIC60; DEFINITIONS.md found rms 0.018 mm with a fitted placement).
  EXPECT_LT(d40.worst_mm, 0.05);
  EXPECT_LT(d40.rms_mm, 0.03);
  EXPECT_LT(d40.rms_mm, d20.rms_mm);  // the inclination is 1:40, not 1:20 or upright
  EXPECT_LT(d40.rms_mm, d0.rms_mm);
  std::printf(
      "Manchester UIC60 vs 60E1: 1:40 worst %.4f rms %.4f mm; 1:20 rms %.4f; upright rms "
      "%.4f mm\n",
      d40.worst_mm, d40.rms_mm, d20.rms_mm, d0.rms_mm);
}

}  // namespace
}  // namespace tread::profile
