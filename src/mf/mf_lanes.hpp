#pragma once
// Four float lanes as a Magic Formula scalar: `evaluate` instantiated with lanes::F4 computes four
// wheels in one pass (SSE on x86-64, NEON on aarch64; plain scalar code on targets without a
// vector unit, where it is correct but no faster). Same parameters and options for the four lanes.
//
//   - F4: arithmetic with F4 and float (a float broadcasts), comparisons give a Mask4 (all bits set
//     where true); if_else(mask, a, b) selects per lane, any_lane(mask) tells whether a branch is
//     needed at all.
//   - The elementary functions the evaluation calls, per lane: atan, sin, cos and tan with tread's
//     float polynomials (mf_math.hpp), exp and log as Cephes' float polynomials (relative error a
//     few ulp; errors tested in tests/mf/mf_lanes_test.cpp), pow(x, y) = exp(y·log x) for x > 0
//     (the scalar float path's mf_pow does the same with libm's expf/logf; its fz62 calls powf),
//     sqrt as the vector instruction. Angles beyond the reduction's range and acos (turn slip
//     only) go lane by lane through libm.
//   - MfOutput<F4>::status is a LaneStatus: two Mask4s, the lanes whose input left the
//     finite-arithmetic envelope and the lanes with a non-finite output.
// Not for the ECU's scalar build (Cortex-M4F): there the node evaluates wheel by wheel.

#include <bit>
#include <cmath>
#include <concepts>
#include <cstdint>

#include "mf/mf_math.hpp"
#include "mf/mf_types.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#elif defined(__ARM_NEON) && defined(__aarch64__)
#include <arm_neon.h>
#endif

namespace tread::mf::lanes {

using V = detail::fast::F4;
using VI = detail::fast::I4;

/// A per-lane truth value: all bits set where true.
struct Mask4 {
  VI m{};
  friend Mask4 operator&&(Mask4 a, Mask4 b) { return {a.m & b.m}; }
  friend Mask4 operator||(Mask4 a, Mask4 b) { return {a.m | b.m}; }
  friend Mask4 operator!(Mask4 a) { return {~a.m}; }
  bool operator[](int i) const { return m[i] != 0; }
};

inline bool any_lane(Mask4 a) {
#if defined(__SSE2__)
  return _mm_movemask_ps(__m128(a.m)) != 0;
#elif defined(__ARM_NEON) && defined(__aarch64__)
  return vmaxvq_u32(uint32x4_t(a.m)) != 0U;
#else
  return ((a.m[0] | a.m[1]) | (a.m[2] | a.m[3])) != 0;
#endif
}

/// Four floats.
struct F4 {
  V v{};
  F4() = default;
  explicit F4(V x) : v(x) {}
  F4(float x) : v(V{x, x, x, x}) {}  // NOLINT(google-explicit-constructor): a float broadcasts
  template <typename U>
  requires(std::is_arithmetic_v<U> && !std::same_as<U, float>) explicit F4(U x)
      : F4(static_cast<float>(x)) {}
  float operator[](int i) const { return v[i]; }

  friend F4 operator+(F4 a, F4 b) { return F4(a.v + b.v); }
  friend F4 operator-(F4 a, F4 b) { return F4(a.v - b.v); }
  friend F4 operator*(F4 a, F4 b) { return F4(a.v * b.v); }
  friend F4 operator/(F4 a, F4 b) { return F4(a.v / b.v); }
  friend F4 operator-(F4 a) { return F4(-a.v); }
  friend Mask4 operator<(F4 a, F4 b) { return {a.v < b.v}; }
  friend Mask4 operator>(F4 a, F4 b) { return {a.v > b.v}; }
  friend Mask4 operator<=(F4 a, F4 b) { return {a.v <= b.v}; }
  friend Mask4 operator>=(F4 a, F4 b) { return {a.v >= b.v}; }
};

inline F4 if_else(Mask4 m, F4 a, F4 b) {
  return F4(m.m ? a.v : b.v);
}

/// The evaluation's max_of/min_of (a < b ? b : a and b < a ? b : a) as single instructions where
/// the target has them (x86 maxps(b, a) is exactly a < b ? b : a, NaN included).
inline F4 max_of(F4 a, F4 b) {
#if defined(__SSE2__)
  return F4(V(_mm_max_ps(__m128(b.v), __m128(a.v))));
#else
  return F4(a.v < b.v ? b.v : a.v);
#endif
}
inline F4 min_of(F4 a, F4 b) {
#if defined(__SSE2__)
  return F4(V(_mm_min_ps(__m128(b.v), __m128(a.v))));
#else
  return F4(b.v < a.v ? b.v : a.v);
#endif
}

inline F4 abs(F4 x) {
  return F4(std::bit_cast<V>(VI(std::bit_cast<VI>(x.v) & 0x7fffffff)));
}

inline F4 sqrt(F4 x) {
#if defined(__SSE2__)
  return F4(V(_mm_sqrt_ps(__m128(x.v))));
#elif defined(__ARM_NEON) && defined(__aarch64__)
  return F4(V(vsqrtq_f32(float32x4_t(x.v))));
#else
  F4 r;
  for (int i = 0; i < 4; ++i) r.v[i] = std::sqrt(x.v[i]);
  return r;
#endif
}

/// libm lane by lane (the rare paths).
template <typename F>
F4 per_lane(F4 x, F f) {
  F4 r;
  for (int i = 0; i < 4; ++i) r.v[i] = f(x.v[i]);
  return r;
}

inline F4 acos(F4 x) {
  return per_lane(x, [](float a) { return std::acos(a); });
}

/// e^x: x = n·ln 2 + r, |r| ≤ ln2/2, Cephes' expf polynomial, 2^n applied in two halves so that
/// results near the overflow and underflow thresholds come out as expf's (inf, denormals, 0).
inline F4 exp(F4 x) {
  V a = x.v;
  a = a > 89.0f ? V{} + 89.0f : a;
  a = a < -104.0f ? V{} - 104.0f : a;
  const V n = (a * 1.44269504088896341f + 12582912.0f) - 12582912.0f;  // rint(x/ln 2)
  const V r = (a - n * 0.693359375f) - n * -2.12194440e-4f;
  const V z = r * r;
  const V poly =
      ((((1.9875691500e-4f * r + 1.3981999507e-3f) * r + 8.3334519073e-3f) * r + 4.1665795894e-2f) *
           r +
       1.6666665459e-1f) *
          r +
      5.0000001201e-1f;
  const V y = r + z * poly + 1.0f;
  const VI ni = __builtin_convertvector(n, VI);
  const VI n1 = ni >> 1;
  const VI n2 = ni - n1;
  const V s1 = std::bit_cast<V>(VI((n1 + 127) << 23));
  const V s2 = std::bit_cast<V>(VI((n2 + 127) << 23));
  return F4(y * s1 * s2);
}

/// Natural logarithm for x > 0 (denormals included): Cephes' logf polynomial on the mantissa in
/// [√½, √2). x ≤ 0, inf and NaN give unspecified finite values or NaN: callers select them away.
inline F4 log(F4 x) {
  V a = x.v;
  const VI tiny = a < 1.17549435e-38f;
  a = tiny != 0 ? a * 8388608.0f : a;  // denormal → normal (2^23)
  const VI bits = std::bit_cast<VI>(a);
  V e = __builtin_convertvector(VI(((bits >> 23) & 0xff) - 126), V);
  e = tiny != 0 ? e - 23.0f : e;
  V m = std::bit_cast<V>(VI((bits & 0x007fffff) | 0x3f000000));  // [0.5, 1)
  const VI low = m < 0.707106781186547524f;
  e = low != 0 ? e - 1.0f : e;
  m = low != 0 ? m + m - 1.0f : m - 1.0f;
  const V z = m * m;
  V y = 7.0376836292e-2f * m - 1.1514610310e-1f;
  y = y * m + 1.1676998740e-1f;
  y = y * m - 1.2420140846e-1f;
  y = y * m + 1.4249322787e-1f;
  y = y * m - 1.6668057665e-1f;
  y = y * m + 2.0000714765e-1f;
  y = y * m - 2.4999993993e-1f;
  y = y * m + 3.3333331174e-1f;
  y = y * m * z;
  y = y + e * -2.12194440e-4f;
  y = y - 0.5f * z;
  return F4((m + y) + e * 0.693359375f);
}

/// x^y for x > 0 as exp(y·log x), like the scalar float path.
inline F4 pow(F4 x, F4 y) {
  return exp(y * log(x));
}

// The Magic Formula's elementary functions (found by ADL from mf_evaluate.hpp).
/// sin (cosine false) or cos of four lanes; lanes beyond the reduction's range go through libm.
inline F4 sin_or_cos(F4 y, bool cosine) {
  const VI turns = VI{} + (cosine ? 1 : 0);
  F4 r(detail::fast::sin_cos4(y.v, turns));
  const Mask4 out_of_range = !(abs(y) <= F4(detail::fast::kTrigMax));
  if (any_lane(out_of_range)) {
    for (int i = 0; i < 4; ++i)
      if (out_of_range[i]) r.v[i] = cosine ? std::cos(y.v[i]) : std::sin(y.v[i]);
  }
  return r;
}
inline F4 mf_sin(F4 x) {
  return sin_or_cos(x, false);
}
inline F4 mf_cos(F4 x) {
  return sin_or_cos(x, true);
}
inline F4 mf_atan(F4 x) {
  return F4(detail::fast::atan4(x.v));
}
inline F4 mf_tan(F4 x) {
  F4 t(detail::fast::tan4(x.v));
  const Mask4 out_of_range = !(abs(x) <= F4(detail::fast::kTrigMax));
  if (any_lane(out_of_range)) {
    for (int i = 0; i < 4; ++i)
      if (out_of_range[i]) t.v[i] = std::tan(x.v[i]);
  }
  return t;
}
/// The Magic Formula cores of an evaluation (mf_math.hpp), each on four wheels: four cores at a
/// time written side by side, so that their long dependent chains (atan, division, atan, sin)
/// overlap. Angles beyond the reduction's range go through libm.
inline void mf_cores(const detail::Cores<F4>& in, F4 (&out)[detail::kMaxCores]) {
  for (int g = 0; g < detail::kMaxCores; g += 4) {
    if (g >= in.count) break;
    V y[4];
    for (int k = 0; k < 4; ++k) {
      const V x = in.x[g + k].v;
      y[k] = x - in.e[g + k].v * (x - detail::fast::atan4(x));
    }
    for (int k = 0; k < 4; ++k) y[k] = in.c[g + k].v * detail::fast::atan4(y[k]);
    Mask4 wide;
    for (int k = 0; k < 4; ++k) {
      const VI turns = VI{} + (in.cosine[g + k] ? 1 : 0);
      out[g + k] = F4(detail::fast::sin_cos4(y[k], turns));
      wide = wide || !(abs(F4(y[k])) <= F4(detail::fast::kTrigMax));
    }
    if (any_lane(wide)) {
      for (int k = 0; k < 4; ++k) out[g + k] = sin_or_cos(F4(y[k]), in.cosine[g + k]);
    }
  }
}

/// cos(atan x) = 1/√(1+x²) (x² = inf gives the limit 0).
inline F4 cos_atan(F4 x) {
  return F4(1.0f) / sqrt(F4(1.0f) + x * x);
}
inline F4 mf_exp(F4 x) {
  return exp(x);
}
inline F4 mf_pow(F4 x, F4 y) {
  return pow(x, y);
}

}  // namespace tread::mf::lanes

namespace tread::mf {

namespace lanes {
/// MfOutput<F4>::status: per lane, whether an input left the finite-arithmetic envelope and
/// whether an output came out non-finite (and was replaced by 0); [i] is lane i's Status.
struct LaneStatus {
  Mask4 out_of_range{};
  Mask4 non_finite{};
  Status operator[](int i) const {
    if (non_finite[i]) return Status::non_finite;
    return out_of_range[i] ? Status::out_of_range : Status::ok;
  }
};
}  // namespace lanes

template <>
struct StatusFor<lanes::F4> {
  using type = lanes::LaneStatus;
};
}  // namespace tread::mf
