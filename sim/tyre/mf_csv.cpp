#include "tyre/mf_csv.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <istream>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "io/line_chunks.hpp"
#include "io/ordered_pipeline.hpp"
#include "io/shortest_number.hpp"
#include "io/text_line.hpp"
#include "mf/mf_evaluate.hpp"
#include "mf/mf_evaluate_batch.hpp"
#include "mf/mf_evaluate_rows.hpp"
#include "mf/mf_fixed.hpp"
#include "mf/mf_free_radius.hpp"
#include "tir/tir_file.hpp"

namespace tread::tyre {

namespace {

/// An input in the evaluation's scalar: float/double by a cast, fixed point rounded to nearest
/// Q31.32 — a value beyond its range (±2^31) taken as ±2^31, so that it is clamped to the
/// model's envelope and reported out_of_range as in double (the reader refuses NaN and inf).
template <typename T>
T scalar_of(double v) {
  if constexpr (std::is_same_v<T, fixed::Fixed64>) {
    constexpr double kLimit = 2147483647.0;
    return fixed::Fixed64::from_double(v > kLimit ? kLimit : (v < -kLimit ? -kLimit : v));
  } else {
    return static_cast<T>(v);
  }
}
template <typename T>
double as_double(const T& v) {
  if constexpr (std::is_same_v<T, fixed::Fixed64>) {
    return v.to_double();
  } else {
    return static_cast<double>(v);
  }
}

// One limit of the model's range, checked on the SI ISO-W inputs.
struct Limit {
  InputQuantity quantity;
  bool above;  // true: value > bound is outside
  double bound;
  const char* key;
  const char* unit;
};

std::string short_number(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

std::string describe(const Limit& l) {
  return std::string(si_name(l.quantity)) + (l.above ? " > " : " < ") + l.key + " = " +
         short_number(l.bound) + (*l.unit != '\0' ? std::string(" ") + l.unit : std::string());
}

// Why a value may lie outside: the likely mistake in the input file.
std::string hint(const InputTable& table, const Limit& l, double value) {
  const std::string column = host::text::excerpt(table.column_name(l.quantity));
  const std::string_view unit = table.column_unit(l.quantity);
  if ((l.quantity == InputQuantity::alpha || l.quantity == InputQuantity::gamma) && unit == "rad") {
    const std::string deg = l.quantity == InputQuantity::alpha ? "alpha_deg" : "gamma_deg";
    return "; column '" + column + "' is read in radians: if it holds degrees, name it " + deg;
  }
  if (l.quantity == InputQuantity::kappa && unit == "1" && std::fabs(value) > 1.0) {
    return "; column '" + column + "' is read as a ratio: if it holds percent, name it kappa_pct";
  }
  if (l.quantity == InputQuantity::fz && value < 0.0) {
    if (iso_w_sign(table.convention(), InputQuantity::fz) > 0.0) {
      return "; a negative load: is the file in SAE axes (z down)? Use --convention sae";
    }
    // Its sign already changed: the file's load was positive in its own convention.
    return std::string("; a negative load after the sign change from ") +
           std::string(to_string(table.convention())) +
           ": is the file's load already positive? Use --convention iso-w";
  }
  if (l.quantity == InputQuantity::pressure && unit == "Pa") {
    return "; column '" + column + "' is read in Pa: name it P_kPa, P_bar or P_psi otherwise";
  }
  return {};
}

constexpr std::size_t kLimitCount = 14;

// Rows outside one limit, in one chunk or so far.
struct Tally {
  std::size_t rows = 0;
  int first_line = 0;
  double first_value = 0.0;  ///< the first row's value, where one is counted
};

// Adds a later chunk's tally to the one so far (the first line stays the earliest).
void merge(Tally& so_far, const Tally& chunk) {
  if (chunk.rows == 0) return;
  if (so_far.rows == 0) {
    so_far.first_line = chunk.first_line;
    so_far.first_value = chunk.first_value;
  }
  so_far.rows += chunk.rows;
}

// Rows evaluated together by --batch: 16 blocks of 16 lanes (32 of 8), their rows, inputs and
// outputs (≈ 60 KiB) staying in the core's cache between parsing, evaluating and formatting.
constexpr std::size_t kBatchRows = 256;

// A batch's rows as read, their inputs and their outputs.
template <typename T>
struct BatchScratch {
  std::vector<InputRow> rows;
  std::vector<mf::MfInput<T>> inputs;
  std::vector<mf::MfOutput<T>> outputs;
  std::vector<unsigned char> outside;  ///< per row: an input outside the tyre's limits
};

// One chunk of the stream: its lines in, its formatted rows out. Reused from chunk to chunk.
struct Chunk {
  host::LineChunk lines;
  std::unique_ptr<char[]> text;  ///< the formatted rows (uninitialised beyond `used`)
  std::size_t capacity = 0;
  std::size_t used = 0;
  std::size_t rows = 0;
  std::array<Tally, kLimitCount> outside{};
  Tally above_free;                  ///< rows whose Rl lies above the free radius (see EvalSetup)
  BatchScratch<float> batch;         ///< --batch only (allocated on the chunk's first use)
  BatchScratch<double> double_rows;  ///< double on mf::evaluate_rows (the same)
};

// What every chunk of one evaluation shares (read only).
struct EvalSetup {
  const InputTable& table;
  const std::string& in_name;
  const std::array<Limit, kLimitCount>& limits;
  mf::MfOptions options;
  bool strict = false;
  std::vector<std::size_t> columns;
  std::size_t row_bytes = 0;  ///< the most a formatted row takes
  /// The limits per input (value[q] < low[q] or > high[q] is outside; ±inf where none applies),
  /// for check_range's test of a whole row at once.
  std::array<double, kInputQuantityCount> low{};
  std::array<double, kInputQuantityCount> high{};
  /// Where Rl is shown and found as a root of MF 6.2's vertical force (MF 6.2, MF 5.2, PAC2002):
  /// the tyre, for check_loaded_radius; null where not checked.
  const mf::MfParameters<double>* radius_check = nullptr;
};

// The coefficients through which the inflation pressure acts that are nonzero, as "KEY = value"
// (QSY8 only in MF 6.x, whose rolling resistance has the pressure power).
std::vector<std::string> pressure_terms(const mf::MfParameters<double>& p, bool mf5x) {
  const std::array<std::pair<const char*, double>, 16> terms{{
      {"PFZ1", p.pfz1},
      {"PPX1", p.ppx1},
      {"PPX2", p.ppx2},
      {"PPX3", p.ppx3},
      {"PPX4", p.ppx4},
      {"PPY1", p.ppy1},
      {"PPY2", p.ppy2},
      {"PPY3", p.ppy3},
      {"PPY4", p.ppy4},
      {"PPY5", p.ppy5},
      {"PPZ1", p.ppz1},
      {"PPZ2", p.ppz2},
      {"PPMX1", p.ppmx1},
      {"QSY8", mf5x ? 0.0 : p.qsy8},
      {"PCFX3", p.pcfx3},
      {"PCFY3", p.pcfy3},
  }};
  std::vector<std::string> nonzero;
  for (const auto& [key, v] : terms) {
    if (std::fabs(v) > 0.0) nonzero.push_back(std::string(key) + " = " + short_number(v));
  }
  return nonzero;
}

// Fills setup.low and setup.high from setup.limits (the pressure's only where the table has a
// pressure column).
void set_bounds(EvalSetup& setup) {
  setup.low.fill(-std::numeric_limits<double>::infinity());
  setup.high.fill(std::numeric_limits<double>::infinity());
  for (const Limit& l : setup.limits) {
    if (l.quantity == InputQuantity::pressure && !setup.table.has(InputQuantity::pressure)) {
      continue;
    }
    (l.above ? setup.high : setup.low)[static_cast<std::size_t>(l.quantity)] = l.bound;
  }
}

// Whether any of `row`'s values may lie outside the model's range: each input against the bounds
// set once, not limit by limit (a pressure of 0, the file's INFLPRES, is never outside).
bool maybe_outside(const EvalSetup& setup, const InputRow& row) {
  bool outside = false;
  for (std::size_t q = 0; q < kInputQuantityCount; ++q) {
    const double v = row.value[q];
    const bool beyond = v < setup.low[q] || v > setup.high[q];
    const bool counts =
        q != static_cast<std::size_t>(InputQuantity::pressure) || std::fabs(v) > 0.0;
    outside = outside || (beyond && counts);
  }
  return outside;
}

// Counts `row`'s values outside the model's range in `outside` (with --strict: refuses the first).
// True if one was: with the limits on (useMode 1xx) the core clamps it, and the row's status says
// `out of range`.
bool check_range(const EvalSetup& setup, const InputRow& row, std::array<Tally, kLimitCount>& out) {
  if (!maybe_outside(setup, row)) return false;
  bool any = false;
  for (std::size_t i = 0; i < kLimitCount; ++i) {
    const Limit& l = setup.limits[i];
    const double v = row[l.quantity];
    if (l.quantity == InputQuantity::pressure &&
        (!(std::fabs(v) > 0.0) || !setup.table.has(InputQuantity::pressure))) {
      continue;
    }
    if (!(l.above ? v > l.bound : v < l.bound)) continue;
    if (setup.strict) {
      throw tir::TirError(setup.in_name, row.line,
                          std::string(si_name(l.quantity)) + " = " + short_number(v) +
                              " outside the model's range (" + describe(l) + ", --strict)" +
                              hint(setup.table, l, v));
    }
    if (out[i].rows++ == 0) {
      out[i].first_line = row.line;
      out[i].first_value = v;
    }
    // A load of 0 or less is a wheel off the ground (no forces), not a clamped input.
    any = any || !(l.quantity == InputQuantity::fz && v <= 0.0);
  }
  return any;
}

// An ok result for a row whose input the core clamped at the tyre's limits is `out of range`
// (the README's promise), a worse status stays.
template <typename T>
void mark_clamped(const EvalSetup& setup, bool outside, mf::MfOutput<T>& result) {
  if (outside && setup.options.use_limits && result.status == Status::ok) {
    result.status = Status::out_of_range;
  }
}

// Counts a row whose loaded radius lies more than 2 % above the free radius at its wheel speed,
// Romega = R0·(Q_RE0 + Q_V1·(ω·R0/V0)²): MF 6.2's vertical force has such roots (a light,
// cambered wheel, through the Fy and camber terms), which no tyre has.
template <typename T>
void check_loaded_radius(const EvalSetup& setup, const InputRow& row, const mf::MfOutput<T>& result,
                         Tally& tally) {
  if (setup.radius_check == nullptr) return;
  const double romega = mf::free_radius_m(*setup.radius_check, as_double(result.omega_radps));
  if (as_double(result.rl_m) > 1.02 * romega && tally.rows++ == 0) tally.first_line = row.line;
}

// Makes room in `chunk` for its formatted rows and clears what the last use left.
void start_chunk(const EvalSetup& setup, Chunk& chunk) {
  // write_shortest may write blocks of digits past a number's end, up to kShortestNumberRoom
  // from its start: room for that after the last row.
  const std::size_t needed = chunk.lines.lines * setup.row_bytes + host::kShortestNumberRoom;
  if (chunk.capacity < needed) {
    chunk.text = std::make_unique_for_overwrite<char[]>(needed);
    chunk.capacity = needed;
  }
  chunk.used = 0;
  chunk.rows = 0;
  chunk.outside = {};
  chunk.above_free = {};
}

// A row's inputs in the evaluation's scalar.
template <typename T>
mf::MfInput<T> input_of(const InputRow& row) {
  mf::MfInput<T> in;
  in.fz_n = scalar_of<T>(row.value[0]);
  in.kappa = scalar_of<T>(row.value[1]);
  in.alpha_rad = scalar_of<T>(row.value[2]);
  in.gamma_rad = scalar_of<T>(row.value[3]);
  in.vx_mps = scalar_of<T>(row.value[4]);
  in.phit_1pm = scalar_of<T>(row.value[5]);
  in.p_pa = scalar_of<T>(row.value[6]);
  return in;
}

// Writes the selected columns of `row` and its `result`, then the status, at `p`; returns the end.
// Throws tir::TirError for a non-finite value under status ok.
template <typename T>
char* format_row(const EvalSetup& setup, const InputRow& row, const mf::MfOutput<T>& result,
                 char* p) {
  constexpr auto members = eval_output_members<T>();
  const std::array<EvalColumn, kEvalColumnCount>& columns = eval_columns();
  // The statuses under which every number must be finite: ok, and out of range (clamped inputs).
  const bool ok = result.status == Status::ok || result.status == Status::out_of_range;
  // The text of each input written in this row: an output that repeats it to the bit (kappa_1
  // and in_kappa, ...) copies it instead of formatting it again.
  std::array<const char*, kEvalInputColumns> input_text{};
  std::array<std::size_t, kEvalInputColumns> input_length{};
  for (const std::size_t c : setup.columns) {
    if (c < kEvalInputColumns) {
      input_text[c] = p;
      p = host::write_shortest(p, row.value[c]);
      input_length[c] = static_cast<std::size_t>(p - input_text[c]);
      *p++ = ',';
      continue;
    }
    const double v = as_double(result.*(members[c - kEvalInputColumns]));
    const int echoes = columns[c].echoes;
    if (echoes >= 0 && input_text[static_cast<std::size_t>(echoes)] != nullptr &&
        std::bit_cast<std::uint64_t>(v) ==
            std::bit_cast<std::uint64_t>(row.value[static_cast<std::size_t>(echoes)])) {
      const auto e = static_cast<std::size_t>(echoes);
      std::memcpy(p, input_text[e], input_length[e]);
      p += input_length[e];
      *p++ = ',';
      continue;
    }
    if (ok && !std::isfinite(v)) {
      // Never a NaN or Inf under status ok (or out of range). The core already writes a
      // non-finite output as 0 with Status::non_finite; this is the last check where numbers
      // leave the program.
      char number[host::kShortestNumberRoom];
      char* end = host::write_shortest(number, v);
      throw tir::TirError(setup.in_name, row.line,
                          std::string(columns[c].name) + " = " + std::string(number, end) +
                              " under status " + to_string(result.status) +
                              ": the tyre's parameters give no finite "
                              "result for this row (check the .tir for zero or missing "
                              "stiffnesses and radii)");
    }
    p = host::write_shortest(p, v);
    *p++ = ',';
  }
  const char* status = to_string(result.status);
  const std::size_t n = std::strlen(status);
  std::memcpy(p, status, n);
  p += n;
  *p++ = '\n';
  return p;
}

// Parses, checks, evaluates (in T, row by row) and formats every row of `chunk`.
template <typename T>
void evaluate_chunk(const EvalSetup& setup, const mf::MfParameters<T>& params, Chunk& chunk) {
  start_chunk(setup, chunk);
  char* p = chunk.text.get();
  InputRow row;
  host::for_each_line(chunk.lines, [&](std::string_view line, int line_no) {
    if (!setup.table.parse_row(line, line_no, row)) return;
    const bool outside = check_range(setup, row, chunk.outside);
    mf::MfOutput<T> result = evaluate(params, input_of<T>(row), setup.options);
    mark_clamped(setup, outside, result);
    check_loaded_radius(setup, row, result, chunk.above_free);
    p = format_row(setup, row, result, p);
    ++chunk.rows;
  });
  chunk.used = static_cast<std::size_t>(p - chunk.text.get());
}

// The same kBatchRows rows at a time: the rows are parsed and checked, evaluated together by
// `evaluate_many` (mf::evaluate_batch: float on wide lanes, --batch; mf::evaluate_rows: double,
// evaluate<double>'s bits), then formatted. A row that cannot be read (or, with --strict, is out
// of range) is an error only after the rows before it are evaluated and formatted, so that an
// error among those (a non-finite output under status ok) comes first, as row by row.
template <typename T, typename EvaluateMany>
void evaluate_chunk_batch(const EvalSetup& setup, const mf::MfParameters<T>& params, Chunk& chunk,
                          BatchScratch<T>& batch, EvaluateMany evaluate_many) {
  start_chunk(setup, chunk);
  if (batch.rows.size() < kBatchRows) {
    batch.rows.resize(kBatchRows);
    batch.inputs.resize(kBatchRows);
    batch.outputs.resize(kBatchRows);
    batch.outside.resize(kBatchRows);
  }
  char* p = chunk.text.get();
  std::size_t pending = 0;
  const auto flush = [&] {
    evaluate_many(params, std::span<const mf::MfInput<T>>(batch.inputs).first(pending),
                  setup.options, std::span<mf::MfOutput<T>>(batch.outputs).first(pending));
    for (std::size_t i = 0; i < pending; ++i) {
      mark_clamped(setup, batch.outside[i] != 0, batch.outputs[i]);
      check_loaded_radius(setup, batch.rows[i], batch.outputs[i], chunk.above_free);
      p = format_row(setup, batch.rows[i], batch.outputs[i], p);
      ++chunk.rows;
    }
    pending = 0;
  };
  host::for_each_line(chunk.lines, [&](std::string_view line, int line_no) {
    InputRow& row = batch.rows[pending];
    try {
      if (!setup.table.parse_row(line, line_no, row)) return;
      batch.outside[pending] = check_range(setup, row, chunk.outside) ? 1 : 0;
    } catch (...) {
      flush();  // may throw an earlier row's error instead
      throw;
    }
    batch.inputs[pending] = input_of<T>(row);
    if (++pending == kBatchRows) flush();
  });
  flush();
  chunk.used = static_cast<std::size_t>(p - chunk.text.get());
}

}  // namespace

MfCsvReport evaluate_csv(const mf::MfParameters<double>& params, const mf::MfOptions& options,
                         const MfCsvOptions& csv, std::istream& in, const std::string& in_name,
                         std::ostream& out) {
  const mf::MfParameters<float> params_f = mf::convert_parameters<float>(params);
  const mf::MfParameters<fixed::Fixed64> params_q =
      csv.use_fixed ? to_fixed_parameters(params) : mf::MfParameters<fixed::Fixed64>{};
  InputTable table(in, in_name, csv.table);
  MfCsvReport report;
  report.ignored = table.ignored_columns();
  // What a pressure column does where the model has no pressure terms of its own: the user should
  // hear it rather than read the output as a pressure study.
  if (table.has(InputQuantity::pressure)) {
    const bool mf5x = params.fit_type != mf::FitType::mf61 && params.fit_type != mf::FitType::mf62;
    const std::vector<std::string> terms = pressure_terms(params, mf5x);
    if (terms.empty()) {
      report.warnings.emplace_back(
          "the pressure column changes no output: the tyre's pressure coefficients (PFZ1, PPX1-4, "
          "PPY1-5, PPZ1-2, PPMX1, QSY8, PCFX3, PCFY3) are all 0");
    } else if (mf5x) {
      std::string list;
      for (const std::string& t : terms) list += (list.empty() ? "" : ", ") + t;
      report.warnings.push_back(
          "this tyre is MF 5.x / PAC2002, which has no pressure terms of its own: the pressure "
          "column acts only through MF 6.1's coefficients " +
          list + " (MF 6.1 defaults where the file does not give them, as MFeval takes them)");
    }
  }

  using Q = InputQuantity;
  const std::array<Limit, kLimitCount> limits = {{
      {Q::fz, false, params.fzmin_n, "FZMIN", "N"},
      {Q::fz, true, params.fzmax_n, "FZMAX", "N"},
      {Q::kappa, false, params.kpumin, "KPUMIN", ""},
      {Q::kappa, true, params.kpumax, "KPUMAX", ""},
      {Q::alpha, false, params.alpmin_rad, "ALPMIN", "rad"},
      {Q::alpha, true, params.alpmax_rad, "ALPMAX", "rad"},
      {Q::gamma, false, params.cammin_rad, "CAMMIN", "rad"},
      {Q::gamma, true, params.cammax_rad, "CAMMAX", "rad"},
      {Q::pressure, false, params.presmin_pa, "PRESMIN", "Pa"},
      {Q::pressure, true, params.presmax_pa, "PRESMAX", "Pa"},
      // The core's finite-arithmetic envelope (mf_inputs.hpp) where the tyre has no limit: rows
      // beyond it were `out of range` without a count or a reason, and --strict let them pass.
      {Q::vx, false, -1000.0, "tread's envelope", "m/s"},
      {Q::vx, true, 1000.0, "tread's envelope", "m/s"},
      {Q::phit, false, -100.0, "tread's envelope", "1/m"},
      {Q::phit, true, 100.0, "tread's envelope", "1/m"},
  }};

  EvalSetup setup{table, in_name, limits, options, csv.strict, csv.columns, 0, {}, {}};
  set_bounds(setup);
  // The extras (radii, contact patch, relaxation) change no force or moment, and Mx and My no
  // other output: each skipped when no selected column shows it (the status then covers what is
  // computed and shown).
  if (!needs_extras(csv.columns)) setup.options.extras = false;
  if (!needs_moments_xy(csv.columns)) setup.options.moments_xy = false;
  const bool shows_rl = std::any_of(csv.columns.begin(), csv.columns.end(), [](std::size_t c) {
    return std::string_view(eval_columns()[c].name) == "Rl_m";
  });
  if (shows_rl && setup.options.extras && params.fit_type != mf::FitType::mf61) {
    setup.radius_check = &params;
  }
  constexpr std::size_t kStatusBytes = 32;  // "non-finite result" and its '\n'
  setup.row_bytes = csv.columns.size() * (host::kShortestNumberMaxChars + 1) + kStatusBytes;

  out << "# tread mf eval: ISO-W (TYDEX W) axes, SI units (inputs read in "
      << to_string(csv.table.convention) << " axes and converted)\n";
  for (const std::size_t c : csv.columns) out << eval_columns()[c].name << ',';
  out << "status\n";

  // The first line after the header that is not blank or a comment may be a units row; if it is
  // not, it is the first data line and goes first into the stream of chunks.
  std::string pending;
  int next_line = table.line() + 1;
  for (std::string line; std::getline(in, line);) {
    const int line_no = next_line++;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    if (!table.take_units_row(line, line_no)) {
      pending = line + '\n';
      next_line = line_no;
    }
    break;
  }
  host::LineChunker chunker(in, in_name, csv.chunk_lines, next_line, std::move(pending));

  std::array<Tally, kLimitCount> outside{};
  Tally above_free;
  std::uint64_t bytes = 0;
  const unsigned workers = csv.threads > 0 ? csv.threads : host::default_worker_count();
  host::run_ordered_pipeline<Chunk>(
      workers, 2 * std::size_t{workers} + 2,
      [&](Chunk& chunk) { return chunker.next(chunk.lines); },
      [&](Chunk& chunk) {
        if (csv.use_fixed) {
          evaluate_chunk(setup, params_q, chunk);
        } else if (csv.use_batch) {
          evaluate_chunk_batch(setup, params_f, chunk, chunk.batch, mf::evaluate_batch);
        } else if (csv.use_float) {
          evaluate_chunk(setup, params_f, chunk);
        } else if (mf::rows_lanes() > 1) {
          evaluate_chunk_batch(setup, params, chunk, chunk.double_rows, mf::evaluate_rows);
        } else {
          evaluate_chunk(setup, params, chunk);
        }
      },
      [&](Chunk& chunk) {
        out.write(chunk.text.get(), static_cast<std::streamsize>(chunk.used));
        for (std::size_t i = 0; i < kLimitCount; ++i) merge(outside[i], chunk.outside[i]);
        merge(above_free, chunk.above_free);
        report.rows += chunk.rows;
        bytes += chunk.lines.text.size();
        if (csv.progress) csv.progress(bytes, report.rows);
      });
  for (std::size_t i = 0; i < kLimitCount; ++i) {
    if (outside[i].rows > 0) {
      MfRangeCount c;
      c.limit = describe(limits[i]);
      c.rows = outside[i].rows;
      c.first_line = outside[i].first_line;
      // Below FZMIN the load is not clamped (MFeval limits only FZMAX), and one of 0 or less is
      // a wheel off the ground: no forces, under ok. Said, with the likely cause of a negative
      // one; "evaluated clamped" was said of rows in SAE axes read as ISO-W.
      if (limits[i].quantity == InputQuantity::vx || limits[i].quantity == InputQuantity::phit) {
        c.clamped = false;
        c.note = "; clamped to it at any useMode (no tyre is measured there)";
      }
      if (limits[i].quantity == InputQuantity::fz && !limits[i].above) {
        c.clamped = false;
        if (outside[i].first_value <= 0.0) {
          c.note = "; a load of 0 or less gives no forces (status ok)" +
                   hint(table, limits[i], outside[i].first_value);
        }
      }
      report.out_of_range.push_back(c);
    }
  }
  if (above_free.rows > 0) {
    report.warnings.push_back(
        std::to_string(above_free.rows) + " rows (the first at " + in_name + ":" +
        std::to_string(above_free.first_line) +
        ") have a loaded radius Rl more than 2 % above the free radius R0·(Q_RE0 + Q_V1·(ω·R0/"
        "V0)²): MF 6.2's vertical force has its root there (a light or cambered wheel, through "
        "the Fy and camber terms); the radius is the model's, not a tyre's");
  }
  report.mapping = table.mapping();  // after a units row, if any, was read
  return report;
}

}  // namespace tread::tyre
