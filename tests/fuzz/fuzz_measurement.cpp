// Measurement files and `tread mf eval` input tables (fit/measurement.hpp, mf/input_table.hpp) from
// bytes no one wrote. The first byte picks the reader (low 2 bits: 0 measurement CSV, 1 TYDEX,
// 2 or 3 input table) and the sign convention (bits 2-3); the rest is the file. Either the reader
// returns or its error names the file; what it returns holds finite inputs (in SI units) and
// outputs that are finite or NaN ("not measured"), never infinite, each with the line it came from.
#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "fit/measurement.hpp"
#include "fuzz_support.hpp"
#include "tyre/input_table.hpp"

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

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::Input input(data, size);
  const std::uint8_t pick = input.byte();
  const tyre::SignConvention convention = kConventions[(pick >> 2U) % kConventions.size()];
  std::istringstream in{std::string(input.rest())};
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
      break;
    }
  }
  return 0;
}
