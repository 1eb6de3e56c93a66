// Measurement files and `tread mf eval` input tables (fit/measurement.hpp, tyre/input_table.hpp) from
// bytes no one wrote. The first byte picks the reader (low 2 bits: 0 measurement CSV, 1 TYDEX,
// 2 or 3 input table) and the sign convention (bits 2-3); the rest is the file. Either the reader
// returns or its error names the file; what it returns holds finite inputs (in SI units) and
// outputs that are finite or NaN ("not measured"), never infinite, each with the line it came from.
// An input table without ';' gives the same rows and error read with ',' as its copy with every
// ',' made a ';' read with ';' (a ',' row has a one-pass reader of its own). An input table also
// goes through `tread mf eval`'s stream (tyre::evaluate_csv: chunks of lines read, parsed,
// evaluated and formatted on worker threads, written in order) twice, in chunks of one line on two
// threads and in one chunk on one: the same output and report, or the same error naming the file
// (bit 4 of the first byte: --strict; bit 5: every column, else Fx, Fy and Mz).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "fit/measurement.hpp"
#include "fuzz_support.hpp"
#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"
#include "tyre/input_table.hpp"
#include "tyre/mf_csv.hpp"
#include "tyre/mf_eval_columns.hpp"

namespace {

using namespace tread;
using fuzz::fuzz_check;
using fuzz::is_finite;

constexpr std::array kConventions{tyre::SignConvention::iso_w, tyre::SignConvention::sae,
                                  tyre::SignConvention::adapted_iso};

void check_points(const fit::MeasurementSet& set) {
  for (const fit::MeasurementPoint& p : set.points) {
    fuzz_check(is_finite(p.fz_n) && is_finite(p.kappa) && is_finite(p.alpha_rad) &&
                   is_finite(p.gamma_rad) && is_finite(p.vx_mps),
               "a measurement input that is not finite, line " + std::to_string(p.line));
    for (const double out : {p.fx_n, p.fy_n, p.mz_nm}) {
      fuzz_check(!std::isinf(out), "an infinite measured output, line " + std::to_string(p.line));
    }
    fuzz_check(p.line > 0, "a measurement without its line");
  }
}

// Every row of an input table with `separator`, then the error that ended the reading ("" if
// none): a row's values as bits, so that -0 and 0 differ.
struct TableRead {
  std::vector<std::pair<int, std::array<std::uint64_t, tyre::kInputQuantityCount>>> rows;
  std::string error;
};

TableRead read_table(const std::string& text, char separator, tyre::SignConvention convention) {
  TableRead read;
  std::istringstream in(text);
  tyre::InputTableOptions options;
  options.separator = separator;
  options.convention = convention;
  options.required = {tyre::InputQuantity::fz, tyre::InputQuantity::kappa};
  try {
    tyre::InputTable table(in, "fuzz_input.csv", options);
    while (const std::optional<tyre::InputRow> row = table.next()) {
      std::array<std::uint64_t, tyre::kInputQuantityCount> bits{};
      for (std::size_t i = 0; i < bits.size(); ++i) {
        bits[i] = std::bit_cast<std::uint64_t>(row->value[i]);
      }
      read.rows.emplace_back(row->line, bits);
    }
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    read.error = e.what();
  }
  return read;
}

// `tread mf eval`'s stream over `text` (MF 6.1 with its default coefficients, useMode 111): the
// output and report as text, or the error.
struct StreamRun {
  std::string output;
  std::string error;
};

StreamRun run_stream(const std::string& text, tyre::SignConvention convention, bool strict,
                     bool all_columns, std::size_t chunk_lines, unsigned threads) {
  static const mf::MfParameters<double> kParams{};
  StreamRun run;
  std::istringstream in(text);
  std::ostringstream out;
  tyre::MfCsvOptions csv;
  csv.table.convention = convention;
  csv.strict = strict;
  csv.columns = tyre::select_eval_columns(all_columns ? "all" : "Fx_N,Fy_N,Mz_Nm").columns;
  csv.chunk_lines = chunk_lines;
  csv.threads = threads;
  static_cast<void>(fuzz::returns_or_names_source(
      "fuzz_input.csv",
      [&] {
        const tyre::MfCsvReport report =
            tyre::evaluate_csv(kParams, mf::MfOptions{}, csv, in, "fuzz_input.csv", out);
        run.output = out.str() + "\nrows " + std::to_string(report.rows);
        for (const tyre::MfRangeCount& c : report.out_of_range) {
          run.output +=
              "\n" + c.limit + " " + std::to_string(c.rows) + " " + std::to_string(c.first_line);
        }
      },
      &run.error));
  return run;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::Input input(data, size);
  const std::uint8_t pick = input.byte();
  const tyre::SignConvention convention = kConventions[((pick >> 2U) & 3U) % kConventions.size()];
  const std::string file(input.rest());
  std::istringstream in{file};
  switch (pick & 3U) {
    case 0: {
      constexpr const char* kSource = "fuzz.csv";
      fit::MeasurementSet set;
      if (fuzz::returns_or_names_source(
              kSource, [&] { set = fit::read_measurement_csv(in, kSource, convention); })) {
        check_points(set);
      }
      break;
    }
    case 1: {
      constexpr const char* kSource = "fuzz.tdx";
      fit::MeasurementSet set;
      if (fuzz::returns_or_names_source(kSource, [&] { set = fit::read_tydex(in, kSource); })) {
        check_points(set);
      }
      break;
    }
    default: {
      constexpr const char* kSource = "fuzz_input.csv";
      tyre::InputTableOptions options;
      options.convention = convention;
      options.required = {tyre::InputQuantity::fz, tyre::InputQuantity::kappa};
      static_cast<void>(fuzz::returns_or_names_source(kSource, [&] {
        tyre::InputTable table(in, kSource, options);
        int last_line = 0;
        while (const std::optional<tyre::InputRow> row = table.next()) {
          for (const double v : row->value) {
            fuzz_check(is_finite(v),
                       "an input that is not finite, line " + std::to_string(row->line));
          }
          fuzz_check(row->line > last_line, "input rows out of line order");
          last_line = row->line;
        }
      }));
      // A ',' row is read in one pass where it can be (InputTable::read_comma_row), a ';' row
      // cell by cell. A file without ';' read with ',', and the same file with every ',' made a
      // ';' read with ';', give the same rows and the same error: no cell then holds a comma, so
      // the decimal-comma rule of ';' files changes nothing.
      if (file.find(';') == std::string::npos) {
        std::string semicolons = file;
        std::replace(semicolons.begin(), semicolons.end(), ',', ';');
        const TableRead commas = read_table(file, ',', convention);
        const TableRead other = read_table(semicolons, ';', convention);
        fuzz_check(commas.rows == other.rows, "a ',' file and its ';' copy gave different rows (" +
                                                  std::to_string(commas.rows.size()) + " and " +
                                                  std::to_string(other.rows.size()) + ")");
        fuzz_check(commas.error == other.error,
                   "a ',' file and its ';' copy gave different "
                   "errors: '" +
                       commas.error + "' and '" + other.error + "'");
      }
      const bool strict = (pick & 16U) != 0;
      const bool all_columns = (pick & 32U) != 0;
      const StreamRun lines = run_stream(file, convention, strict, all_columns, 1, 2);
      const StreamRun whole = run_stream(file, convention, strict, all_columns, 1U << 20, 1);
      fuzz_check(lines.error == whole.error, "the stream's error depends on its chunks: '" +
                                                 lines.error + "' and '" + whole.error + "'");
      fuzz_check(lines.output == whole.output, "the stream's output depends on its chunks");
      break;
    }
  }
  return 0;
}
