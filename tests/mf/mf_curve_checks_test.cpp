// tyre::curve_warnings (sim/tyre/mf_curve_checks.hpp): none for the MF 6.1 sample tyre; each kind of
// inverted curve reported once, for a tyre made inverted on purpose through the .tir API.
#include "tyre/mf_curve_checks.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "golden_path.hpp"
#include "tir/tir_file.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace {

std::vector<std::string> warnings_with(const char* section, const char* key, double value) {
  tread::tir::TirFile file =
      tread::tir::read_tir(tread::testing::tyre_file("MagicFormula61_Parameters.tir"));
  if (key != nullptr) file.set(section, key, value);
  const auto p = tread::tyre::mf_parameters_from_tir(file).params;
  return tread::tyre::curve_warnings(p, tread::mf::MfOptions{}, {2000.0, 4000.0, 6000.0}, 16.7);
}

std::string joined(const std::vector<std::string>& w) {
  std::string s;
  for (const auto& x : w) s += x + "\n";
  return s;
}

TEST(MfCurveChecks, SampleTyreHasNoWarnings) {
  const auto w = warnings_with(nullptr, nullptr, 0.0);
  EXPECT_TRUE(w.empty()) << joined(w);
}

TEST(MfCurveChecks, FxPeakThroughZeroBelowFzmax) {
  // μx = PDX1 + PDX2·dfz = 1.1632 - dfz: zero at Fz = 2.16 · FNOMIN = 14600 N < FZMAX = 18000 N.
  const auto w = warnings_with("LONGITUDINAL_COEFFICIENTS", "PDX2", -1.0);
  const std::string s = joined(w);
  EXPECT_NE(s.find("Fx peak changes sign below FZMAX"), std::string::npos) << s;
  EXPECT_EQ(s.find("cornering stiffness"), std::string::npos) << s;
}

TEST(MfCurveChecks, CorneringStiffnessOfTheWrongSign) {
  const auto w = warnings_with("LATERAL_COEFFICIENTS", "PKY1", 28.3155);
  const std::string s = joined(w);
  ASSERT_FALSE(w.empty());
  EXPECT_NE(s.find("Fy(alpha) has the wrong sign of cornering stiffness"), std::string::npos) << s;
  EXPECT_EQ(s.find("Fx peak"), std::string::npos) << s;
}

TEST(MfCurveChecks, FrictionRisingWithLoad) {
  const auto w = warnings_with("LATERAL_COEFFICIENTS", "PDY2", 0.5);
  const std::string s = joined(w);
  EXPECT_NE(s.find("muy rises with load"), std::string::npos) << s;
}

}  // namespace
