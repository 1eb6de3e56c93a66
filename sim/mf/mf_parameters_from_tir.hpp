#pragma once
// .tir property file → tread::mf::MfParameters<double> (host side: allocates, throws).
//
// Every key of TREAD_MF_PARAMETER_LIST is looked up by name in any section (TNO key names are
// unique across the standard sections); a missing key takes MFeval's default (the Pacejka-book
// value) and is listed in `missing` / `warning`. FITTYP 6 and 21 select MF 5.2, 61 MF 6.1, 62
// MF 6.2; a file without FITTYP (Adams PAC2002) selects FitType::pac2002 (the MF 5.2 path with
// LGAX/LGAY/LGAZ) and says so in the warning. TYRESIDE 'RIGHT' (any case) sets TyreSide::right.

#include <filesystem>
#include <string>
#include <vector>

#include "mf/mf_parameters.hpp"
#include "tir/tir_file.hpp"

namespace tread::mf {

struct MfTirParameters {
  MfParameters<double> params;
  std::vector<std::string> missing;  ///< keys that took their default
  std::string warning;               ///< empty if nothing is worth saying
};

/// Throws tir::TirError (file:line) for a key whose value is not a number and for an unknown
/// FITTYP.
MfTirParameters mf_parameters_from_tir(const tir::TirFile& file);

/// read_tir() + mf_parameters_from_tir().
MfTirParameters load_mf_parameters(const std::filesystem::path& path);

}  // namespace tread::mf
