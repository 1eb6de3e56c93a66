// Measures of sampled wheel and rail profiles (EN 15313 style flange measures, hollow wear, outer
// slope, rail top and gauge point), the local slope, the synthetic worn wheel and the choice of
// the nominal profile.
#include "profile/wheel_measures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "golden_path.hpp"
#include "profile/nominal_wheel.hpp"
#include "profile/profile_csv.hpp"
#include "profile/profile_slope.hpp"
#include "profile/rail_measures.hpp"
#include "profile/rail_profile.hpp"
#include "profile/synthetic_wear.hpp"
#include "profile/wheel_profile.hpp"

namespace tread::profile {
namespace {

/// y on the face of `w` where z = level (bisection between the tip and the tread).
double face_y(const WheelProfile& w, double level) {
  double lo = -55.0;
  double hi = -30.0;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (w.at(mid).z_mm >= level ? lo : hi) = mid;
  }
  return lo;
}

TEST(SampledWheelMeasures, S1002NewEqualsTheAnalyticMeasures) {
  const WheelProfile w({WheelFamily::kS1002, 28.0, 32.5});
  const SampledWheelMeasures m = measure_wheel(w.sample(0.1));
  EXPECT_NEAR(m.flange.height_mm, 28.0, 0.01);
  EXPECT_NEAR(m.flange.thickness_mm, 32.5, 0.01);
  EXPECT_NEAR(m.flange.qr_mm, 10.79, 0.01);
  EXPECT_NEAR(m.taping_z_mm, 0.0, 1e-12);
  EXPECT_LT(m.hollow_depth_mm, 1e-9);  // a new tread never rises toward the field side
  ASSERT_TRUE(m.outer_slope.has_value());
  EXPECT_NEAR(*m.outer_slope, 1.0 / 15.0, 1e-9);
  std::printf("S1002 h28 e32.5 sampled at 0.1 mm: Sh %.4f Sd %.4f qR %.4f\n", m.flange.height_mm,
              m.flange.thickness_mm, m.flange.qr_mm);
}

TEST(SampledWheelMeasures, EveryStandardProfileMatchesTheAnalyticMeasures) {
  double worst = 0.0;
  std::size_t n = 0;
  for (const WheelParameters& p : standard_wheel_parameters()) {
    const WheelProfile w(p);
    const FlangeMeasures a = measure_flange(w);
    const SampledWheelMeasures s = measure_wheel(w.sample(0.1));
    EXPECT_NEAR(s.flange.height_mm, a.height_mm, 0.01) << w.name();
    EXPECT_NEAR(s.flange.thickness_mm, a.thickness_mm, 0.01) << w.name();
    EXPECT_NEAR(s.flange.qr_mm, a.qr_mm, 0.01) << w.name();
    EXPECT_NEAR(s.flange.thickness_mm, p.flange_thickness_mm, 0.01) << w.name();
    EXPECT_LT(s.hollow_depth_mm, 1e-3) << w.name();
    worst = std::max({worst, std::fabs(s.flange.height_mm - a.height_mm),
                      std::fabs(s.flange.thickness_mm - a.thickness_mm),
                      std::fabs(s.flange.qr_mm - a.qr_mm)});
    ++n;
  }
  EXPECT_EQ(n, 81u);
  std::printf("81 profiles sampled at 0.1 mm: worst |sampled - analytic| %.2g mm\n", worst);
}

TEST(SampledWheelMeasures, RefusesAProfileWithoutFlangeOrTapingLine) {
  const WheelProfile w({WheelFamily::kS1002, 28.0, 32.5});
  SampledProfile tread = w.sample(0.5);
  tread.name = "tread-only";
  tread.y_mm.erase(tread.y_mm.begin(), tread.y_mm.begin() + 100);  // from y = -20
  tread.z_mm.erase(tread.z_mm.begin(), tread.z_mm.begin() + 100);
  try {
    (void)measure_wheel(tread);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("tread-only: the profile runs from y = -20"),
              std::string::npos)
        << e.what();
  }
  SampledProfile no_tip = w.sample(0.5);
  no_tip.name = "no-tip";
  no_tip.y_mm.erase(no_tip.y_mm.begin(), no_tip.y_mm.begin() + 40);  // from y = -50
  no_tip.z_mm.erase(no_tip.z_mm.begin(), no_tip.z_mm.begin() + 40);
  try {
    (void)measure_wheel(no_tip);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no-tip: the highest flange point is the profile's first"),
              std::string::npos)
        << e.what();
  }
}

TEST(SyntheticWear, FlangeFaceMovedByTwoMillimetresGivesTheThinFlangeOfTheStandard) {
  const WheelProfile nominal({WheelFamily::kS1002, 28.0, 32.5});
  SyntheticWear wear;
  wear.flange_thinning_mm = 2.0;
  const SampledWheelMeasures m = measure_wheel(apply_synthetic_wear(nominal, wear, 0.1));
  EXPECT_NEAR(m.flange.thickness_mm, 30.5, 0.01);
  // The tip is the cusp of two R12 arcs 2 mm apart, as EN 13715's e = 30.5 flange.
  EXPECT_NEAR(m.flange.height_mm, 16.0 + std::sqrt(143.0), 0.01);
  const FlangeMeasures thin = measure_flange(WheelProfile({WheelFamily::kS1002, 28.0, 30.5}));
  EXPECT_NEAR(m.flange.height_mm, thin.height_mm, 0.01);
  EXPECT_NEAR(m.flange.qr_mm, thin.qr_mm, 0.01);
  EXPECT_LT(m.hollow_depth_mm, 1e-6);
}

TEST(SyntheticWear, HollowTreadRaisesTheFlangeAndMakesAFalseFlange) {
  const WheelProfile nominal({WheelFamily::kS1002, 28.0, 32.5});
  SyntheticWear wear;
  wear.hollow_depth_mm = 1.5;
  wear.hollow_centre_y_mm = 5.0;
  wear.hollow_half_width_mm = 25.0;
  const SampledWheelMeasures m = measure_wheel(apply_synthetic_wear(nominal, wear, 0.1));
  const double worn_at_0 = 1.5 * std::pow(std::cos(0.5 * std::numbers::pi * (0.0 - 5.0) / 25.0), 2);
  EXPECT_NEAR(m.taping_z_mm, -worn_at_0, 1e-6);
  EXPECT_NEAR(m.flange.height_mm, 28.0 + worn_at_0, 0.01);
  // The face is unchanged; the 10 mm level moves down with the taping line.
  const double face = face_y(nominal, 10.0 - worn_at_0);
  EXPECT_NEAR(m.flange.thickness_mm, face + 70.0, 0.01);
  // The band [-20, 30] lowers the tread by up to 1.5 mm; beyond y = 30 it is new again, so the
  // tread rises toward the field side (a false flange) by about the depth less the new tread's own
  // fall over that span.
  // The bottom and the top are where the worn tread is level: tan + dwear/dy = 0, found here on
  // the construction by bisection.
  const auto worn = [&](double y) {
    const double c = std::cos(0.5 * std::numbers::pi * (y - 5.0) / 25.0);
    return nominal.at(y).z_mm - 1.5 * c * c;
  };
  const auto level_at = [&](double lo, double hi) {
    const auto dz = [&](double y) {
      return nominal.at(y).tan +
             1.5 * std::numbers::pi / 50.0 * std::sin(std::numbers::pi * (y - 5.0) / 25.0);
    };
    const bool rising_at_lo = dz(lo) > 0.0;
    for (int i = 0; i < 100; ++i) {
      const double mid = 0.5 * (lo + hi);
      ((dz(mid) > 0.0) == rising_at_lo ? lo : hi) = mid;
    }
    return lo;
  };
  const double bottom = level_at(0.0, 15.0);
  const double top = level_at(15.0, 30.0);
  EXPECT_NEAR(m.hollow_bottom_y_mm, bottom, 0.1);
  EXPECT_NEAR(m.false_flange_y_mm, top, 0.1);
  EXPECT_NEAR(m.hollow_depth_mm, worn(top) - worn(bottom), 1e-4);
  std::printf("hollow 1.5 mm at y 5 +- 25: bottom %.2f top %.2f depth %.4f mm\n", bottom, top,
              m.hollow_depth_mm);
}

TEST(SampledWheelMeasures, HollowDepthOfACosineDipInAFlatTread) {
  // A flange-like bump for the measures, then a flat tread with a 1 mm cosine dip at y 10 … 30.
  SampledProfile p;
  p.name = "dip";
  for (int i = 0; i <= 1400; ++i) {
    const double y = -70.0 + 0.1 * i;
    double z = 0.0;
    if (y < -30.0) {
      z = 25.0 - 0.02 * (y + 55.0) * (y + 55.0);
    }
    if (y > 10.0 && y < 30.0) {
      z -= std::pow(std::sin(std::numbers::pi * (y - 10.0) / 20.0), 2);
    }
    p.y_mm.push_back(y);
    p.z_mm.push_back(z);
  }
  const SampledWheelMeasures m = measure_wheel(p);
  EXPECT_NEAR(m.hollow_depth_mm, 1.0, 1e-9);
  EXPECT_NEAR(m.hollow_bottom_y_mm, 20.0, 1e-9);
  // A smooth apex: the tip refinement lies above it by at most step² / (2 R) (R = 25 here).
  EXPECT_NEAR(m.flange.height_mm, 25.0, 0.1 * 0.1 / 50.0 + 1e-12);
}

TEST(OuterSlope, AnySlopeFrom6Point7To15PercentBuildsAndIsMeasuredBack) {
  for (const WheelFamily family : {WheelFamily::kS1002, WheelFamily::kEps, WheelFamily::k1in40}) {
    for (const std::string text : {"6.7", "7", "8.5%", "9.25 %", "1:12", "1:8", "12.345", "15"}) {
      const OuterSlope slope = parse_outer_slope(text);
      const WheelProfile w({family, 30.0, 31.5, slope, 140.0, true});
      const SampledWheelMeasures m = measure_wheel(w.sample(0.1));
      ASSERT_TRUE(m.outer_slope.has_value()) << text;
      EXPECT_NEAR(*m.outer_slope, slope.gradient, 1e-6) << w.name();
      EXPECT_LT(m.outer_slope_rms_mm, 1e-9) << w.name();
      EXPECT_EQ(to_string(WheelFamily::kS1002), std::string("S1002"));
    }
  }
  EXPECT_NEAR(parse_outer_slope("1:12").gradient, 1.0 / 12.0, 1e-15);
  EXPECT_NEAR(parse_outer_slope("8.5%").gradient, 0.085, 1e-15);
  EXPECT_EQ(to_string(parse_outer_slope("8.5 %")), "8.5");
  EXPECT_EQ(parse_outer_slope("1:15.0"), OuterSlope::k1in15);
}

TEST(OuterSlope, TheFourNamedValuesAreTheOldOnesExactly) {
  EXPECT_EQ(parse_outer_slope("1:15"), OuterSlope::k1in15);
  EXPECT_EQ(parse_outer_slope("6.7"), OuterSlope::k6_7);
  EXPECT_EQ(parse_outer_slope("10"), OuterSlope::k10);
  EXPECT_EQ(parse_outer_slope("15%"), OuterSlope::k15);
  // Bit for bit: the gradients the enum gave.
  EXPECT_EQ(std::bit_cast<std::uint64_t>(parse_outer_slope("6.7").gradient),
            std::bit_cast<std::uint64_t>(0.067));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(parse_outer_slope("10").gradient),
            std::bit_cast<std::uint64_t>(0.10));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(parse_outer_slope("15").gradient),
            std::bit_cast<std::uint64_t>(0.15));
  EXPECT_EQ(to_string(OuterSlope::k1in15), "1:15");
  EXPECT_EQ(to_string(OuterSlope::k6_7), "6.7");
}

TEST(OuterSlope, OutOfRangeOrMalformedIsRefusedNamingTheRange) {
  for (const std::string text : {"6.5", "16", "1:20", "1:6", "0.1", "-8", "8,5", "abc", "", "1:"}) {
    try {
      (void)parse_outer_slope(text);
      ADD_FAILURE() << "accepted '" << text << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("6.7 % to 15 %"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("'" + text + "'"), std::string::npos) << e.what();
    }
  }
}

TEST(LocalSlopes, ExactOnALineAndMatchesTheConstructionOnTheTread) {
  SampledProfile line;
  line.name = "line";
  for (int i = 0; i < 50; ++i) {
    line.y_mm.push_back(0.3 * i + 0.01 * (i % 3));  // uneven spacing
    line.z_mm.push_back(2.0 - 0.125 * line.y_mm.back());
  }
  for (const double window : {0.0, 0.5, 2.0}) {
    for (const double s : local_slopes(line, window)) {
      EXPECT_NEAR(s, -0.125, 1e-12);
    }
  }
  const WheelProfile w({WheelFamily::kS1002, 28.0, 32.5});
  const SampledProfile s = w.sample(0.1);
  const std::vector<double> slopes = local_slopes(s, 0.5);
  for (std::size_t i = 0; i < s.y_mm.size(); ++i) {
    if (s.y_mm[i] > -20.0 && s.y_mm[i] < 30.0) {
      EXPECT_NEAR(slopes[i], w.at(s.y_mm[i]).tan, 1e-3) << s.y_mm[i];
    }
  }
  EXPECT_THROW((void)local_slopes(line, -1.0), std::invalid_argument);
}

TEST(RailMeasures, SixtyE1MatchesTheConstruction) {
  const RailProfile rail(RailSection::k60E1, RailInclination::kNone);
  const RailMeasures m = measure_rail(rail.sample(0.05));
  EXPECT_NEAR(m.top_z_mm, rail.top_z_mm(), 1e-3);
  EXPECT_NEAR(m.top_y_mm, rail.top_y_mm(), 0.05);
  ASSERT_TRUE(m.reaches_gauge_depth);
  EXPECT_NEAR(m.gauge_point_y_mm, rail.gauge_point_y_mm(14.0), 0.01);
  ASSERT_TRUE(m.head_width_mm.has_value());
  // Symmetric upright head: the gauge point is at -width/2.
  EXPECT_NEAR(*m.head_width_mm, -2.0 * m.gauge_point_y_mm, 0.02);
  std::printf("60E1 upright: gauge point y %.3f mm, head width at 14 mm %.3f mm\n",
              m.gauge_point_y_mm, *m.head_width_mm);
}

TEST(NominalWheel, DerivedFromTheMeasuresOrGiven) {
  const WheelProfile eps({WheelFamily::kEps, 30.0, 30.0, OuterSlope::k10, 135.0, true});
  const SampledProfile s = eps.sample(0.1);
  const SampledWheelMeasures m = measure_wheel(s);
  NominalChoice c = choose_nominal("auto", s, m);
  EXPECT_EQ(c.parameters.family, WheelFamily::kEps);
  EXPECT_DOUBLE_EQ(c.parameters.flange_height_mm, 30.0);
  EXPECT_DOUBLE_EQ(c.parameters.flange_thickness_mm, 30.0);
  EXPECT_EQ(c.parameters.outer_slope, OuterSlope::k10);
  EXPECT_DOUBLE_EQ(c.parameters.width_mm, 135.0);
  EXPECT_EQ(choose_nominal("", s, m).parameters.family, WheelFamily::kS1002);
  c = choose_nominal("S1002:e=32.5", s, m);
  EXPECT_EQ(c.parameters.family, WheelFamily::kS1002);
  EXPECT_DOUBLE_EQ(c.parameters.flange_thickness_mm, 32.5);
  EXPECT_DOUBLE_EQ(c.parameters.flange_height_mm, 30.0);
  EXPECT_THROW((void)choose_nominal("S1002:q=1", s, m), std::invalid_argument);
  EXPECT_THROW((void)choose_nominal("S1002:slope=20", s, m), std::invalid_argument);
}

/// The README's worn wheel: the procedure data/PROVENANCE.md describes.
SampledProfile worn_example() {
  const WheelProfile nominal({WheelFamily::kS1002, 28.0, 32.5});
  SyntheticWear wear;
  wear.flange_thinning_mm = 2.0;
  wear.hollow_depth_mm = 1.5;
  wear.hollow_centre_y_mm = 5.0;
  wear.hollow_half_width_mm = 25.0;
  wear.noise_mm = 0.002;
  wear.noise_seed = 13;
  SampledProfile p = apply_synthetic_wear(nominal, wear, 0.2);
  p.name = "worn_s1002_example";
  return p;
}

TEST(SyntheticWear, TheExampleFileIsTheDocumentedProcedure) {
  const auto path = ::tread::testing::test_data("profiles/worn_s1002_example.csv");
  if (const char* write = std::getenv("TREAD_WRITE_WORN_EXAMPLE"); write != nullptr) {
    std::ofstream out(path);
    out << "# Synthetic worn wheel (not a measurement): S1002 h28 e32.5 1:15 w140, flange face "
           "moved 2 mm toward the back,\n# 1.5 mm cos^2 hollow over y 5 +- 25 mm, +-2 um noise "
           "(seed 13), 0.2 mm spacing. See data/PROVENANCE.md.\n";
    write_profile_csv(out, worn_example(), {}, 6);
  }
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const SampledProfile file = read_profile_csv(path);
  const SampledProfile made = worn_example();
  ASSERT_EQ(file.y_mm.size(), made.y_mm.size());
  for (std::size_t i = 0; i < made.y_mm.size(); ++i) {
    EXPECT_NEAR(file.y_mm[i], made.y_mm[i], 1e-9);
    EXPECT_NEAR(file.z_mm[i], made.z_mm[i], 1e-9);
  }
  // Expected from the procedure: the face 2 mm toward the back, the 10 mm level and the tip
  // raised by the hollow's depth at y = 0 (noise +-2 um).
  const SampledWheelMeasures m = measure_wheel(file);
  const double worn_at_0 = 1.5 * std::pow(std::cos(0.5 * std::numbers::pi * 5.0 / 25.0), 2);
  const WheelProfile nominal({WheelFamily::kS1002, 28.0, 32.5});
  EXPECT_NEAR(m.taping_z_mm, -worn_at_0, 0.003);
  EXPECT_NEAR(m.flange.height_mm, 16.0 + std::sqrt(143.0) + worn_at_0, 0.01);
  EXPECT_NEAR(m.flange.thickness_mm, face_y(nominal, 10.0 - worn_at_0) - 2.0 + 70.0, 0.01);
  EXPECT_GT(m.hollow_depth_mm, 0.5);
  std::printf("worn example: Sh %.3f Sd %.3f qR %.3f hollow %.3f z(0) %.3f\n", m.flange.height_mm,
              m.flange.thickness_mm, m.flange.qr_mm, m.hollow_depth_mm, m.taping_z_mm);
}

}  // namespace
}  // namespace tread::profile
