#include "profile/simpack_profile.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "golden_path.hpp"

namespace tread::profile {
namespace {

std::string error_of(const std::string& text) {
  std::istringstream in(text);
  try {
    (void)read_simpack_profile(in, "w.prw");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

const char* kMinimal =
    "header.begin\n type = 1 ! wheel\nheader.end\n"
    "spline.begin\n mirror.y = 1\n units.len.f = 1.0\n point.begin\n"
    "! y z\n 0.001 0.0005\n 0.0 0.0\n-0.002 -0.001 1.0\n point.end\nspline.end\n";

TEST(SimpackProfile, AppliesUnitsAndMirrorAndSortsByY) {
  std::istringstream in(kMinimal);
  const SimpackProfile p = read_simpack_profile(in, "w.prw");
  EXPECT_EQ(p.type, SimpackProfileType::kWheel);
  ASSERT_EQ(p.profile.y_mm.size(), 3u);
  EXPECT_DOUBLE_EQ(p.profile.y_mm[0], -1.0);
  EXPECT_DOUBLE_EQ(p.profile.z_mm[0], 0.5);
  EXPECT_DOUBLE_EQ(p.profile.y_mm[2], 2.0);
  EXPECT_DOUBLE_EQ(p.profile.z_mm[2], -1.0);
}

// Settings that change the profile SIMPACK uses: point.dist.min is applied (points closer than it
// to the one kept before are dropped), approx.smooth and inversion are not, and each is said at
// its line (they were ignored without a word).
TEST(SimpackProfile, PointDistanceSmoothingAndInversionAreAppliedOrSaid) {
  std::istringstream in(
      "header.begin\n type = 1\nheader.end\n"
      "spline.begin\n approx.smooth = 0.5\n point.dist.min = 0.15\n inversion = 1\n"
      " point.begin\n0 0\n0.1 0\n0.2 0\n0.3 0\n0.4 0\n point.end\nspline.end\n");
  const SimpackPoints p = read_simpack_points(in, "w.prw");
  EXPECT_EQ(p.points.y_mm, (std::vector<double>{0.0, 0.2, 0.4}));
  ASSERT_EQ(p.notes.size(), 3U);
  EXPECT_EQ(p.notes[0],
            "w.prw:5: approx.smooth = 0.5: SIMPACK approximates these points by a smoothing "
            "spline; tread takes them as given (--smooth fits them locally)");
  EXPECT_EQ(p.notes[1],
            "w.prw:7: inversion = 1 is not applied: the points are read as the other settings "
            "place them");
  EXPECT_EQ(p.notes[2],
            "w.prw:6: point.dist.min = 0.15 mm: 2 points closer than that to the one before were "
            "dropped, as SIMPACK does");
  // tread's own files (every setting 0) read without a note.
  std::ostringstream out;
  write_simpack_profile(out, SampledProfile{"p", {-3.0, 0.0, 7.5}, {1.0, 0.0, -0.5}},
                        SimpackProfileType::kWheel, "");
  std::istringstream back(out.str());
  EXPECT_TRUE(read_simpack_points(back, "rt").notes.empty());
}

TEST(SimpackProfile, ErrorsNameFileAndLine) {
  EXPECT_EQ(error_of("spline.begin\npoint.begin\n1 2\n2 3\npoint.end\nspline.end\n"),
            "w.prw:6: no header.begin … header.end block");
  EXPECT_EQ(error_of("header.begin\ntype=1\nheader.end\nspline.begin\npoint.begin\n1 2\n2 x\n"
                     "point.end\nspline.end\n"),
            "w.prw:7: expected a point 'y z [weight]', got '2 x'");
  EXPECT_EQ(error_of("header.begin\ntype=7\nheader.end\nspline.begin\npoint.begin\n1 2\n2 3\n"
                     "point.end\nspline.end\n"),
            "w.prw:2: header.type must be 0 (rail) or 1 (wheel)");
  EXPECT_EQ(error_of("header.begin\ntype=1\nheader.end\nspline.begin\nshift.y = abc\npoint.begin\n"
                     "1 2\n2 3\npoint.end\nspline.end\n"),
            "w.prw:5: spline.shift.y: 'abc' is not a number");
  EXPECT_EQ(error_of("header.begin\ntype=1\nheader.end\nspline.begin\npoint.begin\n1 2\n3 3\n"
                     "2 3\npoint.end\nspline.end\n"),
            "w.prw:8: y is not strictly monotonic after processing (previous point at line 7)");
}

TEST(SimpackProfile, WriteReadRoundTripForWheelAndRail) {
  const SampledProfile p{"p", {-3.0, -1.25, 0.0, 7.5}, {1.0, 0.25, 0.0, -0.5}};
  for (const auto type : {SimpackProfileType::kWheel, SimpackProfileType::kRail}) {
    std::ostringstream out;
    write_simpack_profile(out, p, type, "it's a test");
    std::istringstream in(out.str());
    const SimpackProfile q = read_simpack_profile(in, "rt");
    EXPECT_EQ(q.type, type);
    EXPECT_EQ(q.comment, "it s a test");
    ASSERT_EQ(q.profile.y_mm.size(), p.y_mm.size());
    for (std::size_t i = 0; i < p.y_mm.size(); ++i) {
      EXPECT_NEAR(q.profile.y_mm[i], p.y_mm[i], 1e-12);
      EXPECT_NEAR(q.profile.z_mm[i], p.z_mm[i], 1e-12);
    }
  }
}

TEST(SimpackProfileGolden, ReadsManchesterWheelAndRail) {
  const auto wheel_path = testing::test_data("rail/manchester_benchmark/MBench_S1002_v3.prw");
  ASSERT_TRUE(std::filesystem::exists(wheel_path)) << wheel_path;
  const SimpackProfile wheel = read_simpack_profile(wheel_path);
  EXPECT_EQ(wheel.type, SimpackProfileType::kWheel);
  EXPECT_EQ(wheel.profile.name, "MBench_S1002_v3");
  // mirror.y = 1: the listed y run from 69.6 (flange back side) to -60; after mirroring the
  // flange is at negative y, the field side positive, as in this project's wheel convention.
  EXPECT_NEAR(wheel.profile.y_mm.front(), -69.612628, 1e-9);
  EXPECT_NEAR(wheel.profile.y_mm.back(), 60.0, 1e-9);
  EXPECT_NEAR(wheel.profile.z_mm.back(), -2.6356764, 1e-9);
  const auto tip = std::max_element(wheel.profile.z_mm.begin(), wheel.profile.z_mm.end());
  EXPECT_NEAR(*tip, 28.0, 1e-3);  // flange height of S1002

  const auto rail_path = testing::test_data("rail/manchester_benchmark/MBench_UIC60_v3.prr");
  ASSERT_TRUE(std::filesystem::exists(rail_path)) << rail_path;
  const SimpackProfile rail = read_simpack_profile(rail_path);
  EXPECT_EQ(rail.type, SimpackProfileType::kRail);
  EXPECT_EQ(rail.profile.y_mm.size(), 495u);
  // SIMPACK z down becomes height up: the top of the rail is the maximum, near 0.
  const auto top = std::max_element(rail.profile.z_mm.begin(), rail.profile.z_mm.end());
  EXPECT_NEAR(*top, 0.0, 1e-3);
  EXPECT_NEAR(rail.profile.z_mm.front(), -38.510726, 1e-9);
}

}  // namespace
}  // namespace tread::profile
