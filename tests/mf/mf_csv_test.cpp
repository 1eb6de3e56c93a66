// mf::evaluate_csv (sim/mf/mf_csv.hpp) as a stream: the output does not depend on the chunk size
// or the number of worker threads, rows keep their order, numbers are the scalar mf::evaluate's to
// the bit, errors name the line of the first bad row in input order, and skipping the extras for
// a selection without them changes no selected output. Also mf::select_eval_columns.
#include "mf/mf_csv.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "golden_path.hpp"
#include "mf/mf_eval_columns.hpp"
#include "mf/mf_evaluate.hpp"
#include "mf/mf_fixed.hpp"
#include "mf/mf_parameters_from_tir.hpp"
#include "tir/tir_file.hpp"

namespace {

using tread::mf::MfCsvOptions;
using tread::mf::MfCsvReport;
using tread::mf::MfOptions;
using tread::mf::MfParameters;

const MfParameters<double>& mf61() {
  static const MfParameters<double> p =
      tread::mf::load_mf_parameters(tread::testing::tyre_file("MagicFormula61_Parameters.tir"))
          .params;
  return p;
}

struct Point {
  double fz_n, kappa, alpha_rad, gamma_rad, vx_mps, p_pa;
};

// Operating points inside the MF 6.1 sample tyre's ranges, with full-precision values.
std::vector<Point> points(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> fz(200.0, 9000.0), kappa(-0.3, 0.3), alpha(-0.3, 0.3),
      gamma(-0.08, 0.08), vx(1.0, 40.0), p(200000.0, 300000.0);
  std::vector<Point> out(n);
  for (Point& q : out) q = {fz(rng), kappa(rng), alpha(rng), gamma(rng), vx(rng), p(rng)};
  return out;
}

std::string text(double v) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr);
}

// The points as a CSV: `sep` between cells, a decimal comma instead of the point if asked.
std::string csv_text(const std::vector<Point>& pts, char sep = ',', bool decimal_comma = false) {
  const auto cell = [&](double v) {
    std::string t = text(v);
    if (decimal_comma) std::replace(t.begin(), t.end(), '.', ',');
    return t;
  };
  std::string s = std::string("Fz_N") + sep + "kappa" + sep + "alpha_rad" + sep + "gamma_rad" +
                  sep + "Vx_mps" + sep + "P_Pa\n";
  for (const Point& q : pts) {
    s += cell(q.fz_n) + sep + cell(q.kappa) + sep + cell(q.alpha_rad) + sep + cell(q.gamma_rad) +
         sep + cell(q.vx_mps) + sep + cell(q.p_pa) + '\n';
  }
  return s;
}

MfCsvOptions stream_options(std::size_t chunk_lines, unsigned threads) {
  MfCsvOptions csv;
  csv.chunk_lines = chunk_lines;
  csv.threads = threads;
  return csv;
}

std::string evaluate(const std::string& input, const MfCsvOptions& csv,
                     MfCsvReport* report = nullptr, const MfOptions& options = {}) {
  std::istringstream in(input);
  std::ostringstream out;
  const MfCsvReport r = tread::mf::evaluate_csv(mf61(), options, csv, in, "in.csv", out);
  if (report != nullptr) *report = r;
  return out.str();
}

std::vector<std::string> split(const std::string& line, char sep = ',') {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = line.find(sep, start);
    cells.push_back(line.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) return cells;
    start = end + 1;
  }
}

// The data lines of an output (after the '#' line and the header).
std::vector<std::string> data_lines(const std::string& output) {
  std::vector<std::string> lines = split(output, '\n');
  if (!lines.empty() && lines.back().empty()) lines.pop_back();
  return std::vector<std::string>(lines.begin() + 2, lines.end());
}

std::string header_line(const std::string& output) {
  return split(output, '\n').at(1);
}

std::uint64_t bits(double v) {
  return std::bit_cast<std::uint64_t>(v);
}

double number(const std::string& cell) {
  char* end = nullptr;
  const double v = std::strtod(cell.c_str(), &end);
  EXPECT_EQ(end, cell.c_str() + cell.size()) << cell;
  return v;
}

TEST(MfCsvStream, OutputIsTheSameForAnyChunkSizeAndThreadCount) {
  const std::vector<Point> pts = points(2000, 1);
  MfCsvOptions all = stream_options(1 << 20, 1);
  all.columns = tread::mf::select_eval_columns("all").columns;
  const std::string input = csv_text(pts);
  const std::string one_chunk = evaluate(input, all);
  const std::vector<std::pair<std::size_t, unsigned>> runs = {{7, 3},    {1, 2},    {64, 4},
                                                              {1999, 2}, {2000, 2}, {2001, 2}};
  for (const auto& [chunk, threads] : runs) {
    MfCsvOptions csv = all;
    csv.chunk_lines = chunk;
    csv.threads = threads;
    MfCsvReport report;
    EXPECT_EQ(evaluate(input, csv, &report), one_chunk) << chunk << " lines, " << threads;
    EXPECT_EQ(report.rows, pts.size());
  }
  // Row i of the output is row i of the input.
  const std::vector<std::string> rows = data_lines(one_chunk);
  ASSERT_EQ(rows.size(), pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const std::vector<std::string> cells = split(rows[i]);
    EXPECT_EQ(bits(number(cells[0])), bits(pts[i].fz_n)) << i;
    EXPECT_EQ(bits(number(cells[2])), bits(pts[i].alpha_rad)) << i;
  }
}

template <typename T>
T scalar(double v) {
  if constexpr (std::is_same_v<T, tread::fixed::Fixed64>) {
    return tread::fixed::Fixed64::from_double(v);
  } else {
    return static_cast<T>(v);
  }
}

template <typename T>
double as_double(const T& v) {
  if constexpr (std::is_same_v<T, tread::fixed::Fixed64>) {
    return v.to_double();
  } else {
    return static_cast<double>(v);
  }
}

// Every value written reads back (strtod) to exactly the scalar evaluation's value, as the 17
// significant digits written before did; the status is the core's.
template <typename T>
void expect_scalar_numbers(const char* flag) {
  const std::vector<Point> pts = points(300, 2);
  MfCsvOptions csv = stream_options(16, 2);
  csv.use_float = std::is_same_v<T, float>;
  csv.use_fixed = std::is_same_v<T, tread::fixed::Fixed64>;
  csv.columns = tread::mf::select_eval_columns("all").columns;
  const std::vector<std::string> rows = data_lines(evaluate(csv_text(pts), csv));
  ASSERT_EQ(rows.size(), pts.size());
  MfParameters<T> params;
  if constexpr (std::is_same_v<T, tread::fixed::Fixed64>) {
    params = tread::mf::to_fixed_parameters(mf61());
  } else {
    params = tread::mf::convert_parameters<T>(mf61());
  }
  constexpr auto members = tread::mf::eval_output_members<T>();
  for (std::size_t i = 0; i < pts.size(); i += 3) {
    const Point& q = pts[i];
    tread::mf::MfInput<T> in;
    in.fz_n = scalar<T>(q.fz_n);
    in.kappa = scalar<T>(q.kappa);
    in.alpha_rad = scalar<T>(q.alpha_rad);
    in.gamma_rad = scalar<T>(q.gamma_rad);
    in.vx_mps = scalar<T>(q.vx_mps);
    in.p_pa = scalar<T>(q.p_pa);
    const tread::mf::MfOutput<T> expected = tread::mf::evaluate(params, in, MfOptions{});
    const std::vector<std::string> cells = split(rows[i]);
    ASSERT_EQ(cells.size(), tread::mf::kEvalColumnCount + 1);
    const double inputs[] = {q.fz_n, q.kappa, q.alpha_rad, q.gamma_rad, q.vx_mps, 0.0, q.p_pa};
    for (std::size_t c = 0; c < tread::mf::kEvalInputColumns; ++c) {
      EXPECT_EQ(bits(number(cells[c])), bits(inputs[c])) << flag << " row " << i << " col " << c;
    }
    for (std::size_t c = 0; c < tread::mf::kEvalOutputColumns; ++c) {
      const double v = as_double(expected.*(members[c]));
      EXPECT_EQ(bits(number(cells[tread::mf::kEvalInputColumns + c])), bits(v))
          << flag << " row " << i << ' '
          << tread::mf::eval_columns()[tread::mf::kEvalInputColumns + c].name << ": "
          << cells[tread::mf::kEvalInputColumns + c] << " vs " << text(v);
    }
    EXPECT_EQ(cells.back(), to_string(expected.status)) << flag << " row " << i;
  }
}

TEST(MfCsvStream, NumbersAreTheScalarEvaluationsToTheBit) {
  expect_scalar_numbers<double>("double");
  expect_scalar_numbers<float>("--float");
  expect_scalar_numbers<tread::fixed::Fixed64>("--fixed");
}

// Without an output that needs them the extras are skipped: every output computed without them
// (forces, moments, slips, friction, trail, stiffnesses in slip) and the status stay the same to
// the bit, for every Magic Formula sample tyre, modes with and without limits, α* and turn slip,
// in double, float and fixed point, inside and outside the ranges.
template <typename T>
void expect_extras_change_nothing_else(const MfParameters<double>& file, const std::string& what) {
  MfParameters<T> params;
  if constexpr (std::is_same_v<T, tread::fixed::Fixed64>) {
    params = tread::mf::to_fixed_parameters(file);
  } else {
    params = tread::mf::convert_parameters<T>(file);
  }
  constexpr auto members = tread::mf::eval_output_members<T>();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> fz(-1000.0, 25000.0), kappa(-1.5, 1.5), alpha(-1.2, 1.2),
      gamma(-0.2, 0.2), vx(-5.0, 60.0), phit(-0.5, 0.5), p(0.0, 450000.0);
  for (const int mode : {111, 121, 112, 211, 222}) {
    MfOptions with = tread::mf::options_from_use_mode(mode).value;
    MfOptions without = with;
    without.extras = false;
    for (int i = 0; i < 400; ++i) {
      tread::mf::MfInput<T> in;
      in.fz_n = scalar<T>(fz(rng));
      in.kappa = scalar<T>(kappa(rng));
      in.alpha_rad = scalar<T>(alpha(rng));
      in.gamma_rad = scalar<T>(gamma(rng));
      in.vx_mps = scalar<T>(i % 50 == 0 ? 0.0 : vx(rng));
      in.phit_1pm = scalar<T>(phit(rng));
      in.p_pa = scalar<T>(i % 3 == 0 ? 0.0 : p(rng));
      const tread::mf::MfOutput<T> a = tread::mf::evaluate(params, in, with);
      const tread::mf::MfOutput<T> b = tread::mf::evaluate(params, in, without);
      for (std::size_t c = 0; c < tread::mf::kEvalOutputColumns; ++c) {
        const tread::mf::EvalColumn& column =
            tread::mf::eval_columns()[tread::mf::kEvalInputColumns + c];
        if (column.needs_extras) continue;
        EXPECT_EQ(bits(as_double(a.*(members[c]))), bits(as_double(b.*(members[c]))))
            << what << " mode " << mode << " row " << i << ' ' << column.name;
      }
      EXPECT_EQ(a.status, b.status) << what << " mode " << mode << " row " << i;
    }
  }
}

TEST(MfCsvStream, SkippingTheExtrasChangesNoOtherOutput) {
  int tyres = 0;
  for (const auto& entry : std::filesystem::directory_iterator(tread::testing::tyres_dir())) {
    if (entry.path().extension() != ".tir") continue;
    MfParameters<double> params;
    try {
      params = tread::mf::load_mf_parameters(entry.path()).params;
    } catch (const std::exception&) {
      continue;  // PAC89 and other files `mf eval` refuses
    }
    ++tyres;
    const std::string name = entry.path().filename().string();
    expect_extras_change_nothing_else<double>(params, name + " double");
    expect_extras_change_nothing_else<float>(params, name + " float");
    expect_extras_change_nothing_else<tread::fixed::Fixed64>(params, name + " fixed");
  }
  EXPECT_GE(tyres, 8);
}

TEST(MfCsvStream, DefaultAllAndSelectedColumns) {
  const std::string input = csv_text(points(50, 4));
  const MfCsvOptions defaults = stream_options(8, 2);
  const std::string out_default = evaluate(input, defaults);
  EXPECT_EQ(header_line(out_default),
            "in_Fz_N,in_kappa,in_alpha_rad,in_gamma_rad,in_Vx_mps,in_phit_1pm,in_P_Pa,Fx_N,Fy_N,"
            "Fz_N,Mx_Nm,My_Nm,Mz_Nm,status");
  MfCsvOptions all = defaults;
  all.columns = tread::mf::select_eval_columns("all").columns;
  const std::string out_all = evaluate(input, all);
  EXPECT_EQ(header_line(out_all),
            "in_Fz_N,in_kappa,in_alpha_rad,in_gamma_rad,in_Vx_mps,in_phit_1pm,in_P_Pa,Fx_N,Fy_N,"
            "Fz_N,Mx_Nm,My_Nm,Mz_Nm,Rl_m,Re_m,kappa_1,alpha_rad,gamma_rad,phit_1pm,Vx_mps,P_Pa,"
            "rho_m,2a_m,t_m,mux_1,muy_1,omega_radps,2b_m,Mzr_Nm,Cx_Npm,Cy_Npm,Cz_Npm,Kya_Nprad,"
            "sigmax_m,sigmay_m,Kxk_N,status");
  MfCsvOptions some = defaults;
  some.columns = tread::mf::select_eval_columns("Mz_Nm, in_Fz_N,Rl_m,Kxk_N").columns;
  const std::string out_some = evaluate(input, some);
  EXPECT_EQ(header_line(out_some), "Mz_Nm,in_Fz_N,Rl_m,Kxk_N,status");
  MfCsvOptions forces = defaults;  // no extras: evaluated without them
  forces.columns = tread::mf::select_eval_columns("Fx_N,Fy_N,Mz_Nm").columns;
  const std::string out_forces = evaluate(input, forces);
  EXPECT_EQ(header_line(out_forces), "Fx_N,Fy_N,Mz_Nm,status");
  // The same cells as in the full output, row by row.
  const std::vector<std::string> full = data_lines(out_all);
  const std::vector<std::string> def = data_lines(out_default);
  const std::vector<std::string> sel = data_lines(out_some);
  const std::vector<std::string> fym = data_lines(out_forces);
  ASSERT_EQ(full.size(), 50U);
  for (std::size_t r = 0; r < full.size(); ++r) {
    const std::vector<std::string> a = split(full[r]);
    const std::vector<std::string> d = split(def[r]);
    ASSERT_EQ(d.size(), 14U);
    for (std::size_t c = 0; c < 13; ++c) EXPECT_EQ(d[c], a[c]) << r;
    EXPECT_EQ(d.back(), a.back());
    EXPECT_EQ(split(sel[r]), (std::vector<std::string>{a[12], a[0], a[13], a[35], a[36]}));
    EXPECT_EQ(split(fym[r]), (std::vector<std::string>{a[7], a[8], a[12], a[36]}));
  }
}

TEST(MfCsvStream, ColumnSelectionErrorsListTheValidNames) {
  using tread::mf::select_eval_columns;
  EXPECT_EQ(select_eval_columns("all").columns.size(), tread::mf::kEvalColumnCount);
  EXPECT_EQ(select_eval_columns(" Fx_N , status").columns, std::vector<std::size_t>{7});
  EXPECT_TRUE(select_eval_columns("status").columns.empty());
  const tread::mf::EvalColumnSelection unknown = select_eval_columns("Fx_N,Fq_N");
  EXPECT_NE(unknown.error.find("unknown column 'Fq_N'"), std::string::npos) << unknown.error;
  EXPECT_NE(unknown.error.find("valid names: all, in_Fz_N, in_kappa"), std::string::npos)
      << unknown.error;
  EXPECT_NE(unknown.error.find("Kxk_N, status"), std::string::npos) << unknown.error;
  EXPECT_NE(select_eval_columns("Fx_N,Fx_N").error.find("'Fx_N' named twice"), std::string::npos);
  EXPECT_NE(select_eval_columns("Fx_N,,Fy_N").error.find("an empty name"), std::string::npos);
  EXPECT_NE(select_eval_columns("").error.find("an empty name"), std::string::npos);
  EXPECT_FALSE(select_eval_columns("fx_n").error.empty());  // names are case-sensitive
  EXPECT_FALSE(tread::mf::needs_extras(select_eval_columns("Fx_N,Kya_Nprad,in_P_Pa").columns));
  EXPECT_TRUE(tread::mf::needs_extras(select_eval_columns("Fx_N,sigmay_m").columns));
}

TEST(MfCsvStream, DecimalCommasWithSemicolonsOrTabsGiveTheSameOutput) {
  const std::vector<Point> pts = points(500, 5);
  MfCsvOptions csv = stream_options(33, 2);
  csv.columns = tread::mf::select_eval_columns("all").columns;
  const std::string reference = evaluate(csv_text(pts), csv);
  EXPECT_EQ(evaluate(csv_text(pts, ';', true), csv), reference);
  EXPECT_EQ(evaluate(csv_text(pts, '\t', true), csv), reference);
  EXPECT_EQ(evaluate(csv_text(pts, ';', false), csv), reference);  // points are read too
}

// Blank lines, comments, CRLF, a units row, no final newline: the rows and their line numbers are
// those InputTable::next() reads, for any chunk size.
TEST(MfCsvStream, RowsAreThoseTheTableReads) {
  const std::string input =
      "# a comment\r\n\r\nFZ;SA;SL;IA;V;P\r\nN;deg;1;deg;kph;kPa\r\n\r\n# more\r\n"
      "-4000;-3,5;0,05;2;40;220\r\n  \r\n-6000;4;-0,1;-1;40;220\r\n# between\r\n"
      "-3000;1,25;0;0,5;60;180\r\n-2000;0;0;0;0;0";
  tread::mf::InputTableOptions table_options;
  table_options.convention = tread::mf::SignConvention::sae;
  std::istringstream table_in(input);
  tread::mf::InputTable table(table_in, "in.csv", table_options);
  std::vector<tread::mf::InputRow> expected;
  while (const auto row = table.next()) expected.push_back(*row);
  ASSERT_EQ(expected.size(), 4U);
  EXPECT_EQ(expected[0].line, 7);
  EXPECT_EQ(expected[3].line, 12);
  for (const std::size_t chunk : {1U, 2U, 3U, 100U}) {
    MfCsvOptions csv = stream_options(chunk, 2);
    csv.table = table_options;
    MfCsvReport report;
    const std::vector<std::string> rows = data_lines(evaluate(input, csv, &report));
    ASSERT_EQ(rows.size(), expected.size()) << chunk;
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const std::vector<std::string> cells = split(rows[r]);
      for (std::size_t q = 0; q < tread::mf::kInputQuantityCount; ++q) {
        EXPECT_EQ(bits(number(cells[q])), bits(expected[r].value[q])) << chunk << ' ' << r;
      }
    }
    // Rows 3 and 4 are outside (60 km/h is fine; 180 kPa < PRESMIN 200 kPa; Vx 0 is not
    // checked): counted with the first row's line.
    ASSERT_EQ(report.out_of_range.size(), 1U) << chunk;
    EXPECT_EQ(report.out_of_range[0].rows, 1U);
    EXPECT_EQ(report.out_of_range[0].first_line, 11);
    EXPECT_NE(report.mapping[0].find("'FZ' → Fz_N"), std::string::npos);
  }
}

std::string error_of(const std::string& input, const MfCsvOptions& csv) {
  try {
    evaluate(input, csv);
  } catch (const tread::tir::TirError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MfCsvStream, TheFirstBadRowInInputOrderIsTheError) {
  std::vector<Point> pts = points(5000, 6);
  std::string input = csv_text(pts);
  // Line n of the file is row n - 1 (the header is line 1).
  const auto line_start = [&](int line) {
    std::size_t at = 0;
    for (int i = 1; i < line; ++i) at = input.find('\n', at) + 1;
    return at;
  };
  std::string bad = input;
  bad.replace(line_start(4321), 0, "7,x,0,0,10,0\n");  // the new line 4321; kappa 'x'
  for (const unsigned threads : {1U, 2U, 5U}) {
    const std::string e = error_of(bad, stream_options(64, threads));
    EXPECT_NE(e.find("in.csv:4321: kappa: 'x' is not a finite number"), std::string::npos) << e;
  }
  // A later line with the wrong number of cells does not hide it; an earlier one does.
  std::string two = bad;
  two.replace(line_start(4900), 0, "1,2\n");
  EXPECT_NE(error_of(two, stream_options(64, 3)).find("in.csv:4321:"), std::string::npos);
  two.replace(line_start(700), 0, "1,2\n");
  const std::string e = error_of(two, stream_options(64, 3));
  EXPECT_NE(e.find("in.csv:700: expected 6 cells, found 2"), std::string::npos) << e;
  // --strict: the first row outside the range, in a late chunk, before a later parse error.
  std::string strict = bad;
  strict.replace(line_start(3001), 0, "4000,0,5,0,10,250000\n");
  MfCsvOptions csv = stream_options(64, 3);
  csv.strict = true;
  const std::string s = error_of(strict, csv);
  EXPECT_NE(s.find("in.csv:3001: alpha_rad = 5 outside the model's range"), std::string::npos) << s;
}

}  // namespace
