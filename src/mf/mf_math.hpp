#pragma once
// The elementary functions of the Magic Formula, per scalar:
//   - double and ceres::Jet: the standard library / ceres (ADL), so results match MFeval to the
//     last bits and Jet derivatives stay exact;
//   - float: tread's own branch-light polynomial approximations (sin, cos, tan, atan), about
//     1e-7 relative error — float's own resolution — and several times faster than libm's, which
//     is what lets one MF 6.1 combined evaluation fit the 1 kHz budget of an ECU. They are
//     deterministic (no libm differences between host and target).
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

inline constexpr float kPi = 3.14159265358979f;
inline constexpr float kHalfPi = 1.57079632679490f;
inline constexpr float kTwoPi = 6.28318530717959f;
inline constexpr float kInvTwoPi = 0.159154943091895f;

/// sin on [−π/2, π/2]: odd Taylor polynomial to x¹¹ (truncation < 6e-8).
inline float sin_core(float x) {
  const float z = x * x;
  return x * (1.0f +
              z * (-1.0f / 6.0f +
                   z * (1.0f / 120.0f + z * (-1.0f / 5040.0f +
                                             z * (1.0f / 362880.0f + z * (-1.0f / 39916800.0f))))));
}

/// x reduced to [−π, π] (one multiple of 2π; float inputs here are small angles).
inline float reduce(float x) {
  const float q = x * kInvTwoPi;
  const float k = static_cast<float>(static_cast<int>(q + (q < 0.0f ? -0.5f : 0.5f)));
  return x - k * kTwoPi;
}

inline float sin(float x) {
  if (!(std::fabs(x) <= 1e5f)) return std::sin(x);  // huge or NaN: libm
  float r = reduce(x);
  if (r > kHalfPi) r = kPi - r;
  if (r < -kHalfPi) r = -kPi - r;
  return sin_core(r);
}

inline float cos(float x) {
  if (!(std::fabs(x) <= 1e5f)) return std::cos(x);
  // cos x = sin(π/2 − |x|) on [0, π]
  const float r = std::fabs(reduce(x));
  return sin_core(kHalfPi - r);
}

inline float tan(float x) {
  const float c = cos(x);
  if (!(c < 0.0f) && !(c > 0.0f)) return std::tan(x);  // exactly zero: libm's huge value
  return sin(x) / c;
}

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
  return fast::sin(x);
}
inline float mf_cos(const float& x) {
  return fast::cos(x);
}
inline float mf_tan(const float& x) {
  return fast::tan(x);
}
inline float mf_atan(const float& x) {
  return fast::atan(x);
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
