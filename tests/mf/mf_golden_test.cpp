// Golden tests of src/mf against MFeval 4.3.1 (../shared/refdata/mfeval): every output column both
// define, in double within 1e-9·max(|ref|, 1); in float within 2e-4 × the file's largest |force|
// (forces), largest |moment| (moments) or the column's largest |value| (other columns). Rows where
// MFeval is NaN/Inf are compared only for tread being finite. iKya_Nprad is ignored.
//
// Where MFeval's Fx or Fy is NaN (turn slip at Vx = 0), its rho/Rl/Cz are not compared either.
// Known, documented exception: for FITTYP ≠ 61 MFeval finds rho/Rl with fminsearch (TolX 1e-6), we
// solve exactly; rho_m and Rl_m are compared within 1e-8 m there and Cz_Npm within 1e-5 relative.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "csv_table.hpp"
#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "mf/mf_parameters_from_tir.hpp"
#include "mf_output_columns.hpp"

namespace tread::mf {
namespace {

using testing::CsvTable;
using testing::refdata;

struct Worst {
  double double_rel = 0.0;  // max |d| / max(|ref|, 1)
  double float_rel = 0.0;   // max |d| / scale (scale = largest |force|, |moment| or |column|)
  std::string double_column, float_column;
};

template <typename T>
MfInput<T> input_row(const CsvTable& table, std::size_t r) {
  MfInput<T> in;
  in.fz_n = static_cast<T>(table.at(r, "in_Fz_N"));
  in.kappa = static_cast<T>(table.at(r, "in_kappa_1"));
  in.alpha_rad = static_cast<T>(table.at(r, "in_alpha_rad"));
  in.gamma_rad = static_cast<T>(table.at(r, "in_gamma_rad"));
  in.phit_1pm = static_cast<T>(table.at(r, "in_phit_1pm"));
  in.vx_mps = static_cast<T>(table.at(r, "in_Vx_mps"));
  return in;
}

/// Compares every row of `table` (rows with useMode == mode, or all rows if the table has no
/// useMode column) and returns the worst errors. Fails the test for any violation.
Worst compare(const std::string& tir, const CsvTable& table, int mode) {
  const MfTirParameters loaded = load_mf_parameters(refdata("tir/" + tir));
  const MfParameters<double> pd = loaded.params;
  const MfParameters<float> pf = convert_parameters<float>(pd);
  const Result<MfOptions> options = options_from_use_mode(mode);
  EXPECT_TRUE(options.ok());
  const bool exact_rl = pd.fit_type == FitType::mf61;

  const int mode_column = table.column("useMode");
  std::vector<std::size_t> rows;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    if (mode_column < 0 ||
        static_cast<int>(table.rows[r][static_cast<std::size_t>(mode_column)]) == mode) {
      rows.push_back(r);
    }
  }
  EXPECT_FALSE(rows.empty());

  // Float scales over the rows compared.
  double max_force = 0.0;
  double max_moment = 0.0;
  std::map<std::string, double> max_column;
  for (const auto& column : testing::output_columns<double>()) {
    const std::string name(column.name);
    if (table.column(name) < 0) continue;
    for (std::size_t r : rows) {
      const double v = std::fabs(table.at(r, name));
      if (!std::isfinite(v)) continue;
      max_column[name] = std::max(max_column[name], v);
      if (column.kind == testing::ColumnKind::force) max_force = std::max(max_force, v);
      if (column.kind == testing::ColumnKind::moment) max_moment = std::max(max_moment, v);
    }
  }

  Worst worst;
  int compared = 0;
  for (std::size_t r : rows) {
    const MfOutput<double> od = evaluate(pd, input_row<double>(table, r), options.value);
    const MfOutput<float> of = evaluate(pf, input_row<float>(table, r), options.value);
    const auto columns_d = testing::output_columns<double>();
    const auto columns_f = testing::output_columns<float>();
    for (std::size_t c = 0; c < columns_d.size(); ++c) {
      const std::string name(columns_d[c].name);
      const double ours_d = od.*(columns_d[c].member);
      const double ours_f = static_cast<double>(of.*(columns_f[c].member));
      EXPECT_TRUE(std::isfinite(ours_d)) << tir << " mode " << mode << " row " << r << " " << name;
      EXPECT_TRUE(std::isfinite(ours_f)) << tir << " mode " << mode << " row " << r << " " << name;
      if (table.column(name) < 0) continue;
      const double ref = table.at(r, name);
      if (!std::isfinite(ref)) continue;
      // Where MFeval's Fx or Fy is NaN its rho/Rl/Cz are finite only because MATLAB's max()
      // drops the NaN: not a value to compare with.
      const bool forces_finite =
          std::isfinite(table.at(r, "Fx_N")) && std::isfinite(table.at(r, "Fy_N"));
      if (!forces_finite && (name == "rho_m" || name == "Rl_m" || name == "Cz_Npm")) continue;
      ++compared;
      // double
      double tol_rel = 1e-9;
      double scale_d = std::max(std::fabs(ref), 1.0);
      if (!exact_rl && (name == "rho_m" || name == "Rl_m")) tol_rel = 1e-8;
      if (!exact_rl && name == "Cz_Npm") tol_rel = 1e-5;
      const double rel_d = std::fabs(ours_d - ref) / scale_d;
      EXPECT_LE(rel_d, tol_rel) << tir << " mode " << mode << " row " << r << " " << name
                                << ": tread " << ours_d << " MFeval " << ref;
      if (tol_rel <= 1e-9 && rel_d > worst.double_rel) {
        worst.double_rel = rel_d;
        worst.double_column = name;
      }
      // float
      double scale_f = max_column[name];
      if (columns_d[c].kind == testing::ColumnKind::force) scale_f = max_force;
      if (columns_d[c].kind == testing::ColumnKind::moment) scale_f = max_moment;
      scale_f = std::max(scale_f, 1e-12);
      const double rel_f = std::fabs(ours_f - ref) / scale_f;
      EXPECT_LE(rel_f, 2e-4) << "float: " << tir << " mode " << mode << " row " << r << " " << name
                             << ": tread " << ours_f << " MFeval " << ref;
      if (rel_f > worst.float_rel) {
        worst.float_rel = rel_f;
        worst.float_column = name;
      }
    }
  }
  EXPECT_GT(compared, 0);
  std::printf("[ worst    ] %s mode %d: double %.3g (%s), float %.3g (%s)\n", tir.c_str(), mode,
              worst.double_rel, worst.double_column.c_str(), worst.float_rel,
              worst.float_column.c_str());
  return worst;
}

CsvTable load(const std::string& name) {
  const auto path = refdata("mfeval/" + name);
  EXPECT_TRUE(std::filesystem::exists(path)) << path << " is missing";
  return testing::read_csv(path.string());
}

TEST(MfGolden, Mf61Mode111Grid) {
  const CsvTable t = load("mfeval_MagicFormula61_Parameters_mode111.csv");
  ASSERT_EQ(t.rows.size(), 702u);
  compare("MagicFormula61_Parameters.tir", t, 111);
}

TEST(MfGolden, Mf61Mode121Grid) {
  const CsvTable t = load("mfeval_MagicFormula61_Parameters_mode121.csv");
  ASSERT_EQ(t.rows.size(), 702u);
  compare("MagicFormula61_Parameters.tir", t, 121);
}

TEST(MfGolden, Mf52Mode111Grid) {
  const CsvTable t = load("mfeval_MagicFormula52_Parameters_mode111.csv");
  ASSERT_EQ(t.rows.size(), 702u);
  compare("MagicFormula52_Parameters.tir", t, 111);
}

TEST(MfGolden, Mf61EdgeCases) {
  const CsvTable t = load("mfeval_edge_MagicFormula61_Parameters.csv");
  ASSERT_EQ(t.rows.size(), 92u);
  for (int mode : {121, 122, 221, 222}) compare("MagicFormula61_Parameters.tir", t, mode);
}

}  // namespace
}  // namespace tread::mf
