#pragma once
// Synthetic PAC89/PAC94 coefficient sets whose B, C, D, E, Sh, Sv are simple closed forms, so the
// properties tests can state the expected slope, peak and asymptote directly.

#include <cmath>
#include <numbers>

#include "pac/pac_params.hpp"

namespace tread::pac::testing {

/// C, D = mu·Fz, BCD = k·Fz and E for Fx; Fy and Mz likewise. Shifts are 0 (symmetric set).
template <typename T>
PacParams<T> symmetric_set() {
  PacParams<T> p;
  // Fx: C = 1.6, D = 1000 N/kN · Fz, BCD = 200 N/% per kN · Fz, E = 0.3
  p.b[0] = T(1.6);
  p.b[2] = T(1000);
  p.b[4] = T(200);
  p.b[8] = T(0.3);
  // Fy: C = 1.3, D = 900 · Fz, BCD = 1500 sin(2 atan(Fz / 5)), E = -0.5
  p.a[0] = T(1.3);
  p.a[2] = T(900);
  p.a[3] = T(1500);
  p.a[4] = T(5);
  p.a[7] = T(-0.5);
  // Mz: C = 2.4, D = -2 Fz² + 30 Fz, BCD = -(Fz² + 5 Fz), E = -1
  p.c[0] = T(2.4);
  p.c[1] = T(-2);
  p.c[2] = T(30);
  p.c[3] = T(-1);
  p.c[4] = T(-5);
  p.c[9] = T(-1);
  return p;
}

// Expected factors of symmetric_set() at a load in kN (model units: N per % or per degree).
inline double fx_D(double fz_kn) {
  return 1000.0 * fz_kn;
}
inline double fx_BCD(double fz_kn) {
  return 200.0 * fz_kn;
}
inline double fy_D(double fz_kn) {
  return 900.0 * fz_kn;
}
inline double fy_BCD(double fz_kn) {
  return 1500.0 * std::sin(2.0 * std::atan(fz_kn / 5.0));
}
inline double mz_D(double fz_kn) {
  return -2.0 * fz_kn * fz_kn + 30.0 * fz_kn;
}
inline double mz_BCD(double fz_kn) {
  return -(fz_kn * fz_kn + 5.0 * fz_kn);
}
constexpr double kCx = 1.6, kCy = 1.3, kCz = 2.4;

inline double deg(double rad) {
  return rad * 180.0 / std::numbers::pi;
}

}  // namespace tread::pac::testing
