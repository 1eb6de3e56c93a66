// tyre::evaluate_csv (sim/tyre/mf_csv.hpp) as a stream: the output does not depend on the chunk size
// or the number of worker threads, rows keep their order, numbers are the scalar mf::evaluate's to
// the bit, errors name the line of the first bad row in input order, and skipping the extras for
// a selection without them changes no selected output. Also tyre::select_eval_columns, and --batch
// (float on mf::evaluate_batch's lanes) against the scalar float path.
#include "tyre/mf_csv.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "mf/mf_fixed.hpp"
#include "tir/tir_file.hpp"
#include "tyre/mf_eval_columns.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace {

using tread::mf::MfOptions;
using tread::mf::MfParameters;
using tread::tyre::MfCsvOptions;
using tread::tyre::MfCsvReport;

const MfParameters<double>& mf61() {
  static const MfParameters<double> p =
      tread::tyre::load_mf_parameters(tread::testing::tyre_file("MagicFormula61_Parameters.tir"))
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

std::string evaluate_with(const MfParameters<double>& params, const std::string& input,
                          const MfCsvOptions& csv, MfCsvReport* report = nullptr,
                          const MfOptions& options = {}) {
  std::istringstream in(input);
  std::ostringstream out;
  const MfCsvReport r = tread::tyre::evaluate_csv(params, options, csv, in, "in.csv", out);
  if (report != nullptr) *report = r;
  return out.str();
}

std::string evaluate(const std::string& input, const MfCsvOptions& csv,
                     MfCsvReport* report = nullptr, const MfOptions& options = {}) {
  return evaluate_with(mf61(), input, csv, report, options);
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

/// Calls `f(file name, parameters)` for every shipped tyre that `mf eval` takes (PAC89 and other
/// files it refuses are skipped); returns how many.
template <typename F>
int for_each_mf_tyre(F&& f) {
  int tyres = 0;
  for (const auto& entry : std::filesystem::directory_iterator(tread::testing::tyres_dir())) {
    if (entry.path().extension() != ".tir") continue;
    MfParameters<double> params;
    try {
      params = tread::tyre::load_mf_parameters(entry.path()).params;
    } catch (const std::exception&) {
      continue;
    }
    ++tyres;
    f(entry.path().filename().string(), params);
  }
  return tyres;
}

TEST(MfCsvStream, OutputIsTheSameForAnyChunkSizeAndThreadCount) {
  const std::vector<Point> pts = points(2000, 1);
  MfCsvOptions all = stream_options(1 << 20, 1);
  all.columns = tread::tyre::select_eval_columns("all").columns;
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
  csv.columns = tread::tyre::select_eval_columns("all").columns;
  const std::vector<std::string> rows = data_lines(evaluate(csv_text(pts), csv));
  ASSERT_EQ(rows.size(), pts.size());
  MfParameters<T> params;
  if constexpr (std::is_same_v<T, tread::fixed::Fixed64>) {
    params = tread::mf::to_fixed_parameters(mf61());
  } else {
    params = tread::mf::convert_parameters<T>(mf61());
  }
  constexpr auto members = tread::tyre::eval_output_members<T>();
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
    ASSERT_EQ(cells.size(), tread::tyre::kEvalColumnCount + 1);
    const double inputs[] = {q.fz_n, q.kappa, q.alpha_rad, q.gamma_rad, q.vx_mps, 0.0, q.p_pa};
    for (std::size_t c = 0; c < tread::tyre::kEvalInputColumns; ++c) {
      EXPECT_EQ(bits(number(cells[c])), bits(inputs[c])) << flag << " row " << i << " col " << c;
    }
    for (std::size_t c = 0; c < tread::tyre::kEvalOutputColumns; ++c) {
      const double v = as_double(expected.*(members[c]));
      EXPECT_EQ(bits(number(cells[tread::tyre::kEvalInputColumns + c])), bits(v))
          << flag << " row " << i << ' '
          << tread::tyre::eval_columns()[tread::tyre::kEvalInputColumns + c].name << ": "
          << cells[tread::tyre::kEvalInputColumns + c] << " vs " << text(v);
    }
    EXPECT_EQ(cells.back(), to_string(expected.status)) << flag << " row " << i;
  }
}

TEST(MfCsvStream, NumbersAreTheScalarEvaluationsToTheBit) {
  expect_scalar_numbers<double>("double");
  expect_scalar_numbers<float>("--float");
  expect_scalar_numbers<tread::fixed::Fixed64>("--fixed");
}

// Without an output that needs them the extras are skipped, and Mx and My: every output computed
// without them (forces, moments, slips, friction, trail, stiffnesses in slip) and the status stay
// the same to the bit, and Mx, My are 0 where skipped, for every Magic Formula sample tyre, modes
// with and without limits, α* and turn slip, in double, float and fixed point, inside and outside
// the ranges.
enum class Skip { extras, moments_xy, both };

template <typename T>
void expect_skips_change_nothing_else(const MfParameters<double>& file, Skip skip,
                                      const std::string& what) {
  MfParameters<T> params;
  if constexpr (std::is_same_v<T, tread::fixed::Fixed64>) {
    params = tread::mf::to_fixed_parameters(file);
  } else {
    params = tread::mf::convert_parameters<T>(file);
  }
  constexpr auto members = tread::tyre::eval_output_members<T>();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> fz(-1000.0, 25000.0), kappa(-1.5, 1.5), alpha(-1.2, 1.2),
      gamma(-0.2, 0.2), vx(-5.0, 60.0), phit(-0.5, 0.5), p(0.0, 450000.0);
  for (const int mode : {111, 121, 112, 211, 222}) {
    MfOptions with = tread::mf::options_from_use_mode(mode).value;
    MfOptions without = with;
    without.extras = skip == Skip::moments_xy;
    without.moments_xy = skip == Skip::extras;
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
      for (std::size_t c = 0; c < tread::tyre::kEvalOutputColumns; ++c) {
        const tread::tyre::EvalColumn& column =
            tread::tyre::eval_columns()[tread::tyre::kEvalInputColumns + c];
        const bool moment_xy = column.name == "Mx_Nm" || column.name == "My_Nm";
        if (column.needs_extras && !without.extras) continue;
        if (moment_xy && !without.moments_xy) {
          EXPECT_EQ(as_double(b.*(members[c])), 0.0) << what << " row " << i << ' ' << column.name;
          continue;
        }
        EXPECT_EQ(bits(as_double(a.*(members[c]))), bits(as_double(b.*(members[c]))))
            << what << " mode " << mode << " row " << i << ' ' << column.name;
      }
      EXPECT_EQ(a.status, b.status) << what << " mode " << mode << " row " << i;
    }
  }
}

TEST(MfCsvStream, SkippingTheExtrasOrMxMyChangesNoOtherOutput) {
  const int tyres =
      for_each_mf_tyre([&](const std::string& name, const MfParameters<double>& params) {
        for (const Skip skip : {Skip::extras, Skip::moments_xy, Skip::both}) {
          const std::string what = name + " skip " + std::to_string(static_cast<int>(skip));
          expect_skips_change_nothing_else<double>(params, skip, what + " double");
          expect_skips_change_nothing_else<float>(params, skip, what + " float");
          expect_skips_change_nothing_else<tread::fixed::Fixed64>(params, skip, what + " fixed");
        }
      });
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
  all.columns = tread::tyre::select_eval_columns("all").columns;
  const std::string out_all = evaluate(input, all);
  EXPECT_EQ(header_line(out_all),
            "in_Fz_N,in_kappa,in_alpha_rad,in_gamma_rad,in_Vx_mps,in_phit_1pm,in_P_Pa,Fx_N,Fy_N,"
            "Fz_N,Mx_Nm,My_Nm,Mz_Nm,Rl_m,Re_m,kappa_1,alpha_rad,gamma_rad,phit_1pm,Vx_mps,P_Pa,"
            "rho_m,2a_m,t_m,mux_1,muy_1,omega_radps,2b_m,Mzr_Nm,Cx_Npm,Cy_Npm,Cz_Npm,Kya_Nprad,"
            "sigmax_m,sigmay_m,Kxk_N,status");
  MfCsvOptions some = defaults;
  some.columns = tread::tyre::select_eval_columns("Mz_Nm, in_Fz_N,Rl_m,Kxk_N").columns;
  const std::string out_some = evaluate(input, some);
  EXPECT_EQ(header_line(out_some), "Mz_Nm,in_Fz_N,Rl_m,Kxk_N,status");
  MfCsvOptions forces = defaults;  // no extras: evaluated without them
  forces.columns = tread::tyre::select_eval_columns("Fx_N,Fy_N,Mz_Nm").columns;
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
  using tread::tyre::select_eval_columns;
  EXPECT_EQ(select_eval_columns("all").columns.size(), tread::tyre::kEvalColumnCount);
  EXPECT_EQ(select_eval_columns(" Fx_N , status").columns, std::vector<std::size_t>{7});
  EXPECT_TRUE(select_eval_columns("status").columns.empty());
  const tread::tyre::EvalColumnSelection unknown = select_eval_columns("Fx_N,Fq_N");
  EXPECT_NE(unknown.error.find("unknown column 'Fq_N'"), std::string::npos) << unknown.error;
  EXPECT_NE(unknown.error.find("valid names: all, in_Fz_N, in_kappa"), std::string::npos)
      << unknown.error;
  EXPECT_NE(unknown.error.find("Kxk_N, status"), std::string::npos) << unknown.error;
  EXPECT_NE(select_eval_columns("Fx_N,Fx_N").error.find("'Fx_N' named twice"), std::string::npos);
  EXPECT_NE(select_eval_columns("Fx_N,,Fy_N").error.find("an empty name"), std::string::npos);
  EXPECT_NE(select_eval_columns("").error.find("an empty name"), std::string::npos);
  EXPECT_FALSE(select_eval_columns("fx_n").error.empty());  // names are case-sensitive
  EXPECT_FALSE(tread::tyre::needs_extras(select_eval_columns("Fx_N,Kya_Nprad,in_P_Pa").columns));
  EXPECT_TRUE(tread::tyre::needs_extras(select_eval_columns("Fx_N,sigmay_m").columns));
}

TEST(MfCsvStream, DecimalCommasWithSemicolonsOrTabsGiveTheSameOutput) {
  const std::vector<Point> pts = points(500, 5);
  MfCsvOptions csv = stream_options(33, 2);
  csv.columns = tread::tyre::select_eval_columns("all").columns;
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
  tread::tyre::InputTableOptions table_options;
  table_options.convention = tread::tyre::SignConvention::sae;
  std::istringstream table_in(input);
  tread::tyre::InputTable table(table_in, "in.csv", table_options);
  std::vector<tread::tyre::InputRow> expected;
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
      for (std::size_t q = 0; q < tread::tyre::kInputQuantityCount; ++q) {
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

// The rows counted outside each limit, at every bound, one step either side of it, far beyond it,
// 0 and -0, one input at a time (the others inside): a value equal to its bound is inside; a
// pressure of 0 (the file's INFLPRES) is never outside; without a pressure column (read as 0) no
// row is outside PRESMIN or PRESMAX. Counted against the limits' definition, row by row.
// MF 6.2's vertical force has roots far above the free radius for a light, cambered wheel (Rl
// 0.47 m for the 0.394 m sample tyre at 200 N and 0.05 rad): counted and said where Rl is shown,
// with the first row's line; a row at a normal load is not counted, nor is an MF 6.1 tyre.
TEST(MfCsvStream, LoadedRadiusAboveTheFreeRadiusIsSaid) {
  const MfParameters<double> mf62 =
      tread::tyre::load_mf_parameters(tread::testing::tyre_file("MagicFormula62_Parameters.tir"))
          .params;
  const std::string input =
      "Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps\n4000,0,0.05,0.05,16\n200,0,0.05,0.05,16\n"
      "200,0,0.05,0.05,16\n";
  MfCsvOptions csv;
  csv.columns = tread::tyre::select_eval_columns("all").columns;
  MfCsvReport report;
  const std::string out = evaluate_with(mf62, input, csv, &report);
  ASSERT_EQ(report.warnings.size(), 1u) << out;
  EXPECT_EQ(report.warnings[0].rfind("2 rows (the first at in.csv:3) have a loaded radius Rl more "
                                     "than 2 % above the free radius",
                                     0),
            0u)
      << report.warnings[0];
  csv.columns = tread::tyre::select_eval_columns("Fx_N,Fy_N").columns;  // no Rl shown: no check
  evaluate_with(mf62, input, csv, &report);
  EXPECT_TRUE(report.warnings.empty());
  csv.columns = tread::tyre::select_eval_columns("all").columns;
  evaluate_with(mf61(), input, csv, &report);
  EXPECT_TRUE(report.warnings.empty());
}

TEST(MfCsvStream, RangeCountsAtEveryBound) {
  const MfParameters<double>& p = mf61();
  struct Bound {
    std::size_t column;  // in Point order: Fz, kappa, alpha, gamma, Vx, P
    double value;
    bool above;
    const char* key;
  };
  const Bound bounds[] = {{0, p.fzmin_n, false, "FZMIN"},      {0, p.fzmax_n, true, "FZMAX"},
                          {1, p.kpumin, false, "KPUMIN"},      {1, p.kpumax, true, "KPUMAX"},
                          {2, p.alpmin_rad, false, "ALPMIN"},  {2, p.alpmax_rad, true, "ALPMAX"},
                          {3, p.cammin_rad, false, "CAMMIN"},  {3, p.cammax_rad, true, "CAMMAX"},
                          {5, p.presmin_pa, false, "PRESMIN"}, {5, p.presmax_pa, true, "PRESMAX"}};
  const Point inside = {4000.0, 0.01, 0.02, 0.01, 20.0, 0.5 * (p.presmin_pa + p.presmax_pa)};
  std::vector<Point> rows;
  for (const Bound& b : bounds) {
    const double inf = std::numeric_limits<double>::infinity();
    // Far below PRESMIN is still a positive pressure (0 and below take the file's INFLPRES).
    const double far = b.above                                ? 2.0 * std::fabs(b.value) + 1.0
                       : b.key == std::string_view("PRESMIN") ? 0.5 * b.value
                                                              : -2.0 * std::fabs(b.value) - 1.0;
    for (const double v :
         {b.value, std::nextafter(b.value, inf), std::nextafter(b.value, -inf), far, 0.0, -0.0}) {
      Point q = inside;
      double* cell[] = {&q.fz_n, &q.kappa, &q.alpha_rad, &q.gamma_rad, &q.vx_mps, &q.p_pa};
      *cell[b.column] = v;
      rows.push_back(q);
    }
  }
  for (const bool with_pressure : {true, false}) {
    std::string input = csv_text(rows);
    if (!with_pressure) {  // the last column dropped
      std::string cut;
      std::istringstream lines(input);
      for (std::string line; std::getline(lines, line);)
        cut += line.substr(0, line.rfind(',')) + '\n';
      input = cut;
    }
    MfCsvReport report;
    evaluate(input, stream_options(7, 2), &report);
    for (const Bound& b : bounds) {
      std::size_t expected = 0;
      int first_line = 0;
      for (std::size_t r = 0; r < rows.size(); ++r) {
        const Point& q = rows[r];
        const double values[] = {q.fz_n, q.kappa, q.alpha_rad, q.gamma_rad, q.vx_mps, q.p_pa};
        const double v = values[b.column];
        if (b.column == 5 && (!with_pressure || !(std::fabs(v) > 0.0))) continue;
        if (b.above ? v > b.value : v < b.value) {
          if (expected++ == 0) first_line = static_cast<int>(r) + 2;  // after the header
        }
      }
      const auto found =
          std::find_if(report.out_of_range.begin(), report.out_of_range.end(),
                       [&](const auto& c) { return c.limit.find(b.key) != std::string::npos; });
      if (expected == 0) {
        EXPECT_EQ(found, report.out_of_range.end()) << b.key << ' ' << with_pressure;
      } else {
        ASSERT_NE(found, report.out_of_range.end()) << b.key << ' ' << with_pressure;
        EXPECT_EQ(found->rows, expected) << b.key << ' ' << with_pressure;
        EXPECT_EQ(found->first_line, first_line) << b.key << ' ' << with_pressure;
      }
    }
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

// --batch: the rows of a chunk evaluated in float on mf::evaluate_batch's lanes (256 rows at a
// time, 8 lanes on x86-64) instead of row by row. Against --float (the scalar float path) over
// every shipped Magic Formula tyre, modes with and without limits, α* and turn slip, all columns:
// the same rows, inputs as read, the same status and every output within 2e-5 of its column's
// largest magnitude. The batch equals evaluate_four within 1e-5 of that scale
// (tests/mf/mf_evaluate_batch_test.cpp), evaluate_four the scalar path within float rounding
// (the lanes' elementary functions are not libm's; mf_evaluate_four_test.cpp), so the two add
// up: on these inputs every column is within 1e-5 except the residual moment Mzr_Nm, a
// difference of larger terms, at two rows of MF 6.1 / MF 6.2 at large slip (κ 0.85, α 0.59 rad
// at 0.58 m/s, limits off; κ −0.72 at Fz 22.6 kN): 1.6e-5 and 1.3e-5 of its scale, where the two
// are 0.45e-5 / 1.15e-5 and 0.8e-5 / 0.45e-5 of it from double (--float / --batch): float
// rounding either way, not a lane's error. The worst is printed. The
// row count is no multiple of the lanes or the batch, and chunks of 333 lines end mid-block, so
// that partial blocks (padded by evaluate_batch) are everywhere; blank and comment lines shift
// the rows against the blocks.

// Operating points inside and well outside the usual ranges, with a phit column.
std::string wide_input(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> fz(-500.0, 25000.0), kappa(-1.2, 1.2), alpha(-0.8, 0.8),
      gamma(-0.25, 0.25), vx(-5.0, 60.0), phit(-0.5, 0.5), p(0.0, 450000.0);
  std::string s = "Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps,phit_1pm,P_Pa\n";
  for (std::size_t i = 0; i < n; ++i) {
    if (i % 97 == 13) s += "\n";
    if (i % 151 == 40) s += "# a comment between rows\n";
    s += text(fz(rng)) + ',' + text(kappa(rng)) + ',' + text(alpha(rng)) + ',' + text(gamma(rng)) +
         ',' + text(i % 41 == 7 ? 0.0 : vx(rng)) + ',' + text(i % 3 == 0 ? phit(rng) : 0.0) + ',' +
         text(i % 5 == 0 ? 0.0 : p(rng)) + '\n';
  }
  return s;
}

// Rows that are numbers to the reader but not sensible inputs: beyond float's range (inf in
// float), subnormal, zero load and speed, negative pressure.
const std::vector<std::string>& wild_rows() {
  static const std::vector<std::string> rows = {"1e39,0.1,0.05,0,16,0,0",
                                                "4000,-1e39,0,0,16,0,0",
                                                "4000,0,1e39,0.01,16,0,0",
                                                "4000,0.05,0.05,-1e39,16,0,0",
                                                "4000,0.05,0.05,0,1e39,0,0",
                                                "4000,0.05,0.05,0,16,1e39,0",
                                                "4000,0.05,0.05,0,16,0,1e39",
                                                "1e-45,1e-45,1e-45,1e-45,1e-45,1e-45,1e-45",
                                                "0,0,0,0,0,0,0",
                                                "-3e38,3e38,-3e38,3e38,-3e38,3e38,-3e38",
                                                "4000,0.1,0.1,0.05,16,0,-2e5",
                                                "1e30,0.1,0.1,0.05,16,0.2,2e5"};
  return rows;
}

struct Cells {
  std::vector<double> value;
  std::string status;
};

std::vector<Cells> table_of(const std::string& output) {
  std::vector<Cells> rows;
  for (const std::string& line : data_lines(output)) {
    std::vector<std::string> cells = split(line);
    Cells c;
    c.status = cells.back();
    cells.pop_back();
    for (const std::string& cell : cells) c.value.push_back(number(cell));
    rows.push_back(std::move(c));
  }
  return rows;
}

// The largest |--batch − --float| relative to the column's scale, and where.
struct Worst {
  double ratio = 0.0;
  std::string where;
  std::size_t rows = 0;       // rows compared
  std::size_t bit_equal = 0;  // rows with every value the same to the bit
};

// Compares --batch with --float row by row; `ordinary` rows (flagged per row) set the column
// scales, a row outside them is compared within 2e-5 of the larger of that scale and its value.
void expect_batch_as_float(const std::string& batch, const std::string& scalar,
                           const std::vector<bool>& ordinary, const std::string& what,
                           Worst* worst) {
  ASSERT_EQ(header_line(batch), header_line(scalar)) << what;
  const std::vector<Cells> b = table_of(batch);
  const std::vector<Cells> f = table_of(scalar);
  ASSERT_EQ(b.size(), f.size()) << what;
  ASSERT_EQ(b.size(), ordinary.size()) << what;
  std::vector<double> scale(tread::tyre::kEvalColumnCount, 0.0);
  for (std::size_t r = 0; r < f.size(); ++r) {
    if (!ordinary[r]) continue;
    for (std::size_t c = 0; c < scale.size(); ++c) {
      scale[c] = std::max(scale[c], std::fabs(f[r].value[c]));
    }
  }
  const std::vector<std::string> names = split(header_line(scalar));
  for (std::size_t r = 0; r < f.size(); ++r) {
    ASSERT_EQ(b[r].status, f[r].status) << what << " row " << r;
    bool same = true;
    for (std::size_t c = 0; c < scale.size(); ++c) {
      const double expected = f[r].value[c];
      const double got = b[r].value[c];
      same = same && bits(got) == bits(expected);
      if (c < tread::tyre::kEvalInputColumns) {
        ASSERT_EQ(bits(got), bits(expected)) << what << " row " << r << ' ' << names[c];
        continue;
      }
      const double column_scale = std::max(scale[c], ordinary[r] ? 0.0 : std::fabs(expected));
      const double difference = std::fabs(got - expected);
      ASSERT_LE(difference, 2e-5 * column_scale)
          << what << " row " << r << ' ' << names[c] << ": " << got << " vs " << expected;
      if (difference > worst->ratio * column_scale) {
        worst->ratio = difference / column_scale;
        worst->where = what + " row " + std::to_string(r) + ' ' + names[c];
      }
    }
    ++worst->rows;
    worst->bit_equal += same ? 1U : 0U;
  }
}

TEST(MfCsvBatch, AgreesWithTheScalarFloatPathOverEveryTyre) {
  MfCsvOptions csv = stream_options(333, 2);
  csv.columns = tread::tyre::select_eval_columns("all").columns;
  MfCsvOptions as_float = csv;
  as_float.use_float = true;
  MfCsvOptions as_batch = csv;
  as_batch.use_batch = true;
  Worst worst;
  const int tyres =
      for_each_mf_tyre([&](const std::string& name, const MfParameters<double>& params) {
        // 1003 ordinary rows, then the same with the wild rows among them, every 83rd row.
        const std::string input = wide_input(1003, 11);
        std::vector<std::string> lines = split(input, '\n');
        lines.pop_back();
        std::string mixed = lines[0] + '\n';
        std::vector<bool> ordinary;
        std::size_t wild = 0;
        for (std::size_t l = 1; l < lines.size(); ++l) {
          if (l % 83 == 50) {
            mixed += wild_rows()[wild++ % wild_rows().size()] + '\n';
            ordinary.push_back(false);
          }
          mixed += lines[l] + '\n';
          if (!lines[l].empty() && lines[l][0] != '#') ordinary.push_back(true);
        }
        const std::vector<bool> all_ordinary(1003, true);
        for (const int mode : {111, 121, 112, 211, 222}) {
          const MfOptions o = tread::mf::options_from_use_mode(mode).value;
          const std::string what = name + " mode " + std::to_string(mode);
          const std::string batch = evaluate_with(params, input, as_batch, nullptr, o);
          expect_batch_as_float(batch, evaluate_with(params, input, as_float, nullptr, o),
                                all_ordinary, what, &worst);
          const std::string batch_mixed = evaluate_with(params, mixed, as_batch, nullptr, o);
          expect_batch_as_float(batch_mixed, evaluate_with(params, mixed, as_float, nullptr, o),
                                ordinary, what + " with wild rows", &worst);
          // A row's values do not depend on its neighbours or its place in a block: the ordinary
          // rows are the same to the bit with the wild rows among them.
          const std::vector<std::string> plain_rows = data_lines(batch);
          const std::vector<std::string> mixed_rows = data_lines(batch_mixed);
          ASSERT_EQ(mixed_rows.size(), ordinary.size());
          std::size_t next = 0;
          for (std::size_t r = 0; r < mixed_rows.size(); ++r) {
            if (ordinary[r]) {
              EXPECT_EQ(mixed_rows[r], plain_rows[next++]) << what << " row " << r;
            }
          }
        }
      });
  EXPECT_GE(tyres, 8);
  std::printf(
      "[ compared ] %zu rows with --float, %zu bit for bit; worst %.2g of the column's "
      "scale (%s)\n",
      worst.rows, worst.bit_equal, worst.ratio, worst.where.c_str());
}

TEST(MfCsvBatch, OutputIsTheSameForAnyChunkSizeAndThreadCount) {
  const std::string input = wide_input(2003, 12);
  MfCsvOptions csv = stream_options(1 << 20, 1);
  csv.use_batch = true;
  csv.columns = tread::tyre::select_eval_columns("all").columns;
  const std::string one_chunk = evaluate(input, csv);
  EXPECT_EQ(data_lines(one_chunk).size(), 2003U);
  for (const auto& [chunk, threads] : std::vector<std::pair<std::size_t, unsigned>>{
           {1, 2}, {7, 3}, {255, 2}, {256, 2}, {257, 4}, {2100, 2}}) {
    MfCsvOptions c = csv;
    c.chunk_lines = chunk;
    c.threads = threads;
    EXPECT_EQ(evaluate(input, c), one_chunk) << chunk << " lines, " << threads;
  }
  // The default columns (no extras: evaluated without them): the same cells as in all columns.
  MfCsvOptions defaults = csv;
  defaults.columns = tread::tyre::default_eval_columns();
  const std::vector<std::string> def = data_lines(evaluate(input, defaults));
  const std::vector<std::string> all = data_lines(one_chunk);
  ASSERT_EQ(def.size(), all.size());
  for (std::size_t r = 0; r < def.size(); ++r) {
    const std::vector<std::string> d = split(def[r]);
    const std::vector<std::string> a = split(all[r]);
    for (std::size_t c = 0; c < 13; ++c) EXPECT_EQ(d[c], a[c]) << r;
    EXPECT_EQ(d.back(), a.back()) << r;
  }
}

// The errors of --batch are those of --float: the first bad row in input order, named by its line,
// whether it is a cell that is no number (NaN, inf, text) in the middle of a batch, a row with the
// wrong number of cells, or (--strict) a row outside the range before a later bad cell in the same
// batch.
TEST(MfCsvBatch, TheFirstBadRowInInputOrderIsTheError) {
  const std::vector<Point> pts = points(3000, 7);
  const std::string input = csv_text(pts);
  const auto line_start = [&](const std::string& text, int line) {
    std::size_t at = 0;
    for (int i = 1; i < line; ++i) at = text.find('\n', at) + 1;
    return at;
  };
  const auto with = [&](const std::string& text, int line, const std::string& row) {
    std::string t = text;
    t.replace(line_start(t, line), 0, row + '\n');
    return t;
  };
  const auto errors = [&](const std::string& text, bool strict) {
    std::vector<std::string> e;
    for (const bool batch : {false, true}) {
      MfCsvOptions csv = stream_options(1000, 2);
      csv.use_float = !batch;
      csv.use_batch = batch;
      csv.strict = strict;
      e.push_back(error_of(text, csv));
    }
    return e;
  };
  const std::string nan_cell = with(input, 1130, "4000,nan,0,0,10,250000");
  for (const std::string& e : errors(nan_cell, false)) {
    EXPECT_NE(e.find("in.csv:1130: kappa: 'nan' is not a finite number"), std::string::npos) << e;
  }
  const std::string inf_cell = with(nan_cell, 1010, "4000,0,inf,0,10,250000");
  for (const std::string& e : errors(inf_cell, false)) {
    EXPECT_NE(e.find("in.csv:1010: alpha_rad: 'inf' is not a finite number"), std::string::npos)
        << e;
  }
  const std::string short_row = with(inf_cell, 1005, "1,2");
  for (const std::string& e : errors(short_row, false)) {
    EXPECT_NE(e.find("in.csv:1005: expected 6 cells, found 2"), std::string::npos) << e;
  }
  // --strict: a row outside the range in the same batch, before the bad cells.
  const std::string strict = with(short_row, 1003, "4000,0,5,0,10,250000");
  for (const std::string& e : errors(strict, true)) {
    EXPECT_NE(e.find("in.csv:1003: alpha_rad = 5 outside the model's range"), std::string::npos)
        << e;
  }
  // Without --strict the range is counted and the first bad cell is the error.
  for (const std::string& e : errors(strict, false)) {
    EXPECT_NE(e.find("in.csv:1006: expected 6 cells, found 2"), std::string::npos) << e;
  }
}

// The --batch report is --float's: rows, mapping, the rows outside each limit and their first
// lines.
TEST(MfCsvBatch, ReportsTheSameRangeCounts) {
  const std::string input = wide_input(1500, 13);
  MfCsvOptions as_float = stream_options(400, 2);
  as_float.use_float = true;
  MfCsvOptions as_batch = stream_options(400, 2);
  as_batch.use_batch = true;
  MfCsvReport f;
  MfCsvReport b;
  evaluate(input, as_float, &f);
  evaluate(input, as_batch, &b);
  EXPECT_EQ(b.rows, 1500U);
  EXPECT_EQ(b.rows, f.rows);
  EXPECT_EQ(b.mapping, f.mapping);
  ASSERT_EQ(b.out_of_range.size(), f.out_of_range.size());
  EXPECT_GE(b.out_of_range.size(), 6U);
  for (std::size_t i = 0; i < b.out_of_range.size(); ++i) {
    EXPECT_EQ(b.out_of_range[i].limit, f.out_of_range[i].limit);
    EXPECT_EQ(b.out_of_range[i].rows, f.out_of_range[i].rows);
    EXPECT_EQ(b.out_of_range[i].first_line, f.out_of_range[i].first_line);
  }
}

}  // namespace
