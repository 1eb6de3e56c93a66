#pragma once
// Load-time checks of Magic Formula parameters read from a .tir (host side). Values that make the
// model's outputs NaN/Inf or meaningless are errors naming the key and file:line; doubtful ones
// are warnings.
//
// Errors: FNOMIN, UNLOADED_RADIUS, VERTICAL_STIFFNESS, LONGVL, LFZO ≤ 0; BREFF, DREFF and FREFF
// all 0 (no effective rolling radius law); PCX1·LCX or PCY1·LCY = 0 (B = K/(C·D) divides by it);
// a range whose maximum is not above its minimum (FZMIN/FZMAX, KPUMIN/KPUMAX, ALPMIN/ALPMAX,
// CAMMIN/CAMMAX, PRESMIN/PRESMAX); MF 6.x: NOMPRES or INFLPRES ≤ 0 (the pressure terms divide by
// NOMPRES); Q_RE0 ≤ 0, or an effective rolling radius ≤ 0 at FNOMIN. Warnings: VXLOW ≤ 0,
// WIDTH ≤ 0 (MF 6.x contact width), FNOMIN outside FZMIN…FZMAX.
#include <string>

#include "mf/mf_parameters.hpp"
#include "tir/tir_file.hpp"

namespace tread::tyre {

/// Throws tir::TirError for the first error; appends warnings (one per line, `file:line: …`) to
/// `warning`.
void check_mf_parameters(const mf::MfParameters<double>& p, const tir::TirFile& file,
                         std::string& warning);

}  // namespace tread::tyre
