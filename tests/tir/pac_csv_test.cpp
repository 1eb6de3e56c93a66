// CSV evaluation of PAC89/PAC94: values equal direct calls (double, float, ISO-W), extra columns
// ignored, and input errors name file and line.
#include "tyre/pac_csv.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "pac/pac89.hpp"
#include "pac/pac94.hpp"
#include "tir/tir_file.hpp"

namespace {

using tread::pac::PacInput;
using tread::pac::PacParams;
using tread::pac::Slip;
using tread::tyre::PacCsvOptions;

PacParams<double> params() {
  PacParams<double> p;
  p.b = {1.6, 0, 1000, 0, 200, 0, 0, 0, 0.3, 0.01, 0.1, 0, 0, 0};
  p.a[0] = 1.3, p.a[2] = 900, p.a[3] = 1500, p.a[4] = 5, p.a[7] = -0.5, p.a[13] = 20;
  p.c[0] = 2.4, p.c[1] = -2, p.c[2] = 30, p.c[3] = -1, p.c[4] = -5, p.c[9] = -1;
  p.lateral_stiffness_npm = 2e5;
  p.rolling_resistance = 0.015;
  p.unloaded_radius_m = 0.4;
  return p;
}

std::vector<std::vector<double>> read_rows(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("# tread pac eval: ", 0), 0U) << line;
  std::getline(in, line);
  EXPECT_EQ(line, "in_Fz_N,in_kappa,in_alpha_rad,in_gamma_rad,Fx_N,Fy_N,Mz_Nm,Mx_Nm,My_Nm,status");
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> r;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) {
      const auto v = tread::tir::parse_number(cell);
      if (v) {
        r.push_back(*v);
      } else {
        EXPECT_EQ(cell, "ok");  // the status column
      }
    }
    rows.push_back(r);
  }
  return rows;
}

// Rows the status column marks are counted with the first one's line (pac eval says them on
// stderr, as mf eval does; they were only in the status column).
TEST(PacCsv, RowsOutOfRangeAreCountedWithTheirFirstLine) {
  const std::string input =
      "Fz_N,kappa,alpha_rad,gamma_rad\n4000,0.1,0,0\n4000,0.1,5,0\n"
      "200000,0,0,0\n";
  std::istringstream in(input);
  std::ostringstream out;
  tread::tyre::PacCsvTally tally;
  EXPECT_EQ(tread::tyre::evaluate_pac_csv(params(), {}, in, "in.csv", out, &tally), 3U);
  EXPECT_EQ(tally.out_of_range, 2U);
  EXPECT_EQ(tally.first_out_of_range_line, 3);
  EXPECT_EQ(tally.other, 0U);
}

// Columns `mf eval` reads that PAC89/PAC94 have no terms for (the same forces at 16, -16 and 0 m/s
// were written without a word) are listed for a warning; the table's own inputs are not.
TEST(PacCsv, ColumnsThePacModelsDoNotReadAreListed) {
  std::istringstream in("Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps,P_kPa\n4000,0.1,0,0,16,220\n");
  std::ostringstream out;
  tread::tyre::PacCsvTally tally;
  EXPECT_EQ(tread::tyre::evaluate_pac_csv(params(), {}, in, "in.csv", out, &tally), 1U);
  EXPECT_EQ(tally.unused_columns, (std::vector<std::string>{"Vx_mps", "P_kPa"}));
  std::istringstream plain("Fz_N,kappa,alpha_rad,gamma_rad\n4000,0.1,0,0\n");
  tread::tyre::PacCsvTally none;
  (void)tread::tyre::evaluate_pac_csv(params(), {}, plain, "in.csv", out, &none);
  EXPECT_TRUE(none.unused_columns.empty());
}

TEST(PacCsv, RowsEqualDirectEvaluation) {
  const std::string input =
      "# comment\nVx_mps,gamma_rad,alpha_rad,kappa,Fz_N\n16.7,0.01,0.05,0.1,4000\n\n"
      "16.7,0,-0.2,-0.3,6000\n";
  for (const bool use_float : {false, true}) {
    for (const bool iso : {false, true}) {
      PacCsvOptions o;
      o.model = tread::tir::PacModel::kPac94;
      o.use_float = use_float;
      o.iso_w = iso;
      std::istringstream in(input);
      std::ostringstream out;
      EXPECT_EQ(tread::tyre::evaluate_pac_csv(params(), o, in, "in.csv", out), 2U);
      const auto rows = read_rows(out.str());
      ASSERT_EQ(rows.size(), 2U);
      const PacInput<double> ins[] = {{4000, 0.1, 0.05, 0.01}, {6000, -0.3, -0.2, 0}};
      for (std::size_t i = 0; i < 2; ++i) {
        auto d = tread::pac::pac94_eval(params(), ins[i], Slip::kCombined);
        if (iso) d = tread::pac::to_iso_w(d);
        const double tol = use_float ? 2e-4 * 6000 : 1e-12 * 6000;
        EXPECT_EQ(rows[i][0], ins[i].fz_n);
        EXPECT_NEAR(rows[i][4], d.fx_n, tol);
        EXPECT_NEAR(rows[i][5], d.fy_n, tol);
        EXPECT_NEAR(rows[i][6], d.mz_nm, tol);
        EXPECT_NEAR(rows[i][7], d.mx_nm, tol);
        EXPECT_NEAR(rows[i][8], d.my_nm, tol);
      }
    }
  }
}

void expect_error(const std::string& input, int line, const std::string& what) {
  std::istringstream in(input);
  std::ostringstream out;
  try {
    (void)tread::tyre::evaluate_pac_csv(params(), {}, in, "bad.csv", out);
    ADD_FAILURE() << input;
  } catch (const tread::tir::TirError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

TEST(PacCsv, ErrorsNameFileAndLine) {
  expect_error("Fz_N,kappa,alpha_rad\n1,2,3\n", 1, "missing column 'gamma_rad'");
  expect_error("Fz_N,kappa,alpha_rad,gamma_rad,kappa\n", 1, "'kappa' and 'kappa' both give kappa");
  expect_error("Fz_N,kappa,alpha_rad,gamma_rad,SA\n", 1, "'alpha_rad' and 'SA' both give");
  expect_error("Fz_N,kappa,alpha_rad,gamma_rad\n1,2,3,4\n1,2,3\n", 3, "expected 4 cells");
  expect_error("Fz_N,kappa,alpha_rad,gamma_rad\n1,x,3,4\n", 2, "kappa: 'x' is not a finite number");
  expect_error("Fz_N,kappa,alpha_rad,gamma_rad\n1,nan,3,4\n", 2, "not a finite number");
  expect_error("# only a comment\n", 1, "no header row");
}

// A defective coefficient set (Fx's peak D overflows to Inf, B = BCD / (C D) to 0, D sin(0) is
// NaN): never a NaN or Inf under status ok — either the row's status says so or the evaluation
// fails naming the row.
TEST(PacCsv, NoNonFiniteOutputUnderStatusOk) {
  PacParams<double> defective = params();
  defective.b[1] = 1e308;
  defective.b[2] = 1e308;
  std::istringstream in("Fz_N,kappa,alpha_rad,gamma_rad\n4000,0.05,0.05,0\n");
  std::ostringstream out;
  try {
    (void)tread::tyre::evaluate_pac_csv(defective, {}, in, "defective.csv", out);
  } catch (const tread::tir::TirError& e) {
    EXPECT_EQ(e.line(), 2) << e.what();
    EXPECT_NE(std::string(e.what()).find("non-finite output under status ok"), std::string::npos);
    return;
  }
  // The core writes a non-finite output as 0 and says so in the row's status.
  std::istringstream lines(out.str());
  std::string line;
  int rows = 0;
  while (std::getline(lines, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("in_", 0) == 0) continue;
    ++rows;
    EXPECT_EQ(line.find("nan"), std::string::npos) << line;
    EXPECT_EQ(line.find("inf"), std::string::npos) << line;
    EXPECT_EQ(line.substr(line.rfind(',') + 1), "non-finite result") << line;
  }
  EXPECT_EQ(rows, 1) << out.str();
}

}  // namespace
