#pragma once
// Plausibility checks of a Magic Formula tyre's pure-slip curves (host side). Real .tir files do
// carry inverted curves (a load dependency that takes the peak through zero below FZMAX, a
// cornering stiffness of the wrong sign); `tread mf plot` prints these warnings on stderr.
//
// Checked at `loads_n` and at 41 loads from max(FZMIN, FNOMIN/10) to FZMAX (2·FNOMIN when FZMAX
// lies below that), γ = 0, at `vx_mps`, in ISO-W axes (options as given, e.g. limit checks):
//  - Fx(κ): slip stiffness dFx/dκ at κ = 0 and the drive peak max Fx(0 < κ ≤ 1) must be positive,
//    the brake peak min Fx(-1 ≤ κ < 0) negative;
//  - Fy(α): cornering stiffness dFy/dα at α = 0 must be negative (ISO-W: α > 0 gives Fy < 0);
//  - friction: μx and μy (peak |F| / Fz) above 3, or rising by more than 10 % from the lowest to
//    the highest load checked (tyres lose friction with load).
// One warning per kind, naming the first load where it happens.

#include <string>
#include <vector>

#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"

namespace tread::tyre {

std::vector<std::string> curve_warnings(const mf::MfParameters<double>& params,
                                        const mf::MfOptions& options,
                                        const std::vector<double>& loads_n, double vx_mps);

}  // namespace tread::tyre
