#pragma once
// CSV evaluation of PAC89/PAC94 (host side: allocates, throws).
//
// Input: a table read by InputTable (sim/tyre/input_table.hpp: the accepted column names and
// units, separator, the file's sign convention). Required inputs: Fz, kappa, alpha, gamma (ISO-W
// after conversion); other columns (e.g. Vx_mps of an MF input file) are ignored. Errors (TirError,
// `file:line: message`): a missing or repeated input column, a row with the wrong number of
// cells, an input cell that is not a finite number, a non-finite output under status ok.
// Output: a '#' line naming the axes, then in_Fz_N, in_kappa, in_alpha_rad, in_gamma_rad, Fx_N,
// Fy_N, Mz_Nm, Mx_Nm, My_Nm (17 significant digits) and status (PacOutput::status as text: "ok",
// "out of range", "non-finite result" where an output came out NaN/inf and was written as 0). With
// `iso_w` (the default, as `tread mf eval`) the outputs are in ISO-W axes, converted by
// pac::to_iso_w(): for the same physical situation Fy and Mz have the signs `tread mf eval` gives
// (α > 0: Fy < 0, Mz > 0); without it, in the PAC89/PAC94 coefficient set's own ("modified SAE")
// axes.

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "pac/pac_params.hpp"
#include "tir/pac_plot.hpp"
#include "tyre/input_table.hpp"

namespace tread::tyre {

struct PacCsvOptions {
  tir::PacModel model = tir::PacModel::kPac89;
  pac::Slip slip = pac::Slip::kCombined;
  bool use_float = false;  ///< evaluate in float (coefficients converted once)
  bool iso_w = true;       ///< outputs in ISO-W (false: the model's own axes)
  InputTableOptions table{
      '\0',
      SignConvention::iso_w,
      {InputQuantity::fz, InputQuantity::kappa, InputQuantity::alpha, InputQuantity::gamma}};
};

/// Rows whose status is not ok: how many, and the first's line in the input.
struct PacCsvTally {
  std::size_t out_of_range = 0;  ///< an input clamped to the tyre's limits
  int first_out_of_range_line = 0;
  std::size_t other = 0;  ///< another status (a non-finite result written as 0)
  int first_other_line = 0;
  /// Input columns the file has that PAC89/PAC94 do not read (speed, turn slip, pressure).
  std::vector<std::string> unused_columns;
};

/// Returns the number of rows evaluated; `tally`, if given, counts the rows by status.
std::size_t evaluate_pac_csv(const pac::PacParams<double>& params, const PacCsvOptions& options,
                             std::istream& in, const std::string& in_name, std::ostream& out,
                             PacCsvTally* tally = nullptr);

}  // namespace tread::tyre
