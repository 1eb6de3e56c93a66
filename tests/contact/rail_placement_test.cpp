// Rail placement: a 60E1 head built here from its arcs (EN 13674-1 radii and tangency, as tabulated
// in the rail definitions in data/PROVENANCE.md), inclined 1:20 and placed at gauge 1435.16, must
// land on EN 15302 rail A (which is 60E1 at 1:20 in the running-circle frame).
#include "contact/rail_placement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "contact/profile_csv.hpp"
#include "contact/profile_function.hpp"
#include "golden_path.hpp"

namespace tread::contact {
namespace {

double head_60e1_z(double x) {
  const double a = std::abs(x);
  if (a <= 10.228) {
    return std::sqrt(300.0 * 300.0 - a * a) - 300.0;
  }
  if (a <= 26.0265) {
    const double d = a - 7.500533;
    return -80.127896 + std::sqrt(80.0 * 80.0 - d * d);
  }
  const double d = a - 23.016030;
  return -14.949147 + std::sqrt(13.0 * 13.0 - d * d);
}

/// Upright 60E1 head, x < 0 on the gauge side, down to 30 mm below the top on both sides.
profile::SampledProfile upright_60e1() {
  profile::SampledProfile p{"60E1", {}, {}};
  const double x_side = 35.999811;
  const double z_side = -14.299958;
  for (double z = -30.0; z < z_side; z += 0.05) {  // gauge face, 1:20 from vertical
    p.y_mm.push_back(-(x_side + (z_side - z) / 20.0));
    p.z_mm.push_back(z);
  }
  for (double x = -x_side; x <= x_side; x += 0.01) {
    p.y_mm.push_back(x);
    p.z_mm.push_back(head_60e1_z(x));
  }
  for (double z = z_side - 0.05; z >= -30.0; z -= 0.05) {
    p.y_mm.push_back(x_side + (z_side - z) / 20.0);
    p.z_mm.push_back(z);
  }
  return p;
}

TEST(RailPlacement, UprightHeadHasGaugePointAt35_981) {
  RailPlacement upright;
  upright.inclination_rad = 0.0;
  upright.gauge_mm = 1500.0;  // gauge point at the track-frame origin
  const PlacedRail placed = place_rail(upright_60e1(), upright);
  EXPECT_NEAR(placed.gauge_point_y_mm, 0.0, 1e-9);
  EXPECT_NEAR(placed.gauge_point_z_mm, -14.0, 1e-9);
  // The head is symmetric: its top is at the track-frame lateral of 35.981 from the gauge point.
  const ProfileFunction f(placed.track);
  EXPECT_NEAR(f.z_at(35.981), 0.0, 2e-3);
}

TEST(RailPlacement, SixtyE1At1To20IsEn15302RailA) {
  const auto rail_a_file = tread::testing::test_data("rail/en15302/RailA.csv");
  ASSERT_TRUE(std::filesystem::exists(rail_a_file)) << rail_a_file;
  const auto rail_a = read_profile_csv(rail_a_file);
  RailPlacement at_1_20;
  at_1_20.inclination_rad = std::atan(1.0 / 20.0);
  at_1_20.gauge_mm = 1435.16;
  const PlacedRail placed = place_rail(upright_60e1(), at_1_20);
  EXPECT_NEAR(placed.gauge_point_y_mm, -32.42, 0.01);
  EXPECT_NEAR(track_frame_gauge_mm(placed.track), 1435.16, 1e-3);

  const ProfileFunction ours(placed.track);
  double top_a = -1e9;
  for (const double z : rail_a.z_mm) {
    top_a = std::max(top_a, z);
  }
  // Compare over the head (from the gauge point band to the field-side shoulder).
  double sum2 = 0.0;
  double worst = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < rail_a.y_mm.size(); ++i) {
    const double y = rail_a.y_mm[i];
    if (y < -32.0 || y > 30.0) {
      continue;
    }
    const double d = ours.z_at(y) - (rail_a.z_mm[i] - top_a);
    sum2 += d * d;
    worst = std::max(worst, std::abs(d));
    ++n;
  }
  const double rms = std::sqrt(sum2 / n);
  EXPECT_LT(rms, 0.03);  // DEFINITIONS.md: the fit of 60E1 at 1:20 to rail A has rms 0.017 mm
  EXPECT_LT(worst, 0.1);
  std::printf("60E1 at 1:20 vs rail A: rms %.4f mm, max %.4f mm over %d points\n", rms, worst, n);
}

TEST(RailPlacement, RejectsAHeadThatIsTooShallow) {
  profile::SampledProfile flat{"flat", {-10.0, 0.0, 10.0}, {-1.0, 0.0, -1.0}};
  EXPECT_THROW((void)place_rail(flat, RailPlacement{}), std::invalid_argument);
}

}  // namespace
}  // namespace tread::contact
