#pragma once
// Tyre measurements for the fitter (host side: allocates, throws).
//
// Two formats:
//  - CSV read by tyre::InputTable, as `tread mf eval` reads it (the same input names and units,
//    e.g. FZ, SL, SA [deg], IA [deg], V [km/h]; ',', ';' or tab separators, decimal commas with
//    ';' or tab; a units row under the header), with InputTableOptions::measured: the measured
//    outputs Fx_N|FX|FXW, Fy_N|FY|FYW, Mz_Nm|MZ|MZW (and kN names; any subset, at least one),
//    converted from the file's sign convention to ISO-W by tyre::output_sign. Fz_N, kappa and
//    alpha_rad are required; gamma and Vx default to 0. Other columns (and pressure, turn slip)
//    are listed as ignored. An empty cell of a measured column means "not measured there".
//  - TYDEX (.tdx): the **MEASURCHANNELS section names the channels (name, description, unit,
//    conversion factor, measurement offset, physical offset) and **MEASURDATA holds one row per
//    sample in that order. Channels used: FZW (vertical load), LONGSLIP, SLIPANGL, INCLANGL,
//    LONGVEL, FXW, FYW, MZW. Units converted: deg → rad, % → 1, kN → N, kNm → Nm, km/h → m/s.
//    A sample's physical value is (raw − measurement offset) · factor + physical offset, in the
//    channel's unit (our reading of TYDEX 1.3; files written by MFeval use 1, 0, 0).
// Errors: std::runtime_error with `file:line: message` (a bad cell, a row with the wrong number of
// cells, a missing required column/channel, a repeated column, an unknown unit).

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <limits>
#include <string>
#include <vector>

#include "tyre/input_table.hpp"

namespace tread::fit {

/// One sample. Measured values that the file does not hold are NaN.
struct MeasurementPoint {
  double fz_n = 0.0;
  double kappa = 0.0;
  double alpha_rad = 0.0;
  double gamma_rad = 0.0;
  double vx_mps = 0.0;
  double fx_n = std::numeric_limits<double>::quiet_NaN();
  double fy_n = std::numeric_limits<double>::quiet_NaN();
  double mz_nm = std::numeric_limits<double>::quiet_NaN();
  std::size_t line = 0;  ///< line in the source file (for messages)
};

struct MeasurementSet {
  std::string source;  ///< file name (for messages and reports)
  std::vector<MeasurementPoint> points;
  /// CSV header cells that are not read (the fit takes no pressure, turn slip or other column).
  std::vector<std::string> ignored_columns;
  bool has_pressure = false;  ///< a pressure column was among them
};

MeasurementSet read_measurement_csv(std::istream& in, const std::string& name,
                                    tyre::SignConvention convention = tyre::SignConvention::iso_w);
MeasurementSet read_tydex(std::istream& in, const std::string& name);

/// Throws (file:line of the first) if a point has Vx = 0: the staged Magic Formula fit needs the
/// rolling speed (its residuals and their derivatives are not finite at standstill).
void check_rolling(const MeasurementSet& set);

/// Removes the points with Fz ≤ 0 (a wheel off the ground: the Magic Formula has no force there)
/// and returns how many there were (`first_line`: the first's line). Throws (file:line of the
/// first) if they are half the points or more: loads written with z down (SAE J670, FSAE TTC
/// data) read as ISO-W, for which the message names --convention sae.
std::size_t drop_unloaded(MeasurementSet& set, std::size_t& first_line);

/// Reads `path` as TYDEX if it ends in .tdx (any case; TYDEX W axes), otherwise as CSV in
/// `convention`.
MeasurementSet load_measurements(const std::filesystem::path& path,
                                 tyre::SignConvention convention = tyre::SignConvention::iso_w);

}  // namespace tread::fit
