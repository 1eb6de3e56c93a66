// PAC89 with the Chrono HMMWV coefficients (data/tyres/chrono_HMMWV_Pac89Tire.tir; tests/data/tyres
// for the JSON): values computed by hand from the seed's equations, plausibility of the curves, and
// the loaders (JSON, and .tir written from it and read back).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "golden_path.hpp"
#include "pac/pac89.hpp"
#include "pac/pac94.hpp"
#include "test_dir.hpp"
#include "tir/pac_coefficients.hpp"
#include "tir/tir_file.hpp"

namespace {

using tread::pac::pac89_eval;
using tread::pac::pac94_eval;
using tread::pac::PacInput;
using tread::pac::PacParams;
using tread::pac::Slip;

PacParams<double> hmmwv() {
  const auto path = tread::testing::test_data("tyres/chrono_HMMWV_Pac89Tire.json");
  EXPECT_TRUE(std::filesystem::exists(path)) << path << " is missing";
  return tread::tir::pac_from_chrono_json(path).params;
}

// Expected values: /usr/bin/python3, independent of this code base — the JSON is read with
// json.loads after stripping `//` comments, and seed eq. 21–49 are typed in directly:
//   def mf(B,C,D,E,x): return D*sin(C*atan(B*x - E*(B*x - atan(B*x))))
//   fx: C=b0, D=(b1 Fz+b2)Fz, BCD=(b3 Fz²+b4 Fz)exp(-b5 Fz), E=b6 Fz²+b7 Fz+b8, Sh=b9 Fz+b10
//   fy: C=a0, D=(a1 Fz+a2)Fz, BCD=a3 sin(2 atan(Fz/a4))(1-a5|γ|), E=a6 Fz+a7,
//       Sh=a8 γ+a9 Fz+a10, Sv=a11 Fz γ+a12 Fz+a13
//   mz: C=c0, D=c1 Fz²+c2 Fz, BCD=(c3 Fz²+c4 Fz)(1-c6|γ|)exp(-c5 Fz),
//       E=(c7 Fz²+c8 Fz+c9)(1-c10|γ|), Sh=c11 γ+c12 Fz+c13, Sv=(c14 Fz²+c15 Fz)γ+c16 Fz+c17
// with Fz in kN, κ in %, α and γ in degrees (math.degrees of the radian inputs below).
TEST(Pac89Hmmwv, HandComputedValues) {
  const auto p = hmmwv();
  struct Case {
    PacInput<double> in;
    double fx, fy, mz;
  };
  const Case cases[] = {
      {{4000.0, 0.05, 0.05, 0.0}, 3082.5208907314504, 1156.8393412428993, -20.69075274512079},
      {{2000.0, -0.10, -0.10, 0.02}, -1981.0384961928319, -1020.7007137177859, 9.862650890555223},
      {{6000.0, 0.30, 0.20, 0.0}, 4922.18461966646, 4275.702790688574, -32.9267617846748},
  };
  for (const auto& c : cases) {
    const auto o = pac89_eval(p, c.in, Slip::kPure);
    EXPECT_NEAR(o.fx_n, c.fx, 1e-9 * std::abs(c.fx));
    EXPECT_NEAR(o.fy_n, c.fy, 1e-9 * std::abs(c.fy));
    EXPECT_NEAR(o.mz_nm, c.mz, 1e-9 * std::abs(c.mz));
    // PAC94 with a PAC89 set whose shift terms are all 0 is the same model.
    const auto o94 = pac94_eval(p, c.in, Slip::kPure);
    EXPECT_NEAR(o94.fx_n, c.fx, 1e-9 * std::abs(c.fx));
    EXPECT_NEAR(o94.fy_n, c.fy, 1e-9 * std::abs(c.fy));
    EXPECT_NEAR(o94.mz_nm, c.mz, 1e-9 * std::abs(c.mz));
  }
}

TEST(Pac89Hmmwv, PlausibleCurves) {
  const auto p = hmmwv();
  for (const double fz : {2000.0, 4000.0, 6000.0, 10000.0}) {
    SCOPED_TRACE(fz);
    double fx_max = 0, fx_min = 0, fy_max = 0, mz_absmax = 0;
    for (double s = -1.0; s <= 1.0; s += 1e-3) {
      const auto k = pac89_eval(p, PacInput<double>{fz, s, 0.0, 0.0}, Slip::kPure);
      const auto a = pac89_eval(p, PacInput<double>{fz, 0.0, s * 0.5, 0.0}, Slip::kPure);
      fx_max = std::max(fx_max, k.fx_n);
      fx_min = std::min(fx_min, k.fx_n);
      fy_max = std::max(fy_max, a.fy_n);
      mz_absmax = std::max(mz_absmax, std::abs(a.mz_nm));
    }
    // Peak friction of a truck tyre on a μ = 0.8 road (the JSON's "Coefficient of Friction").
    EXPECT_GT(fx_max / fz, 0.6);
    EXPECT_LT(fx_max / fz, 1.3);
    EXPECT_NEAR(fx_min, -fx_max, 1e-9 * fx_max);  // no shifts: odd curve
    EXPECT_GT(fy_max / fz, 0.5);
    EXPECT_LT(fy_max / fz, 1.2);
    // Stiffnesses: positive, and per unit load within the usual ranges (CFκ/Fz 5…50,
    // CFα/Fz 3…30 per radian).
    const double h = 1e-6;
    const double cfk = (pac89_eval(p, PacInput<double>{fz, h, 0.0, 0.0}, Slip::kPure).fx_n -
                        pac89_eval(p, PacInput<double>{fz, -h, 0.0, 0.0}, Slip::kPure).fx_n) /
                       (2 * h);
    const auto lat_p = pac89_eval(p, PacInput<double>{fz, 0.0, h, 0.0}, Slip::kPure);
    const auto lat_m = pac89_eval(p, PacInput<double>{fz, 0.0, -h, 0.0}, Slip::kPure);
    const double cfa = (lat_p.fy_n - lat_m.fy_n) / (2 * h);
    EXPECT_GT(cfk / fz, 5.0);
    EXPECT_LT(cfk / fz, 50.0);
    EXPECT_GT(cfa / fz, 3.0);
    EXPECT_LT(cfa / fz, 30.0);
    // Aligning moment: pneumatic trail behind the contact centre, so Mz and Fy have opposite signs
    // at small slip angles (true in any axis system that flips Fy and Mz together), and a
    // pneumatic trail |Mz/Fy| between 0 and ~1/3 of the radius (0.464 m).
    const auto small = pac89_eval(p, PacInput<double>{fz, 0.0, 0.02, 0.0}, Slip::kPure);
    EXPECT_LT(small.mz_nm * small.fy_n, 0.0);
    EXPECT_LT(std::abs(small.mz_nm / small.fy_n), 0.464 / 3);
    EXPECT_GT(mz_absmax, 0.0);
  }
}

TEST(Pac89Hmmwv, CombinedSlipStaysInsideTheFrictionCircle) {
  const auto p = hmmwv();
  for (double k = -0.5; k <= 0.5; k += 0.05) {
    for (double a = -0.3; a <= 0.3; a += 0.05) {
      const auto c = pac89_eval(p, PacInput<double>{4000.0, k, a, 0.0}, Slip::kCombined);
      const double fx_peak = (p.b[1] * 4 + p.b[2]) * 4;  // D_x at 4 kN
      const double fy_peak = (p.a[1] * 4 + p.a[2]) * 4;  // D_y at 4 kN
      EXPECT_LE(std::hypot(c.fx_n / fx_peak, c.fy_n / fy_peak), std::sqrt(2.0) * (1 + 1e-12));
      EXPECT_LE(std::abs(c.fx_n), fx_peak * (1 + 1e-12));
      EXPECT_LE(std::abs(c.fy_n), fy_peak * (1 + 1e-12));
    }
  }
}

TEST(PacLoaders, ChronoJsonValues) {
  const auto path = tread::testing::test_data("tyres/chrono_HMMWV_Pac89Tire.json");
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const auto c = tread::tir::pac_from_chrono_json(path);
  // Values as printed in the file.
  EXPECT_EQ(c.params.a[0], 1.49975356208205);
  EXPECT_EQ(c.params.a[4], 48.857910109076);
  EXPECT_EQ(c.params.b[5], 0.0073134908964823);
  EXPECT_EQ(c.params.b[10], 0.0);
  EXPECT_EQ(c.params.c[0], 2.34);
  EXPECT_EQ(c.params.c[9], -1.3329);
  EXPECT_EQ(c.params.unloaded_radius_m, 0.464);
  EXPECT_EQ(c.params.lateral_stiffness_npm, 261065.0);
  EXPECT_EQ(c.params.rolling_resistance, 0.015);
  // A PAC89 set: the PAC94-only coefficients are reported missing.
  EXPECT_EQ(c.missing.size(), 4U + 3U + 3U);
  EXPECT_NE(std::find(c.missing.begin(), c.missing.end(), "Lateral Coefficients.a17"),
            c.missing.end());
  for (const std::string& w : c.warnings) {
    EXPECT_EQ(w.find("does not read"), std::string::npos) << w;
  }
}

// A coefficient key tread does not read is said, with the likely intended key where only its case
// differs ('A0' showed only as a0 among the missing values, its number unused).
TEST(PacLoaders, JsonKeysNotReadAreSaid) {
  const auto dir = tread::testing::test_dir("pac_json_keys");
  const auto path = dir / "keys.json";
  {
    std::ofstream(path) << R"({"Lateral Coefficients": {"A0": 1.5, "a1": -22, "a 2": 1, "a99": 0},
                               "Longitudinal Coefficients": {"b00": 1},
                               "Aligning Coefficients": {"c1": 2}})";
  }
  const auto c = tread::tir::pac_from_chrono_json(path);
  EXPECT_EQ(c.params.a[0], 0.0);
  EXPECT_EQ(c.params.a[1], -22.0);
  const std::vector<std::string> expected = {
      "\"Lateral Coefficients\" has a key tread does not read: 'A0' (keys are case-sensitive: "
      "'a0'?)",
      "\"Lateral Coefficients\" has a key tread does not read: 'a 2' (it reads a0 … a" +
          std::to_string(c.params.a.size() - 1) + ")",
      "\"Lateral Coefficients\" has a key tread does not read: 'a99' (it reads a0 … a" +
          std::to_string(c.params.a.size() - 1) + ")",
      "\"Longitudinal Coefficients\" has a key tread does not read: 'b00' (it reads b0 … b" +
          std::to_string(c.params.b.size() - 1) + ")"};
  std::vector<std::string> said;
  for (const std::string& w : c.warnings) {
    if (w.find("does not read") != std::string::npos) said.push_back(w);
  }
  EXPECT_EQ(said, expected);
}

// A [UNITS] section that names the wrong length unit: R0 = 0.46 mm gave Mx and My 1000 times too
// small without a word (the Magic Formula path said so already).
TEST(PacLoaders, ValuesNoTyreHasAreSaid) {
  const auto c = tread::tir::pac_from_tir(tread::tir::parse_tir(
      "[MDI_HEADER]\nPROPERTY_FILE_FORMAT = 'PAC89'\n[UNITS]\nLENGTH = 'mm'\n"
      "[DIMENSION]\nUNLOADED_RADIUS = 0.464\n[LATERAL_COEFFICIENTS]\nA0 = 1.5\nA1 = -22\n"
      "A2 = 1000\n[LONGITUDINAL_COEFFICIENTS]\nB0 = 1.6\nB2 = 1000\n"
      "[ALIGNING_COEFFICIENTS]\nC0 = 2.3\n",
      "mm.tir"));
  bool said = false;
  for (const std::string& w : c.warnings) {
    said = said || w.find("UNLOADED_RADIUS = 0.000464") != std::string::npos;
  }
  EXPECT_TRUE(said);
  const auto shipped = tread::tir::pac_from_tir(
      tread::tir::read_tir(tread::testing::tyre_file("chrono_HMMWV_Pac89Tire.tir")));
  for (const std::string& w : shipped.warnings) {
    EXPECT_EQ(w.find("in SI"), std::string::npos) << w;
  }
}

TEST(PacLoaders, TirRoundTripIsExact) {
  const auto p = hmmwv();
  tread::tir::TirFile f("hmmwv.tir");
  tread::tir::pac_to_tir(p, f);
  const auto back = tread::tir::pac_from_tir(tread::tir::parse_tir(tread::tir::write_tir(f), "w"));
  EXPECT_TRUE(back.missing.empty());
  EXPECT_EQ(back.params.a, p.a);
  EXPECT_EQ(back.params.b, p.b);
  EXPECT_EQ(back.params.c, p.c);
  EXPECT_EQ(back.params.unloaded_radius_m, p.unloaded_radius_m);
  EXPECT_EQ(back.params.lateral_stiffness_npm, p.lateral_stiffness_npm);
}

TEST(PacLoaders, TirKeysAreCaseInsensitiveAndErrorsNameTheLine) {
  const auto f = tread::tir::parse_tir(
      "[lateral_coefficients]\na0 = 1.3\nA3 = 1500\n[LONGITUDINAL_COEFFICIENTS]\nB0 = 'x'\n",
      "p.tir");
  try {
    (void)tread::tir::pac_from_tir(f);
    ADD_FAILURE();
  } catch (const tread::tir::TirError& e) {
    EXPECT_EQ(e.line(), 5);
  }
  const auto g = tread::tir::parse_tir(
      "[MODEL]\nTYRESIDE = 'Right'\n[lateral_coefficients]\na0 = 1.3\nA3 = 1500\n", "p.tir");
  const auto c = tread::tir::pac_from_tir(g);
  EXPECT_EQ(c.tyreside, "RIGHT");
  EXPECT_EQ(c.params.a[0], 1.3);
  EXPECT_EQ(c.params.a[3], 1500.0);
}

TEST(PacLoaders, JsonErrorsNameFileAndLine) {
  const auto dir = std::filesystem::temp_directory_path() / "tread_pac_loader_test";
  std::filesystem::create_directories(dir);
  const auto bad = dir / "bad.json";
  { std::ofstream(bad) << "{\n  \"Lateral Coefficients\": {\n    \"a0\": 1.5,,\n  }\n}\n"; }
  try {
    (void)tread::tir::pac_from_chrono_json(bad);
    ADD_FAILURE();
  } catch (const tread::tir::TirError& e) {
    EXPECT_EQ(e.line(), 3) << e.what();
  }
  const auto text = dir / "text.json";
  {
    std::ofstream(text) << R"({"Lateral Coefficients": {"a0": "x"}, "Longitudinal Coefficients": {},
                               "Aligning Coefficients": {}})";
  }
  EXPECT_THROW((void)tread::tir::pac_from_chrono_json(text), tread::tir::TirError);
}

}  // namespace
