#pragma once
// CSV evaluation of PAC89/PAC94 (host side: allocates, throws).
//
// Input: a header row, then one row per evaluation. Required columns (any order): Fz_N, kappa,
// alpha_rad, gamma_rad; other columns (e.g. Vx_mps of an MF input file) are ignored. Blank lines
// and lines starting with '#' are skipped. Errors (TirError, `file:line: message`): a missing or
// repeated required column, a row with the wrong number of cells, a required cell that is not a
// finite number.
// Output: in_Fz_N, in_kappa, in_alpha_rad, in_gamma_rad, Fx_N, Fy_N, Mz_Nm, Mx_Nm, My_Nm (17
// significant digits), in the coefficient set's axes or, with `iso_w`, converted by
// pac::to_iso_w(); then status (PacOutput::status as text: "ok", "out of range", "non-finite
// result" where an output came out NaN/inf and was written as 0).

#include <cstddef>
#include <iosfwd>
#include <string>

#include "pac/pac_params.hpp"
#include "tir/pac_plot.hpp"

namespace tread::tir {

struct PacCsvOptions {
  PacModel model = PacModel::kPac89;
  pac::Slip slip = pac::Slip::kCombined;
  bool use_float = false;  ///< evaluate in float (coefficients converted once)
  bool iso_w = false;
};

/// Returns the number of rows evaluated.
std::size_t evaluate_pac_csv(const pac::PacParams<double>& params, const PacCsvOptions& options,
                             std::istream& in, const std::string& in_name, std::ostream& out);

}  // namespace tread::tir
