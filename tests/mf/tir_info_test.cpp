// sim/tyre/tir_info: the `tread tir info` report.
#include "tyre/tir_info.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "golden_path.hpp"
#include "tir/tir_file.hpp"

namespace tread::mf {
namespace {

std::filesystem::path variant(const std::string& name) {
  return std::filesystem::path(TREAD_SOURCE_DIR) / "tests/data/tir-variants" / name;
}

void expect_has(const std::string& report, const std::string& text) {
  EXPECT_NE(report.find(text), std::string::npos) << "missing: " << text << "\nin:\n" << report;
}

TEST(TirInfo, Mf61Report) {
  const std::string r = tyre::tir_info_report(testing::tyre_file("MagicFormula61_Parameters.tir"));
  expect_has(r, "model: MF 6.1 (PROPERTY_FILE_FORMAT 'USER', FITTYP 61)");
  expect_has(r, "FNOMIN: 6752 N");
  expect_has(r, "pressure: NOMPRES 260000 Pa, INFLPRES 260000 Pa");
  expect_has(r, "warnings: none");
  expect_has(r, "defaulted keys (0):");
  expect_has(r, "peak μx: drive ");
  expect_has(r, "cornering stiffness Kyα: ");
  EXPECT_EQ(r.find("peak changes sign"), std::string::npos) << r;
}

TEST(TirInfo, UnitsAreShownAndConverted) {
  const std::string r = tyre::tir_info_report(variant("mf61_mm_kN_deg.tir"));
  expect_has(r, "units: LENGTH 'mm', FORCE 'kN', ANGLE 'deg'");
  expect_has(r, "(values below converted to SI)");
  expect_has(r, "FNOMIN: 6752 N, R0: 0.3943 m");
}

TEST(TirInfo, PeakSignChangeIsWarned) {
  const std::string r = tyre::tir_info_report(variant("fx_peak_sign_change.tir"));
  expect_has(r, "warning: Fx peak changes sign at Fz = 12000 N, below FZMAX = 20000 N");
  EXPECT_EQ(r.find("Fy peak changes sign"), std::string::npos) << r;  // at 44000 N
  expect_has(r, "defaulted keys (");
  EXPECT_EQ(r.find("keys missing"), std::string::npos) << r;  // listed once, above
}

TEST(TirInfo, PacAndOtherFiles) {
  const std::string r = tyre::tir_info_report(variant("pac94_header.tir"));
  expect_has(r, "model: PAC94 (PROPERTY_FILE_FORMAT 'PAC94', FITTYP -)");
  expect_has(r, "evaluate with: tread pac eval");
  EXPECT_THROW((void)tyre::tir_info_report(variant("fiala.tir")), tir::TirError);
}

}  // namespace
}  // namespace tread::mf
