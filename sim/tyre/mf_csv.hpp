#pragma once
// CSV evaluation of the Magic Formula (host side: allocates, throws).
//
// Input: a table read by tyre::InputTable (sim/tyre/input_table.hpp: the accepted column names and
// units, the separator, the sign convention of the file). Required inputs: Fz, kappa, alpha, gamma,
// Vx; optional: phit, P (0 or absent → the file's INFLPRES). Every row's inputs are checked against
// the model's ranges (FZMIN/FZMAX, KPUMIN/KPUMAX, ALPMIN/ALPMAX, CAMMIN/CAMMAX, PRESMIN/PRESMAX);
// rows outside are counted per limit (limit checks on: the model clamps them as MFeval does) or,
// with `strict`, refused at the first one with a hint at the likely cause (degrees in a radian
// column, SAE signs). Errors: tir::TirError (`file:line: message`), also for a row with a NaN or
// Inf output under status ok (a defective parameter set: never written as ok). Output: a '#' line
// stating the axes (ISO-W, SI), then a header: the selected columns of tyre::eval_columns()
// (sim/tyre/mf_eval_columns.hpp: the inputs as evaluated, in SI and ISO-W, in_Fz_N, in_kappa, ...,
// and MfOutput values under MFeval's column names, Fx_N, Fy_N, ..., Rl_m, Re_m, kappa_1, ...),
// then status. Numbers are written as the shortest text that reads back to the same double
// (std::to_chars); --float and --batch results are the float values as doubles.
//
// A stream: the input is read in chunks of lines, each chunk parsed, evaluated and formatted on a
// worker thread (one per core), the chunks written in input order; memory is bounded by the
// chunks in flight, not the number of rows. An error is the first one in input order, with the
// rows before it already written to `out` (write to a host::ReplaceFile to keep the output whole
// or nothing).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"
#include "tyre/input_table.hpp"
#include "tyre/mf_eval_columns.hpp"

namespace tread::tyre {

struct MfCsvOptions {
  bool use_float = false;  ///< evaluate in float (parameters converted once), as on the ECU
  /// Evaluate in float many rows at once on wide lanes (mf::evaluate_batch: 16 with AVX-512): the
  /// status of use_float and its values within 1e-5 of each column's scale, not bit for bit
  /// (use_float is the ECU's scalar path). Before use_float; use_fixed before it.
  bool use_batch = false;
  /// Evaluate in fixed point (fixed::Fixed64, Q31.32): the exact integer arithmetic of an
  /// FPU-less target; inputs and parameters rounded to Q31.32.
  bool use_fixed = false;
  bool strict = false;    ///< a row outside the model's range is an error
  std::string tyre_name;  ///< the .tir, for messages
  InputTableOptions table;
  /// Columns to write: indices into eval_columns() (select_eval_columns()). Without an output that
  /// needs MfOptions::extras the evaluation runs without them (the same forces and moments).
  std::vector<std::size_t> columns = default_eval_columns();
  std::size_t chunk_lines = 8192;  ///< input lines per chunk
  unsigned threads = 0;            ///< worker threads; 0: one per hardware thread
  /// Called on the calling thread after each chunk is written: input bytes and rows done so far.
  std::function<void(std::uint64_t bytes, std::uint64_t rows)> progress;
};

/// Rows outside one limit of the model.
struct MfRangeCount {
  std::string limit;  ///< e.g. "alpha > ALPMAX = 1.5 rad"
  std::size_t rows = 0;
  int first_line = 0;
  bool clamped = true;  ///< the core clamps such a value (with the limits of useMode 1xx)
  std::string note;     ///< what else to say ("; ..."), or empty
};

struct MfCsvReport {
  std::size_t rows = 0;
  std::vector<std::string> mapping;        ///< InputTable::mapping()
  std::vector<std::string> ignored;        ///< header cells that name no input
  std::vector<MfRangeCount> out_of_range;  ///< limits with at least one row outside
  std::vector<std::string> warnings;       ///< inputs read but not used by the tyre's model
};

/// Evaluates every row of `in` (named `in_name` in messages) and writes `out`.
MfCsvReport evaluate_csv(const mf::MfParameters<double>& params, const mf::MfOptions& options,
                         const MfCsvOptions& csv, std::istream& in, const std::string& in_name,
                         std::ostream& out);

}  // namespace tread::tyre
