// End-to-end test of `tread mf eval` (sim/cli/mf_command.cpp): runs the built CLI on a CSV made
// from the inputs of MFeval's MF 6.1 mode-111 grid and checks its output against MFeval's values;
// bad input must fail with file:line and a non-zero exit status.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "csv_table.hpp"
#include "golden_path.hpp"
#include "test_dir.hpp"

namespace {

std::filesystem::path tmp_dir() {
  return tread::testing::test_dir("mf_command_test");
}

int run(const std::string& args, const std::filesystem::path& stderr_file) {
  const std::string command = std::string(TREAD_CLI) + " " + args + " 2> " + stderr_file.string();
  return std::system(command.c_str());
}

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(MfCommand, EvalMatchesMfevalGrid) {
  const auto ref_path =
      tread::testing::test_data("mfeval/mfeval_MagicFormula61_Parameters_mode111.csv");
  const auto tir = tread::testing::tyre_file("MagicFormula61_Parameters.tir");
  ASSERT_TRUE(std::filesystem::exists(ref_path)) << ref_path;
  const tread::testing::CsvTable ref = tread::testing::read_csv(ref_path.string());
  const auto dir = tmp_dir();
  const auto in_csv = dir / "in.csv";
  {
    std::ofstream in(in_csv);
    in.precision(17);
    // Columns in a different order than documented, and an explicit P_Pa = 0 (→ INFLPRES).
    in << "kappa,Fz_N,alpha_rad,gamma_rad,Vx_mps,P_Pa\n";
    for (std::size_t r = 0; r < ref.rows.size(); r += 7) {
      in << ref.at(r, "in_kappa_1") << ',' << ref.at(r, "in_Fz_N") << ','
         << ref.at(r, "in_alpha_rad") << ',' << ref.at(r, "in_gamma_rad") << ','
         << ref.at(r, "in_Vx_mps") << ",0\n";
    }
  }
  for (bool use_float : {false, true}) {
    const auto out_csv = dir / (use_float ? "out_float.csv" : "out.csv");
    const int status =
        run("mf eval --tir " + tir.string() + " --mode 111" + (use_float ? " --float" : "") +
                " --input " + in_csv.string() + " --output " + out_csv.string(),
            dir / "stderr.txt");
    ASSERT_EQ(status, 0) << slurp(dir / "stderr.txt");
    const tread::testing::CsvTable out = tread::testing::read_csv(out_csv.string());
    ASSERT_EQ(out.rows.size(), (ref.rows.size() + 6) / 7);
    for (const char* name : {"Fx_N", "Fy_N", "Fz_N", "Mx_Nm", "My_Nm", "Mz_Nm", "Rl_m", "Re_m"}) {
      ASSERT_GE(out.column(name), 0) << name;
    }
    ASSERT_GE(out.column("in_Fz_N"), 0);
    for (std::size_t i = 0; i < out.rows.size(); ++i) {
      const std::size_t r = i * 7;
      EXPECT_EQ(out.at(i, "in_Fz_N"), ref.at(r, "in_Fz_N"));
      for (const char* name : {"Fx_N", "Fy_N", "Fz_N", "Mx_Nm", "My_Nm", "Mz_Nm", "Rl_m", "Re_m"}) {
        const double expected = ref.at(r, name);
        const double tol = use_float
                               ? 2e-4 * (std::string(name).substr(0, 1) == "F" ? 6000.0 : 200.0)
                               : 1e-9 * std::max(std::fabs(expected), 1.0);
        EXPECT_NEAR(out.at(i, name), expected, tol)
            << name << " row " << r << " float " << use_float;
      }
    }
  }
}

TEST(MfCommand, BadInputNamesFileAndLine) {
  const auto tir = tread::testing::tyre_file("MagicFormula61_Parameters.tir");
  const auto dir = tmp_dir();
  const auto bad = dir / "bad.csv";
  {
    std::ofstream in(bad);
    in << "Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps\n4000,0,0,0,10\n4000,zero,0,0,10\n";
  }
  const int status = run("mf eval --tir " + tir.string() + " --input " + bad.string() +
                             " --output " + (dir / "bad_out.csv").string(),
                         dir / "bad_stderr.txt");
  EXPECT_NE(status, 0);
  const std::string err = slurp(dir / "bad_stderr.txt");
  EXPECT_NE(err.find("bad.csv:3"), std::string::npos) << err;
  EXPECT_NE(err.find("kappa"), std::string::npos) << err;

  const auto short_row = dir / "short.csv";
  {
    std::ofstream in(short_row);
    in << "Fz_N,kappa,alpha_rad,gamma_rad\n4000,0,0,0\n";
  }
  EXPECT_NE(run("mf eval --tir " + tir.string() + " --input " + short_row.string() + " --output " +
                    (dir / "short_out.csv").string(),
                dir / "short_stderr.txt"),
            0);
  EXPECT_NE(slurp(dir / "short_stderr.txt").find("short.csv:1: missing column 'Vx_mps'"),
            std::string::npos)
      << slurp(dir / "short_stderr.txt");

  EXPECT_NE(run("mf eval --tir " + tir.string() + " --mode 131 --input " + short_row.string() +
                    " --output " + (dir / "x.csv").string(),
                dir / "mode_stderr.txt"),
            0);
}

TEST(MfCommand, PlotWritesPngAndSvg) {
  const auto tir = tread::testing::tyre_file("MagicFormula52_Parameters.tir");
  const auto dir = tmp_dir();
  const auto png = dir / "curves.png";
  const auto svg = dir / "curves.svg";
  std::filesystem::remove(png);
  std::filesystem::remove(svg);
  ASSERT_EQ(run("mf plot --tir " + tir.string() + " --output " + png.string(), dir / "plot.txt"), 0)
      << slurp(dir / "plot.txt");
  const std::string png_bytes = slurp(png);
  ASSERT_GT(png_bytes.size(), 10000u);
  EXPECT_EQ(png_bytes.substr(1, 3), "PNG");
  const std::string svg_text = slurp(svg);
  EXPECT_NE(svg_text.find("<svg"), std::string::npos);
  EXPECT_NE(svg_text.find("Aligning moment"), std::string::npos);
  // Not a .png name: refused.
  EXPECT_NE(run("mf plot --tir " + tir.string() + " --output " + (dir / "x.jpg").string(),
                dir / "plot_bad.txt"),
            0);
}

}  // namespace
