#pragma once
// Test helper: the float comparison of tread's Magic Formula against MFeval 4.3.1's tables
// (tests/data/mfeval), shared by mf_golden_test (scalar float) and mf_evaluate_four_test
// (four lanes): which rows and values are references, the float scales (the grid's largest |force|
// for forces, |moment| for moments, the column's largest |value| otherwise) and the check of one
// row's outputs within 2e-4 × scale.
//
// Where MFeval's Fx or Fy is NaN (turn slip at Vx = 0), its rho/Rl/Cz are not references: they are
// finite only because MATLAB's max() drops the NaN.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "csv_table.hpp"
#include "golden_path.hpp"
#include "mf/mf_types.hpp"
#include "mf_output_columns.hpp"

namespace tread::testing {

/// The float tolerance against MFeval, relative to the scale of the column.
inline constexpr double kGoldenFloatTolerance = 2e-4;

/// An MFeval table of tests/data/mfeval; a missing file fails the test.
inline CsvTable load_golden(const std::string& name) {
  const auto path = test_data("mfeval/" + name);
  EXPECT_TRUE(std::filesystem::exists(path)) << path << " is missing";
  return read_csv(path.string());
}

/// The inputs of row r.
template <typename T>
mf::MfInput<T> golden_input(const CsvTable& table, std::size_t r) {
  mf::MfInput<T> in;
  in.fz_n = static_cast<T>(table.at(r, "in_Fz_N"));
  in.kappa = static_cast<T>(table.at(r, "in_kappa_1"));
  in.alpha_rad = static_cast<T>(table.at(r, "in_alpha_rad"));
  in.gamma_rad = static_cast<T>(table.at(r, "in_gamma_rad"));
  in.phit_1pm = static_cast<T>(table.at(r, "in_phit_1pm"));
  in.vx_mps = static_cast<T>(table.at(r, "in_Vx_mps"));
  return in;
}

/// The rows of one useMode (all rows if the table has no useMode column) and their float scales.
struct GoldenRows {
  std::vector<std::size_t> rows;
  double max_force = 0.0;
  double max_moment = 0.0;
  std::map<std::string, double> max_column;

  /// The float scale of a column (never below 1e-12).
  double float_scale(const OutputColumn<double>& column) const {
    double scale = 0.0;
    if (const auto it = max_column.find(std::string(column.name)); it != max_column.end()) {
      scale = it->second;
    }
    if (column.kind == ColumnKind::force) scale = max_force;
    if (column.kind == ColumnKind::moment) scale = max_moment;
    return std::max(scale, 1e-12);
  }
};

inline GoldenRows golden_rows(const CsvTable& table, int mode) {
  GoldenRows g;
  const int mode_column = table.column("useMode");
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    if (mode_column < 0 ||
        static_cast<int>(table.rows[r][static_cast<std::size_t>(mode_column)]) == mode) {
      g.rows.push_back(r);
    }
  }
  EXPECT_FALSE(g.rows.empty());
  for (const auto& column : output_columns<double>()) {
    const std::string name(column.name);
    if (table.column(name) < 0) continue;
    for (std::size_t r : g.rows) {
      const double v = std::fabs(table.at(r, name));
      if (!std::isfinite(v)) continue;
      g.max_column[name] = std::max(g.max_column[name], v);
      if (column.kind == ColumnKind::force) g.max_force = std::max(g.max_force, v);
      if (column.kind == ColumnKind::moment) g.max_moment = std::max(g.max_moment, v);
    }
  }
  return g;
}

/// Whether MFeval's value of column `name` in row r is a reference to compare with.
inline bool is_golden_reference(const CsvTable& table, std::size_t r, const std::string& name) {
  if (table.column(name) < 0) return false;
  if (!std::isfinite(table.at(r, name))) return false;
  const bool forces_finite =
      std::isfinite(table.at(r, "Fx_N")) && std::isfinite(table.at(r, "Fy_N"));
  return forces_finite || !(name == "rho_m" || name == "Rl_m" || name == "Cz_Npm");
}

struct GoldenFloatWorst {
  double relative = 0.0;  // max |d| / scale
  std::string column;
  int compared = 0;
};

/// Checks one row's float outputs: every column finite, and within 2e-4 × scale of MFeval where
/// MFeval gives a reference. `what` names the case in failure messages.
inline void check_golden_float_row(const std::string& what, const CsvTable& table,
                                   const GoldenRows& g, std::size_t r,
                                   const mf::MfOutput<float>& out, GoldenFloatWorst& worst) {
  const auto columns_d = output_columns<double>();
  const auto columns_f = output_columns<float>();
  for (std::size_t c = 0; c < columns_d.size(); ++c) {
    const std::string name(columns_d[c].name);
    const double ours = static_cast<double>(out.*(columns_f[c].member));
    EXPECT_TRUE(std::isfinite(ours)) << what << " row " << r << " " << name;
    if (!is_golden_reference(table, r, name)) continue;
    const double ref = table.at(r, name);
    ++worst.compared;
    const double rel = std::fabs(ours - ref) / g.float_scale(columns_d[c]);
    EXPECT_LE(rel, kGoldenFloatTolerance) << "float: " << what << " row " << r << " " << name
                                          << ": tread " << ours << " MFeval " << ref;
    if (rel > worst.relative) {
      worst.relative = rel;
      worst.column = name;
    }
  }
}

}  // namespace tread::testing
