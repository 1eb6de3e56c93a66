// read_profile_file on the corpus of tests/data/profiles (written by make_corpus.py from tread's
// S1002 and the Manchester UIC60, see data/PROVENANCE.md): every variant of a clean profile reads
// back as the clean one, with warnings saying what was changed.
#include "profile/profile_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "golden_path.hpp"
#include "profile/miniprof_profile.hpp"
#include "profile/profile_csv.hpp"
#include "test_dir.hpp"

namespace tread::profile {
namespace {

namespace fs = std::filesystem;

fs::path corpus(const std::string& name) {
  const fs::path p = testing::test_data("profiles/" + name);
  EXPECT_TRUE(fs::exists(p)) << p;
  return p;
}

std::string error_of(const fs::path& path, ProfileRole role, const ProfileReadOptions& o = {}) {
  try {
    (void)read_profile_file(path, role, o);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

bool has_warning(const ProfileFile& f, const std::string& part) {
  for (const std::string& w : f.warnings) {
    if (w.find(part) != std::string::npos) {
      return true;
    }
  }
  return false;
}

/// Linear interpolation of an increasing profile.
double z_at(const SampledProfile& p, double y) {
  for (std::size_t k = 1; k < p.y_mm.size(); ++k) {
    if (p.y_mm[k] >= y) {
      const double t = (y - p.y_mm[k - 1]) / (p.y_mm[k] - p.y_mm[k - 1]);
      return p.z_mm[k - 1] + t * (p.z_mm[k] - p.z_mm[k - 1]);
    }
  }
  return p.z_mm.back();
}

void expect_same_points(const SampledProfile& a, const SampledProfile& b, double tol) {
  ASSERT_EQ(a.y_mm.size(), b.y_mm.size());
  for (std::size_t k = 0; k < a.y_mm.size(); ++k) {
    EXPECT_NEAR(a.y_mm[k], b.y_mm[k], tol) << k;
    EXPECT_NEAR(a.z_mm[k], b.z_mm[k], tol) << k;
  }
}

TEST(ProfileFile, CleanFilesReadPointForPointWithoutWarnings) {
  const ProfileFile wheel = read_profile_file(corpus("s1002_clean.csv"), ProfileRole::kWheel);
  EXPECT_TRUE(wheel.warnings.empty()) << wheel.warnings.front();
  EXPECT_EQ(wheel.profile.y_mm.size(), 1401u);
  EXPECT_EQ(wheel.points_hidden, 0u);
  EXPECT_DOUBLE_EQ(wheel.y_shift_mm, 0.0);
  const SampledProfile strict = read_profile_csv(corpus("s1002_clean.csv"));
  expect_same_points(wheel.profile, strict, 0.0);
  const ProfileFile rail = read_profile_file(corpus("uic60_upright_clean.csv"), ProfileRole::kRail);
  EXPECT_TRUE(rail.warnings.empty());
  ASSERT_TRUE(rail.rail_inclination_rad.has_value());
  EXPECT_NEAR(*rail.rail_inclination_rad, 0.0, 2e-4);  // the upright head
}

TEST(ProfileFile, ZDownAndMirroredWheelEqualsTheCleanOne) {
  const ProfileFile clean = read_profile_file(corpus("s1002_clean.csv"), ProfileRole::kWheel);
  ProfileReadOptions o;
  o.z_down = true;
  o.mirror_y = true;
  const ProfileFile flipped =
      read_profile_file(corpus("s1002_zdown_mirrored.csv"), ProfileRole::kWheel, o);
  EXPECT_TRUE(flipped.warnings.empty());
  expect_same_points(flipped.profile, clean.profile, 1e-9);
  // Without the options the reader says which one is missing.
  const std::string path = corpus("s1002_zdown_mirrored.csv").string();
  const std::string no_z = error_of(path, ProfileRole::kWheel);
  EXPECT_EQ(no_z.rfind(path + ": ", 0), 0u) << no_z;
  EXPECT_NE(no_z.find("pass --z-down"), std::string::npos) << no_z;
  ProfileReadOptions z_only;
  z_only.z_down = true;
  const std::string no_mirror = error_of(path, ProfileRole::kWheel, z_only);
  EXPECT_NE(no_mirror.find("pass --mirror-y"), std::string::npos) << no_mirror;
}

TEST(ProfileFile, OffOriginWheelIsLocatedByItsFlangeBack) {
  const ProfileFile clean = read_profile_file(corpus("s1002_clean.csv"), ProfileRole::kWheel);
  const ProfileFile off = read_profile_file(corpus("s1002_offset.csv"), ProfileRole::kWheel);
  EXPECT_NEAR(off.y_shift_mm, -74.0, 1e-9);
  ASSERT_EQ(off.warnings.size(), 1u);
  EXPECT_NE(off.warnings[0].find("shifted by -74.000 mm"), std::string::npos) << off.warnings[0];
  expect_same_points(off.profile, clean.profile, 1e-9);
  EXPECT_NEAR(z_at(off.profile, 0.0), z_at(clean.profile, 0.0), 1e-9);  // r(0) = r0 + z(0)
  // Only checked, not moved, on request.
  ProfileReadOptions keep;
  keep.locate_wheel_origin = false;
  const ProfileFile kept = read_profile_file(corpus("s1002_offset.csv"), ProfileRole::kWheel, keep);
  EXPECT_DOUBLE_EQ(kept.profile.y_mm.front(), 4.0);
  EXPECT_TRUE(has_warning(kept, "74.000 mm from -70"));
}

// A wheel cut short of its taping line (a flange only), a tread with one gap among fine points,
// a SIMPACK file that ends inside its point block: each was read without a word, the first with
// z(0) taken from its last point and contacts at its end under ok.
TEST(ProfileFile, CutWheelsGapsAndCutFilesAreSaid) {
  const SampledProfile clean = read_profile_csv(corpus("s1002_clean.csv"));
  const fs::path dir = testing::test_dir("profile_file_test_cut");
  const auto write_csv = [&](const std::string& name, const auto& keep) {
    std::ofstream out(dir / name);
    out << "y_mm,z_mm\n";
    for (std::size_t k = 0; k < clean.y_mm.size(); ++k) {
      if (keep(clean.y_mm[k])) out << clean.y_mm[k] << ',' << clean.z_mm[k] << '\n';
    }
    return dir / name;
  };
  const fs::path flange = write_csv("flange.csv", [](double y) { return y <= -14.0; });
  EXPECT_NE(error_of(flange, ProfileRole::kWheel)
                .find("flange.csv: the wheel's points run from y = -70.000 to -14.000 mm and do "
                      "not reach the taping line"),
            std::string::npos)
      << error_of(flange, ProfileRole::kWheel);
  const fs::path gap = write_csv("gap.csv", [](double y) { return y <= 0.0 || y >= 20.0; });
  const ProfileFile with_gap = read_profile_file(gap, ProfileRole::kWheel);
  EXPECT_TRUE(
      has_warning(with_gap, "no points between y = 0.000 and 20.000 mm (a gap of 20.000 mm"))
      << (with_gap.warnings.empty() ? "" : with_gap.warnings[0]);
  EXPECT_FALSE(has_warning(read_profile_file(corpus("s1002_clean.csv"), ProfileRole::kWheel),
                           "no points between"));
  const fs::path prw = dir / "cut.prw";
  {
    std::ifstream in(testing::test_data("rail/manchester_benchmark/MBench_S1002_v3.prw"));
    std::ofstream out(prw);
    std::string line;
    for (int k = 0; k < 250 && std::getline(in, line); ++k) out << line << '\n';
  }
  EXPECT_NE(error_of(prw, ProfileRole::kWheel).find("ends inside a point block"), std::string::npos)
      << error_of(prw, ProfileRole::kWheel);
}

TEST(ProfileFile, PointsSpanningMoreThanAMetreAreRefusedWithTheirLines) {
  // A rail whose one point lies 26 km off (found by fuzzing: resampled at 0.5 mm it took 30 s and
  // 1.7 GB); a file in micrometres reads the same way.
  const fs::path path = testing::test_dir("profile_file_test_extent") / "far.csv";
  {
    std::ofstream out(path);
    out << "y_mm,z_mm\n-30,0\n0,0.5\n26096761,0\n";
  }
  ProfileReadOptions o;
  o.resample_step_mm = 0.5;
  EXPECT_EQ(error_of(path, ProfileRole::kRail, o),
            path.string() +
                ":4: the points span 26096791.0 mm in y (lines 2 and 4): a wheel or rail profile "
                "spans less than 1000 mm (is the file in millimetres?)");
}

TEST(ProfileFile, OffOriginWheelWithoutItsFlangeBackIsRefusedWithTheOffset) {
  // The clean S1002 from y = -50 (no back flank), shifted by +20 mm.
  const SampledProfile clean = read_profile_csv(corpus("s1002_clean.csv"));
  const fs::path path = testing::test_dir("profile_file_test_no_back") / "cut.csv";
  {
    std::ofstream out(path);
    out << "y_mm,z_mm\n";
    for (std::size_t k = 0; k < clean.y_mm.size(); ++k) {
      if (clean.y_mm[k] >= -62.0) {
        out << clean.y_mm[k] + 20.0 << ',' << clean.z_mm[k] << '\n';
      }
    }
  }
  const std::string e = error_of(path, ProfileRole::kWheel);
  EXPECT_EQ(e.rfind(path.string() + ": y = 0 does not look like the taping line", 0), 0u) << e;
  EXPECT_NE(e.find("the flange tip is at y = -35.000 mm, 20.000 mm from"), std::string::npos) << e;
}

TEST(ProfileFile, MiniProfWheelWithNoiseBackStepsAndItsBackFace) {
  const fs::path path = corpus("s1002_measured.whl");
  const ProfileFile clean = read_profile_file(corpus("s1002_clean.csv"), ProfileRole::kWheel);
  const ProfileFile m = read_profile_file(path, ProfileRole::kWheel);
  EXPECT_EQ(m.format, ProfileFormat::kMiniProf);
  EXPECT_EQ(m.points_read, 1452u);
  // Header kept; 35 inserted points 0.004 mm behind their neighbour are noise, the 16 points of
  // the vertical back face lie under the flange's back.
  ASSERT_GE(m.header.size(), 6u);
  EXPECT_EQ(m.header[4].first, "ColumnDef");
  EXPECT_EQ(m.header[4].second, "X,Y");
  ASSERT_EQ(m.warnings.size(), 2u);
  EXPECT_NE(m.warnings[0].find("35 points in 35 places"), std::string::npos) << m.warnings[0];
  EXPECT_NE(m.warnings[0].find("by up to 0.004 mm (measurement noise"), std::string::npos)
      << m.warnings[0];
  EXPECT_NE(m.warnings[1].find("runs vertical (lines 8-23"), std::string::npos) << m.warnings[1];
  EXPECT_NE(m.warnings[1].find("16 points up to 15.518 mm"), std::string::npos) << m.warnings[1];
  EXPECT_EQ(m.points_hidden, 35u + 16u);
  EXPECT_DOUBLE_EQ(m.y_shift_mm, 0.0);  // X from the flange back: y = X - 70
  EXPECT_NEAR(z_at(m.profile, 0.0), 0.0, 1e-12);
  // Within the noise (+-0.002 mm, and 0.004 mm back-steps on flanks up to 10:1) of the clean one.
  double worst = 0.0;
  for (double y = -69.5; y <= 69.5; y += 0.05) {
    worst = std::max(worst, std::abs(z_at(m.profile, y) - z_at(clean.profile, y)));
  }
  EXPECT_LT(worst, 0.05);
  EXPECT_GT(worst, 0.0005);  // the noise is there
}

TEST(ProfileFile, MiniProfRailWithColumnDefOrderAndBackSteps) {
  const ProfileFile clean =
      read_profile_file(corpus("uic60_upright_clean.csv"), ProfileRole::kRail);
  const ProfileFile m = read_profile_file(corpus("uic60_measured.ban"), ProfileRole::kRail);
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("measurement noise"), std::string::npos) << m.warnings[0];
  EXPECT_NE(m.warnings[0].find("the upper envelope is kept"), std::string::npos);
  double worst = 0.0;
  for (double y = -44.0; y <= 29.0; y += 0.05) {
    worst = std::max(worst, std::abs(z_at(m.profile, y) - z_at(clean.profile, y)));
  }
  EXPECT_LT(worst, 0.01);
  ASSERT_TRUE(m.rail_inclination_rad.has_value());
  EXPECT_NEAR(*m.rail_inclination_rad, 0.0, 5e-4);
}

TEST(ProfileFile, MiniProfErrorsNameFileAndLine) {
  const auto err = [](const std::string& text) {
    std::istringstream in(text);
    try {
      (void)read_miniprof(in, "m.whl");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(err("Date=1\n\n1 2\nSide=Left\n"),
            "m.whl:4: header line 'Side=Left' after the points (the header ends at the first "
            "blank line)");
  EXPECT_EQ(err("XOffset=left\n\n1 2\n2 3\n"), "m.whl:1: XOffset 'left' is not a number (mm)");
  EXPECT_EQ(err("ColumnDef=A,B\n\n1 2\n"),
            "m.whl:1: ColumnDef 'A,B' does not name the columns X and Y");
  EXPECT_EQ(err("Points=3\n\n1 2\n2 3\n"), "m.whl:1: the header declares 3 points, the file has 2");
  EXPECT_EQ(err("A=1\n\n1 2\n2 x\n"), "m.whl:4: expected a point 'X Y', got '2 x'");
  EXPECT_EQ(err("ColumnDef=Y,X,F\n\n1 2 0\n2\n"), "m.whl:4: expected at least 2 columns, got 1");
}

TEST(ProfileFile, MiniProfPlainWordsCommentsAndOffsets) {
  std::istringstream in(
      "MiniProf\n! exported\nDate=1\nXOffset=1.5\nYoffset=-0,25\n\n% first point\n1 2\n"
      "\"x\n2 3\n");
  const MiniProfFile m = read_miniprof(in, "m.ban");
  ASSERT_EQ(m.header.size(), 4u);
  EXPECT_EQ(m.header[0].first, "MiniProf");
  EXPECT_EQ(m.header[0].second, "");
  EXPECT_DOUBLE_EQ(m.x_offset_mm, 1.5);
  EXPECT_DOUBLE_EQ(m.y_offset_mm, -0.25);
  EXPECT_EQ(m.x_offset_line, 4u);
  EXPECT_EQ(m.y_offset_line, 5u);
  ASSERT_EQ(m.points.y_mm.size(), 2u);
  EXPECT_DOUBLE_EQ(m.points.y_mm[0], 2.5);
  EXPECT_DOUBLE_EQ(m.points.z_mm[0], 1.75);
  EXPECT_DOUBLE_EQ(m.points.y_mm[1], 3.5);
  EXPECT_DOUBLE_EQ(m.points.z_mm[1], 2.75);
  EXPECT_EQ(m.points.line[1], 10u);
}

TEST(ProfileFile, MiniProfOffsetsAreAppliedAndSaid) {
  const fs::path dir = tread::testing::test_dir("miniprof_offsets");
  std::ifstream src(corpus("uic60_measured.ban"));
  std::stringstream body;
  body << src.rdbuf();
  const fs::path shifted = dir / "shifted.ban";
  {
    // Every point 3 mm to -y and 1 mm down, with the shift kept in the header: the same rail.
    std::ofstream out(shifted);
    std::string line;
    bool header = true;
    out << "XOffset=3\nYOffset=1\n";
    while (std::getline(body, line)) {
      if (header) {
        out << line << '\n';
        header = !line.empty();
        continue;
      }
      std::replace(line.begin(), line.end(), ',', ' ');
      std::istringstream fields(line);  // ColumnDef=Y, X, Flags
      double x = 0.0;
      double y = 0.0;
      int flags = 0;
      ASSERT_TRUE(fields >> y >> x >> flags) << line;
      out << std::setprecision(17) << y - 1.0 << ", " << x - 3.0 << ", " << flags << '\n';
    }
  }
  const ProfileFile a = read_profile_file(corpus("uic60_measured.ban"), ProfileRole::kRail);
  const ProfileFile b = read_profile_file(shifted, ProfileRole::kRail);
  bool said = false;
  for (const auto& w : b.warnings) {
    said = said || w.find("XOffset = 3.000 mm (line 1), YOffset = 1.000 mm (line 2) added") !=
                       std::string::npos;
  }
  EXPECT_TRUE(said) << (b.warnings.empty() ? "" : b.warnings.back());
  for (double y = -44.0; y <= 29.0; y += 0.5) {
    EXPECT_NEAR(z_at(b.profile, y), z_at(a.profile, y), 1e-6) << y;
  }
}

TEST(ProfileFile, ContactStyleUndercutRailKeepsItsUpperEnvelope) {
  const ProfileFile clean =
      read_profile_file(corpus("uic60_upright_clean.csv"), ProfileRole::kRail);
  const ProfileFile u = read_profile_file(corpus("uic60_undercut.prr"), ProfileRole::kRail);
  EXPECT_EQ(u.format, ProfileFormat::kSimpack);
  ASSERT_EQ(u.warnings.size(), 1u);
  EXPECT_NE(u.warnings[0].find("turns back in y by 2.000 mm (lines 10-13"), std::string::npos)
      << u.warnings[0];
  EXPECT_NE(u.warnings[0].find("4 points"), std::string::npos) << u.warnings[0];
  EXPECT_EQ(u.points_hidden, 4u);
  // From the undercut's start on, the envelope is the clean head: its points, and 3 more on it
  // at the y of the undercut's points (y16 + 0.5, 1.5 and 2).
  const double y16 = u.profile.y_mm.front();
  std::size_t k0 = 0;
  while (clean.profile.y_mm[k0] < y16) {
    ++k0;
  }
  EXPECT_EQ(u.profile.y_mm.size(), clean.profile.y_mm.size() - k0 + 3);
  for (std::size_t k = k0; k < clean.profile.y_mm.size(); ++k) {
    EXPECT_NEAR(z_at(u.profile, clean.profile.y_mm[k]), clean.profile.z_mm[k], 1e-9) << k;
  }
  for (std::size_t k = 0; k < u.profile.y_mm.size(); ++k) {
    EXPECT_NEAR(z_at(clean.profile, u.profile.y_mm[k]), u.profile.z_mm[k], 1e-9) << k;
  }
}

TEST(ProfileFile, EnvelopeOfAZigzagAndOfACrossing) {
  const fs::path dir = testing::test_dir("profile_file_test_zigzag");
  {
    // A back-step of 0.005 mm: the point behind its neighbour is above the segment it falls on.
    std::ofstream(dir / "z.csv") << "0 0\n1 1\n0.995 1.2\n2 1.2\n3 1.2\n";
  }
  const ProfileFile f = read_profile_file(dir / "z.csv", ProfileRole::kRail);
  // Breakpoints 0, 0.995, 1, 2, 3: at 0.995 the top of (0.995,1.2)-(1,1)... is 1.2; at 1 the
  // segment from (0.995, 1.2) to (2, 1.2) gives 1.2 and hides the point (1, 1).
  EXPECT_EQ(f.profile.y_mm, (std::vector<double>{0.0, 0.995, 1.0, 2.0, 3.0}));
  EXPECT_EQ(f.profile.z_mm, (std::vector<double>{0.0, 1.2, 1.2, 1.2, 1.2}));
  EXPECT_EQ(f.points_hidden, 1u);
  EXPECT_TRUE(has_warning(f,
                          "1 point in 1 place between y = 1.000 and 1.000 mm step back in y "
                          "by up to 0.005 mm"));
  {
    // Two segments crossing between the breakpoints (0 and 4): (0,3)-(4,1) and (0,0)-(4,4).
    std::ofstream(dir / "x.csv") << "0 3\n4 1\n0 0\n4 4\n";
  }
  const ProfileFile x = read_profile_file(dir / "x.csv", ProfileRole::kRail);
  EXPECT_EQ(x.profile.y_mm, (std::vector<double>{0.0, 2.0, 4.0}));
  EXPECT_EQ(x.profile.z_mm, (std::vector<double>{3.0, 2.0, 4.0}));
  EXPECT_EQ(x.points_hidden, 2u);  // (4,1) and (0,0), 3 mm below the envelope
  EXPECT_TRUE(has_warning(x,
                          "turns back in y by 4.000 mm (lines 2-3, y 0.000 to 4.000 mm: an "
                          "undercut): 2 points up to 3.000 mm below"));
}

TEST(ProfileFile, RoleAndHeaderTypeMustAgree) {
  const fs::path prw = testing::test_data("rail/manchester_benchmark/MBench_S1002_v3.prw");
  const fs::path prr = testing::test_data("rail/manchester_benchmark/MBench_UIC60_v3.prr");
  EXPECT_EQ(error_of(prw, ProfileRole::kRail),
            prw.string() +
                ": the header says this is a wheel profile (type = 1), but it was given as the "
                "rail");
  EXPECT_EQ(error_of(prr, ProfileRole::kWheel),
            prr.string() +
                ": the header says this is a rail profile (type = 0), but it was given as the "
                "wheel");
  const ProfileFile w = read_profile_file(prw, ProfileRole::kWheel);
  EXPECT_TRUE(w.warnings.empty());  // its flange back (y = -69.61) is within 1 mm of -70
  EXPECT_EQ(w.header.front().first, "type");
}

// A CSV has no header to say what it holds: its shape does. A rail head given as the wheel (its
// crown taken for a flange: the contact table came out with only a warning about a shift) and a
// wheel given as the rail are refused, by the width of the top 10 mm below it.
TEST(ProfileFile, CsvRoleIsCheckedByTheShapeOfItsTop) {
  const fs::path rail = corpus("uic60_upright_clean.csv");
  EXPECT_EQ(error_of(rail, ProfileRole::kWheel),
            rail.string() +
                ": not a wheel profile: its top (y = -7.725 mm) is 70.1 mm wide 10 mm below it, a "
                "rail head's width (a wheel's flange is 25 to 31 mm wide there); a rail goes in as "
                "the rail (--rail-file, --role rail)");
  const fs::path wheel = corpus("s1002.csv");
  EXPECT_EQ(error_of(wheel, ProfileRole::kRail),
            wheel.string() +
                ": not a rail profile: its top (y = -55.000 mm) is 27.4 mm wide 10 mm below it "
                "with 125 mm of profile beside it: a wheel's flange and tread (a rail head is 60 "
                "to 72 mm wide there); a wheel goes in as the wheel (--wheel-file, --role wheel)");
  // The EN 15302 wheels (a thin-flanged one among them) and rail read in their own roles.
  for (const char* w : {"WheelA.csv", "WheelC.csv", "WheelH.csv"}) {
    EXPECT_NO_THROW((void)read_profile_file(testing::test_data(std::string("rail/en15302/") + w),
                                            ProfileRole::kWheel))
        << w;
  }
  EXPECT_NO_THROW(
      (void)read_profile_file(testing::test_data("rail/en15302/RailA.csv"), ProfileRole::kRail));
}

// One point 5 mm off a measured tread (dust on the wheel, a reflection): the contact search would
// take it for the profile. Said with where it is; a clean profile says nothing.
TEST(ProfileFile, ASpikeInAMeasuredProfileIsSaid) {
  const fs::path dir = testing::test_dir("profile_file_test_spike");
  std::ifstream in(corpus("s1002_clean.csv"));
  std::ofstream out(dir / "spike.csv");
  std::string line;
  while (std::getline(in, line)) {
    const auto comma = line.find(',');
    if (comma != std::string::npos && std::isdigit(static_cast<unsigned char>(line.back())) &&
        std::abs(std::stod(line.substr(0, comma)) - 10.0) < 1e-9) {
      out << "10," << std::stod(line.substr(comma + 1)) + 5.0 << '\n';
    } else {
      out << line << '\n';
    }
  }
  out.close();
  const ProfileFile f = read_profile_file(dir / "spike.csv", ProfileRole::kWheel);
  ASSERT_EQ(f.warnings.size(), 1U);
  EXPECT_NE(f.warnings[0].find("1 point stands off its neighbours as a spike (the first at y = "
                               "10.000 mm, 5.000 mm off the line between them)"),
            std::string::npos)
      << f.warnings[0];
  EXPECT_TRUE(read_profile_file(corpus("s1002_clean.csv"), ProfileRole::kWheel).warnings.empty());
}

TEST(ProfileFile, CantedManchesterRailIsMeasuredAsOneInForty) {
  const fs::path prr = testing::test_data("rail/manchester_benchmark/MBench_UIC60_v3.prr");
  const ProfileFile r = read_profile_file(prr, ProfileRole::kRail);
  ASSERT_TRUE(r.rail_inclination_rad.has_value());
  EXPECT_NEAR(*r.rail_inclination_rad, std::atan(1.0 / 40.0), 2e-4);
  bool listed = false;
  for (const auto& [key, value] : r.header) {
    listed = listed || (key == "tread.head_inclination" && value.rfind("1:40.", 0) == 0);
  }
  EXPECT_TRUE(listed);
  // Mirrored, it leans the other way.
  ProfileReadOptions m;
  m.mirror_y = true;
  const ProfileFile rm = read_profile_file(prr, ProfileRole::kRail, m);
  ASSERT_TRUE(rm.rail_inclination_rad.has_value());
  EXPECT_NEAR(*rm.rail_inclination_rad, -*r.rail_inclination_rad, 1e-6);
}

TEST(ProfileFile, TolerantCsvDialectAndErrorsNameTheFile) {
  const fs::path dir = testing::test_dir("profile_file_test_csv");
  std::ofstream(dir / "semi.csv") << "# comment\nY;Z\n0;0\n1;-0.1\n2;-0.2\n";
  const ProfileFile f = read_profile_file(dir / "semi.csv", ProfileRole::kRail);
  EXPECT_EQ(f.profile.y_mm, (std::vector<double>{0.0, 1.0, 2.0}));
  std::ofstream(dir / "bad.csv") << "0 0\n1 x\n";
  EXPECT_EQ(error_of(dir / "bad.csv", ProfileRole::kRail),
            (dir / "bad.csv").string() + ":2: column z_mm: 'x' is not a number");
  EXPECT_EQ(error_of(dir / "missing.csv", ProfileRole::kRail),
            (dir / "missing.csv").string() + ": cannot open the file");
  ProfileReadOptions mp;
  mp.format = ProfileFormat::kMiniProf;
  std::ofstream(dir / "mp.txt") << "ColumnDef=X,Y\n\n0 0\n1 -0.1\n";
  const ProfileFile g = read_profile_file(dir / "mp.txt", ProfileRole::kRail, mp);
  EXPECT_EQ(g.format, ProfileFormat::kMiniProf);
  EXPECT_EQ(g.profile.z_mm, (std::vector<double>{0.0, -0.1}));
  ProfileReadOptions resample;
  resample.resample_step_mm = 0.5;
  const ProfileFile h = read_profile_file(dir / "semi.csv", ProfileRole::kRail, resample);
  EXPECT_EQ(h.profile.y_mm, (std::vector<double>{0.0, 0.5, 1.0, 1.5, 2.0}));
  EXPECT_NEAR(h.profile.z_mm[3], -0.15, 1e-12);
}

TEST(ProfileFile, DecimalCommasByteOrderMarkAndMiniProfRole) {
  const fs::path dir = testing::test_dir("profile_file_test_locale");
  // ';' or tab separated with decimal commas (European spreadsheets): the comma is a point.
  std::ofstream(dir / "comma.csv") << "y_mm;z_mm\n-1,5;0,25\n0;0\n2,75;-0,125\n";
  const ProfileFile c = read_profile_file(dir / "comma.csv", ProfileRole::kRail);
  EXPECT_EQ(c.profile.y_mm, (std::vector<double>{-1.5, 0.0, 2.75}));
  EXPECT_EQ(c.profile.z_mm, (std::vector<double>{0.25, 0.0, -0.125}));
  std::ofstream(dir / "tab.csv") << "-1,5\t0,25\n0\t0\n";
  EXPECT_EQ(read_profile_file(dir / "tab.csv", ProfileRole::kRail).profile.y_mm,
            (std::vector<double>{-1.5, 0.0}));
  // A UTF-8 byte-order mark before the header does not hide the column names.
  std::ofstream(dir / "bom.csv") << "\xEF\xBB\xBFz_mm,y_mm\n0.5,-1\n0.25,0\n";
  const ProfileFile b = read_profile_file(dir / "bom.csv", ProfileRole::kRail);
  EXPECT_EQ(b.profile.y_mm, (std::vector<double>{-1.0, 0.0}));
  EXPECT_EQ(b.profile.z_mm, (std::vector<double>{0.5, 0.25}));
  // MiniProf names the role by the extension.
  std::ofstream(dir / "r.ban") << "ColumnDef=X,Y\n\n0 0\n1 -0.1\n";
  EXPECT_EQ(error_of(dir / "r.ban", ProfileRole::kWheel),
            (dir / "r.ban").string() +
                ": a MiniProf .ban file is a rail profile, but it was given as the wheel");
}

// From an audit with users' files (each read without a word before): a rail written with z down
// is refused; a wheel whose z is not 0 at the taping line (an absolute radius) is referred to it;
// a profile sampled every 5 mm and a wheel without a flange are said.
TEST(ProfileFile, RailZDownCoarsePointsNoFlangeAndZReferenceAreSaid) {
  const fs::path dir = testing::test_dir("profile_file_test_audit");
  const auto copy = [&](const fs::path& from, const std::string& name, double z_sign, double z_add,
                        std::size_t every) {
    std::ifstream in(from);
    std::ofstream out(dir / name);
    std::string line;
    std::size_t k = 0;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#' || std::isalpha(static_cast<unsigned char>(line[0]))) {
        out << line << '\n';
        continue;
      }
      const auto comma = line.find(',');
      const double y = std::stod(line.substr(0, comma));
      const double z = std::stod(line.substr(comma + 1));
      if (k++ % every == 0) out << y << ',' << z_sign * z + z_add << '\n';
    }
    return dir / name;
  };
  const fs::path rail = corpus("uic60_upright_clean.csv");
  const fs::path wheel = corpus("s1002_clean.csv");
  ProfileReadOptions z_down;
  z_down.z_down = true;
  EXPECT_NE(error_of(copy(rail, "r_zdown.csv", -1.0, 0.0, 1), ProfileRole::kRail)
                .find("with its ends above it: z points down; pass --z-down"),
            std::string::npos);
  EXPECT_EQ(error_of(dir / "r_zdown.csv", ProfileRole::kRail, z_down), "");
  EXPECT_EQ(error_of(rail, ProfileRole::kRail), "");

  const ProfileFile radius =
      read_profile_file(copy(wheel, "absolute.csv", 1.0, 460.0, 1), ProfileRole::kWheel);
  EXPECT_TRUE(has_warning(radius, "z at the taping line (y = 0) is 460.000 mm in the file"));
  EXPECT_NEAR(z_at(radius.profile, 0.0), 0.0, 1e-9);

  const ProfileFile coarse =
      read_profile_file(copy(wheel, "coarse.csv", 1.0, 0.0, 50), ProfileRole::kWheel);
  EXPECT_TRUE(has_warning(coarse, "mm apart (median): too coarse")) << coarse.warnings.size();
  EXPECT_FALSE(has_warning(read_profile_file(wheel, ProfileRole::kWheel), "too coarse"));

  {
    std::ofstream cone(dir / "cone.csv");
    cone << "y_mm,z_mm\n-20,1\n60,-1\n";
  }
  EXPECT_TRUE(has_warning(read_profile_file(dir / "cone.csv", ProfileRole::kWheel), "no flange"));
}

}  // namespace
}  // namespace tread::profile
