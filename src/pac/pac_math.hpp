#pragma once
// The Magic Formula curve and the guarded helpers PAC89/PAC94 share. Templated on the scalar
// (float, double, ceres::Jet): math functions are called unqualified after `using std::...` so that
// argument-dependent lookup finds the Jet overloads.

#include <cmath>

namespace tread::pac::detail {

template <typename T>
constexpr T clamp(const T& x, const T& lo, const T& hi) {
  return x < lo ? lo : (hi < x ? hi : x);
}

/// sgn(x) ∈ {−1, 0, 1} (a constant for Jets: its derivative is 0 almost everywhere).
template <typename T>
constexpr T sgn(const T& x) {
  return T(0) < x ? T(1) : (x < T(0) ? T(-1) : T(0));
}

/// n / d, or 0 when d is 0 (e.g. B = BCD / (C·D) with D = 0 at Fz = 0: the force is then D·… = 0
/// anyway).
template <typename T>
constexpr T div_or_zero(const T& n, const T& d) {
  return (d < T(0) || T(0) < d) ? n / d : T(0);
}

/// Y(X) = D sin(C atan(B X − E (B X − atan(B X)))) + Sv with X = x + Sh (Pacejka's Magic Formula).
/// B·X is bounded to ±1e8 (atan has saturated long before) and E to [−1e4, 1] (E > 1 makes the
/// curve non-monotonic before the peak and is rejected by the Adams/TNO checks; the bound also
/// keeps the argument finite in float).
template <typename T>
T magic_formula(const T& B, const T& C, const T& D, const T& E, const T& Sh, const T& Sv,
                const T& x) {
  using std::atan;
  using std::sin;
  const T bx = clamp(B * (x + Sh), T(-1e8), T(1e8));
  const T e = clamp(E, T(-1e4), T(1));
  return D * sin(C * atan(bx - e * (bx - atan(bx)))) + Sv;
}

}  // namespace tread::pac::detail
