#pragma once
// Test helper: MFeval's output column names (units in the names, as in tests/data/mfeval)
// mapped onto tread::mf::MfOutput members.

#include <array>
#include <string_view>

#include "mf/mf_types.hpp"

namespace tread::testing {

enum class ColumnKind { force, moment, other };

template <typename T>
struct OutputColumn {
  std::string_view name;
  T mf::MfOutput<T>::*member;
  ColumnKind kind;
};

template <typename T>
constexpr std::array<OutputColumn<T>, 29> output_columns() {
  using O = mf::MfOutput<T>;
  using K = ColumnKind;
  return {{
      {"Fx_N", &O::fx_n, K::force},
      {"Fy_N", &O::fy_n, K::force},
      {"Fz_N", &O::fz_n, K::force},
      {"Mx_Nm", &O::mx_nm, K::moment},
      {"My_Nm", &O::my_nm, K::moment},
      {"Mz_Nm", &O::mz_nm, K::moment},
      {"kappa_1", &O::kappa, K::other},
      {"alpha_rad", &O::alpha_rad, K::other},
      {"gamma_rad", &O::gamma_rad, K::other},
      {"phit_1pm", &O::phit_1pm, K::other},
      {"Vx_mps", &O::vx_mps, K::other},
      {"P_Pa", &O::p_pa, K::other},
      {"Re_m", &O::re_m, K::other},
      {"rho_m", &O::rho_m, K::other},
      {"2a_m", &O::contact_length_m, K::other},
      {"t_m", &O::t_m, K::other},
      {"mux_1", &O::mux, K::other},
      {"muy_1", &O::muy, K::other},
      {"omega_radps", &O::omega_radps, K::other},
      {"Rl_m", &O::rl_m, K::other},
      {"2b_m", &O::contact_width_m, K::other},
      {"Mzr_Nm", &O::mzr_nm, K::moment},
      {"Cx_Npm", &O::cx_npm, K::other},
      {"Cy_Npm", &O::cy_npm, K::other},
      {"Cz_Npm", &O::cz_npm, K::other},
      {"Kya_Nprad", &O::kya_nprad, K::other},
      {"sigmax_m", &O::sigmax_m, K::other},
      {"sigmay_m", &O::sigmay_m, K::other},
      {"Kxk_N", &O::kxk_n, K::other},
  }};
}

}  // namespace tread::testing
