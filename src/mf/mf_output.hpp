#pragma once
// The output side of an evaluation: TYRESIDE mirroring (y → −y) of the lateral inputs and
// outputs, and the last step, which replaces a non-finite output by 0 and sets MfOutput::status.

#include "mf/mf_detail_common.hpp"
#include "mf/mf_types.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <type_traits>

namespace tread::mf::detail {

/// MfOutput<T>::status from the out-of-range and non-finite truth values.
template <typename T, typename M>
typename StatusFor<T>::type to_status(const M& out_of_range, const M& non_finite) {
  if constexpr (is_lanes<T>) {
    return {out_of_range, non_finite};
  } else {
    if (non_finite) return Status::non_finite;
    return out_of_range ? Status::out_of_range : Status::ok;
  }
}

/// Pointers to every value of an MfOutput.
template <typename T>
std::array<T*, 29> output_values(MfOutput<T>& o) {
  return {&o.fx_n,        &o.fy_n,      &o.fz_n,
          &o.mx_nm,       &o.my_nm,     &o.mz_nm,
          &o.kappa,       &o.alpha_rad, &o.gamma_rad,
          &o.phit_1pm,    &o.vx_mps,    &o.p_pa,
          &o.re_m,        &o.rho_m,     &o.contact_length_m,
          &o.t_m,         &o.mux,       &o.muy,
          &o.omega_radps, &o.rl_m,      &o.contact_width_m,
          &o.mzr_nm,      &o.cx_npm,    &o.cy_npm,
          &o.cz_npm,      &o.kya_nprad, &o.sigmax_m,
          &o.sigmay_m,    &o.kxk_n};
}

/// Whether x is finite, per lane: x − x is 0 for a finite x and NaN for NaN and ±inf. For
/// ceres::Jet (which compares by value only) isfinite() also checks the derivatives.
template <typename T>
auto finite(const T& x) {
  if constexpr (is_lanes<T> || std::is_floating_point_v<T>) {
    return (x - x) <= T(0);
  } else {
    using std::isfinite;
    return static_cast<bool>(isfinite(x));
  }
}

/// Σ (v − v) over v[B, E) as a balanced tree (no long dependency chain): 0 when every value is
/// finite, NaN otherwise (a sum of zeros cannot overflow).
template <std::size_t B, std::size_t E, typename T, std::size_t N>
T zero_or_nan(const std::array<T*, N>& v) {
  if constexpr (E - B == 1) {
    return *v[B] - *v[B];
  } else {
    constexpr std::size_t kMid = B + (E - B) / 2;
    return zero_or_nan<B, kMid>(v) + zero_or_nan<kMid, E>(v);
  }
}

/// Replaces every non-finite output by 0 and returns the non-finite truth value (per lane): one
/// subtraction per output, a tree of additions and one compare; the replacement runs only when a
/// lane needs it.
template <typename T>
MaskOf<T> replace_non_finite(MfOutput<T>& out) {
  const std::array<T*, 29> v = output_values(out);
  MaskOf<T> non_finite{};
  if constexpr (is_lanes<T> || std::is_floating_point_v<T>) {
    static_assert(offsetof(MfOutput<T>, status) == 29 * sizeof(T), "output_values: all of them");
    non_finite = !finite(zero_or_nan<0, 29>(v));
  } else {
    for (T* x : v) non_finite = non_finite || !finite(*x);
  }
  if (any_lane(non_finite)) {
    for (T* x : v) *x = if_else(finite(*x), *x, T(0));
  }
  return non_finite;
}

/// A lifted wheel (Fz ≤ 0, where `lifted` is set) has no contact and no forces: its forces and
/// moments, trail and Mzr become 0 (MFeval gives 0 as well).
template <typename T, typename M>
void zero_lifted(MfOutput<T>& out, const M& lifted) {
  if (!any_lane(lifted)) return;
  for (T* y : {&out.fx_n, &out.fy_n, &out.mx_nm, &out.my_nm, &out.mz_nm, &out.t_m, &out.mzr_nm}) {
    *y = if_else(lifted, T(0), *y);
  }
}

/// TYRESIDE mirroring, y → −y, where `mirror` is set (per lane for lanes): the lateral inputs
/// (α, γ, φt) on the way in, the lateral outputs on the way out.
template <typename T, typename M>
MfInput<T> mirror_input(MfInput<T> in, const M& mirror) {
  in.alpha_rad = if_else(mirror, -in.alpha_rad, in.alpha_rad);
  in.gamma_rad = if_else(mirror, -in.gamma_rad, in.gamma_rad);
  in.phit_1pm = if_else(mirror, -in.phit_1pm, in.phit_1pm);
  return in;
}
template <typename T, typename M>
void mirror_output(MfOutput<T>& out, const M& mirror) {
  for (T* y : {&out.fy_n, &out.mx_nm, &out.mz_nm, &out.mzr_nm, &out.alpha_rad, &out.gamma_rad,
               &out.phit_1pm}) {
    *y = if_else(mirror, -*y, *y);
  }
}

}  // namespace tread::mf::detail
