// sim/tir/tir_model: model detection from PROPERTY_FILE_FORMAT and FITTYP; PAC loaders refuse MF
// files and files without PAC coefficients.
#include "tir/tir_model.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "golden_path.hpp"
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
  // No header at all: the coefficient names decide.
  EXPECT_EQ(detect("[LATERAL_COEFFICIENTS]\nA0 = 1.3\n").model, TirModel::kPac89);
  EXPECT_EQ(detect("[LATERAL_COEFFICIENTS]\nA0 = 1.3\nA17 = 0\n").model, TirModel::kPac94);
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

}  // namespace
}  // namespace tread::tir
