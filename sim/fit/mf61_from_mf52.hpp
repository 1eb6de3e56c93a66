#pragma once
// Refitting a PAC2002 or MF 5.2 tyre as MF 6.1 (`tread fit --model mf61 --start PAC2002.tir`):
// the start set and the property file the fit is written into. Host side.
//
// The two models share most coefficients under the same keys. MF 6.1 does not read LGAX, LGAY,
// LGAZ (PAC2002's camber scalings), PHY3 (MF 5.2's camber shift of Fy), PTX1-3, PTY1-2, LSGKP,
// LSGAL (MF 5.2's relaxation lengths: MF 6.1 has carcass stiffnesses instead) and Q_A1, Q_A2 (MF
// 5.2's contact length); it adds the pressure terms (neutral at NOMPRES), PKY4-7 (PKY6, PKY7: the
// camber stiffness replacing PHY3) and the other MF 6.1 keys, which start at their book values.
// The camber stages of the fit then find PKY6/PKY7 and the rest from the data.

#include <string>
#include <vector>

#include "mf/mf_parameters.hpp"
#include "tir/tir_file.hpp"

namespace tread::fit {

/// .tir keys an MF 5.2 / PAC2002 file may hold that MF 6.1 does not read.
const std::vector<std::string>& mf52_only_keys();

/// `p` (FITTYP 6/21 or PAC2002) as an MF 6.1 start: fit_type mf61, every shared coefficient kept.
/// `notes` receives one line per MF 5.2 term with an effect that MF 6.1 cannot carry over (a
/// camber scaling other than 1, a PHY3 other than 0).
mf::MfParameters<double> mf61_start_from_mf52(const mf::MfParameters<double>& p,
                                              std::vector<std::string>& notes);

/// Rewrites `file` as an MF 6.1 property file holding `p`'s values for the keys it lacks:
/// FITTYP = 61, PROPERTY_FILE_FORMAT = 'USER' (as TNO's MF 6.1 sample file), the keys of
/// mf52_only_keys() removed, every MF 6.1 key the file does not have added in its section.
/// Returns the keys removed.
std::vector<std::string> rewrite_as_mf61(tir::TirFile& file, const mf::MfParameters<double>& p);

}  // namespace tread::fit
