#pragma once
// Adams Tire PAC94 (Bakker & Pacejka 1993) in its own units — Fz in kN, α and γ in degrees, κ in
// percent — with an SI entry point (pac94_eval). PAC89 (pac89.hpp) with these changes (seed eq.
// 53–62, checked against the Adams "mirror" parameter list A8, A9, A11, A12, A17, C11, C12, C14,
// C15, C20, i.e. exactly the constant terms of Sh, Sv and the sgn-terms of E):
//
//   Fx0:  E = (b6 Fz² + b7 Fz + b8)(1 − b13 sgn(κ + Sh)),  Sv = b11 Fz + b12
//   Fy0:  D = (a1 Fz + a2)(1 − a15 γ²) Fz,  E = (a6 Fz + a7)(1 − (a16 γ + a17) sgn(α + Sh)),
//         Sh = a8 Fz + a9 + a10 γ,  Sv = a11 Fz + a12 + (a13 Fz² + a14 Fz) γ
//   Mz0:  D = (c1 Fz² + c2 Fz)(1 − c18 γ²),
//         E = (c7 Fz² + c8 Fz + c9)(1 − (c19 γ + c20) sgn(α + Sh)) / (1 − c10 |γ|),
//         Sh = c11 Fz + c12 + c13 γ,  Sv = c14 Fz + c15 + (c16 Fz² + c17 Fz) γ
// The seed writes eq. 54 as "S_Vy"; it is the longitudinal S_Vx. The division by (1 − c10|γ|) is as
// the seed gives it (PAC89 multiplies); a zero denominator yields E = 0 instead of a division by 0.

#include "pac/pac_eval.hpp"
#include "pac/pac_math.hpp"
#include "pac/pac_params.hpp"

namespace tread::pac {

struct Pac94 {
  template <typename T>
  static T fx0(const PacParams<T>& p, const T& fz_kn, const T& kappa_pct) {
    using std::exp;
    const auto& b = p.b;
    const T C = b[0];
    const T D = (b[1] * fz_kn + b[2]) * fz_kn;
    const T BCD = (b[3] * fz_kn * fz_kn + b[4] * fz_kn) * exp(-b[5] * fz_kn);
    const T Sh = b[9] * fz_kn + b[10];
    const T Sv = b[11] * fz_kn + b[12];
    const T E =
        (b[6] * fz_kn * fz_kn + b[7] * fz_kn + b[8]) * (T(1) - b[13] * detail::sgn(kappa_pct + Sh));
    return detail::magic_formula(detail::div_or_zero(BCD, C * D), C, D, E, Sh, Sv, kappa_pct);
  }

  template <typename T>
  static T fy0(const PacParams<T>& p, const T& fz_kn, const T& alpha_deg, const T& gamma_deg) {
    using std::abs;
    using std::atan;
    using std::sin;
    const auto& a = p.a;
    const T C = a[0];
    const T D = (a[1] * fz_kn + a[2]) * (T(1) - a[15] * gamma_deg * gamma_deg) * fz_kn;
    const T BCD =
        a[3] * sin(T(2) * atan(detail::div_or_zero(fz_kn, a[4]))) * (T(1) - a[5] * abs(gamma_deg));
    const T Sh = a[8] * fz_kn + a[9] + a[10] * gamma_deg;
    const T Sv = a[11] * fz_kn + a[12] + (a[13] * fz_kn * fz_kn + a[14] * fz_kn) * gamma_deg;
    const T E =
        (a[6] * fz_kn + a[7]) * (T(1) - (a[16] * gamma_deg + a[17]) * detail::sgn(alpha_deg + Sh));
    return detail::magic_formula(detail::div_or_zero(BCD, C * D), C, D, E, Sh, Sv, alpha_deg);
  }

  template <typename T>
  static T mz0(const PacParams<T>& p, const T& fz_kn, const T& alpha_deg, const T& gamma_deg) {
    using std::abs;
    using std::exp;
    const auto& c = p.c;
    const T fz2 = fz_kn * fz_kn;
    const T C = c[0];
    const T D = (c[1] * fz2 + c[2] * fz_kn) * (T(1) - c[18] * gamma_deg * gamma_deg);
    const T BCD = (c[3] * fz2 + c[4] * fz_kn) * (T(1) - c[6] * abs(gamma_deg)) * exp(-c[5] * fz_kn);
    const T Sh = c[11] * fz_kn + c[12] + c[13] * gamma_deg;
    const T Sv = c[14] * fz_kn + c[15] + (c[16] * fz2 + c[17] * fz_kn) * gamma_deg;
    const T E =
        detail::div_or_zero((c[7] * fz2 + c[8] * fz_kn + c[9]) *
                                (T(1) - (c[19] * gamma_deg + c[20]) * detail::sgn(alpha_deg + Sh)),
                            T(1) - c[10] * abs(gamma_deg));
    return detail::magic_formula(detail::div_or_zero(BCD, C * D), C, D, E, Sh, Sv, alpha_deg);
  }
};

/// PAC94 forces and moments for SI inputs (see pac_eval.hpp for limits and combined slip).
template <typename T>
PacOutput<T> pac94_eval(const PacParams<T>& p, const PacInput<T>& in, Slip slip) {
  return detail::evaluate<Pac94>(p, in, slip);
}

// float and double are compiled once, in the core (pac.cpp), with the core's flags: every program
// runs those, whatever its own build.
extern template PacOutput<float> pac94_eval(const PacParams<float>&, const PacInput<float>&, Slip);
extern template PacOutput<double> pac94_eval(const PacParams<double>&, const PacInput<double>&,
                                             Slip);

}  // namespace tread::pac
