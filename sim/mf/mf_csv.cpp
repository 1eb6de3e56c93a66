#include "mf/mf_csv.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "mf/mf_evaluate.hpp"

namespace tread::mf {

namespace {

enum Column { kFz, kKappa, kAlpha, kGamma, kVx, kPhit, kP, kColumnCount };

constexpr std::array<std::string_view, kColumnCount> kInputNames = {
    "Fz_N", "kappa", "alpha_rad", "gamma_rad", "Vx_mps", "phit_1pm", "P_Pa"};

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

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    std::string cell =
        line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    // trim spaces
    const std::size_t a = cell.find_first_not_of(" \t");
    const std::size_t b = cell.find_last_not_of(" \t");
    cells.push_back(a == std::string::npos ? std::string() : cell.substr(a, b - a + 1));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return cells;
}

[[noreturn]] void fail(const std::string& file, int line, const std::string& message) {
  throw std::runtime_error(file + ":" + std::to_string(line) + ": " + message);
}

std::string format(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

template <typename T>
void write_row(std::ostream& out, const std::array<double, kColumnCount>& values,
               const MfParameters<T>& params, const MfOptions& options) {
  MfInput<T> in;
  in.fz_n = static_cast<T>(values[kFz]);
  in.kappa = static_cast<T>(values[kKappa]);
  in.alpha_rad = static_cast<T>(values[kAlpha]);
  in.gamma_rad = static_cast<T>(values[kGamma]);
  in.vx_mps = static_cast<T>(values[kVx]);
  in.phit_1pm = static_cast<T>(values[kPhit]);
  in.p_pa = static_cast<T>(values[kP]);
  const MfOutput<T> result = evaluate(params, in, options);
  for (double v : values) out << format(v) << ',';
  for (const auto& c : out_columns<T>())
    out << format(static_cast<double>(result.*(c.member))) << ',';
  out << to_string(result.status) << '\n';
}

}  // namespace

std::size_t evaluate_csv(const MfParameters<double>& params, const MfOptions& options,
                         bool use_float, std::istream& in, const std::string& in_name,
                         std::ostream& out) {
  const MfParameters<float> params_f = convert_parameters<float>(params);
  std::array<int, kColumnCount> index{};
  index.fill(-1);
  std::size_t header_cells = 0;
  bool have_header = false;
  std::size_t rows = 0;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos || line[0] == '#') continue;
    const std::vector<std::string> cells = split(line);
    if (!have_header) {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        int found = -1;
        for (int c = 0; c < kColumnCount; ++c) {
          if (cells[i] == kInputNames[static_cast<std::size_t>(c)]) found = c;
        }
        if (found < 0) {
          fail(in_name, line_no,
               "unknown column '" + cells[i] +
                   "' (expected Fz_N, kappa, alpha_rad, gamma_rad, Vx_mps, phit_1pm, P_Pa)");
        }
        if (index[static_cast<std::size_t>(found)] >= 0) {
          fail(in_name, line_no, "column '" + cells[i] + "' appears twice");
        }
        index[static_cast<std::size_t>(found)] = static_cast<int>(i);
      }
      for (int c = 0; c <= kVx; ++c) {
        if (index[static_cast<std::size_t>(c)] < 0) {
          fail(in_name, line_no,
               "missing column '" + std::string(kInputNames[static_cast<std::size_t>(c)]) + "'");
        }
      }
      header_cells = cells.size();
      have_header = true;
      out << "in_Fz_N,in_kappa,in_alpha_rad,in_gamma_rad,in_Vx_mps,in_phit_1pm,in_P_Pa";
      for (const auto& c : out_columns<double>()) out << ',' << c.name;
      out << ",status\n";
      continue;
    }
    if (cells.size() != header_cells) {
      fail(in_name, line_no,
           "expected " + std::to_string(header_cells) + " cells, found " +
               std::to_string(cells.size()));
    }
    std::array<double, kColumnCount> values{};
    for (int c = 0; c < kColumnCount; ++c) {
      const int i = index[static_cast<std::size_t>(c)];
      if (i < 0) continue;  // optional column absent: 0
      const std::string& text = cells[static_cast<std::size_t>(i)];
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v)) {
        fail(in_name, line_no,
             std::string(kInputNames[static_cast<std::size_t>(c)]) + ": '" + text +
                 "' is not a finite number");
      }
      values[static_cast<std::size_t>(c)] = v;
    }
    if (use_float) {
      write_row(out, values, params_f, options);
    } else {
      write_row(out, values, params, options);
    }
    ++rows;
  }
  if (!have_header) fail(in_name, line_no, "no header row");
  return rows;
}

}  // namespace tread::mf
