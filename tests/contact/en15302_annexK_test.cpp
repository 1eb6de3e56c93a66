// Golden: every EN 15302:2021 test case on rail A (Annex I profiles, Annex J delta r, Annex K
// conicity): wheels A, B, C, H, I on both sides; the "mod" cases (the same wheel with rolling
// radii 460 / 459 mm, i.e. diameters 920 / 918: delta r shifted by +1 mm); and the A/B pair.
// Conditions as for wheel A: rail A in the running-circle frame, back-to-back 1360 mm.
//
// Two checks per case:
//  - on the standard's own tabulated delta r (Annex J, 0.1 mm steps, independent of our profile
//    reconstruction and contact search): Annex B and Annex C conicity against the Annex K windows
//    at every amplitude whose motion stays inside the table;
//  - from the profiles: delta r against Annex J, then the conicity against Annex K at every
//    amplitude.
//
// Documented typos of the transcription (rohrbecka/EN15302, see data/PROVENANCE.md), and only
// these, are tolerated:
//  - Annex J, wheel A, y = +-1.7: 0.572 for 0.527 (the 2008 edition's value);
//  - Annex J, wheel A mod, y = +1.7: 1.572 for 1.527 (wheel A's value + 1; -1.7 is right);
//  - Annex J, wheel H, y = +3.1: 1.514 for 2.514 (-3.1 is -2.514; wheel H mod has 3.514);
//  - Annex K, wheel C, 4.2 mm: 0.249 between 0.221 and 0.207 (probably 0.214); its window is
//    centred on 0.249 and is kept, only the deviation from the ideal value is not counted there;
//  - Annex K, wheel H mod, 6.4 mm: the tolerance window is printed reversed (0.486 ... 0.386).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "contact/equivalent_conicity.hpp"
#include "contact/profile_csv.hpp"
#include "contact/rigid_contact.hpp"
#include "golden_path.hpp"

namespace tread::contact {
namespace {

struct Case {
  std::string name;   ///< file prefix, e.g. "WheelAmodRailA"
  std::string left;   ///< left wheel profile file
  std::string right;  ///< right wheel profile file
  double r0_left_mm;
  double r0_right_mm;
  std::map<double, double> delta_r_typos;                  ///< y -> the correct value
  std::vector<double> annexB_tabulated_outside_tolerance;  ///< amplitudes (extended window only)
};

std::ostream& operator<<(std::ostream& os, const Case& c) {
  return os << c.name;
}

const std::vector<Case>& cases() {
  static const std::vector<Case> all{
      {"WheelARailA", "WheelA.csv", "WheelA.csv", 460.0, 460.0, {{-1.7, -0.527}, {1.7, 0.527}}, {}},
      // Jump of delta r between 2.9 and 3.0 (tread to flange root): the 0.1 mm table places it
      // only to within 0.1 mm, which moves the 3.0 mm amplitude (just reaching it) a lot.
      {"WheelBRailA", "WheelB.csv", "WheelB.csv", 460.0, 460.0, {}, {3.0}},
      {"WheelCRailA", "WheelC.csv", "WheelC.csv", 460.0, 460.0, {}, {}},
      {"WheelHRailA", "WheelH.csv", "WheelH.csv", 460.0, 460.0, {{3.1, 2.514}}, {}},
      {"WheelIRailA", "WheelI.csv", "WheelI.csv", 460.0, 460.0, {}, {}},
      {"WheelAmodRailA", "WheelA.csv", "WheelA.csv", 460.0, 459.0, {{1.7, 1.527}}, {}},
      {"WheelBmodRailA", "WheelB.csv", "WheelB.csv", 460.0, 459.0, {}, {}},
      {"WheelHmodRailA", "WheelH.csv", "WheelH.csv", 460.0, 459.0, {}, {}},
      {"WheelImodRailA", "WheelI.csv", "WheelI.csv", 460.0, 459.0, {}, {}},
      // The transcription calls this case "wheel A right, wheel B left"; in tread's convention
      // (delta r = r_left - r_right, y > 0 toward the left rail) Annex J is reproduced with wheel A
      // on the left (with B left it comes out mirrored: delta r(0) = +0.182 for the published
      // -0.182), i.e. the standard names the sides from the other end.
      {"WheelABRailA", "WheelA.csv", "WheelB.csv", 460.0, 460.0, {}, {}},
  };
  return all;
}

std::vector<std::vector<double>> read_rows(const std::filesystem::path& file) {
  std::ifstream in(file);
  EXPECT_TRUE(in.good()) << "missing reference file " << file;
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') {
      continue;
    }
    std::stringstream ss(line);
    std::string cell;
    std::vector<double> r;
    while (std::getline(ss, cell, ',')) {
      r.push_back(std::stod(cell));
    }
    rows.push_back(r);
  }
  return rows;
}

std::filesystem::path en15302(const std::string& name) {
  return tread::testing::test_data("rail/en15302/" + name);
}

struct Window {
  double amplitude, ideal, lo, hi, ext_lo, ext_hi;
};

std::vector<Window> annex_k(const Case& c) {
  std::vector<Window> w;
  for (const auto& r : read_rows(en15302(c.name + "_conicity.csv"))) {
    // min/max: the wheel H mod 6.4 mm window is printed reversed.
    w.push_back({r.at(0), r.at(1), std::min(r.at(2), r.at(3)), std::max(r.at(2), r.at(3)), r.at(4),
                 r.at(5)});
  }
  EXPECT_EQ(w.size(), 33u) << c.name;
  return w;
}

bool is_ideal_typo(const Case& c, double amplitude) {
  return c.name == "WheelCRailA" && std::abs(amplitude - 4.2) < 1e-9;
}

/// Counts of one method on one case against Annex K.
struct Tally {
  int computed = 0;
  int in_tolerance = 0;
  int in_extended = 0;
  double worst = 0.0;
  double worst_amplitude = 0.0;
  void add(const Case& c, const Window& w, double got) {
    ++computed;
    in_tolerance += (got >= w.lo && got <= w.hi) ? 1 : 0;
    in_extended += (got >= w.ext_lo && got <= w.ext_hi) ? 1 : 0;
    if (!is_ideal_typo(c, w.amplitude) && std::abs(got - w.ideal) > std::abs(worst)) {
      worst = got - w.ideal;
      worst_amplitude = w.amplitude;
    }
  }
  void print(const std::string& what) const {
    std::printf(
        "%-34s %2d amplitudes: %2d in tolerance, %2d in extended tolerance, worst %+.4f "
        "at %.1f mm\n",
        what.c_str(), computed, in_tolerance, in_extended, worst, worst_amplitude);
  }
};

class En15302AnnexK : public ::testing::TestWithParam<Case> {};

// The standard's Annex J delta r (documented typos corrected) as a table.
ContactTable tabulated_delta_r(const Case& c) {
  const auto rows = read_rows(en15302(c.name + "_deltaR.csv"));
  std::vector<double> d;
  for (const auto& r : rows) {
    double v = r.at(1);
    for (const auto& [y, fixed] : c.delta_r_typos) {
      if (std::abs(r.at(0) - y) < 1e-9) {
        v = fixed;
      }
    }
    d.push_back(v);
  }
  for (std::size_t k = 1; k < rows.size(); ++k) {
    EXPECT_NEAR(rows[k].at(0) - rows[k - 1].at(0), 0.1, 1e-9) << c.name << ": uneven y";
  }
  return delta_r_table(rows.front().at(0), 0.1, d);
}

// Which definitions reproduce the standard, on its own delta r: Annex B (kinematic equation,
// turning points balancing the potential) inside the tolerance window at every amplitude whose
// motion fits in the table except the documented jump case; Annex C (regression, harmonic
// weighting) inside the extended window everywhere.
TEST_P(En15302AnnexK, TabulatedDeltaRGivesAnnexK) {
  const Case& c = GetParam();
  const ContactTable t = tabulated_delta_r(c);
  Tally b;
  Tally r;
  int left_table = 0;
  for (const Window& w : annex_k(c)) {
    try {
      const ConicityResult res = equivalent_conicity(t, w.amplitude);
      b.add(c, w, res.tan_gamma_e);
      const bool documented = std::any_of(
          c.annexB_tabulated_outside_tolerance.begin(), c.annexB_tabulated_outside_tolerance.end(),
          [&](double a) { return std::abs(a - w.amplitude) < 1e-9; });
      EXPECT_GE(res.tan_gamma_e, w.ext_lo) << c.name << " annex B, amplitude " << w.amplitude;
      EXPECT_LE(res.tan_gamma_e, w.ext_hi) << c.name << " annex B, amplitude " << w.amplitude;
      if (!documented) {
        EXPECT_GE(res.tan_gamma_e, w.lo) << c.name << " annex B, amplitude " << w.amplitude;
        EXPECT_LE(res.tan_gamma_e, w.hi) << c.name << " annex B, amplitude " << w.amplitude;
      }
    } catch (const std::domain_error& e) {
      // Only allowed when the motion reaches the end of the table (flange amplitudes).
      EXPECT_NE(std::string(e.what()).find("table"), std::string::npos) << e.what();
      ++left_table;
    }
    try {
      const RegressionResult res = linearised_conicity(t, w.amplitude);
      r.add(c, w, res.tan_gamma_e);
      EXPECT_GE(res.tan_gamma_e, w.ext_lo) << c.name << " annex C, amplitude " << w.amplitude;
      EXPECT_LE(res.tan_gamma_e, w.ext_hi) << c.name << " annex C, amplitude " << w.amplitude;
    } catch (const std::domain_error& e) {
      EXPECT_NE(std::string(e.what()).find("table"), std::string::npos) << e.what();
    }
  }
  // The table ends at |y| = 6.8 ... 9.4 (and the mod cases oscillate off centre): the largest
  // amplitudes cannot be evaluated on it.
  EXPECT_GE(b.computed, 20) << c.name;
  EXPECT_GE(r.computed, 20) << c.name;
  b.print(c.name + " table annex B");
  r.print(c.name + " table annex C");
}

// From the profiles: delta r against Annex J, then conicity against Annex K at every amplitude.
TEST_P(En15302AnnexK, ProfilesGiveAnnexJAndAnnexK) {
  const Case& c = GetParam();
  const auto rail = read_profile_csv(en15302("RailA.csv"));
  const RigidContact contact(read_profile_csv(en15302(c.left)), read_profile_csv(en15302(c.right)),
                             rail, WheelsetSetup{1360.0, c.r0_left_mm, c.r0_right_mm});
  const auto rows = read_rows(en15302(c.name + "_deltaR.csv"));
  // The reference with the documented typos corrected (also for the slopes below).
  const ContactTable corrected = tabulated_delta_r(c);
  const std::vector<double>& refs = corrected.delta_r_mm;
  double worst = 0.0;
  double worst_y = 0.0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double y = rows[k].at(0);
    double ref = rows[k].at(1);
    const double got = contact.at(y).delta_r_mm();
    for (const auto& [ty, fixed] : c.delta_r_typos) {
      if (std::abs(y - ty) < 1e-9) {
        EXPECT_GT(std::abs(got - ref), 0.04) << c.name << ": the typo at " << y << " should show";
        ref = fixed;
      }
    }
    EXPECT_EQ(ref, refs[k]);
    // 0.005 mm where delta r is smooth (as for wheel A); 0.02 mm at and next to a kink of the
    // reference (its slope changes more than twofold from one 0.1 mm step to the next: the
    // contact point moves onto another arc somewhere between the grid points); where delta r is
    // steep (flange contact, slope > 2), 0.04 mm or a lateral offset of 0.003 mm times the slope,
    // whichever is larger (delta r there depends on sub-0.01 mm detail of the profiles).
    auto step_slope = [&](std::size_t i, std::size_t j) {
      return std::abs(refs[j] - refs[i]) / 0.1;
    };
    auto kink_at = [&](std::size_t i) {
      if (i == 0 || i + 1 >= rows.size()) {
        return false;
      }
      const double b = step_slope(i - 1, i);
      const double f = step_slope(i, i + 1);
      return std::max(b, f) > 2.0 * std::min(b, f) + 0.05;
    };
    double slope = 0.0;
    if (k > 0) {
      slope = std::max(slope, step_slope(k - 1, k));
    }
    if (k + 1 < rows.size()) {
      slope = std::max(slope, step_slope(k, k + 1));
    }
    const bool kink = kink_at(k) || (k > 0 && kink_at(k - 1)) || kink_at(k + 1);
    const double tol = slope > 2.0 ? std::max(0.04, 0.003 * slope) : (kink ? 0.02 : 0.005);
    EXPECT_NEAR(got, ref, tol) << c.name << ", y = " << y;
    if (std::abs(got - ref) > std::abs(worst)) {
      worst = got - ref;
      worst_y = y;
    }
  }
  std::printf("%-34s delta r worst %+.4f mm at y = %.1f\n", c.name.c_str(), worst, worst_y);

  const ContactTable t = contact.table(-10.0, 10.0, 0.01);
  Tally b;
  Tally r;
  for (const Window& w : annex_k(c)) {
    const ConicityResult res = equivalent_conicity(t, w.amplitude);
    b.add(c, w, res.tan_gamma_e);
    EXPECT_GE(res.tan_gamma_e, w.lo) << c.name << " annex B, amplitude " << w.amplitude;
    EXPECT_LE(res.tan_gamma_e, w.hi) << c.name << " annex B, amplitude " << w.amplitude;
    const RegressionResult reg = linearised_conicity(t, w.amplitude);
    r.add(c, w, reg.tan_gamma_e);
    EXPECT_GE(reg.tan_gamma_e, w.ext_lo) << c.name << " annex C, amplitude " << w.amplitude;
    EXPECT_LE(reg.tan_gamma_e, w.ext_hi) << c.name << " annex C, amplitude " << w.amplitude;
  }
  EXPECT_EQ(b.computed, 33);
  b.print(c.name + " profiles annex B");
  r.print(c.name + " profiles annex C");
}

INSTANTIATE_TEST_SUITE_P(AllCases, En15302AnnexK, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& param_info) {
                           return param_info.param.name;
                         });

// Wheel A on both sides as a two-profile wheelset gives an odd delta r and a centred motion;
// swapping the wheels of the A/B pair mirrors delta r and the centre of the oscillation and keeps
// the conicity. (Not to 1e-9: rail A is sampled from y = -32.634, so the two rails' samples are
// not mirror images of each other; the contact differs by up to a few 1e-4 mm.)
TEST(En15302AnnexKSelfChecks, TwoProfileWheelsetReproducesSymmetricAndMirrors) {
  const auto rail = read_profile_csv(en15302("RailA.csv"));
  const auto a = read_profile_csv(en15302("WheelA.csv"));
  const auto b = read_profile_csv(en15302("WheelB.csv"));
  const RigidContact aa(a, a, rail, WheelsetSetup{1360.0, 460.0, 460.0});
  const ContactTable taa = aa.table(-8.0, 8.0, 0.01);
  for (std::size_t k = 0; k < taa.delta_r_mm.size(); ++k) {
    EXPECT_NEAR(taa.delta_r_mm[k], -taa.delta_r_mm[taa.delta_r_mm.size() - 1 - k], 1e-3);
  }
  for (const double amp : {1.0, 3.0, 6.0}) {
    EXPECT_NEAR(equivalent_conicity(taa, amp).centre_y_mm, 0.0, 0.005);
  }
  const RigidContact ba(b, a, rail, WheelsetSetup{1360.0, 460.0, 460.0});
  const RigidContact ab(a, b, rail, WheelsetSetup{1360.0, 460.0, 460.0});
  const ContactTable tba = ba.table(-8.0, 8.0, 0.01);
  const ContactTable tab = ab.table(-8.0, 8.0, 0.01);
  for (std::size_t k = 0; k < tba.delta_r_mm.size(); ++k) {
    EXPECT_NEAR(tba.delta_r_mm[k], -tab.delta_r_mm[tab.delta_r_mm.size() - 1 - k], 1e-3);
  }
  for (const double amp : {1.0, 2.0, 4.0, 6.0}) {
    const ConicityResult x = equivalent_conicity(tba, amp);
    const ConicityResult y = equivalent_conicity(tab, amp);
    EXPECT_GT(std::abs(x.centre_y_mm), 0.01) << amp;
    EXPECT_NEAR(x.tan_gamma_e, y.tan_gamma_e, 5e-4) << amp;
    EXPECT_NEAR(x.centre_y_mm, -y.centre_y_mm, 0.005) << amp;
    EXPECT_NEAR(linearised_conicity(tba, amp).tan_gamma_e,
                linearised_conicity(tab, amp).tan_gamma_e, 1e-6)
        << amp;
  }
}

}  // namespace
}  // namespace tread::contact
