// End-to-end tests of `tread profile` (runs the built executable).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>

#include "golden_path.hpp"
#include "profile/profile_csv.hpp"
#include "profile/simpack_profile.hpp"
#include "profile/wheel_profile.hpp"
#include "test_dir.hpp"

namespace tread::profile {
namespace {

struct CommandResult {
  int status;
  std::string out;
};

CommandResult run(const std::string& args) {
  const std::string command = std::string(TREAD_EXE) + " profile " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  EXPECT_NE(pipe, nullptr);
  std::string out;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    out.append(buffer.data(), n);
  }
  return {pclose(pipe), out};
}

std::filesystem::path tmp_dir() {
  // One scratch directory per test case: CTest runs the cases of this binary in parallel.
  return tread::testing::test_dir(std::string("profile_command_test_") +
                                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
}

TEST(ProfileCommandGolden, TableReproducesTheSeedAppendix) {
  const CommandResult r =
      run("--family S1002 --flange-height 28 --flange-thickness 32.5 --outer-slope 6.7");
  ASSERT_EQ(r.status, 0) << r.out;
  // The seed's appendix rows (tests/data/seed/: its header names the first two columns the wrong
  // way round: the first is y).
  const auto seed = ::tread::testing::test_data("seed/s1002_h28_e32.5_slope6.7_appendix.csv");
  std::ifstream in(seed);
  ASSERT_TRUE(in) << seed;
  std::string line;
  std::size_t compared = 0;
  double worst = 0.0;
  std::istringstream ours(r.out);
  std::string our_line;
  // Skip our header (4 lines before the column names, then the column names).
  while (std::getline(ours, our_line) && our_line.rfind("y [mm]", 0) != 0) {
  }
  ASSERT_EQ(our_line, "y [mm]\tz [mm]\ttan");
  while (std::getline(in, line)) {
    double y = 0.0;
    double z = 0.0;
    double tan = 0.0;
    if (std::sscanf(line.c_str(), "%lf,%lf,%lf", &y, &z, &tan) != 3) {
      continue;
    }
    ASSERT_TRUE(std::getline(ours, our_line));
    double oy = 0.0;
    double oz = 0.0;
    double otan = 0.0;
    ASSERT_EQ(std::sscanf(our_line.c_str(), "%lf %lf %lf", &oy, &oz, &otan), 3) << our_line;
    EXPECT_NEAR(oy, y, 1e-12);
    EXPECT_NEAR(oz, z, 1e-5) << our_line;
    EXPECT_NEAR(otan, tan, 1e-5) << our_line;
    worst = std::max({worst, std::fabs(oz - z), std::fabs(otan - tan)});
    ++compared;
  }
  EXPECT_EQ(compared, 445u);
  std::printf("tread profile table vs seed appendix: %zu rows, worst %.3g\n", compared, worst);
  // The table runs on down to the wheel back, where the slope is vertical.
  const std::string tail = r.out.substr(r.out.size() - 40);
  EXPECT_NE(tail.find("-70.0\t9.51926\tinf\n"), std::string::npos) << tail;
}

TEST(ProfileCommand, CsvAndPrwOutputsReadBackToTheConstruction) {
  const auto dir = tmp_dir();
  const WheelProfile w({WheelFamily::kEps, 32.0, 29.5, OuterSlope::k10, 135.0, true});
  const CommandResult csv =
      run("--family EPS --flange-height 32 --flange-thickness 29.5 --outer-slope 10 "
          "--width 135 --step 0.25 --format csv --output " +
          (dir / "eps.csv").string());
  ASSERT_EQ(csv.status, 0) << csv.out;
  std::ifstream first_line_in(dir / "eps.csv");
  std::string header;
  std::getline(first_line_in, header);
  EXPECT_EQ(header, "y_mm,z_mm,tan");
  const SampledProfile p = read_profile_csv(dir / "eps.csv");
  ASSERT_EQ(p.y_mm.size(), 541u);  // -70 … 65 at 0.25
  EXPECT_DOUBLE_EQ(p.y_mm.front(), -70.0);
  EXPECT_DOUBLE_EQ(p.y_mm.back(), 65.0);
  for (std::size_t i = 0; i < p.y_mm.size(); ++i) {
    EXPECT_NEAR(p.z_mm[i], w.at(p.y_mm[i]).z_mm, 6e-7);
  }

  const CommandResult prw =
      run("--family EPS --flange-height 32 --flange-thickness 29.5 --outer-slope 10 "
          "--width 135 --step 0.25 --format prw --output " +
          (dir / "eps.prw").string());
  ASSERT_EQ(prw.status, 0) << prw.out;
  const SimpackProfile s = read_simpack_profile(dir / "eps.prw");
  EXPECT_EQ(s.type, SimpackProfileType::kWheel);
  ASSERT_EQ(s.profile.y_mm.size(), 541u);
  for (std::size_t i = 0; i < s.profile.y_mm.size(); ++i) {
    EXPECT_NEAR(s.profile.z_mm[i], w.at(s.profile.y_mm[i]).z_mm, 1e-9);
  }
}

TEST(ProfileCommand, PlotWritesAPng) {
  const auto png = tmp_dir() / "s1002.png";
  std::filesystem::remove(png);
  const CommandResult r = run("--family S1002 --flange-thickness 30 --output " +
                              (tmp_dir() / "t.txt").string() + " --plot " + png.string());
  ASSERT_EQ(r.status, 0) << r.out;
  std::ifstream in(png, std::ios::binary);
  std::array<char, 8> magic{};
  in.read(magic.data(), magic.size());
  EXPECT_EQ(std::string(magic.data() + 1, 3), "PNG");
  EXPECT_GT(std::filesystem::file_size(png), 10000u);
}

TEST(ProfileCommand, BadInputFailsWithAMessage) {
  CommandResult r = run("--family P8");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("unknown wheel profile family 'P8'"), std::string::npos) << r.out;
  r = run("--family S1002 --flange-height 31");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("flange height must be 28, 30 or 32"), std::string::npos) << r.out;
  r = run("--family EPS --flange-thickness 30.2");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("Table D.1"), std::string::npos) << r.out;
  r = run("--format xml");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("--format must be table, csv or prw"), std::string::npos) << r.out;
  r = run("--slope-window nan");  // was taken (a slope of NaN everywhere with --input --plot)
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("--slope-window: 'nan'"), std::string::npos) << r.out;
}

TEST(ProfileCommand, InputFileConvertsBetweenFormats) {
  const auto dir = tmp_dir();
  const auto prr = ::tread::testing::test_data("rail/manchester_benchmark/MBench_UIC60_v3.prr");
  const SimpackProfile original = read_simpack_profile(prr);
  // SIMPACK rail → CSV → SIMPACK rail: the same points.
  CommandResult r =
      run("--input " + prr.string() + " --format csv --output " + (dir / "rail.csv").string());
  ASSERT_EQ(r.status, 0) << r.out;
  r = run("--input " + (dir / "rail.csv").string() + " --format prr --output " +
          (dir / "rail.prr").string());
  ASSERT_EQ(r.status, 0) << r.out;
  const SimpackProfile back = read_simpack_profile(dir / "rail.prr");
  EXPECT_EQ(back.type, SimpackProfileType::kRail);
  ASSERT_EQ(back.profile.y_mm.size(), original.profile.y_mm.size());
  for (std::size_t i = 0; i < back.profile.y_mm.size(); ++i) {
    EXPECT_NEAR(back.profile.y_mm[i], original.profile.y_mm[i], 1e-9);
    EXPECT_NEAR(back.profile.z_mm[i], original.profile.z_mm[i], 1e-9);
  }
  // A rail file is not written as a wheel; a missing file is refused by name.
  r = run("--input " + prr.string() + " --format prw");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("a rail profile cannot be written as --format prw"), std::string::npos)
      << r.out;
  r = run("--input " + (dir / "missing.prw").string() + " --format csv");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("missing.prw"), std::string::npos) << r.out;
}

TEST(ProfileCommand, InputInspectShowsTheFileAndItsMeasures) {
  const auto worn = ::tread::testing::test_data("profiles/worn_s1002_example.csv");
  const CommandResult r = run("--input " + worn.string());
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* field :
       {"format    csv", "role      wheel", "header    ", "points    701",
        "y         -70.000 ... 70.000 mm", "spacing   min 0.2  median 0.2  max 0.2 mm",
        "warnings  1:",
        "z at the taping line (y = 0) is -1.358 mm in the file: z referred to it (z = 0 there, "
        "where --r0 is the radius)",
        "taping_z             -1.358 mm  z(0) in the file", "Sh ", "Sd ", "qR ", "hollow_depth",
        "outer_slope", "nominal   S1002 h28 e31.5 1:15 w140"}) {
    EXPECT_NE(r.out.find(field), std::string::npos) << field << "\n" << r.out;
  }
  // A rail: top, gauge point and head width.
  const auto prr = ::tread::testing::test_data("rail/manchester_benchmark/MBench_UIC60_v3.prr");
  const CommandResult rail = run("--input " + prr.string());
  ASSERT_EQ(rail.status, 0) << rail.out;
  for (const char* field :
       {"format    simpack", "role      rail", "top_z", "gauge_point_y", "head_width"}) {
    EXPECT_NE(rail.out.find(field), std::string::npos) << field << "\n" << rail.out;
  }
  // A SIMPACK rail given as a wheel is refused by the reader, naming the file.
  const CommandResult wrong = run("--input " + prr.string() + " --role wheel");
  EXPECT_NE(wrong.status, 0);
  EXPECT_NE(wrong.out.find("MBench_UIC60_v3.prr"), std::string::npos) << wrong.out;
}

// Measuring, converting and plotting say what the reader changed (they said nothing: only the
// inspection listed it); an empty file and a directory are said as such ("file:0: fewer than 2
// points").
TEST(ProfileCommand, OtherModesSayTheReadersWarningsAndEmptyInputsAreNamed) {
  const auto worn = ::tread::testing::test_data("profiles/worn_s1002_example.csv");
  const CommandResult measured = run("--input " + worn.string() + " --measure --format csv");
  ASSERT_EQ(measured.status, 0) << measured.out;
  EXPECT_NE(measured.out.find("tread profile: warning: " + worn.string() +
                              ": z at the taping line (y = 0) is -1.358 mm in the file"),
            std::string::npos)
      << measured.out;
  EXPECT_NE(measured.out.find("taping_z,-1.35"), std::string::npos) << measured.out;
  const auto dir = tmp_dir();
  std::ofstream(dir / "empty.csv").close();
  const CommandResult empty = run("--input " + (dir / "empty.csv").string());
  EXPECT_NE(empty.status, 0);
  EXPECT_NE(empty.out.find("empty.csv: the file is empty"), std::string::npos) << empty.out;
}

// The header's fields as the summary lists them: each quoted short, at most 30 of them (a header
// line of 100 000 characters with control bytes in it was printed whole).
TEST(ProfileCommand, InputInspectQuotesAHeaderShortly) {
  const auto whl = ::tread::testing::test_data("profiles/s1002_measured.whl");
  std::ifstream in(whl, std::ios::binary);
  const std::string original((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
  std::string header = "Comment=" + std::string(100000, 'c') + "\x1b[2J\n";
  for (int i = 0; i < 40; ++i) header += "Note" + std::to_string(i) + "=n\n";
  const auto path = tmp_dir() / "long_header.whl";
  std::ofstream(path, std::ios::binary) << header << original;
  const CommandResult r = run("--input " + path.string());
  ASSERT_EQ(r.status, 0) << r.out.substr(0, 2000);
  EXPECT_NE(r.out.find("  Comment = " + std::string(80, 'c') + "… (100004 characters)\n"),
            std::string::npos)
      << r.out.substr(0, 2000);
  // 41 lines written, 6 in the file and 2 tread adds (the flange tip and back it found).
  EXPECT_NE(r.out.find("  … and 19 more\n"), std::string::npos) << r.out.substr(0, 2000);
  EXPECT_EQ(r.out.find('\x1b'), std::string::npos);
  EXPECT_LT(r.out.size(), 20000U);
}

// Options of the other mode were ignored: a file's reading options without --input printed the
// built-in S1002, a built-in wheel's shape with --input changed nothing.
TEST(ProfileCommand, OptionsOfTheOtherModeAreRefused) {
  const auto worn = ::tread::testing::test_data("profiles/worn_s1002_example.csv");
  for (const char* flag :
       {"--mirror-y", "--z-down", "--role rail", "--input-format csv", "--slope-window 3"}) {
    const CommandResult r = run(std::string(flag));
    EXPECT_NE(r.status, 0) << flag;
    EXPECT_NE(r.out.find("applies to --input only"), std::string::npos) << flag << r.out;
  }
  for (const char* flag : {"--family EPS", "--flange-height 32", "--step 1", "--no-chamfer"}) {
    const CommandResult r = run("--input " + worn.string() + " " + flag);
    EXPECT_NE(r.status, 0) << flag;
    EXPECT_NE(r.out.find("shapes a built-in wheel: not used with --input"), std::string::npos)
        << flag << r.out;
  }
}

/// quantity -> value from `--measure --format csv`.
std::map<std::string, double> measures_csv(const std::string& text) {
  std::map<std::string, double> out;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "quantity,value,unit");
  while (std::getline(in, line)) {
    const auto a = line.find(',');
    const auto b = line.find(',', a + 1);
    out[line.substr(0, a)] = std::stod(line.substr(a + 1, b - a - 1));
  }
  return out;
}

TEST(ProfileCommand, MeasureOfABuiltInProfileWrittenAndReadBack) {
  const auto dir = tmp_dir();
  // S1002 h28 e32.5 at 0.1 mm as CSV, then measured from the file: the analytic values.
  CommandResult r =
      run("--family S1002 --format csv --step 0.1 --output " + (dir / "s1002.csv").string());
  ASSERT_EQ(r.status, 0) << r.out;
  r = run("--input " + (dir / "s1002.csv").string() + " --measure --format csv");
  ASSERT_EQ(r.status, 0) << r.out;
  std::map<std::string, double> m = measures_csv(r.out);
  EXPECT_NEAR(m["Sh"], 28.0, 0.01);
  EXPECT_NEAR(m["Sd"], 32.5, 0.01);
  EXPECT_NEAR(m["qR"], 10.79, 0.01);
  EXPECT_NEAR(m["hollow_depth"], 0.0, 1e-6);
  EXPECT_NEAR(m["outer_slope"], 100.0 / 15.0, 1e-4);
  // Any outer slope in 6.7 … 15 %: written by the command, measured back.
  r = run("--family 1/40 --outer-slope 1:12 --format csv --step 0.1 --output " +
          (dir / "s12.csv").string());
  ASSERT_EQ(r.status, 0) << r.out;
  r = run("--input " + (dir / "s12.csv").string() + " --measure --format csv");
  ASSERT_EQ(r.status, 0) << r.out;
  m = measures_csv(r.out);
  EXPECT_NEAR(m["outer_slope"], 100.0 / 12.0, 1e-4);
  // A z-down, mirrored copy of the same file measures the same with --z-down --mirror-y.
  const SampledProfile p = read_profile_csv(dir / "s1002.csv");
  SampledProfile flipped;
  for (std::size_t i = p.y_mm.size(); i-- > 0;) {
    flipped.y_mm.push_back(-p.y_mm[i]);
    flipped.z_mm.push_back(-p.z_mm[i]);
  }
  {
    std::ofstream out(dir / "flipped.csv");
    write_profile_csv(out, flipped, {}, 9);
  }
  r = run("--input " + (dir / "flipped.csv").string() +
          " --z-down --mirror-y --measure --format csv");
  ASSERT_EQ(r.status, 0) << r.out;
  m = measures_csv(r.out);
  EXPECT_NEAR(m["Sd"], 32.5, 0.01);
  EXPECT_NEAR(m["Sh"], 28.0, 0.01);
}

TEST(ProfileCommand, InputPlotAgainstTheNominalWritesAPng) {
  const auto png = tmp_dir() / "worn.png";
  std::filesystem::remove(png);
  const auto worn = ::tread::testing::test_data("profiles/worn_s1002_example.csv");
  const CommandResult r = run("--input " + worn.string() + " --nominal S1002:e=32.5 --output " +
                              (tmp_dir() / "inspect.txt").string() + " --plot " + png.string());
  ASSERT_EQ(r.status, 0) << r.out;
  std::ifstream in(png, std::ios::binary);
  std::array<char, 8> magic{};
  in.read(magic.data(), magic.size());
  EXPECT_EQ(std::string(magic.data() + 1, 3), "PNG");
  EXPECT_GT(std::filesystem::file_size(png), 20000u);
  EXPECT_FALSE(std::filesystem::exists(tmp_dir() / "worn.plotdata.tsv"));
  std::ifstream text(tmp_dir() / "inspect.txt");
  std::stringstream all;
  all << text.rdbuf();
  EXPECT_NE(all.str().find("nominal   S1002 h28 e32.5 1:15 w140"), std::string::npos) << all.str();
}

TEST(ProfileCommand, OuterSlopeRangeAndBadInputOptions) {
  CommandResult r = run("--outer-slope 8.5 --format csv --step 1");
  EXPECT_EQ(r.status, 0) << r.out;
  r = run("--outer-slope 16");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("6.7 % to 15 %"), std::string::npos) << r.out;
  const auto worn = ::tread::testing::test_data("profiles/worn_s1002_example.csv");
  r = run("--input " + worn.string() + " --role tyre");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("--role must be auto, wheel or rail"), std::string::npos) << r.out;
  r = run("--input " + worn.string() + " --measure --format prw");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("--format with --measure must be table or csv"), std::string::npos) << r.out;
  r = run("--measure");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("--measure and --nominal need --input"), std::string::npos) << r.out;
  r = run("--input " + worn.string() + " --nominal S1002:slope=5 --plot " +
          (tmp_dir() / "x.png").string());
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("6.7 % to 15 %"), std::string::npos) << r.out;
  // A rail has no EN 13715 nominal: --nominal is refused, not ignored.
  const auto prr = ::tread::testing::test_data("rail/manchester_benchmark/MBench_UIC60_v3.prr");
  r = run("--input " + prr.string() + " --nominal S1002");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("was read as a rail"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace tread::profile
