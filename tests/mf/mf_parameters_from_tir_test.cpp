// sim/tyre/mf_parameters_from_tir: .tir → MfParameters, missing keys listed, FITTYP and TYRESIDE.
#include "tyre/mf_parameters_from_tir.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"

namespace tread::mf {
namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

TEST(MfParametersFromTir, ReadsValuesAndListsMissingKeys) {
  const auto path = testing::tyre_file("MagicFormula61_Parameters.tir");
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const tyre::MfTirParameters r = tyre::load_mf_parameters(path);
  EXPECT_EQ(r.params.fit_type, FitType::mf61);
  EXPECT_EQ(r.params.tyre_side, TyreSide::right);
  EXPECT_DOUBLE_EQ(r.params.fnomin_n, 6752.0);
  EXPECT_DOUBLE_EQ(r.params.longvl_mps, 16.6);
  EXPECT_DOUBLE_EQ(r.params.cammax_rad, 0.105);
  // A complete MF 6.1 file: the MF 6.2-only and MF 5.2-only keys are not reported missing.
  EXPECT_TRUE(r.missing.empty()) << r.warning;
  EXPECT_TRUE(r.warning.empty()) << r.warning;
  EXPECT_EQ(r.model, "MF 6.1");
}

// From an audit with edited files, each read before without a word: a slip-angle range that
// excludes 0 (tir info's "pure slip" figures were taken at 28.6 degrees), a [UNITS] section that
// names the wrong unit (R0 = 0.39 mm), a key in two sections (the first silently won).
TEST(MfParametersFromTir, RangesWithoutZeroUnitsOffByFactorsAndKeysTwiceAreSaid) {
  std::ifstream in(testing::tyre_file("MagicFormula61_Parameters.tir"));
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string original = buffer.str();
  const auto edited = [&](const std::string& from, const std::string& to) {
    std::string text = original;
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    return tir::parse_tir(text, "e.tir");
  };
  try {
    (void)tyre::mf_parameters_from_tir(edited("ALPMIN", "ALPMIN = 0.5\nALPMIN_WAS"));
    ADD_FAILURE() << "ALPMIN = 0.5 accepted";
  } catch (const tir::TirError& e) {
    EXPECT_NE(std::string(e.what()).find("ALPMIN…ALPMAX = 0.5…"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("does not contain 0"), std::string::npos) << e.what();
  }
  const tyre::MfTirParameters mm = tyre::mf_parameters_from_tir(
      edited("LENGTH                   = 'meter'", "LENGTH                   = 'mm'"));
  EXPECT_NE(mm.warning.find("UNLOADED_RADIUS = 0.0003"), std::string::npos) << mm.warning;
  EXPECT_NE(mm.warning.find("is the [UNITS] section right?"), std::string::npos) << mm.warning;
  const tyre::MfTirParameters twice =
      tyre::mf_parameters_from_tir(edited("[DIMENSION]", "[DIMENSION]\nFNOMIN = 3000"));
  EXPECT_DOUBLE_EQ(twice.params.fnomin_n, 3000.0);
  EXPECT_NE(twice.warning.find("'FNOMIN' is also in [DIMENSION]"), std::string::npos)
      << twice.warning;
}

// From a second audit: values in the wrong unit or out of their range that changed outputs under
// status ok without a word: INFLPRES above PRESMAX (evaluated at PRESMAX), PRESMIN/PRESMAX in kPa
// in an SI file (every row at 400 Pa), a vertical or structural stiffness left in N/mm or N/m
// beside an mm file, a structural stiffness of 0 or below (σ = 0 or |K/C|), VXLOW in mm/s left at
// 1 (0.001 m/s).
TEST(MfParametersFromTir, PressuresStiffnessesAndVxlowNoTyreHasAreSaid) {
  std::ifstream in(testing::tyre_file("MagicFormula61_Parameters.tir"));
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string original = buffer.str();
  const auto warning_with = [&](const std::vector<std::pair<std::string, std::string>>& values) {
    std::string text = original;
    for (const auto& [key, value] : values) {
      const std::size_t at = text.find("\n" + key + " ");
      EXPECT_NE(at, std::string::npos) << key;
      const std::size_t eol = text.find('\n', at + 1);
      text.replace(at + 1, eol - at - 1, key + " = " + value);
    }
    return tyre::mf_parameters_from_tir(tir::parse_tir(text, "e.tir")).warning;
  };
  const auto expect_said = [](const std::string& warning, const std::string& what) {
    EXPECT_NE(warning.find(what), std::string::npos) << what << "\n" << warning;
  };
  expect_said(warning_with({{"INFLPRES", "500000"}}),
              "e.tir:32: INFLPRES = 5e+05 Pa lies outside PRESMIN…PRESMAX (2e+05…4e+05 Pa): "
              "without a pressure input the tyre is evaluated at 4e+05 Pa");
  const std::string kpa = warning_with({{"PRESMIN", "200"}, {"PRESMAX", "400"}});
  expect_said(kpa, "PRESMIN = 200 Pa in SI");
  expect_said(kpa, "PRESMAX = 400 Pa in SI");
  expect_said(warning_with({{"VERTICAL_STIFFNESS", "314931296.9"}}),
              "N/m in SI: a tyre's vertical stiffness lies within");
  expect_said(warning_with({{"LONGITUDINAL_STIFFNESS", "391.2"}}),
              "LONGITUDINAL_STIFFNESS = 391.2 N/m in SI");
  expect_said(warning_with({{"LATERAL_STIFFNESS", "0"}}),
              "LATERAL_STIFFNESS = 0: the relaxation lengths and the structural stiffnesses");
  expect_said(warning_with({{"LONGITUDINAL_STIFFNESS", "-391219"}}),
              "LONGITUDINAL_STIFFNESS = -391219:");
  expect_said(warning_with({{"VXLOW", "0.001"}}), "VXLOW = 0.001 m/s in SI");
  // The file as shipped: none of these.
  EXPECT_EQ(warning_with({{"VXLOW", "1"}}), "");
}

// A file evaluated by another generation's equations than its own (its FITTYP changed, or absent):
// the keys those equations do not read are said where their values are not what tread assumes
// (an MF 6.2 file under FITTYP 61 lost Q_FCY2, Q_CAM1-3 and Q_FYS1-3, Rl 4.5 % off, in silence);
// without FITTYP a PROPERTY_FILE_FORMAT naming MF 6.1 or 6.2 decides (it was PAC2002).
TEST(MfParametersFromTir, KeysTheEvaluatingGenerationDoesNotReadAreSaid) {
  const auto text_of = [](const char* name) {
    std::ifstream in(testing::tyre_file(name));
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
  };
  const auto with_fittyp = [](std::string text, const std::string& fittyp) {
    const std::size_t at = text.find("\nFITTYP ");
    EXPECT_NE(at, std::string::npos);
    const std::size_t eol = text.find('\n', at + 1);
    text.replace(at + 1, eol - at - 1, fittyp.empty() ? "" : "FITTYP = " + fittyp);
    return tyre::mf_parameters_from_tir(tir::parse_tir(text, "g.tir"));
  };
  const std::string mf62 = text_of("MagicFormula62_Parameters.tir");
  const tyre::MfTirParameters as61 = with_fittyp(mf62, "61");
  EXPECT_NE(as61.warning.find("g.tir: 7 keys of MF 6.2 with values of their own, which the MF 6.1 "
                              "equations the file is evaluated with do not read: Q_FCY2 (line "),
            std::string::npos)
      << as61.warning;
  const tyre::MfTirParameters as52 = with_fittyp(text_of("MagicFormula61_Parameters.tir"), "52");
  EXPECT_NE(as52.warning.find("keys of MF 6.1/6.2 with values of their own, which the MF 5.2 "
                              "equations the file is evaluated with do not read: PKY6"),
            std::string::npos)
      << as52.warning;
  // Its own FITTYP: nothing said.
  EXPECT_EQ(with_fittyp(mf62, "62").warning.find("do not read"), std::string::npos);
  // No FITTYP, PROPERTY_FILE_FORMAT 'MF62'.
  std::string named = mf62;
  const std::size_t format = named.find("PROPERTY_FILE_FORMAT");
  ASSERT_NE(format, std::string::npos);
  named.replace(format, named.find('\n', format) - format, "PROPERTY_FILE_FORMAT = 'MF62'");
  const tyre::MfTirParameters by_format = with_fittyp(named, "");
  EXPECT_EQ(by_format.params.fit_type, FitType::mf62);
  EXPECT_NE(by_format.warning.find("no FITTYP: evaluated as MF 6.2, which PROPERTY_FILE_FORMAT "
                                   "'MF62' names"),
            std::string::npos)
      << by_format.warning;
}

// TYRESIDE = 'Right ' (a fixed-width field) is RIGHT: it was evaluated as LEFT, with a warning.
TEST(MfParametersFromTir, TyreSideIsReadWithoutItsBlanks) {
  const tyre::MfTirParameters r = tyre::mf_parameters_from_tir(tir::parse_tir(
      "[MODEL]\nFITTYP = 61\nTYRESIDE = ' Right '\n[LATERAL_COEFFICIENTS]\nPCY1 = 1.3\n", "s.tir"));
  EXPECT_EQ(r.params.tyre_side, TyreSide::right);
  EXPECT_EQ(r.warning.find("TYRESIDE"), std::string::npos) << r.warning;
}

TEST(MfParametersFromTir, CompleteMf62FileReportsNoMissingKeys) {
  const tyre::MfTirParameters r =
      tyre::load_mf_parameters(testing::tyre_file("MagicFormula62_Parameters.tir"));
  EXPECT_EQ(r.params.fit_type, FitType::mf62);
  EXPECT_TRUE(r.missing.empty()) << r.warning;
  EXPECT_TRUE(r.warning.empty()) << r.warning;
}

TEST(MfParametersFromTir, MissingKeysAreThoseOfTheFilesOwnModel) {
  const tir::TirFile f = tir::parse_tir(
      "[MODEL]\nFITTYP = 61\n[VERTICAL]\nFNOMIN = 4000\n[LATERAL_COEFFICIENTS]\nPCY1 = 1.3\n",
      "m.tir");
  const tyre::MfTirParameters r = tyre::mf_parameters_from_tir(f);
  EXPECT_TRUE(contains(r.missing, "PKY4"));     // MF 6.1 key
  EXPECT_FALSE(contains(r.missing, "Q_CAM1"));  // MF 6.2 only
  EXPECT_FALSE(contains(r.missing, "PTX1"));    // MF 5.2 only
  EXPECT_FALSE(contains(r.missing, "Q_A1"));    // optional
  EXPECT_FALSE(contains(r.missing, "PCY1"));
}

TEST(MfParametersFromTir, Mf52FileTakesDefaults) {
  const tyre::MfTirParameters r =
      tyre::load_mf_parameters(testing::tyre_file("MagicFormula52_Parameters.tir"));
  EXPECT_EQ(r.params.fit_type, FitType::mf52);
  EXPECT_EQ(r.params.tyre_side, TyreSide::left);  // no TYRESIDE
  EXPECT_FALSE(contains(r.missing, "NOMPRES"));   // not an MF 5.2 key
  EXPECT_DOUBLE_EQ(r.params.nompres_pa, 220000.0);
  EXPECT_DOUBLE_EQ(r.params.longitudinal_stiffness_npm, 300000.0);
  EXPECT_DOUBLE_EQ(r.params.pdy3, -7.088);
}

TEST(MfParametersFromTir, FileWithoutFittypIsPac2002WithWarning) {
  const tir::TirFile f = tir::parse_tir(
      "[MODEL]\nTYRESIDE = 'Right'\n[VERTICAL]\nFNOMIN = 5000\nPCX1 = 1.6\n", "x.tir");
  const tyre::MfTirParameters r = tyre::mf_parameters_from_tir(f);
  EXPECT_EQ(r.params.fit_type, FitType::pac2002);
  EXPECT_EQ(r.params.tyre_side, TyreSide::right);
  EXPECT_DOUBLE_EQ(r.params.fnomin_n, 5000.0);
  EXPECT_NE(r.warning.find("no FITTYP"), std::string::npos);
}

TEST(MfParametersFromTir, UnknownFittypNamesFileAndLine) {
  const tir::TirFile f = tir::parse_tir("[MODEL]\n\nFITTYP = 7\nPCX1 = 1\n", "truck.tir");
  try {
    static_cast<void>(tyre::mf_parameters_from_tir(f));
    FAIL() << "no error";
  } catch (const tir::TirError& e) {
    EXPECT_EQ(std::string(e.what()),
              "truck.tir:3: FITTYP 7 is not a known Magic Formula version (expected 5, 6, 21, 52, "
              "61 or 62)");
  }
}

std::filesystem::path variant(const std::string& name) {
  return std::filesystem::path(TREAD_SOURCE_DIR) / "tests/data/tir-variants" / name;
}

// Expects load_mf_parameters(file) to throw a TirError whose message is "<path>:<line>: <what>…".
void expect_refused(const std::string& name, int line, const std::string& what) {
  SCOPED_TRACE(name);
  const auto path = variant(name);
  try {
    (void)tyre::load_mf_parameters(path);
    ADD_FAILURE() << "no error";
  } catch (const tir::TirError& e) {
    const std::string prefix = path.string() + ":" + std::to_string(line) + ": " + what;
    EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0U) << e.what() << "\nexpected " << prefix;
  }
}

TEST(MfParametersFromTir, PacFilesAreSentToTreadPac) {
  expect_refused("pac89_header.tir", 13, "this is a PAC89 file: use tread pac eval");
  expect_refused("pac94_header.tir", 13, "this is a PAC94 file: use tread pac eval");
}

TEST(MfParametersFromTir, OtherTyreModelsAreNotMagicFormulaFiles) {
  expect_refused("harty_function_name.tir", 6,
                 "not a Magic Formula file: FUNCTION_NAME 'HTire501::harty_tyre' is a Harty");
  expect_refused("fiala.tir", 5,
                 "not a Magic Formula file: PROPERTY_FILE_FORMAT 'FIALA' is a Fiala");
  expect_refused("matlab_script.tir", 1, "not a Magic Formula file: not a tyre property file");
  expect_refused("no_mf_coefficients.tir", 3,
                 "not a Magic Formula file: FITTYP 61 but none of the Magic Formula coefficients");
}

TEST(MfParametersFromTir, Mf50IsEvaluatedOnThePac2002PathWithItsDifferencesSaid) {
  const tyre::MfTirParameters r = tyre::load_mf_parameters(variant("mf05_fe_method.tir"));
  EXPECT_EQ(r.params.fit_type, FitType::pac2002);
  EXPECT_EQ(r.model, "MF-Tyre 5.0");
  EXPECT_NE(r.warning.find("FITTYP 5 (MF-Tyre 5.0)"), std::string::npos) << r.warning;
  EXPECT_NE(r.warning.find("FE_METHOD = 'YES'"), std::string::npos) << r.warning;
  EXPECT_DOUBLE_EQ(r.params.fnomin_n, 25990.0);
  const tyre::MfTirParameters feda =
      tyre::load_mf_parameters(testing::tyre_file("chrono_feda_335_65R22_5_G275MSA_60psi.tir"));
  EXPECT_EQ(feda.model, "MF-Tyre 5.0");
}

TEST(MfParametersFromTir, Fittyp52IsMf52) {
  const tir::TirFile f = tir::parse_tir("[MODEL]\nFITTYP = 52\n[L]\nPCX1 = 1.6\n", "f.tir");
  EXPECT_EQ(tyre::mf_parameters_from_tir(f).params.fit_type, FitType::mf52);
}

TEST(MfParametersFromTir, NompresOnlyIsEvaluatedAtNompres) {
  const tyre::MfTirParameters r = tyre::load_mf_parameters(variant("nompres_only.tir"));
  EXPECT_DOUBLE_EQ(r.params.nompres_pa, 80000.0);
  EXPECT_DOUBLE_EQ(r.params.inflpres_pa, 80000.0);
  EXPECT_NE(r.warning.find("no INFLPRES: evaluated at NOMPRES (80000 Pa)"), std::string::npos)
      << r.warning;
  const tir::TirFile infl_only =
      tir::parse_tir("[MODEL]\nFITTYP = 61\n[O]\nINFLPRES = 90000\nPCX1 = 1.6\n", "i.tir");
  const tyre::MfTirParameters i = tyre::mf_parameters_from_tir(infl_only);
  EXPECT_DOUBLE_EQ(i.params.nompres_pa, 90000.0);
  EXPECT_NE(i.warning.find("no NOMPRES"), std::string::npos) << i.warning;
  const tir::TirFile neither = tir::parse_tir("[MODEL]\nFITTYP = 62\n[O]\nPCX1 = 1.6\n", "n.tir");
  const tyre::MfTirParameters n = tyre::mf_parameters_from_tir(neither);
  EXPECT_DOUBLE_EQ(n.params.nompres_pa, n.params.inflpres_pa);
  EXPECT_NE(n.warning.find("no INFLPRES or NOMPRES"), std::string::npos) << n.warning;
}

TEST(MfParametersFromTir, FileWarningsAreForwarded) {
  const tir::TirFile f =
      tir::parse_tir("[MODEL]\nFITTYP = 61\nUSE_MODE =\n[O]\nPCX1 = 1.6\n", "w.tir");
  EXPECT_NE(tyre::mf_parameters_from_tir(f).warning.find("w.tir:3: 'USE_MODE' has no value"),
            std::string::npos);
}

// Defective parameters are errors naming the key and file:line, never NaN outputs later.
TEST(MfParametersFromTir, DefectiveParametersAreRefused) {
  expect_refused("defective_zero_vertical_stiffness.tir", 6, "VERTICAL_STIFFNESS = 0 must be > 0");
  expect_refused("defective_zero_reff.tir", 6, "BREFF, DREFF and FREFF are all 0");
  expect_refused("defective_zero_fnomin.tir", 5, "FNOMIN = 0 must be > 0");
  expect_refused("defective_fz_range.tir", 7, "FZMAX = 100 is not above FZMIN = 9000");
  const auto refused = [](const std::string& text) {
    try {
      (void)tyre::mf_parameters_from_tir(tir::parse_tir(text, "d.tir"));
    } catch (const tir::TirError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refused("[M]\nFITTYP = 61\nPCX1 = 1.6\nNOMPRES = -1\nINFLPRES = 1e5\n"),
            "d.tir:4: NOMPRES = -1 must be > 0 (the pressure terms divide by it)");
  EXPECT_EQ(refused("[M]\nFITTYP = 61\nPCX1 = 1.6\nPCY1 = 0\n"),
            "d.tir:4: PCY1 · LCY = 0: the Fy stiffness factor By = Ky/(Cy·Dy) divides by it");
  EXPECT_EQ(refused("[M]\nFITTYP = 6\nPCX1 = 1.6\nLONGVL = 0\n"),
            "d.tir:4: LONGVL = 0 must be > 0 (speeds are taken relative to it)");
  EXPECT_EQ(refused("[M]\nFITTYP = 6\nPCX1 = 1.6\nALPMIN = 0.5\nALPMAX = 0.5\n"),
            "d.tir:5: ALPMAX = 0.5 is not above ALPMIN = 0.5 (the range is empty)");
  // A range whose other end took its default: the line of the key the file has, and which one
  // is the default (a truck tyre with FZMIN above the book tyre's FZMAX and no FZMAX).
  EXPECT_EQ(refused("[M]\nFITTYP = 6\nPCX1 = 1.6\nFNOMIN = 20000\nFZMIN = 12000\n"),
            "d.tir:5: FZMAX = 10000 (absent: default) is not above FZMIN = 12000 (the range is "
            "empty)");
  // Q_RE0 = 0 (a public FSAE file) made Re negative and Rl 0 under `ok`.
  EXPECT_EQ(refused("[M]\nFITTYP = 6\nPCX1 = 1.6\nQ_RE0 = 0\n"),
            "d.tir:4: Q_RE0 = 0 must be > 0 (the free radius R0·Q_RE0 sets the rolling and "
            "loaded radii)");
  // A rolling-radius law deflecting the tyre by more than its radius at the nominal load.
  EXPECT_EQ(refused("[M]\nFITTYP = 61\nPCX1 = 1.6\nUNLOADED_RADIUS = 0.3\nFREFF = 300\n"),
            "d.tir:4: the effective rolling radius at FNOMIN, UNLOADED_RADIUS·Q_RE0 − "
            "(FNOMIN/VERTICAL_STIFFNESS)·(DREFF·atan(BREFF) + FREFF) = -5.707 m, is not above 0");
  // MF 5.2 has no pressure terms: a zero NOMPRES there is not an error.
  EXPECT_EQ(refused("[M]\nFITTYP = 6\nPCX1 = 1.6\nNOMPRES = 0\n"), "accepted");
  const tyre::MfTirParameters w = tyre::mf_parameters_from_tir(
      tir::parse_tir("[M]\nFITTYP = 6\nPCX1 = 1.6\nVXLOW = 0\nFNOMIN = 50\n", "w.tir"));
  EXPECT_NE(w.warning.find("w.tir:4: VXLOW = 0"), std::string::npos) << w.warning;
  EXPECT_NE(w.warning.find("w.tir:5: FNOMIN = 50 lies outside FZMIN"), std::string::npos)
      << w.warning;
}

TEST(MfParametersFromTir, NonNumericValueIsAnError) {
  const tir::TirFile f =
      tir::parse_tir("[MODEL]\nFITTYP = 61\n[VERTICAL]\nFNOMIN = 'heavy'\n", "b.tir");
  EXPECT_THROW(static_cast<void>(tyre::mf_parameters_from_tir(f)), tir::TirError);
}

}  // namespace
}  // namespace tread::mf

namespace tread::mf {
namespace {

// A file's nonzero coefficient that tread's model lacks is named with its line and the value the
// outputs are for; a neutral one, a transient-only one and a text value are not.
TEST(MfParametersFromTir, CoefficientsOutsideTheModelAreNamed) {
  const tir::TirFile f = tir::parse_tir(
      "[MODEL]\n"                  // 1
      "FITTYP = 61\n"              // 2
      "[VERTICAL]\n"               // 3
      "FNOMIN = 4000\n"            // 4
      "Q_FZ3 = 0.15\n"             // 5: camber on the vertical stiffness
      "Q_FZ1 = 9.9\n"              // 6: derived by tread, as by MFeval
      "BOTTOM_STIFF = 2e6\n"       // 7: bottoming, not steady state
      "[SCALING_COEFFICIENTS]\n"   // 8
      "LMUV = 0.2\n"               // 9: friction decay with slip speed
      "LGYR = 3\n"                 // 10: gyroscopic (transient)
      "LXAL = 1\n"                 // 11: a known key
      "LNEW = 1\n"                 // 12: unknown but neutral
      "LOTHER = 0.5\n"             // 13: unknown, not neutral
      "[ALIGNING_COEFFICIENTS]\n"  // 14
      "QBZ1 = 10\n"                // 15
      "QBZ6 = 0\n"                 // 16: unknown, neutral
      "QBZ7 = -0.1\n"              // 17: unknown, not neutral
      "QNOTE = 'text'\n"           // 18: text
      "[LATERAL_COEFFICIENTS]\n"   // 19
      "PCY1 = 1.3\n"               // 20
      "[STRUCTURAL]\n"             // 21
      "PCMZ1 = 0.5\n",             // 22: structural: transient
      "u.tir");
  const tyre::MfTirParameters r = tyre::mf_parameters_from_tir(f);
  for (const char* expected :
       {"u.tir:5: Q_FZ3 = 0.15 is not in tread's MF 6.1 model (vertical stiffness change with "
        "camber): the outputs are those of Q_FZ3 = 0",
        "u.tir:9: LMUV = 0.2 is not in tread's MF 6.1 model (friction decay with slip speed): the "
        "outputs are those of LMUV = 0",
        "u.tir:13: LOTHER = 0.5 is not in tread's MF 6.1 model ([SCALING_COEFFICIENTS]: a key "
        "tread does not know): the outputs are those of LOTHER = 1",
        "u.tir:17: QBZ7 = -0.1 is not in tread's MF 6.1 model ([ALIGNING_COEFFICIENTS]: a key "
        "tread does not know): the outputs are those of QBZ7 = 0"}) {
    EXPECT_NE(r.warning.find(expected), std::string::npos) << expected << "\nin:\n" << r.warning;
  }
  for (const char* quiet : {"Q_FZ1", "BOTTOM_STIFF", "LGYR", "LXAL", "LNEW", "QBZ6", "QNOTE",
                            "PCMZ1", "QBZ1", "PCY1"}) {
    EXPECT_EQ(r.warning.find(std::string(quiet) + " = "), std::string::npos) << quiet;
  }
}

// The shipped files carry only neutral or transient-only extras: no such warning.
TEST(MfParametersFromTir, ShippedFilesHaveNoCoefficientsOutsideTheModel) {
  for (const char* name :
       {"MagicFormula52_Parameters.tir", "MagicFormula61_Parameters.tir",
        "MagicFormula62_Parameters.tir", "PacejkaBook_Defaults.tir", "reference_tire_tvd3.tir",
        "chrono_Sedan_Pac02Tire.tir", "chrono_VW_mf_185_80R14_PAC2002.tir",
        "chrono_feda_335_65R22_5_G275MSA_60psi.tir"}) {
    const tyre::MfTirParameters r = tyre::load_mf_parameters(testing::tyre_file(name));
    EXPECT_EQ(r.warning.find("is not in tread's"), std::string::npos) << name << ": " << r.warning;
  }
}

// A PROPERTY_FILE_FORMAT that names another generation than FITTYP: FITTYP decides, and says so.
TEST(MfParametersFromTir, FormatNamingAnotherVersionThanFittypIsSaid) {
  const tir::TirFile f = tir::parse_tir(
      "[MODEL]\nPROPERTY_FILE_FORMAT = 'PAC2002'\nFITTYP = 61\n[VERTICAL]\nFNOMIN = 4000\n"
      "[LATERAL_COEFFICIENTS]\nPCY1 = 1.3\n",
      "v.tir");
  const tyre::MfTirParameters r = tyre::mf_parameters_from_tir(f);
  EXPECT_EQ(r.params.fit_type, FitType::mf61);
  EXPECT_NE(r.warning.find("PROPERTY_FILE_FORMAT 'PAC2002' names MF 5.x / PAC2002 but FITTYP 61 "
                           "is MF 6.1: evaluated as MF 6.1 (FITTYP decides)"),
            std::string::npos)
      << r.warning;
  // The same generation: nothing said.
  const tyre::MfTirParameters same = tyre::mf_parameters_from_tir(tir::parse_tir(
      "[MODEL]\nPROPERTY_FILE_FORMAT = 'PAC2002'\nFITTYP = 6\n[VERTICAL]\nFNOMIN = 4000\n"
      "[LATERAL_COEFFICIENTS]\nPCY1 = 1.3\n",
      "w.tir"));
  EXPECT_EQ(same.warning.find("FITTYP decides"), std::string::npos) << same.warning;
}

}  // namespace
// MF 5.2 / PAC2002 files and pressure: the core applies MF 6.1's pressure terms where INFLPRES
// differs from NOMPRES (as MFeval), which is said; a NOMPRES of 0 (dpi = (p − 0)/0) switches them
// off instead of giving NaN outputs.
TEST(MfParametersFromTir, Mf52PressureIsSaid) {
  const tyre::MfTirParameters differs = tyre::mf_parameters_from_tir(tir::parse_tir(
      "[M]\nFITTYP = 6\nPCX1 = 1.6\nINFLPRES = 250000\nNOMPRES = 220000\nPPY1 = 0.5\n", "p.tir"));
  EXPECT_NE(differs.warning.find("p.tir:4: MF 5.2 has no pressure terms, but INFLPRES (250000 Pa) "
                                 "differs from NOMPRES (220000 Pa): evaluated with MF 6.1's "
                                 "pressure terms at INFLPRES, as MFeval does (the file's PPY1; "
                                 "MF 6.1's defaults for the rest)"),
            std::string::npos)
      << differs.warning;
  const tyre::MfTirParameters same = tyre::mf_parameters_from_tir(tir::parse_tir(
      "[M]\nFITTYP = 6\nPCX1 = 1.6\nINFLPRES = 220000\nNOMPRES = 220000\nPPY1 = 0.5\n", "s.tir"));
  EXPECT_EQ(same.warning.find("pressure terms"), std::string::npos) << same.warning;
  const tyre::MfTirParameters zero = tyre::mf_parameters_from_tir(
      tir::parse_tir("[M]\nFITTYP = 6\nPCX1 = 1.6\nNOMPRES = 0\n", "z.tir"));
  EXPECT_NE(zero.warning.find("z.tir:4: NOMPRES = 0, INFLPRES = 220000: MF 5.2 has no pressure "
                              "terms; evaluated without them"),
            std::string::npos)
      << zero.warning;
  EXPECT_EQ(zero.params.nompres_pa, zero.params.inflpres_pa);
  EXPECT_GT(zero.params.nompres_pa, 0.0);
  mf::MfInput<double> in;
  in.fz_n = 4000.0;
  in.alpha_rad = 0.05;
  in.vx_mps = 16.0;
  const mf::MfOutput<double> out = mf::evaluate(zero.params, in, mf::MfOptions{});
  EXPECT_TRUE(std::isfinite(out.fy_n));
  EXPECT_EQ(out.status, Status::ok);
}

}  // namespace tread::mf
