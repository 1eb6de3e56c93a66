#pragma once
// The SI wrapper shared by PAC89 and PAC94: unit conversion, input limits, pure/combined slip,
// Mx and My.
//
// Units: Fz [N] → kN, κ [-] → %, α, γ [rad] → degrees. Inputs are clamped to the limits in
// PacParams (Fz to [0, fz_max_n], |κ| ≤ kappa_max, |α| ≤ alpha_max_rad, |γ| ≤ gamma_max_rad);
// Fz ≤ 0 gives all-zero outputs. PacOutput::status tells whether an input was clamped
// (out_of_range) or not finite (invalid_argument, all outputs 0), or an output came out NaN or
// infinite (non_finite: that output is 0).
//
// Combined slip. The Adams Tire help text for the PAC89/PAC94 combined-slip mode could not be
// consulted while writing this; we use the slip-vector ("friction circle in slip space")
// combination of Bakker, Nyborg & Pacejka with the practical slips σx = κ and σy = tan α:
//   σ = √(σx² + σy²),  Fx = |σx|/σ · Fx0(κ* = sgn(κ) σ),  Fy = |σy|/σ · Fy0(α* = sgn(α) atan σ),
//   Mz = |σy|/σ · Mz0(α*),
// so that each force points along its slip component, the resultant follows the pure curve of the
// combined slip magnitude, and combined = pure exactly when the other slip is 0. At σ = 0 the pure
// values (shifts Sh/Sv) are returned.
//
// Mx = −Fz · Fy / C_Fα (seed eq. 50–51; 0 when lateral_stiffness_npm is 0) and My = f · Fz · R
// (seed eq. 52, rolling resistance coefficient f and unloaded radius R).

#include <initializer_list>

#include "pac/pac_math.hpp"
#include "pac/pac_params.hpp"

namespace tread::pac::detail {

template <typename T>
T rad_to_deg(const T& x) {
  return x * T(57.295779513082320876798154814105);
}

/// False for NaN and ±inf: x − x is 0 for finite x and NaN otherwise (works for Jets too, which
/// compare by value).
template <typename T>
bool is_finite(const T& x) {
  return (x - x) < T(1);
}

template <typename T>
bool outside(const T& x, const T& lo, const T& hi) {
  return x < lo || hi < x;
}

template <typename Model, typename T>
PacOutput<T> evaluate(const PacParams<T>& p, const PacInput<T>& in, Slip slip) {
  using std::atan;
  using std::sqrt;
  using std::tan;
  PacOutput<T> out{};
  if (!is_finite(in.fz_n) || !is_finite(in.kappa) || !is_finite(in.alpha_rad) ||
      !is_finite(in.gamma_rad)) {
    out.status = Status::invalid_argument;
    return out;
  }
  if (outside(in.fz_n, T(0), p.fz_max_n) || outside(in.kappa, -p.kappa_max, p.kappa_max) ||
      outside(in.alpha_rad, -p.alpha_max_rad, p.alpha_max_rad) ||
      outside(in.gamma_rad, -p.gamma_max_rad, p.gamma_max_rad)) {
    out.status = Status::out_of_range;
  }
  if (!(T(0) < in.fz_n)) return out;
  const T fz_n = clamp(in.fz_n, T(0), p.fz_max_n);
  const T fz_kn = fz_n / T(1000);
  const T kappa = clamp(in.kappa, -p.kappa_max, p.kappa_max);
  const T alpha = clamp(in.alpha_rad, -p.alpha_max_rad, p.alpha_max_rad);
  const T gamma_deg = rad_to_deg(clamp(in.gamma_rad, -p.gamma_max_rad, p.gamma_max_rad));

  if (slip == Slip::kPure) {
    out.fx_n = Model::fx0(p, fz_kn, kappa * T(100));
    out.fy_n = Model::fy0(p, fz_kn, rad_to_deg(alpha), gamma_deg);
    out.mz_nm = Model::mz0(p, fz_kn, rad_to_deg(alpha), gamma_deg);
  } else {
    const T sx = kappa;
    const T sy = tan(alpha);
    const T s2 = sx * sx + sy * sy;
    if (!(T(0) < s2)) {
      out.fx_n = Model::fx0(p, fz_kn, T(0));
      out.fy_n = Model::fy0(p, fz_kn, T(0), gamma_deg);
      out.mz_nm = Model::mz0(p, fz_kn, T(0), gamma_deg);
    } else {
      using std::abs;
      const T s = sqrt(s2);
      const T kappa_eq_pct = sgn(sx) * s * T(100);
      const T alpha_eq_deg = sgn(sy) * rad_to_deg(atan(s));
      out.fx_n = abs(sx) / s * Model::fx0(p, fz_kn, kappa_eq_pct);
      out.fy_n = abs(sy) / s * Model::fy0(p, fz_kn, alpha_eq_deg, gamma_deg);
      out.mz_nm = abs(sy) / s * Model::mz0(p, fz_kn, alpha_eq_deg, gamma_deg);
    }
  }
  out.mx_nm = -fz_n * div_or_zero(out.fy_n, p.lateral_stiffness_npm);
  out.my_nm = p.rolling_resistance * fz_n * p.unloaded_radius_m;
  // No NaN or inf leaves: coefficients no tyre has (e.g. b5 = −1e3: e^(−b5 Fz) overflows) make
  // such an output 0 and the status non_finite.
  bool non_finite = false;
  for (T* v : {&out.fx_n, &out.fy_n, &out.mz_nm, &out.mx_nm, &out.my_nm}) {
    if (!is_finite(*v)) {
      *v = T(0);
      non_finite = true;
    }
  }
  if (non_finite) out.status = Status::non_finite;
  return out;
}

}  // namespace tread::pac::detail
