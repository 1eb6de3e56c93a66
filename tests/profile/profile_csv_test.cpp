#include "profile/profile_csv.hpp"

#include <gtest/gtest.h>

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
    (void)read_profile_csv(in, "p.csv");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(ProfileCsv, ReadsIncreasingAndDecreasingWithCommentsAndExtraColumns) {
  std::istringstream a("# comment\ny_mm,z_mm\n-1,0.5\n0,0\n\n2.5,-0.25\n");
  const SampledProfile p = read_profile_csv(a, "a");
  EXPECT_EQ(p.y_mm, (std::vector<double>{-1.0, 0.0, 2.5}));
  EXPECT_EQ(p.z_mm, (std::vector<double>{0.5, 0.0, -0.25}));

  std::istringstream b("tan,z_mm,y_mm\n9,-0.25,2.5\n9,0,0\n9,0.5,-1\n");
  const SampledProfile q = read_profile_csv(b, "b");
  EXPECT_EQ(q.y_mm, p.y_mm);
  EXPECT_EQ(q.z_mm, p.z_mm);
}

TEST(ProfileCsv, ErrorsNameFileAndLine) {
  EXPECT_EQ(error_of("y,z\n1,2\n"),
            "p.csv:1: expected a header naming the columns y_mm and z_mm, got 'y,z'");
  EXPECT_EQ(error_of("y_mm,z_mm\n1,2\n2,x\n"), "p.csv:3: column z_mm: 'x' is not a number");
  EXPECT_EQ(error_of("y_mm,z_mm\n1,2\n2\n"), "p.csv:3: expected 2 columns, got 1");
  EXPECT_EQ(error_of("y_mm,z_mm\n1,2\n2,1\n# c\n2,3\n"),
            "p.csv:5: y_mm is not strictly increasing (previous point at line 3)");
  EXPECT_EQ(error_of("y_mm,z_mm\n1,2\n"), "p.csv:2: fewer than 2 points");
  EXPECT_EQ(error_of("y_mm,z_mm\n1,2\n2,nan\n"), "p.csv:3: column z_mm: value is not finite");
  EXPECT_THROW((void)read_profile_csv(std::filesystem::path("/nonexistent/x.csv")),
               std::runtime_error);
}

TEST(ProfileCsv, RoundTripIsExactAtSeventeenDigits) {
  SampledProfile p{"rt", {-70.0, -1.0 / 3.0, 0.1, 65.0}, {9.519259302, 1.0 / 7.0, -0.0033, -2.98}};
  std::ostringstream out;
  write_profile_csv(out, p, {}, 17);
  std::istringstream in(out.str());
  const SampledProfile q = read_profile_csv(in, "rt");
  ASSERT_EQ(q.y_mm.size(), p.y_mm.size());
  for (std::size_t i = 0; i < p.y_mm.size(); ++i) {
    EXPECT_DOUBLE_EQ(q.y_mm[i], p.y_mm[i]);
    EXPECT_DOUBLE_EQ(q.z_mm[i], p.z_mm[i]);
  }
  std::ostringstream with_tan;
  const std::vector<double> tan{1.0, 2.0, 3.0, 4.0};
  write_profile_csv(with_tan, p, tan, 3);
  EXPECT_EQ(with_tan.str().substr(0, 41), "y_mm,z_mm,tan\n-70.000,9.519,1.000\n-0.333,");
}

TEST(ProfileCsvGolden, ReadsEn15302RailAAndWheelA) {
  const auto rail_path = testing::test_data("rail/en15302/RailA.csv");
  ASSERT_TRUE(std::filesystem::exists(rail_path)) << rail_path;
  const SampledProfile rail = read_profile_csv(rail_path);
  EXPECT_EQ(rail.name, "RailA");
  EXPECT_EQ(rail.y_mm.size(), 7191u);
  EXPECT_DOUBLE_EQ(rail.y_mm.front(), -32.634);
  EXPECT_DOUBLE_EQ(rail.z_mm.front(), -15.521274);
  check_sampled_profile(rail);
  const auto wheel_path = testing::test_data("rail/en15302/WheelA.csv");
  ASSERT_TRUE(std::filesystem::exists(wheel_path)) << wheel_path;
  const SampledProfile wheel = read_profile_csv(wheel_path);
  EXPECT_DOUBLE_EQ(wheel.y_mm.front(), -70.0);
  EXPECT_DOUBLE_EQ(wheel.z_mm.front(), 9.519260);
}

}  // namespace
}  // namespace tread::profile

namespace tread::profile {
namespace {

// A header naming y and z with their units: the columns are taken from it, in any order, and
// converted to mm; an unknown unit is an error at its line; other names leave the first two columns
// as y and z in mm.
TEST(ProfileCsv, TolerantHeaderUnitsAreConvertedToMillimetres) {
  const auto read = [](const std::string& text) {
    std::istringstream in(text);
    return read_profile_csv(in, "h", CsvDialect::kTolerant);
  };
  const std::vector<double> y{-10.0, 20.0, 60.0};
  const std::vector<double> z{1.0, 0.5, 0.25};
  for (const char* text :
       {"y_m,z_m\n-0.01,0.001\n0.02,0.0005\n0.06,0.00025\n",
        "z [m]; y [m]\n0.001;-0.01\n0.0005;0.02\n0.00025;0.06\n",
        "Y(cm)\tZ(mm)\n-1\t1\n2\t0.5\n6\t0.25\n",
        "z[m];y[m]\n0.001;-0.01\n0.0005;0.02\n0.00025;0.06\n", "y,z\n-10,1\n20,0.5\n60,0.25\n",
        "x,y\n-10,1\n20,0.5\n60,0.25\n", "y/mm z/mm extra\n-10 1 7\n20 0.5 7\n60 0.25 7\n",
        // A suffix that is no unit names no axis: the first two columns, in mm.
        "y,z,y_err\n-10,1,0\n20,0.5,0\n60,0.25,0\n", "y_wheel,z_wheel\n-10,1\n20,0.5\n60,0.25\n",
        "y / mm, z / mm\n-10,1\n20,0.5\n60,0.25\n",
        "\"y_m\",\"z_m\"\n-0.01,0.001\n0.02,0.0005\n0.06,0.00025\n",
        "y_\u03bcm,z_\u00b5m\n-10000,1000\n20000,500\n60000,250\n"}) {
    SCOPED_TRACE(text);
    const SampledProfile p = read(text);
    ASSERT_EQ(p.y_mm.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_NEAR(p.y_mm[k], y[k], 1e-12);
      EXPECT_NEAR(p.z_mm[k], z[k], 1e-12);
    }
  }
  EXPECT_THROW((void)read("y_m,z_m\n1e306,0\n2e306,1\n"), std::runtime_error);  // inf in mm
  {  // what the header named is reported (tread profile --input's "fields used")
    std::istringstream text("Z [m]; Y [m]\n0.001;-0.01\n0.0005;0.12\n");
    const ProfilePoints p = read_profile_csv_points(text, "h", CsvDialect::kTolerant);
    ASSERT_EQ(p.header.size(), 2u);
    EXPECT_EQ(p.header[0],
              (std::pair<std::string, std::string>{"y", "column 2 'Y[m]', × 1000 to mm"}));
    EXPECT_EQ(p.header[1],
              (std::pair<std::string, std::string>{"z", "column 1 'Z[m]', × 1000 to mm"}));
  }
  const SampledProfile in = read("y_in,z_in\n0,0\n1,0.5\n");
  EXPECT_DOUBLE_EQ(in.y_mm[1], 25.4);
  EXPECT_DOUBLE_EQ(in.z_mm[1], 12.7);
  try {
    (void)read("# a comment\ny [ft],z [ft]\n0,0\n1,1\n");
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(),
                 "h:2: column 'y[ft]': unit 'ft' not known for a profile (mm, m, cm, in, um)");
  }
  try {  // a unit of length after '_' is one too, not a name: not read as mm
    (void)read("y_ft,z_ft\n0,0\n1,1\n");
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(),
                 "h:1: column 'y_ft': unit 'ft' not known for a profile (mm, m, cm, in, um)");
  }
  // Blank-separated numbers with decimal commas: "-70,0 9,519" is (-70.0, 9.519), not -70 and 0.
  const SampledProfile commas = read("-70,0 9,519\n-69,9 11,542\n-60,5 20,125\n");
  ASSERT_EQ(commas.y_mm.size(), 3u);
  EXPECT_DOUBLE_EQ(commas.y_mm[1], -69.9);
  EXPECT_DOUBLE_EQ(commas.z_mm[1], 11.542);
  try {
    (void)read("Y(in),height\n0,0\n1,1\n");
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(),
                 "h:1: the header gives the unit of y but names no z column: 'Y(in),height'");
  }
}

TEST(ProfileCsv, TolerantDialectTakesAnySeparatorAndAnOptionalHeader) {
  std::istringstream a("# c\n0;0.5\n1\t0.25\n2 0 9\n");
  const SampledProfile p = read_profile_csv(a, "a", CsvDialect::kTolerant);
  EXPECT_EQ(p.y_mm, (std::vector<double>{0.0, 1.0, 2.0}));
  EXPECT_EQ(p.z_mm, (std::vector<double>{0.5, 0.25, 0.0}));
  std::istringstream b("z_mm y_mm\n0.5 0\n0.25 1\n");  // a header naming the columns is used
  const SampledProfile q = read_profile_csv(b, "b", CsvDialect::kTolerant);
  EXPECT_EQ(q.y_mm, (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(q.z_mm, (std::vector<double>{0.5, 0.25}));
  std::istringstream c("y z\n0 0\nfoo\n");
  try {
    (void)read_profile_csv(c, "c", CsvDialect::kTolerant);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "c:3: expected 2 columns, got 1");
  }
  // The strict dialect still wants its header.
  std::istringstream d("0,0\n1,1\n");
  EXPECT_THROW((void)read_profile_csv(d, "d"), std::runtime_error);
}

}  // namespace
}  // namespace tread::profile
