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
/// polynomial; relative error about 1e-7.
inline float atan(float x) {
  const float a = std::fabs(x);
  float y = 0.0f;
  float t = a;
  if (a > 2.41421356237f) {
    y = kHalfPi;
    t = -1.0f / a;
  } else if (a > 0.414213562373f) {
    y = 0.785398163397f;
    t = (a - 1.0f) / (a + 1.0f);
  }
  const float z = t * t;
  y += (((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z -
        3.33329491539e-1f) *
           z * t +
       t;
  return x < 0.0f ? -y : y;
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
