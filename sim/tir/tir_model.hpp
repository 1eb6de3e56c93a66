#pragma once
// Which tyre model a .tir property file describes, from PROPERTY_FILE_FORMAT and FITTYP together
// (one table in tir_model.cpp). Host side; throws TirError with file:line.
//
//   PROPERTY_FILE_FORMAT         FITTYP        model
//   'PAC89' / 'PAC94'            (ignored)     PAC89 / PAC94 (tread pac …)
//   absent, 'USER', 'PAC2002',   6, 21, 52     MF 5.2 (52: read as "5.2", like 61/62)
//   'MF-TYRE', 'MF_05', 'MF5',   61 / 62       MF 6.1 / MF 6.2
//   'PAC-TIME', 'PAC_MC', 'TNO', 5            MF-Tyre 5.0 (see below)
//   'MF-SWIFT', 'SWIFT'          absent        Adams PAC2002 (MF 5.2 equations + LGAX/LGAY/LGAZ);
//                                              'MF_05'/'MF-05'/'MF5': MF-Tyre 5.0
//   any other text               FITTYP/absent as above, with a note naming the unknown format
//   'FIALA', 'UA', 'UATIRE', 'HARTY', 'FTIRE', 'CDTIRE', '5PT', …  → not a Magic Formula file
// A file without PROPERTY_FILE_FORMAT and FITTYP whose coefficients are A0…/B0…/C0… is PAC89
// (PAC94 if it has A14…A17, B11…B13 or C18…C20). FUNCTION_NAME naming another model (Harty
// 'HTIRE…', Fiala '…FIAL…') and a file without any Magic Formula coefficient are refused too.
//
// MF-Tyre 5.0 (FITTYP 5, e.g. Chrono's FED-alpha truck tyre, written by TNO's exporter with
// PROPERTY_FILE_FORMAT 'PAC2002'): MF-Tyre 5.0 (Pacejka & Besselink 1996) is the direct ancestor
// of MF 5.2 and its files use the same coefficient names with the same meaning for the pure-slip
// forces and moments, so tread evaluates it with the PAC2002 path (as Adams' PAC2002 and Chrono's
// Pac02 tyre read these files). Differences, said in the load warning: MF-Tyre 5.0's MFSAFE1-3
// large-slip safeguards are ignored, and with FE_METHOD = 'YES' MF-Tyre 5.0 combines slip with a
// friction ellipse, which tread does not implement: combined-slip outputs then use the MF 5.2
// weighting functions of the file's RBX/RBY… coefficients (pure-slip outputs are unaffected).
#include <string>

#include "tir/tir_file.hpp"
#include "tir/tir_keys.hpp"

namespace tread::tir {

enum class TirModel { kMf50, kMf52, kPac2002, kMf61, kMf62, kPac89, kPac94 };

struct DetectedModel {
  TirModel model = TirModel::kMf61;
  std::string name;   ///< "MF 6.1", "PAC94", … for messages
  ModelSet keys = 0;  ///< the key_table() models whose keys this file should carry
  std::string note;   ///< what the user should know about how it is evaluated, or empty
  bool is_magic_formula() const noexcept {
    return model != TirModel::kPac89 && model != TirModel::kPac94;
  }
};

/// The model of a parsed file. Throws TirError "not a Magic Formula file: <reason>" (line of the
/// key that says so) for other tyre models, and for an unknown FITTYP.
DetectedModel detect_model(const TirFile& file);

/// read_tir() for a file that should be a tyre property file: a file the parser cannot read and
/// that has no [MDI_HEADER]/[MODEL]/[UNITS] section (e.g. a MATLAB script named .tir) is refused
/// as "not a Magic Formula file: …" instead of with the first syntax error.
TirFile read_tyre_property_file(const std::filesystem::path& path);

}  // namespace tread::tir
