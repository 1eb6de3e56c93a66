#pragma once
// The columns `tread mf eval` can write (host side), and `--columns` selections of them.
//
// In the order of `--columns all`: the inputs as evaluated, in SI units and ISO-W axes (in_Fz_N,
// in_kappa, in_alpha_rad, in_gamma_rad, in_Vx_mps, in_phit_1pm, in_P_Pa), then every MfOutput
// value under MFeval's names (Fx_N, Fy_N, Fz_N, Mx_Nm, My_Nm, Mz_Nm, Rl_m, Re_m, kappa_1, ...).
// The default is the inputs and the forces and moments. The status column is always written, last.
// The outputs the core computes only with MfOptions::extras (radii, deflection, contact patch,
// stiffnesses, relaxation lengths, wheel speed) are marked, so that a selection without them can
// skip that work.

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "mf/mf_types.hpp"

namespace tread::tyre {

inline constexpr std::size_t kEvalInputColumns = 7;
inline constexpr std::size_t kEvalOutputColumns = 29;
inline constexpr std::size_t kEvalColumnCount = kEvalInputColumns + kEvalOutputColumns;

struct EvalColumn {
  std::string_view name;
  bool needs_extras = false;  ///< computed only with mf::MfOptions::extras
  /// The input column (index) this output repeats as evaluated, often the same value (kappa_1 is
  /// in_kappa unless clamped or reduced at low speed); -1 for none. Lets a writer reuse its text.
  int echoes = -1;
};

/// Every column, in the order of `--columns all`; the first kEvalInputColumns are the inputs.
const std::array<EvalColumn, kEvalColumnCount>& eval_columns();

/// The MfOutput member behind output column kEvalInputColumns + i.
template <typename T>
constexpr std::array<T mf::MfOutput<T>::*, kEvalOutputColumns> eval_output_members() {
  using O = mf::MfOutput<T>;
  return {&O::fx_n,
          &O::fy_n,
          &O::fz_n,
          &O::mx_nm,
          &O::my_nm,
          &O::mz_nm,
          &O::rl_m,
          &O::re_m,
          &O::kappa,
          &O::alpha_rad,
          &O::gamma_rad,
          &O::phit_1pm,
          &O::vx_mps,
          &O::p_pa,
          &O::rho_m,
          &O::contact_length_m,
          &O::t_m,
          &O::mux,
          &O::muy,
          &O::omega_radps,
          &O::contact_width_m,
          &O::mzr_nm,
          &O::cx_npm,
          &O::cy_npm,
          &O::cz_npm,
          &O::kya_nprad,
          &O::sigmax_m,
          &O::sigmay_m,
          &O::kxk_n};
}

/// Indices into eval_columns(): the inputs, Fx_N, Fy_N, Fz_N, Mx_Nm, My_Nm, Mz_Nm.
std::vector<std::size_t> default_eval_columns();

/// A `--columns` list read: the columns in the order given, or an error saying what is wrong and
/// listing the valid names.
struct EvalColumnSelection {
  std::vector<std::size_t> columns;
  std::string error;  ///< empty when the list is valid
};

/// `list`: comma-separated column names (case-sensitive, blanks around names ignored), or `all`.
/// `status` may be named: it is always written, last. Errors: an unknown name, a name given
/// twice, an empty name (or list).
EvalColumnSelection select_eval_columns(std::string_view list);

/// Whether any of `columns` needs MfOptions::extras.
bool needs_extras(const std::vector<std::size_t>& columns);
/// Whether the columns show Mx or My (mf::MfOptions::moments_xy).
bool needs_moments_xy(const std::vector<std::size_t>& columns);

}  // namespace tread::tyre
