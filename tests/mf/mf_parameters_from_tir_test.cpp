// sim/mf/mf_parameters_from_tir: .tir → MfParameters, missing keys listed, FITTYP and TYRESIDE.
#include "mf/mf_parameters_from_tir.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "golden_path.hpp"

namespace tread::mf {
namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

TEST(MfParametersFromTir, ReadsValuesAndListsMissingKeys) {
  const auto path = testing::tyre_file("MagicFormula61_Parameters.tir");
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const MfTirParameters r = load_mf_parameters(path);
  EXPECT_EQ(r.params.fit_type, FitType::mf61);
  EXPECT_EQ(r.params.tyre_side, TyreSide::right);
  EXPECT_DOUBLE_EQ(r.params.fnomin_n, 6752.0);
  EXPECT_DOUBLE_EQ(r.params.longvl_mps, 16.6);
  EXPECT_DOUBLE_EQ(r.params.cammax_rad, 0.105);
  EXPECT_TRUE(contains(r.missing, "Q_FCY2"));
  EXPECT_FALSE(contains(r.missing, "PCX1"));
  EXPECT_NE(r.warning.find("Q_FCY2"), std::string::npos);
}

TEST(MfParametersFromTir, Mf52FileTakesDefaults) {
  const MfTirParameters r = load_mf_parameters(testing::tyre_file("MagicFormula52_Parameters.tir"));
  EXPECT_EQ(r.params.fit_type, FitType::mf52);
  EXPECT_EQ(r.params.tyre_side, TyreSide::left);  // no TYRESIDE
  EXPECT_TRUE(contains(r.missing, "NOMPRES"));
  EXPECT_DOUBLE_EQ(r.params.nompres_pa, 220000.0);
  EXPECT_DOUBLE_EQ(r.params.longitudinal_stiffness_npm, 300000.0);
  EXPECT_DOUBLE_EQ(r.params.pdy3, -7.088);
}

TEST(MfParametersFromTir, FileWithoutFittypIsPac2002WithWarning) {
  const tir::TirFile f =
      tir::parse_tir("[MODEL]\nTYRESIDE = 'Right'\n[VERTICAL]\nFNOMIN = 5000\n", "x.tir");
  const MfTirParameters r = mf_parameters_from_tir(f);
  EXPECT_EQ(r.params.fit_type, FitType::pac2002);
  EXPECT_EQ(r.params.tyre_side, TyreSide::right);
  EXPECT_DOUBLE_EQ(r.params.fnomin_n, 5000.0);
  EXPECT_NE(r.warning.find("no FITTYP"), std::string::npos);
}

TEST(MfParametersFromTir, UnknownFittypNamesFileAndLine) {
  const tir::TirFile f = tir::parse_tir("[MODEL]\n\nFITTYP = 5\n", "truck.tir");
  try {
    static_cast<void>(mf_parameters_from_tir(f));
    FAIL() << "no error";
  } catch (const tir::TirError& e) {
    EXPECT_NE(std::string(e.what()).find("truck.tir:3"), std::string::npos) << e.what();
  }
}

TEST(MfParametersFromTir, NonNumericValueIsAnError) {
  const tir::TirFile f =
      tir::parse_tir("[MODEL]\nFITTYP = 61\n[VERTICAL]\nFNOMIN = 'heavy'\n", "b.tir");
  EXPECT_THROW(static_cast<void>(mf_parameters_from_tir(f)), tir::TirError);
}

}  // namespace
}  // namespace tread::mf
