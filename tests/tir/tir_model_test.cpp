// sim/tir/tir_model: model detection from PROPERTY_FILE_FORMAT and FITTYP; PAC loaders refuse MF
// files and files without PAC coefficients.
#include "tir/tir_model.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "golden_path.hpp"
#include "pac/pac89.hpp"
#include "test_dir.hpp"
#include "tir/pac_coefficients.hpp"

namespace tread::tir {
namespace {

std::filesystem::path variant(const std::string& name) {
  return std::filesystem::path(TREAD_SOURCE_DIR) / "tests/data/tir-variants" / name;
}

DetectedModel detect(const std::string& text) {
  return detect_model(parse_tir(text, "d.tir"));
}

std::string error_of(const std::string& text) {
  try {
    (void)detect(text);
  } catch (const TirError& e) {
    return e.what();
  }
  return "no error";
}

TEST(TirModel, FormatAndFittypTable) {
  EXPECT_EQ(detect("[M]\nFITTYP = 61\nPCX1 = 1\n").model, TirModel::kMf61);
  EXPECT_EQ(detect("[M]\nFITTYP = 62\nPCX1 = 1\n").model, TirModel::kMf62);
  EXPECT_EQ(detect("[M]\nFITTYP = 6\nPCX1 = 1\n").model, TirModel::kMf52);
  EXPECT_EQ(detect("[M]\nFITTYP = 21\nPCX1 = 1\n").model, TirModel::kMf52);
  EXPECT_EQ(detect("[M]\nFITTYP = 52\nPCX1 = 1\n").model, TirModel::kMf52);
  EXPECT_EQ(detect("[M]\nFITTYP = 5\nPCX1 = 1\n").model, TirModel::kMf50);
  EXPECT_EQ(detect("[M]\nPROPERTY_FILE_FORMAT = 'PAC2002'\nPCX1 = 1\n").model, TirModel::kPac2002);
  EXPECT_EQ(detect("[M]\nPROPERTY_FILE_FORMAT = 'MF_05'\nFITTYP = 5\nPCX1 = 1\n").model,
            TirModel::kMf50);
  EXPECT_EQ(detect("[M]\nPROPERTY_FILE_FORMAT = 'pac94'\n").model, TirModel::kPac94);
  EXPECT_EQ(detect("[M]\nPROPERTY_FILE_FORMAT = 'PAC89'\nFITTYP = 61\n").model, TirModel::kPac89);
  // No header at all: the coefficients decide, a PAC94-only one by being nonzero.
  EXPECT_EQ(detect("[LATERAL_COEFFICIENTS]\nA0 = 1.3\n").model, TirModel::kPac89);
  EXPECT_EQ(detect("[LATERAL_COEFFICIENTS]\nA0 = 1.3\nA17 = 0\n").model, TirModel::kPac89);
  EXPECT_EQ(detect("[LATERAL_COEFFICIENTS]\nA0 = 1.3\nA17 = 0.2\n").model, TirModel::kPac94);
  const DetectedModel odd = detect("[M]\nPROPERTY_FILE_FORMAT = 'ACME'\nFITTYP = 61\nPCX1 = 1\n");
  EXPECT_EQ(odd.model, TirModel::kMf61);
  EXPECT_NE(odd.note.find("unknown PROPERTY_FILE_FORMAT 'ACME'"), std::string::npos);
  // An unknown format without FITTYP but with MF coefficients: PAC2002, and the note says why.
  const DetectedModel acme = detect("[M]\nPROPERTY_FILE_FORMAT = 'ACME'\nPCX1 = 1\n");
  EXPECT_EQ(acme.model, TirModel::kPac2002);
  EXPECT_EQ(acme.note,
            "unknown PROPERTY_FILE_FORMAT 'ACME' and no FITTYP: evaluated as Adams PAC2002 (MF 5.2 "
            "equations with LGAX/LGAY/LGAZ)");
  // MF_05 without FITTYP (TTC-style MF-Tyre 5.0 files) is MF-Tyre 5.0.
  const DetectedModel mf05 =
      detect("[M]\nPROPERTY_FILE_FORMAT = 'MF_05'\nFE_METHOD = 'yes'\nPCX1 = 1\n");
  EXPECT_EQ(mf05.model, TirModel::kMf50);
  EXPECT_NE(mf05.note.find("'MF_05' without FITTYP (MF-Tyre 5.0)"), std::string::npos);
  EXPECT_NE(mf05.note.find("friction-ellipse"), std::string::npos);
}

TEST(TirModel, OtherModelsAreRefusedWithTheReason) {
  EXPECT_EQ(error_of("[M]\n\nPROPERTY_FILE_FORMAT = 'UA'\n"),
            "d.tir:3: not a Magic Formula file: PROPERTY_FILE_FORMAT 'UA' is a UA (University of "
            "Arizona) tyre model");
  EXPECT_EQ(error_of("[M]\nFUNCTION_NAME = 'TFIALA'\nFITTYP = 61\nPCX1 = 1\n"),
            "d.tir:2: not a Magic Formula file: FUNCTION_NAME 'TFIALA' is a Fiala tyre model");

  EXPECT_EQ(error_of("[M]\nWIDTH = 0.2\n"),
            "d.tir:0: not a Magic Formula file: no FITTYP and none of the Magic Formula "
            "coefficients (PCX1, PDY1, PKY1, QBZ1, …)");
}

// Without PROPERTY_FILE_FORMAT, PAC94's own coefficients decide: listed but all 0 (as the PAC89
// files Adams writes list them), the file is PAC89, whose A8…A13 PAC94 would read otherwise.
TEST(TirModel, PacWithoutFormatIsPac94OnlyWithANonzeroPac94Coefficient) {
  std::string text = "[LATERAL_COEFFICIENTS]\n";
  for (int i = 0; i <= 17; ++i)
    text += "A" + std::to_string(i) + " = " + (i == 9 ? "0.1" : "0") + "\n";
  text += "[LONGITUDINAL_COEFFICIENTS]\nB0 = 1.5\n[ALIGNING_COEFFICIENTS]\nC0 = 2.3\n";
  const TirFile zeros = parse_tir(text, "z.tir");
  EXPECT_EQ(detect_model(zeros).model, TirModel::kPac89);
  EXPECT_NE(detect_model(zeros).note.find("read as PAC89 (PAC94's A14…A17"), std::string::npos);
  EXPECT_FALSE(pac_from_tir(zeros).pac94);
  std::string with94 = text;
  with94.replace(with94.find("A15 = 0"), 7, "A15 = 0.3");
  EXPECT_EQ(detect_model(parse_tir(with94, "n.tir")).model, TirModel::kPac94);
}

// The file's own limits: inputs beyond FZMAX, KPUMIN…KPUMAX, ALPMIN…ALPMAX, CAMMIN…CAMMAX are
// clamped (`out of range`), in its units; an asymmetric range takes its smaller side, said.
TEST(TirModel, PacFileLimitsAreApplied) {
  // No FZMAX: the core's default 100 kN, brought down to where a peak factor changes sign (this
  // is the HMMWV tyre's: D of Fx = Fz·(B1·Fz + B2) is 0 at 64.8 kN and negative above).
  const PacCoefficients none = pac_from_tir(read_tyre_property_file(variant("pac89_header.tir")));
  EXPECT_NEAR(none.params.fz_max_n, 64788.5, 0.1);
  ASSERT_EQ(none.warnings.size(), 2U);
  // And its Mz curvature passes 1 at high loads, where the core takes it as 1: said.
  EXPECT_NE(none.warnings[1].find("the curvature E of Mz (C7…C9) is above 1 from Fz = "),
            std::string::npos)
      << none.warnings[1];
  EXPECT_NE(none.warnings[0].find("the peak of Fx changes sign at Fz = 64788.5 N (B1, B2"),
            std::string::npos)
      << none.warnings[0];
  EXPECT_NE(none.warnings[0].find("(the file gives no FZMAX)"), std::string::npos);
  {
    TirFile high = read_tyre_property_file(variant("pac89_header.tir"));
    high.set("VERTICAL_FORCE_RANGE", "FZMAX", 150000.0);  // above the core's 100 kN: capped
    const PacCoefficients h = pac_from_tir(high);
    EXPECT_NEAR(h.params.fz_max_n, 64788.5, 0.1);
    ASSERT_FALSE(h.warnings.empty());
    EXPECT_EQ(h.warnings[0].find("gives no FZMAX"), std::string::npos) << h.warnings[0];
  }
  TirFile f = read_tyre_property_file(variant("pac89_header.tir"));
  f.set("VERTICAL_FORCE_RANGE", "FZMAX", 25000.0);
  f.set("LONG_SLIP_RANGE", "KPUMIN", -0.5);
  f.set("LONG_SLIP_RANGE", "KPUMAX", 0.4);
  f.set("SLIP_ANGLE_RANGE", "ALPMIN", -0.2);
  f.set("SLIP_ANGLE_RANGE", "ALPMAX", 0.2);
  const PacCoefficients p = pac_from_tir(f);
  EXPECT_DOUBLE_EQ(p.params.fz_max_n, 25000.0);
  EXPECT_DOUBLE_EQ(p.params.kappa_max, 0.4);
  EXPECT_DOUBLE_EQ(p.params.alpha_max_rad, 0.2);
  EXPECT_DOUBLE_EQ(p.params.gamma_max_rad, 0.5);  // not given: the default
  EXPECT_NE(p.note.find("KPUMIN…KPUMAX: PAC89/PAC94 limits are symmetric"), std::string::npos)
      << p.note;
  const auto status = [&](double fz, double kappa, double alpha) {
    return pac::pac89_eval(p.params, pac::PacInput<double>{fz, kappa, alpha, 0.0},
                           pac::Slip::kCombined)
        .status;
  };
  EXPECT_EQ(status(20000.0, 0.1, 0.1), Status::ok);
  EXPECT_EQ(status(30000.0, 0.1, 0.1), Status::out_of_range);
  EXPECT_EQ(status(20000.0, 0.8, 0.1), Status::out_of_range);
  EXPECT_EQ(status(20000.0, 0.1, 0.5), Status::out_of_range);
}

TEST(TirModel, PacLoaderRoutesAndRefuses) {
  const PacCoefficients p94 = pac_from_tir(read_tyre_property_file(variant("pac94_header.tir")));
  EXPECT_TRUE(p94.pac94);
  EXPECT_DOUBLE_EQ(p94.params.a[0], 1.49975356208205);
  EXPECT_DOUBLE_EQ(p94.params.unloaded_radius_m, 0.464);
  const PacCoefficients p89 = pac_from_tir(read_tyre_property_file(variant("pac89_header.tir")));
  EXPECT_FALSE(p89.pac94);
  try {
    (void)pac_from_tir(read_tir(testing::tyre_file("MagicFormula61_Parameters.tir")));
    ADD_FAILURE() << "MF file accepted";
  } catch (const TirError& e) {
    EXPECT_NE(std::string(e.what()).find(":13: this is an MF 6.1 file, not PAC89/PAC94: use tread "
                                         "mf eval"),
              std::string::npos)
        << e.what();
  }
  try {
    (void)pac_from_tir(parse_tir("[MODEL]\nPROPERTY_FILE_FORMAT = 'PAC94'\n", "e.tir"));
    ADD_FAILURE() << "file without coefficients accepted";
  } catch (const TirError& e) {
    // The line of the PROPERTY_FILE_FORMAT that made it a PAC file.
    EXPECT_EQ(std::string(e.what()).rfind("e.tir:2: no PAC coefficients", 0), 0U) << e.what();
  }
}

// A Chrono JSON whose design value is written as a string, or whose number overflows double, is
// refused naming the file and key (the string was taken as missing: Mx = 0 under ok; the overflow
// gave nlohmann's message without the file).
TEST(TirModel, ChronoJsonValuesThatAreNotNumbersAreRefused) {
  std::ifstream in(tread::testing::test_data("tyres/chrono_HMMWV_Pac89Tire.json"));
  std::stringstream text;
  text << in.rdbuf();
  const std::string original = text.str();
  const auto dir = tread::testing::test_dir("tir_model_json");
  const auto error_of = [&](const std::string& from, const std::string& to) {
    std::string edited = original;
    const std::size_t at = edited.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    edited.replace(at, from.size(), to);
    const auto path = dir / "edited.json";
    std::ofstream(path) << edited;
    try {
      (void)pac_from_chrono_json(path);
    } catch (const TirError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(
      error_of("\"Unloaded Radius\": 0.464", "\"Unloaded Radius\": \"0.464\""),
      (dir / "edited.json").string() + ":0: Design Parameters.Unloaded Radius is not a number");
  EXPECT_NE(error_of("\"Unloaded Radius\": 0.464", "\"Unloaded Radius\": 1e999")
                .find((dir / "edited.json").string() + ":0: JSON: "),
            std::string::npos);
}

}  // namespace
}  // namespace tread::tir
