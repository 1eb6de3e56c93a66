#pragma once
// The elementary functions of the Magic Formula, per scalar:
//   - double and ceres::Jet: the standard library / ceres (ADL), so results match MFeval to the
//     last bits and Jet derivatives stay exact;
//   - float: libm's float functions (sinf, cosf, tanf: fast and exact enough), tread's own
//     atan (three-interval reduction + odd polynomial, about 1e-7 relative error, ~25 % faster
//     than atanf here) and x^y as exp(y·ln x) (several times cheaper than powf). Measured against
//     libm on this x86 host: a Taylor sin/cos was slower than sinf/cosf (longer dependency
//     chain), so they are not replaced.
// Identities used by the evaluation: cos(atan x) = 1/√(1+x²), sin(atan x) = x/√(1+x²), written
// without overflow for huge x.

#include <cmath>

namespace tread::mf::detail {

// ---- generic: standard library / ADL ------------------------------------------------------------
template <typename T>
T mf_sin(const T& x) {
  using std::sin;
  return sin(x);
}
template <typename T>
T mf_cos(const T& x) {
  using std::cos;
  return cos(x);
}
template <typename T>
T mf_tan(const T& x) {
  using std::tan;
  return tan(x);
}
template <typename T>
T mf_atan(const T& x) {
  using std::atan;
  return atan(x);
}

template <typename T>
T mf_pow(const T& x, const T& y) {
  using std::pow;
  return pow(x, y);
}

// ---- float: polynomial approximations -----------------------------------------------------------
namespace fast {

inline constexpr float kHalfPi = 1.57079632679490f;

/// atan with the classic three-interval reduction (tan π/8, tan 3π/8) and a degree-9 odd
/// polynomial, written branch-free (one division, selects, Estrin evaluation); absolute error
/// below 1.5e-7.
inline float atan(float x) {
  const float a = std::fabs(x);
  const bool big = a > 2.41421356237f;
  const bool mid = a > 0.414213562373f;
  const float num = big ? -1.0f : (mid ? a - 1.0f : a);
  const float den = big ? a : (mid ? a + 1.0f : 1.0f);
  const float base = big ? kHalfPi : (mid ? 0.785398163397f : 0.0f);
  const float t = num / den;
  const float z = t * t;
  const float z2 = z * z;
  const float poly = (-3.33329491539e-1f + 1.99777106478e-1f * z) +
                     z2 * (-1.38776856032e-1f + 8.05374449538e-2f * z);
  return std::copysign(base + (t + t * z * poly), x);
}

}  // namespace fast

inline float mf_sin(const float& x) {
  return std::sin(x);
}
inline float mf_cos(const float& x) {
  return std::cos(x);
}
inline float mf_tan(const float& x) {
  return std::tan(x);
}
inline float mf_atan(const float& x) {
  return fast::atan(x);
}
/// x^y for x > 0 as exp(y·ln x): libm's expf and logf are much cheaper than powf, whose last-bit
/// exactness float does not need.
inline float mf_pow(const float& x, const float& y) {
  return std::exp(y * std::log(x));
}

// ---- identities ---------------------------------------------------------------------------------
/// cos(atan(x)) = 1/√(1+x²), without overflow.
template <typename T>
T cos_atan(const T& x) {
  using std::abs;
  using std::sqrt;
  const T a = abs(x);
  if (a > T(1)) {
    const T inv = T(1) / a;
    return inv / sqrt(T(1) + inv * inv);
  }
  return T(1) / sqrt(T(1) + x * x);
}

/// sin(atan(x)) = x/√(1+x²), without overflow.
template <typename T>
T sin_atan(const T& x) {
  using std::abs;
  using std::sqrt;
  const T a = abs(x);
  if (a > T(1)) {
    const T inv = T(1) / a;
    const T s = T(1) / sqrt(T(1) + inv * inv);
    return x < T(0) ? -s : s;
  }
  return x / sqrt(T(1) + x * x);
}

}  // namespace tread::mf::detail
