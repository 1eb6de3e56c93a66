#include "tyre/mf_eval_columns.hpp"

#include "io/text_line.hpp"

namespace tread::tyre {

namespace {

constexpr std::array<EvalColumn, kEvalColumnCount> kColumns = {{
    {"in_Fz_N"},
    {"in_kappa"},
    {"in_alpha_rad"},
    {"in_gamma_rad"},
    {"in_Vx_mps"},
    {"in_phit_1pm"},
    {"in_P_Pa"},
    {"Fx_N"},
    {"Fy_N"},
    {"Fz_N", false, 0},
    {"Mx_Nm"},
    {"My_Nm"},
    {"Mz_Nm"},
    {"Rl_m", true},
    {"Re_m", true},
    {"kappa_1", false, 1},
    {"alpha_rad", false, 2},
    {"gamma_rad", false, 3},
    {"phit_1pm", false, 5},
    {"Vx_mps", false, 4},
    {"P_Pa", false, 6},
    {"rho_m", true},
    {"2a_m", true},
    {"t_m"},
    {"mux_1"},
    {"muy_1"},
    {"omega_radps", true},
    {"2b_m", true},
    {"Mzr_Nm"},
    {"Cx_Npm", true},
    {"Cy_Npm", true},
    {"Cz_Npm", true},
    {"Kya_Nprad"},
    {"sigmax_m", true},
    {"sigmay_m", true},
    {"Kxk_N"},
}};

constexpr std::size_t kMainOutputs = 6;  // Fx_N … Mz_Nm

std::string valid_names() {
  std::string names = "all";
  for (const EvalColumn& c : kColumns) names += ", " + std::string(c.name);
  return names + ", status";
}

}  // namespace

const std::array<EvalColumn, kEvalColumnCount>& eval_columns() {
  return kColumns;
}

std::vector<std::size_t> default_eval_columns() {
  std::vector<std::size_t> columns;
  for (std::size_t i = 0; i < kEvalInputColumns + kMainOutputs; ++i) columns.push_back(i);
  return columns;
}

EvalColumnSelection select_eval_columns(std::string_view list) {
  EvalColumnSelection selection;
  if (host::text::trim_blanks(list) == "all") {
    for (std::size_t i = 0; i < kEvalColumnCount; ++i) selection.columns.push_back(i);
    return selection;
  }
  std::vector<bool> taken(kEvalColumnCount, false);
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = list.find(',', start);
    const std::string_view name = host::text::trim_blanks(list.substr(start, comma - start));
    if (name.empty()) {
      selection.error =
          "--columns: an empty name in '" + std::string(list) + "'; valid names: " + valid_names();
      return selection;
    }
    if (name != "status") {
      std::size_t i = 0;
      while (i < kEvalColumnCount && kColumns[i].name != name) ++i;
      if (i == kEvalColumnCount) {
        selection.error =
            "--columns: unknown column '" + std::string(name) + "'; valid names: " + valid_names();
        return selection;
      }
      if (taken[i]) {
        selection.error = "--columns: column '" + std::string(name) + "' named twice";
        return selection;
      }
      taken[i] = true;
      selection.columns.push_back(i);
    }
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return selection;
}

bool needs_extras(const std::vector<std::size_t>& columns) {
  for (const std::size_t c : columns) {
    if (kColumns[c].needs_extras) return true;
  }
  return false;
}

bool needs_moments_xy(const std::vector<std::size_t>& columns) {
  for (const std::size_t c : columns) {
    if (kColumns[c].name == "Mx_Nm" || kColumns[c].name == "My_Nm") return true;
  }
  return false;
}

}  // namespace tread::tyre
