#pragma once
// Adams Tire PAC89 (Bakker, Nyborg & Pacejka 1989) in its own units — Fz in kN, α and γ in degrees,
// κ in percent — with an SI entry point (pac89_eval). Equations: seed eq. 21–49, cross-checked with
// Chrono's ChPac89Tire (which follows the Adams Tire help); the seed's "S_Vy" in eq. 30/49 is
// S_Vx/S_Vz.
//
//   Fx0(κ):  C = b0, D = (b1 Fz + b2) Fz, BCD = (b3 Fz² + b4 Fz) e^(−b5 Fz), E = b6 Fz² + b7 Fz +
//   b8,
//            Sh = b9 Fz + b10, Sv = 0
//   Fy0(α):  C = a0, D = (a1 Fz + a2) Fz, BCD = a3 sin(2 atan(Fz / a4)) (1 − a5 |γ|), E = a6 Fz +
//   a7,
//            Sh = a8 γ + a9 Fz + a10, Sv = a11 Fz γ + a12 Fz + a13
//   Mz0(α):  C = c0, D = c1 Fz² + c2 Fz, BCD = (c3 Fz² + c4 Fz)(1 − c6 |γ|) e^(−c5 Fz),
//            E = (c7 Fz² + c8 Fz + c9)(1 − c10 |γ|), Sh = c11 γ + c12 Fz + c13,
//            Sv = (c14 Fz² + c15 Fz) γ + c16 Fz + c17
//   each: Y = D sin(C atan(B X − E (B X − atan(B X)))) + Sv, X = slip + Sh, B = BCD / (C D).

#include "pac/pac_eval.hpp"
#include "pac/pac_math.hpp"
#include "pac/pac_params.hpp"

namespace tread::pac {

struct Pac89 {
  template <typename T>
  static T fx0(const PacParams<T>& p, const T& fz_kn, const T& kappa_pct) {
    using std::exp;
    const auto& b = p.b;
    const T C = b[0];
    const T D = (b[1] * fz_kn + b[2]) * fz_kn;
    const T BCD = (b[3] * fz_kn * fz_kn + b[4] * fz_kn) * exp(-b[5] * fz_kn);
    const T E = b[6] * fz_kn * fz_kn + b[7] * fz_kn + b[8];
    const T Sh = b[9] * fz_kn + b[10];
    return detail::magic_formula(detail::div_or_zero(BCD, C * D), C, D, E, Sh, T(0), kappa_pct);
  }

  template <typename T>
  static T fy0(const PacParams<T>& p, const T& fz_kn, const T& alpha_deg, const T& gamma_deg) {
    using std::abs;
    using std::atan;
    using std::sin;
    const auto& a = p.a;
    const T C = a[0];
    const T D = (a[1] * fz_kn + a[2]) * fz_kn;
    const T BCD =
        a[3] * sin(T(2) * atan(detail::div_or_zero(fz_kn, a[4]))) * (T(1) - a[5] * abs(gamma_deg));
    const T E = a[6] * fz_kn + a[7];
    const T Sh = a[8] * gamma_deg + a[9] * fz_kn + a[10];
    const T Sv = a[11] * fz_kn * gamma_deg + a[12] * fz_kn + a[13];
    return detail::magic_formula(detail::div_or_zero(BCD, C * D), C, D, E, Sh, Sv, alpha_deg);
  }

  template <typename T>
  static T mz0(const PacParams<T>& p, const T& fz_kn, const T& alpha_deg, const T& gamma_deg) {
    using std::abs;
    using std::exp;
    const auto& c = p.c;
    const T fz2 = fz_kn * fz_kn;
    const T C = c[0];
    const T D = c[1] * fz2 + c[2] * fz_kn;
    const T BCD = (c[3] * fz2 + c[4] * fz_kn) * (T(1) - c[6] * abs(gamma_deg)) * exp(-c[5] * fz_kn);
    const T E = (c[7] * fz2 + c[8] * fz_kn + c[9]) * (T(1) - c[10] * abs(gamma_deg));
    const T Sh = c[11] * gamma_deg + c[12] * fz_kn + c[13];
    const T Sv = (c[14] * fz2 + c[15] * fz_kn) * gamma_deg + c[16] * fz_kn + c[17];
    return detail::magic_formula(detail::div_or_zero(BCD, C * D), C, D, E, Sh, Sv, alpha_deg);
  }
};

/// PAC89 forces and moments for SI inputs (see pac_eval.hpp for limits and combined slip).
template <typename T>
PacOutput<T> pac89_eval(const PacParams<T>& p, const PacInput<T>& in, Slip slip) {
  return detail::evaluate<Pac89>(p, in, slip);
}

// float and double are compiled once, in the core (pac.cpp), with the core's flags: every program
// runs those, whatever its own build.
extern template PacOutput<float> pac89_eval(const PacParams<float>&, const PacInput<float>&, Slip);
extern template PacOutput<double> pac89_eval(const PacParams<double>&, const PacInput<double>&,
                                             Slip);

}  // namespace tread::pac
