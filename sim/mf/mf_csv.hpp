#pragma once
// CSV evaluation of the Magic Formula (host side: allocates, throws).
//
// Input: a header row naming the columns, then one row per evaluation. Required columns:
// Fz_N, kappa, alpha_rad, gamma_rad, Vx_mps; optional: phit_1pm, P_Pa (0 → the file's INFLPRES).
// Any order; blank lines and lines starting with '#' are skipped. Errors (std::runtime_error,
// `file:line: message`): a missing required column, an unknown or repeated column, a row with the
// wrong number of cells, a cell that is not a finite number.
// Output: the inputs again (in_Fz_N, in_kappa, in_alpha_rad, in_gamma_rad, in_Vx_mps, in_phit_1pm,
// in_P_Pa), then every MfOutput value under MFeval's column names (Fx_N, Fy_N, Fz_N, Mx_Nm, My_Nm,
// Mz_Nm, kappa_1, ..., Rl_m, Re_m, ...), then status. Numbers are written with 17 significant
// digits.

#include <cstddef>
#include <iosfwd>
#include <string>

#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"

namespace tread::mf {

/// Evaluates every row of `in` (named `in_name` in messages) and writes `out`. `use_float`
/// evaluates in float (parameters converted once). Returns the number of rows evaluated.
std::size_t evaluate_csv(const MfParameters<double>& params, const MfOptions& options,
                         bool use_float, std::istream& in, const std::string& in_name,
                         std::ostream& out);

}  // namespace tread::mf
