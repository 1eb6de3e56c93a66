#pragma once
// CSV evaluation of the Magic Formula (host side: allocates, throws).
//
// Input: a table read by mf::InputTable (sim/mf/input_table.hpp: the accepted column names and
// units, the separator, the sign convention of the file). Required inputs: Fz, kappa, alpha, gamma,
// Vx; optional: phit, P (0 or absent → the file's INFLPRES). Every row's inputs are checked against
// the model's ranges (FZMIN/FZMAX, KPUMIN/KPUMAX, ALPMIN/ALPMAX, CAMMIN/CAMMAX, PRESMIN/PRESMAX);
// rows outside are counted per limit (limit checks on: the model clamps them as MFeval does) or,
// with `strict`, refused at the first one with a hint at the likely cause (degrees in a radian
// column, SAE signs). Errors: tir::TirError (`file:line: message`), also for a row with a NaN or
// Inf output under status ok (a defective parameter set: never written as ok). Output: a '#' line
// stating the axes (ISO-W, SI), then a header: the inputs as evaluated, in SI and ISO-W (in_Fz_N,
// in_kappa, in_alpha_rad, in_gamma_rad, in_Vx_mps, in_phit_1pm, in_P_Pa), every MfOutput value
// under MFeval's column names (Fx_N, Fy_N, Fz_N, Mx_Nm, My_Nm, Mz_Nm, Rl_m, Re_m, kappa_1, ...),
// then status. Numbers are written with 17 significant digits.

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "mf/input_table.hpp"
#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"

namespace tread::mf {

struct MfCsvOptions {
  bool use_float = false;  ///< evaluate in float (parameters converted once), as on the ECU
  /// Evaluate in fixed point (fixed::Fixed64, Q31.32): the exact integer arithmetic of an
  /// FPU-less target; inputs and parameters rounded to Q31.32.
  bool use_fixed = false;
  bool strict = false;    ///< a row outside the model's range is an error
  std::string tyre_name;  ///< the .tir, for messages
  InputTableOptions table;
};

/// Rows outside one limit of the model.
struct MfRangeCount {
  std::string limit;  ///< e.g. "alpha > ALPMAX = 1.5 rad"
  std::size_t rows = 0;
  int first_line = 0;
};

struct MfCsvReport {
  std::size_t rows = 0;
  std::vector<std::string> mapping;        ///< InputTable::mapping()
  std::vector<std::string> ignored;        ///< header cells that name no input
  std::vector<MfRangeCount> out_of_range;  ///< limits with at least one row outside
};

/// Evaluates every row of `in` (named `in_name` in messages) and writes `out`.
MfCsvReport evaluate_csv(const MfParameters<double>& params, const MfOptions& options,
                         const MfCsvOptions& csv, std::istream& in, const std::string& in_name,
                         std::ostream& out);

}  // namespace tread::mf
