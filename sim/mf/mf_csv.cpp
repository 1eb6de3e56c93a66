#include "mf/mf_csv.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <istream>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <vector>

#include "mf/mf_evaluate.hpp"
#include "mf/mf_fixed.hpp"
#include "tir/tir_file.hpp"

namespace tread::mf {

namespace {

enum Column { kFz, kKappa, kAlpha, kGamma, kVx, kPhit, kP, kColumnCount };
static_assert(kColumnCount == kInputQuantityCount);

template <typename T>
struct OutColumn {
  std::string_view name;
  T MfOutput<T>::*member;
};

template <typename T>
constexpr std::array<OutColumn<T>, 29> out_columns() {
  using O = MfOutput<T>;
  return {{{"Fx_N", &O::fx_n},
           {"Fy_N", &O::fy_n},
           {"Fz_N", &O::fz_n},
           {"Mx_Nm", &O::mx_nm},
           {"My_Nm", &O::my_nm},
           {"Mz_Nm", &O::mz_nm},
           {"Rl_m", &O::rl_m},
           {"Re_m", &O::re_m},
           {"kappa_1", &O::kappa},
           {"alpha_rad", &O::alpha_rad},
           {"gamma_rad", &O::gamma_rad},
           {"phit_1pm", &O::phit_1pm},
           {"Vx_mps", &O::vx_mps},
           {"P_Pa", &O::p_pa},
           {"rho_m", &O::rho_m},
           {"2a_m", &O::contact_length_m},
           {"t_m", &O::t_m},
           {"mux_1", &O::mux},
           {"muy_1", &O::muy},
           {"omega_radps", &O::omega_radps},
           {"2b_m", &O::contact_width_m},
           {"Mzr_Nm", &O::mzr_nm},
           {"Cx_Npm", &O::cx_npm},
           {"Cy_Npm", &O::cy_npm},
           {"Cz_Npm", &O::cz_npm},
           {"Kya_Nprad", &O::kya_nprad},
           {"sigmax_m", &O::sigmax_m},
           {"sigmay_m", &O::sigmay_m},
           {"Kxk_N", &O::kxk_n}}};
}

std::string format(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

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

template <typename T>
// Returns the first output column that is not finite under status ok ("" when none).
std::string write_row(std::ostream& out, const std::array<double, kColumnCount>& values,
                      const MfParameters<T>& params, const MfOptions& options) {
  MfInput<T> in;
  in.fz_n = scalar_of<T>(values[kFz]);
  in.kappa = scalar_of<T>(values[kKappa]);
  in.alpha_rad = scalar_of<T>(values[kAlpha]);
  in.gamma_rad = scalar_of<T>(values[kGamma]);
  in.vx_mps = scalar_of<T>(values[kVx]);
  in.phit_1pm = scalar_of<T>(values[kPhit]);
  in.p_pa = scalar_of<T>(values[kP]);
  const MfOutput<T> result = evaluate(params, in, options);
  std::string non_finite;
  for (double v : values) out << format(v) << ',';
  for (const auto& c : out_columns<T>()) {
    const double v = as_double(result.*(c.member));
    if (!std::isfinite(v) && non_finite.empty())
      non_finite = std::string(c.name) + " = " + format(v);
    out << format(v) << ',';
  }
  out << to_string(result.status) << '\n';
  return result.status == Status::ok ? non_finite : std::string();
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
  const std::string column = table.column_name(l.quantity);
  const std::string_view unit = table.column_unit(l.quantity);
  if ((l.quantity == InputQuantity::alpha || l.quantity == InputQuantity::gamma) && unit == "rad") {
    const std::string deg = l.quantity == InputQuantity::alpha ? "alpha_deg" : "gamma_deg";
    return "; column '" + column + "' is read in radians: if it holds degrees, name it " + deg;
  }
  if (l.quantity == InputQuantity::kappa && unit == "1" && std::fabs(value) > 1.0) {
    return "; column '" + column + "' is read as a ratio: if it holds percent, name it kappa_pct";
  }
  if (l.quantity == InputQuantity::fz && value < 0.0) {
    return "; a negative load: is the file in SAE axes (z down)? Use --convention sae";
  }
  if (l.quantity == InputQuantity::pressure && unit == "Pa") {
    return "; column '" + column + "' is read in Pa: name it P_kPa, P_bar or P_psi otherwise";
  }
  return {};
}

}  // namespace

MfCsvReport evaluate_csv(const MfParameters<double>& params, const MfOptions& options,
                         const MfCsvOptions& csv, std::istream& in, const std::string& in_name,
                         std::ostream& out) {
  const MfParameters<float> params_f = convert_parameters<float>(params);
  const MfParameters<fixed::Fixed64> params_q =
      csv.use_fixed ? to_fixed_parameters(params) : MfParameters<fixed::Fixed64>{};
  InputTable table(in, in_name, csv.table);
  MfCsvReport report;
  report.ignored = table.ignored_columns();

  using Q = InputQuantity;
  const Limit limits[] = {
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
  };
  std::vector<MfRangeCount> counts;
  for (const Limit& l : limits) counts.push_back({describe(l), 0, 0});

  out << "# tread mf eval: ISO-W (TYDEX W) axes, SI units (inputs read in "
      << to_string(csv.table.convention) << " axes and converted)\n";
  out << "in_Fz_N,in_kappa,in_alpha_rad,in_gamma_rad,in_Vx_mps,in_phit_1pm,in_P_Pa";
  for (const auto& c : out_columns<double>()) out << ',' << c.name;
  out << ",status\n";
  while (const std::optional<InputRow> row = table.next()) {
    for (std::size_t i = 0; i < std::size(limits); ++i) {
      const Limit& l = limits[i];
      const double v = (*row)[l.quantity];
      if (l.quantity == Q::pressure && (!(std::fabs(v) > 0.0) || !table.has(Q::pressure))) continue;
      if (!(l.above ? v > l.bound : v < l.bound)) continue;
      if (csv.strict) {
        throw tir::TirError(in_name, row->line,
                            std::string(si_name(l.quantity)) + " = " + short_number(v) +
                                " outside the model's range (" + describe(l) + ", --strict)" +
                                hint(table, l, v));
      }
      if (counts[i].rows++ == 0) counts[i].first_line = row->line;
    }
    std::array<double, kColumnCount> values{};
    for (std::size_t q = 0; q < kColumnCount; ++q) values[q] = row->value[q];
    const std::string non_finite = csv.use_fixed   ? write_row(out, values, params_q, options)
                                   : csv.use_float ? write_row(out, values, params_f, options)
                                                   : write_row(out, values, params, options);
    if (!non_finite.empty()) {
      // Never a NaN or Inf under status ok. The core already writes a non-finite output as 0
      // with Status::non_finite; this is the last check where numbers leave the program.
      throw tir::TirError(in_name, row->line,
                          non_finite +
                              " under status ok: the tyre's parameters give no finite "
                              "result for this row (check the .tir for zero or missing "
                              "stiffnesses and radii)");
    }
    ++report.rows;
  }
  for (const MfRangeCount& c : counts) {
    if (c.rows > 0) report.out_of_range.push_back(c);
  }
  report.mapping = table.mapping();  // after a units row, if any, was read
  return report;
}

}  // namespace tread::mf
