#pragma once
// .tir property file → tread::mf::MfParameters<double> (host side: allocates, throws).
//
// The model comes from tir::detect_model() (PROPERTY_FILE_FORMAT and FITTYP, tir/tir_model.hpp):
// MF 5.2 (FITTYP 6/21/52), MF 6.1, MF 6.2, PAC2002 (no FITTYP) and MF-Tyre 5.0 (FITTYP 5, on the
// PAC2002 path); PAC89/PAC94 files are refused ("use tread pac eval"), as are other tyre models.
// Every key of TREAD_MF_PARAMETER_LIST is looked up by name in any section (TNO key names are
// unique across the standard sections) and converted to SI by the file's [UNITS]
// (tir/tir_units.hpp); a missing key takes MFeval's default (the Pacejka-book value). `missing`
// and the warning list only the missing keys of the file's own model (tir/tir_keys.hpp).
// Pressure (MF 6.x): a file with NOMPRES but no INFLPRES is evaluated at NOMPRES when no pressure
// input is given (and INFLPRES alone is also the nominal pressure); the warning says so.
// TYRESIDE 'RIGHT' (any case) sets TyreSide::right.

#include <filesystem>
#include <string>
#include <vector>

#include "mf/mf_parameters.hpp"
#include "tir/tir_file.hpp"

namespace tread::tyre {

struct MfTirParameters {
  mf::MfParameters<double> params;
  std::string model;                 ///< "MF 6.1", "PAC2002", "MF-Tyre 5.0", …
  std::vector<std::string> missing;  ///< keys of the file's model that took their default
  std::string warning;               ///< empty if nothing is worth saying
};

/// Throws tir::TirError (file:line) for a key whose value is not a number, an unknown FITTYP or
/// unit, a PAC89/PAC94 file and a file that is not a Magic Formula file.
MfTirParameters mf_parameters_from_tir(const tir::TirFile& file);

/// tir::read_tyre_property_file() + mf_parameters_from_tir().
MfTirParameters load_mf_parameters(const std::filesystem::path& path);

}  // namespace tread::tyre
