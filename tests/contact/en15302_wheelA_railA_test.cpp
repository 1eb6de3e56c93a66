// Golden: EN 15302:2021 wheel A on rail A (Annex I profiles, Annex J delta r, Annex K conicity).
// Conditions per the standard: rail A is 60E1 inclined 1:20 already in the running-circle frame,
// gauge 1435.16 mm, back-to-back 1360 mm, wheel diameters 920/920 mm.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "contact/equivalent_conicity.hpp"
#include "contact/profile_csv.hpp"
#include "contact/profile_function.hpp"
#include "contact/rail_placement.hpp"
#include "contact/rigid_contact.hpp"
#include "golden_path.hpp"

namespace tread::contact {
namespace {

struct Row {
  std::vector<double> v;
};

std::vector<Row> read_rows(const std::filesystem::path& file) {
  std::ifstream in(file);
  EXPECT_TRUE(in.good()) << "missing reference file " << file;
  std::vector<Row> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') {
      continue;
    }
    std::stringstream ss(line);
    std::string cell;
    Row r;
    while (std::getline(ss, cell, ',')) {
      r.v.push_back(std::stod(cell));
    }
    rows.push_back(r);
  }
  return rows;
}

std::filesystem::path en15302(const std::string& name) {
  const auto p = tread::testing::test_data("rail/en15302/" + name);
  EXPECT_TRUE(std::filesystem::exists(p)) << "missing reference file " << p;
  return p;
}

RigidContact make_contact() {
  const auto wheel = read_profile_csv(en15302("WheelA.csv"));
  const auto rail = read_profile_csv(en15302("RailA.csv"));
  return RigidContact(wheel, wheel, rail, WheelsetSetup{1360.0, 460.0, 460.0});
}

TEST(En15302WheelARailA, RailAGaugeIs1435_16) {
  const auto rail = read_profile_csv(en15302("RailA.csv"));
  EXPECT_NEAR(track_frame_gauge_mm(rail), 1435.16, 0.005);
}

// Annex J: delta r within 0.02 mm everywhere, within 0.005 mm away from the onset of flange-root
// contact, and the +-1.7 entries are the transcription typo (0.572 for 0.527).
TEST(En15302WheelARailA, DeltaRMatchesAnnexJ) {
  const RigidContact contact = make_contact();
  const auto rows = read_rows(en15302("WheelARailA_deltaR.csv"));
  ASSERT_EQ(rows.size(), 137u);
  double worst = 0.0;
  double worst_y = 0.0;
  double worst_smooth = 0.0;
  double worst_smooth_y = 0.0;
  int typo_rows = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double y = rows[k].v.at(0);
    const double ref = rows[k].v.at(1);
    const double got = contact.at(y).delta_r_mm();
    const double err = got - ref;
    if (std::abs(std::abs(y) - 1.7) < 1e-9) {
      // The 2008 edition has 0.527 here; the transcription's 0.572 repeats the 1.8 value.
      EXPECT_NEAR(got, std::copysign(0.527, y), 0.005) << "y = " << y;
      EXPECT_GT(std::abs(err), 0.04) << "the +-1.7 typo should show, y = " << y;
      ++typo_rows;
      continue;
    }
    if (std::abs(err) > std::abs(worst)) {
      worst = err;
      worst_y = y;
    }
    // Onset of flange-root contact: the reference slope more than doubles from one step to the
    // next (only at |y| = 6.2: the R14 root meets the rail's R80/R13 junction; there the contact
    // point moves ~12 mm per mm and delta r depends on sub-0.01 mm detail).
    bool onset = false;
    if (k > 0 && k + 1 < rows.size()) {
      const double back = std::abs(ref - rows[k - 1].v.at(1));
      const double fwd = std::abs(rows[k + 1].v.at(1) - ref);
      onset = std::max(back, fwd) > 2.0 * std::min(back, fwd) && std::max(back, fwd) > 0.2;
    }
    // At the onset the exact rigid answer on the analytic rail A arcs is 4.683 (vertical-gap
    // minimum at 1e-5 mm steps), 0.033 above the reference 4.650: allow 0.04 there.
    EXPECT_NEAR(got, ref, onset ? 0.04 : 0.02) << "y = " << y;
    if (!onset) {
      EXPECT_NEAR(got, ref, 0.005) << "y = " << y;
      if (std::abs(err) > std::abs(worst_smooth)) {
        worst_smooth = err;
        worst_smooth_y = y;
      }
    }
  }
  EXPECT_EQ(typo_rows, 2);
  std::printf(
      "Annex J: worst delta r error %+.4f mm at y = %.1f; away from the flange onset %+.4f mm at y "
      "= %.1f\n",
      worst, worst_y, worst_smooth, worst_smooth_y);
}

// The contact angle from the wheel's slope equals the rail's slope at the contact point (the two
// surfaces are tangent there), on both sides, wherever the contact is not at a corner.
TEST(En15302WheelARailA, ContactAnglesAreTangentToTheRail) {
  const RigidContact contact = make_contact();
  const ProfileFunction rail(read_profile_csv(en15302("RailA.csv")));
  for (int k = -68; k <= 68; ++k) {
    const double y = 0.1 * k;
    const ContactState c = contact.at(y);
    for (const WheelContact* w : {&c.left, &c.right}) {
      const double rail_slope = rail.slope_at(w->y_rail_mm, 0.05);
      EXPECT_NEAR(std::tan(w->gamma_rad), rail_slope, 0.01 * (1.0 + std::abs(rail_slope)))
          << "y = " << y;
      EXPECT_FALSE(w->at_profile_end) << "y = " << y;
    }
  }
}

// Annex K: tan gamma_e (Annex B method) inside the tolerance window and within 0.005 of the
// reference at every amplitude (the requirement is 0.005 only where delta r is smooth, i.e. up to
// 6.0 mm; the flange amplitudes 6.2 ... 7.4 meet it too).
TEST(En15302WheelARailA, EquivalentConicityMatchesAnnexK) {
  const RigidContact contact = make_contact();
  const ContactTable table = contact.table(-8.0, 8.0, 0.01);
  const auto rows = read_rows(en15302("WheelARailA_conicity.csv"));
  ASSERT_EQ(rows.size(), 33u);
  double worst = 0.0;
  double worst_a = 0.0;
  for (const auto& row : rows) {
    const double a = row.v.at(0);
    const double ref = row.v.at(1);
    const double lo = row.v.at(2);
    const double hi = row.v.at(3);
    const ConicityResult r = equivalent_conicity(table, a);
    const double lin = linearised_conicity(table, a).tan_gamma_e;
    std::printf("a %.1f  ref %.3f [%.3f, %.3f]  annex B %.4f (err %+.4f)  regression %.4f\n", a,
                ref, lo, hi, r.tan_gamma_e, r.tan_gamma_e - ref, lin);
    EXPECT_GE(r.tan_gamma_e, lo) << "amplitude " << a;
    EXPECT_LE(r.tan_gamma_e, hi) << "amplitude " << a;
    EXPECT_NEAR(r.tan_gamma_e, ref, 0.005) << "amplitude " << a;
    if (std::abs(r.tan_gamma_e - ref) > std::abs(worst)) {
      worst = r.tan_gamma_e - ref;
      worst_a = a;
    }
  }
  std::printf("Annex K: worst tan gamma_e error %+.4f at %.1f mm\n", worst, worst_a);
}

}  // namespace
}  // namespace tread::contact
