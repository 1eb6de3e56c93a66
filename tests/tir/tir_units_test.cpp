// sim/tir/tir_units + tir_keys: [UNITS] read, dimensional keys converted to SI on read, SI values
// written back in the file's units, the SI rewrite, and the key table covering the MF list.
#include "tir/tir_units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>

#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "tir/tir_keys.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread::tir {
namespace {

std::filesystem::path variant(const std::string& name) {
  return std::filesystem::path(TREAD_SOURCE_DIR) / "tests/data/tir-variants" / name;
}

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void expect_rel(double a, double b, double tol, const std::string& what) {
  const double scale = std::max({std::fabs(a), std::fabs(b), 1e-6});
  EXPECT_LE(std::fabs(a - b) / scale, tol) << what << ": " << a << " vs " << b;
}

TEST(TirUnits, SpellingsAndFactors) {
  EXPECT_EQ(unit_factor(UnitQuantity::kLength, "MM"), 1e-3);
  EXPECT_EQ(unit_factor(UnitQuantity::kLength, "meter"), 1.0);
  EXPECT_EQ(unit_factor(UnitQuantity::kLength, "inch"), 0.0254);
  EXPECT_EQ(unit_factor(UnitQuantity::kForce, "knewton"), 1e3);
  EXPECT_EQ(unit_factor(UnitQuantity::kForce, "kN"), 1e3);
  EXPECT_DOUBLE_EQ(*unit_factor(UnitQuantity::kForce, "lbf"), 4.4482216152605);
  EXPECT_DOUBLE_EQ(*unit_factor(UnitQuantity::kAngle, "degree"), std::numbers::pi / 180.0);
  EXPECT_DOUBLE_EQ(*unit_factor(UnitQuantity::kMass, "slug"), 14.593902937206364);
  EXPECT_EQ(unit_factor(UnitQuantity::kTime, "millisecond"), 1e-3);
  EXPECT_EQ(unit_factor(UnitQuantity::kLength, "furlong"), std::nullopt);
  EXPECT_EQ(unit_factor(UnitQuantity::kForce, "mm"), std::nullopt);
  UnitSystem u;
  u.length_m = 1e-3;
  u.force_n = 1e3;
  EXPECT_DOUBLE_EQ(u.to_si(dim::kPressure), 1e9);
  EXPECT_DOUBLE_EQ(u.to_si(dim::kStiffness), 1e6);
  u.pressure_pa = 1e5;  // bar
  EXPECT_DOUBLE_EQ(u.to_si(dim::kPressure), 1e5);
  EXPECT_DOUBLE_EQ(u.to_si(dim::kStiffness), 1e6);
}

TEST(TirUnits, UnknownUnitNamesUnitKeyFileAndLine) {
  const TirFile f = parse_tir("[UNITS]\nLENGTH = 'mm'\nFORCE = 'stone'\n", "u.tir");
  try {
    (void)read_units(f);
    FAIL() << "no error";
  } catch (const TirError& e) {
    EXPECT_EQ(std::string(e.what()), "u.tir:3: unknown unit 'stone' for FORCE in [UNITS]");
  }
}

TEST(TirKeys, TableCoversEveryMfParameterOnce) {
#define TREAD_CHECK_KEY(member, section, key, value, description) \
  EXPECT_NE(find_key_info(key), nullptr) << key;
  TREAD_MF_PARAMETER_LIST(TREAD_CHECK_KEY)
#undef TREAD_CHECK_KEY
  const auto table = key_table();
  for (std::size_t i = 0; i < table.size(); ++i) {
    for (std::size_t j = i + 1; j < table.size(); ++j) {
      EXPECT_FALSE(iequals(table[i].key, table[j].key)) << table[i].key;
    }
  }
  EXPECT_EQ(find_key_info("fnomin")->dimension, dim::kForce);
  EXPECT_EQ(find_key_info("NOMPRES")->dimension, dim::kPressure);
  EXPECT_EQ(find_key_info("ALPMAX")->dimension, dim::kAngle);
  EXPECT_TRUE(find_key_info("PKY1")->dimension.is_none());
  EXPECT_TRUE(find_key_info("A1")->dimension.is_none());
}

// The same tyre in mm/kN/deg and in inch/lbf evaluates to the SI original's forces and moments.
TEST(TirUnits, NonSiFilesEvaluateLikeTheSiOriginal) {
  const auto si = tyre::load_mf_parameters(testing::tyre_file("MagicFormula61_Parameters.tir"));
  for (const char* name : {"mf61_mm_kN_deg.tir", "mf61_inch_lbf.tir"}) {
    SCOPED_TRACE(name);
    const auto other = tyre::load_mf_parameters(variant(name));
    expect_rel(other.params.unloaded_radius_m, si.params.unloaded_radius_m, 1e-12, "R0");
    expect_rel(other.params.nompres_pa, si.params.nompres_pa, 1e-12, "NOMPRES");
    expect_rel(other.params.cammax_rad, si.params.cammax_rad, 1e-12, "CAMMAX");
    expect_rel(other.params.vertical_stiffness_npm, si.params.vertical_stiffness_npm, 1e-12, "Cz");
    mf::MfOptions o;
    for (const double fz : {1500.0, 4000.0, 6752.0, 9000.0}) {
      for (const double kappa : {-0.3, 0.0, 0.05}) {
        for (const double alpha : {-0.2, 0.0, 0.08}) {
          mf::MfInput<double> in;
          in.fz_n = fz;
          in.kappa = kappa;
          in.alpha_rad = alpha;
          in.gamma_rad = 0.03;
          in.vx_mps = 20.0;
          const auto a = mf::evaluate(si.params, in, o);
          const auto b = mf::evaluate(other.params, in, o);
          const double tol = 1e-9;
          expect_rel(b.fx_n, a.fx_n, tol, "Fx");
          expect_rel(b.fy_n, a.fy_n, tol, "Fy");
          expect_rel(b.mx_nm, a.mx_nm, tol, "Mx");
          expect_rel(b.my_nm, a.my_nm, tol, "My");
          expect_rel(b.mz_nm, a.mz_nm, tol, "Mz");
          expect_rel(b.rl_m, a.rl_m, tol, "Rl");
          expect_rel(b.re_m, a.re_m, tol, "Re");
        }
      }
    }
  }
}

// MF 6.2's loaded-radius keys carry dimensions too: Q_FYS1…3 are forces (Sfyg, taken from Fy),
// Q_CAM2 is Q_CAM1 per length (Q_CAM1·Rl + Q_CAM2·Rl²). The SI sample written in mm and kN (every
// value through set_si) gives the same Rl, rho and forces, with camber and side slip.
TEST(TirUnits, Mf62InMillimetresAndKilonewtonsEvaluatesLikeSi) {
  const TirFile si = read_tir(testing::tyre_file("MagicFormula62_Parameters.tir"));
  TirFile f = si;
  f.set_text("UNITS", "LENGTH", "mm");
  f.set_text("UNITS", "FORCE", "kN");
  for (const auto& s : si.sections()) {
    if (iequals(s.name, "UNITS") || iequals(s.name, "MDI_HEADER")) continue;
    for (const Entry* e : s.entries()) {
      if (e->is_quoted()) continue;
      set_si(f, s.name, e->key, *si.number(s.name, e->key));
    }
  }
  const TirFile g = parse_tir(write_tir(f), "mf62_mm_kN.tir");
  EXPECT_DOUBLE_EQ(*g.number("VERTICAL", "Q_FYS1"), -20.4964);
  EXPECT_DOUBLE_EQ(*g.number("VERTICAL", "Q_CAM2"), 0.2574);
  const auto a = tyre::mf_parameters_from_tir(si).params;
  const auto b = tyre::mf_parameters_from_tir(g).params;
  mf::MfOptions o;
  for (const double fz : {2000.0, 4000.0, 6000.0}) {
    for (const double alpha : {-0.1, 0.0, 0.1}) {
      for (const double gamma : {-0.08, 0.0, 0.08}) {
        mf::MfInput<double> in;
        in.fz_n = fz;
        in.kappa = 0.02;
        in.alpha_rad = alpha;
        in.gamma_rad = gamma;
        in.vx_mps = 20.0;
        const auto x = mf::evaluate(a, in, o);
        const auto y = mf::evaluate(b, in, o);
        const double tol = 1e-9;
        expect_rel(y.fy_n, x.fy_n, tol, "Fy");
        expect_rel(y.mz_nm, x.mz_nm, tol, "Mz");
        expect_rel(y.rl_m, x.rl_m, tol, "Rl");
        expect_rel(y.rho_m, x.rho_m, tol, "rho");
      }
    }
  }
}

TEST(TirUnits, RoundTripKeepsTheFileUnitsAndSetSiConverts) {
  const auto path = variant("mf61_mm_kN_deg.tir");
  TirFile f = read_tir(path);
  EXPECT_EQ(write_tir(f), slurp(path));                       // unmodified: byte for byte
  set_si(f, "VERTICAL", "FNOMIN", 5000.0);                    // N → kN
  set_si(f, "DIMENSION", "UNLOADED_RADIUS", 0.3);             // m → mm
  set_si(f, "SLIP_ANGLE_RANGE", "ALPMAX", std::numbers::pi);  // rad → deg
  set_si(f, "SCALING_COEFFICIENTS", "LMUX", 0.9);             // dimensionless
  const TirFile g = parse_tir(write_tir(f), "g");
  EXPECT_EQ(g.number("VERTICAL", "FNOMIN"), 5.0);
  EXPECT_EQ(g.number("DIMENSION", "UNLOADED_RADIUS"), 300.0);
  EXPECT_DOUBLE_EQ(*g.number("SLIP_ANGLE_RANGE", "ALPMAX"), 180.0);
  EXPECT_EQ(g.number("SCALING_COEFFICIENTS", "LMUX"), 0.9);
  EXPECT_DOUBLE_EQ(*number_si(g, read_units(g), "", "FNOMIN"), 5000.0);
}

// convert_to_si: every dimensional value in SI, [UNITS] SI, the MF coefficients untouched.
TEST(TirUnits, ConvertToSiMatchesTheSiOriginal) {
  const TirFile si = read_tir(testing::tyre_file("MagicFormula61_Parameters.tir"));
  TirFile f = read_tir(variant("mf61_mm_kN_deg.tir"));
  const std::vector<std::string> unknown = convert_to_si(f);
  EXPECT_TRUE(unknown.empty()) << unknown.front();
  const TirFile g = parse_tir(write_tir(f), "g");
  EXPECT_EQ(g.text("UNITS", "LENGTH"), "meter");
  EXPECT_EQ(g.text("UNITS", "FORCE"), "newton");
  EXPECT_EQ(g.text("UNITS", "ANGLE"), "radians");
  EXPECT_TRUE(read_units(g).is_si());
  for (const auto& s : si.sections()) {
    if (iequals(s.name, "UNITS") || iequals(s.name, "MDI_HEADER")) continue;
    for (const Entry* e : s.entries()) {
      if (e->is_quoted()) continue;
      const auto want = si.number(s.name, e->key);
      const auto got = g.number(s.name, e->key);
      ASSERT_TRUE(got.has_value()) << e->key;
      expect_rel(*got, *want, 1e-12, e->key);
    }
  }
  // A second conversion changes nothing.
  const std::string once = write_tir(f);
  EXPECT_TRUE(convert_to_si(f).empty());
  EXPECT_EQ(write_tir(f), once);
}

TEST(TirUnits, ConvertToSiReportsKeysOfUnknownDimension) {
  TirFile f = parse_tir(
      "[UNITS]\nLENGTH = 'mm'\n[VERTICAL]\nFNOMIN = 4000\nMYSTERY = 2\n"
      "[DEFLECTION_LOAD_CURVE]\n{pen fz}\n 0 0\n 10 5000\n",
      "x.tir");
  const auto unknown = convert_to_si(f);
  ASSERT_EQ(unknown.size(), 1U);
  EXPECT_EQ(unknown.front(), "VERTICAL.MYSTERY");
  EXPECT_EQ(f.section("DEFLECTION_LOAD_CURVE")->table_rows().back(), " 0.01  5000");
}

}  // namespace
}  // namespace tread::tir
