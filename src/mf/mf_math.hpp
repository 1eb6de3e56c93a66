#pragma once
// The elementary functions of the Magic Formula, per scalar:
//   - double and ceres::Jet: the standard library / ceres (ADL), so results match MFeval to the
//     last bits and Jet derivatives stay exact;
//   - float: libm's sinf/cosf (glibc's FMA variants: ~28 instructions a call), tread's own tan
//     (Cody–Waite reduction + sin/cos polynomials, one division: ~35 instructions against ~60 for
//     tanf), tread's atan (three-interval reduction + odd polynomial, |error| < 1.5e-7, ~25 %
//     faster than atanf here), expf, and x^y as expf(y·logf x) (several times cheaper than powf).
//   Measured on this x86 host (callgrind and wall time, MF 6.1 combined): branch-free
//   Cephes-style float sin/cos/exp/log polynomials (commit 0d09488) were no faster than glibc's
//   FMA sinf/cosf/expf/logf in scalar code, also with -march=haswell, so they were removed.
//   The Magic Formula's core trig(C·atan(x − E·(x − atan x))) goes through mf_cores, all (up to
//   eight) cores of an evaluation at once: for float in passes of four vector lanes (tread's atan,
//   sin and cos on GCC vector types), ~2x cheaper per core than scalar passes; for double, the
//   double lanes and Jet the formula as written, stage by stage over the cores, so their results
//   do not change by a bit (the four-lane scalar of mf_lanes.hpp has its own mf_cores).
//   Errors of the float functions: tests/mf/mf_math_test.cpp.
// Identity used by the evaluation: cos(atan x) = 1/√(1+x²), written without overflow for huge x.

#include <bit>
#include <cmath>
#include <cstdint>

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
T mf_exp(const T& x) {
  using std::exp;
  return exp(x);
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

/// Cody–Waite reduction by π/2 (for |x| ≤ kTrigMax): x = k·π/2 + r, |r| ≤ π/4 (+ rounding), and
/// the quadrant k mod 4. π/2 is split into three parts; the first has 8 significant bits, so
/// k·1.5703125 is exact for |k| < 2^16.
inline constexpr float kTrigMax = 32768.0f;

struct Reduced {
  float r;
  unsigned quadrant;
};

/// k = rint(x·2/π) and r = x − k·π/2, for a float or four lanes (V).
// The functions of float vectors (V) here are always inlined: an out-of-line copy is compiled for
// the baseline target, and a wider clone (AVX2, AVX-512) calling it passes its 8- or 16-lane
// vectors by the baseline's ABI (GCC: -Wpsabi), slowly at best (an out-of-line atan_lanes made
// the 8-lane batch a third slower) and with a crash where the two disagree.
template <typename V>
[[gnu::always_inline]] inline V quarter_turns_of(V x) {
  return (x * 0.636619772367581f + 12582912.0f) - 12582912.0f;
}
template <typename V>
[[gnu::always_inline]] inline V reduce_by(V x, V k) {
  return ((x - k * 1.5703125f) - k * 4.837512969970703125e-4f) - k * 7.54978995489188e-8f;
}

inline Reduced reduce_pio2(float x) {
  const float k = quarter_turns_of(x);
  return {reduce_by(x, k), static_cast<unsigned>(static_cast<int>(k))};
}

/// sin and cos of the reduced argument r ∈ [−π/4, π/4] (Cephes' minimax polynomials, a few
/// ulp), for a float or four lanes (V).
template <typename V>
[[gnu::always_inline]] inline V sin_poly(V r) {
  const V z = r * r;
  return r + r * z * (-1.6666654611e-1f + z * (8.3321608736e-3f + z * -1.9515295891e-4f));
}
template <typename V>
[[gnu::always_inline]] inline V cos_poly(V r) {
  const V z = r * r;
  return 1.0f - 0.5f * z +
         z * z * (4.166664568298827e-2f + z * (-1.388731625493765e-3f + z * 2.443315711809948e-5f));
}

/// tan = sin/cos of the reduced argument (−cos/sin in odd quadrants); relative error below 1e-6.
inline float tan(float x) {
  if (!(std::fabs(x) <= kTrigMax)) return std::tan(x);
  const Reduced a = reduce_pio2(x);
  const float s = sin_poly(a.r);
  const float c = cos_poly(a.r);
  const bool odd = (a.quadrant & 1u) != 0u;
  return odd ? -c / s : s / c;
}

}  // namespace fast

inline float mf_sin(const float& x) {
  return std::sin(x);
}
inline float mf_cos(const float& x) {
  return std::cos(x);
}
inline float mf_tan(const float& x) {
  return fast::tan(x);
}
inline float mf_atan(const float& x) {
  return fast::atan(x);
}
inline float mf_exp(const float& x) {
  return std::exp(x);
}
/// x^y for x > 0 as exp(y·ln x): much cheaper than powf, whose last-bit exactness float does
/// not need.
inline float mf_pow(const float& x, const float& y) {
  return std::exp(y * std::log(x));
}

// ---- two independent evaluations of a function --------------------------------------------------
// Where an evaluation needs the same function of two independent arguments. For scalars these are
// the two calls; the four-lane path (mf_lanes.hpp) evaluates both in one eight-lane vector on
// x86-64, with the same results per lane.
template <typename T>
struct TwoOf {
  T first, second;
};
/// Whether the two evaluations of a *_two function cost about one (the four-lane path on x86-64:
/// mf_lanes.hpp), so that a value needed later may be computed beside another.
template <typename T>
inline constexpr bool kTwoForOne = false;
template <typename T>
TwoOf<T> mf_atan_two(const T& a, const T& b) {
  return {mf_atan(a), mf_atan(b)};
}
template <typename T>
TwoOf<T> mf_tan_two(const T& a, const T& b) {
  return {mf_tan(a), mf_tan(b)};
}
/// x^y and u^v.
template <typename T>
TwoOf<T> mf_pow_two(const T& x, const T& y, const T& u, const T& v) {
  return {mf_pow(x, y), mf_pow(u, v)};
}
template <typename T>
TwoOf<T> mf_sin_two(const T& a, const T& b) {
  return {mf_sin(a), mf_sin(b)};
}
/// cos a and sin b.
template <typename T>
TwoOf<T> mf_cos_sin(const T& a, const T& b) {
  return {mf_cos(a), mf_sin(b)};
}

// ---- the Magic Formula cores, all of an evaluation at once
// ---------------------------------------
inline constexpr int kMaxCores = 8;

/// Arguments of up to eight Magic Formula cores y = trig(c·atan(x − e·(x − atan x))), trig = sin,
/// or cos where `cosine` is set. Slots from `count` on are not set (not zeroed either: for lanes,
/// zeroing them was 800 bytes of stores an evaluation); the versions that evaluate four cores at a
/// time take the group's first core in their place (slot_of) and nothing reads those outputs.
template <typename T>
struct Cores {
  T c[kMaxCores];
  T x[kMaxCores];
  T e[kMaxCores];
  bool cosine[kMaxCores] = {};
  int count = 0;
  /// Adds a core, returns its lane.
  int add(const T& c_, const T& x_, const T& e_, bool cosine_) {
    c[count] = c_;
    x[count] = x_;
    e[count] = e_;
    cosine[count] = cosine_;
    return count++;
  }
  /// The slot a pass of four cores from `group` reads for its core `group + k`: that core, or the
  /// group's first where there is none (group < count).
  int slot_of(int group, int k) const { return group + k < count ? group + k : group; }
};

/// double, double lanes (mf_double_lanes.hpp) and generic scalars (ceres::Jet): each core exactly
/// as the formula is written, but stage by stage over all cores (every inner atan, then every outer
/// atan, then every sin/cos), so that the library calls next to each other do not wait for each
/// other's results: the same operations on the same values, so the same bits as core by core.
/// (float and the float lanes have their own, with the fast approximants.)
template <typename T>
void mf_cores(const Cores<T>& in, T (&out)[kMaxCores]) {
  T inner[kMaxCores];
  for (int i = 0; i < in.count; ++i) inner[i] = mf_atan(in.x[i]);
  T outer[kMaxCores];
  for (int i = 0; i < in.count; ++i) {
    const T& x = in.x[i];
    outer[i] = mf_atan(x - in.e[i] * (x - inner[i]));
  }
  for (int i = 0; i < in.count; ++i) {
    out[i] = in.cosine[i] ? mf_cos(in.c[i] * outer[i]) : mf_sin(in.c[i] * outer[i]);
  }
}

namespace fast {

// Float lanes (GCC vector extensions): 4 (SSE on x86-64, NEON on aarch64, scalar code where the
// target has no vector unit, e.g. Cortex-M4F), 8 (AVX2) and 16 (AVX-512) where a function is
// compiled for them. Written out per width: GCC drops a vector_size that depends on a template
// parameter.
template <int N>
struct VectorOf;
template <>
struct VectorOf<4> {
  using F = float __attribute__((vector_size(16)));
  using I = std::int32_t __attribute__((vector_size(16)));
  using U = std::uint32_t __attribute__((vector_size(16)));
};
template <>
struct VectorOf<8> {
  using F = float __attribute__((vector_size(32)));
  using I = std::int32_t __attribute__((vector_size(32)));
  using U = std::uint32_t __attribute__((vector_size(32)));
};
template <>
struct VectorOf<16> {
  using F = float __attribute__((vector_size(64)));
  using I = std::int32_t __attribute__((vector_size(64)));
  using U = std::uint32_t __attribute__((vector_size(64)));
};
using F4 = VectorOf<4>::F;
using I4 = VectorOf<4>::I;
/// The int32 vector of a float vector's width.
template <typename V>
struct IntVectorOf;
template <>
struct IntVectorOf<VectorOf<4>::F> {
  using type = VectorOf<4>::I;
};
template <>
struct IntVectorOf<VectorOf<8>::F> {
  using type = VectorOf<8>::I;
};
template <>
struct IntVectorOf<VectorOf<16>::F> {
  using type = VectorOf<16>::I;
};
template <typename V>
using IntOf = typename IntVectorOf<V>::type;

/// fast::atan on lanes (same reduction and polynomial, selects instead of branches).
template <typename V>
[[gnu::always_inline]] inline V atan_lanes(V x) {
  using I = IntOf<V>;
  const I sign_bit = I{} + static_cast<std::int32_t>(0x80000000u);
  const I bits = std::bit_cast<I>(x);
  const V a = std::bit_cast<V>(I(bits & ~sign_bit));
  const I big = a > 2.41421356237f;
  const I mid = a > 0.414213562373f;
  const V one = V{} + 1.0f;
  const V num = big ? -one : (mid ? a - 1.0f : a);
  const V den = big ? a : (mid ? a + 1.0f : one);
  const V base = big ? V{} + kHalfPi : (mid ? V{} + 0.785398163397f : V{});
  const V t = num / den;
  const V z = t * t;
  const V z2 = z * z;
  const V poly = (-3.33329491539e-1f + 1.99777106478e-1f * z) +
                 z2 * (-1.38776856032e-1f + 8.05374449538e-2f * z);
  const V r = base + (t + t * z * poly);
  return std::bit_cast<V>(I(std::bit_cast<I>(r) | (bits & sign_bit)));
}

/// sin (quarter_turns 0) or cos (quarter_turns 1) of lanes with |y| ≤ kTrigMax: the reduction
/// and polynomials of fast::tan, the quadrant advanced by a quarter turn for cos.
template <typename V>
[[gnu::always_inline]] inline V sin_cos_lanes(V y, IntOf<V> quarter_turns) {
  using I = IntOf<V>;
  const V k = quarter_turns_of(y);
  const V r = reduce_by(y, k);
  const I q = __builtin_convertvector(k, I) + quarter_turns;
  const V v = (q & 1) != 0 ? cos_poly(r) : sin_poly(r);
  return std::bit_cast<V>(I(std::bit_cast<I>(v) ^ ((q & 2) << 30)));  // −v in quadrants 2, 3
}

/// fast::tan on lanes with |y| ≤ kTrigMax (same reduction and polynomials).
template <typename V>
[[gnu::always_inline]] inline V tan_lanes(V y) {
  const V k = quarter_turns_of(y);
  const V r = reduce_by(y, k);
  const V s = sin_poly(r);
  const V c = cos_poly(r);
  // One division of the selected operands, the same quotients as −c/s or s/c: GCC 12 compiled
  // the select of the two quotients to a division and a second one merged into its result under
  // a mask (AVX-512), which waits for the first. Four lanes on the Intel VM: MF 6.1 383 → 378 ns
  // and MF 6.2 505 → 498 ns per group of four (medians of three alternating runs).
  const auto odd = (__builtin_convertvector(k, IntOf<V>) & 1) != 0;
  return (odd ? -c : s) / (odd ? s : c);
}

/// The four-lane forms (the scalar float path's mf_cores and the tests use them).
inline F4 atan4(F4 x) {
  return atan_lanes(x);
}
inline F4 sin_cos4(F4 y, I4 quarter_turns) {
  return sin_cos_lanes(y, quarter_turns);
}
inline F4 tan4(F4 y) {
  return tan_lanes(y);
}

}  // namespace fast

/// float: four cores in one pass of four lanes. A lane whose angle c·atan(...) lies beyond the
/// reduction's range (|c| > 2e4, or not finite) is redone with libm.
inline void mf_cores(const Cores<float>& in, float (&out)[kMaxCores]) {
  for (int g = 0; g < kMaxCores; g += 4) {
    if (g >= in.count) {
      for (int i = g; i < kMaxCores; ++i) out[i] = 0.0f;
      continue;
    }
    fast::F4 c;
    fast::F4 x;
    fast::F4 e;
    fast::I4 quarter_turns;
    for (int i = 0; i < 4; ++i) {
      const int s = in.slot_of(g, i);
      c[i] = in.c[s];
      x[i] = in.x[s];
      e[i] = in.e[s];
      quarter_turns[i] = in.cosine[s] ? 1 : 0;
    }
    const fast::F4 y = c * fast::atan4(x - e * (x - fast::atan4(x)));
    const fast::F4 v = fast::sin_cos4(y, quarter_turns);
    for (int i = 0; i < 4; ++i) {
      out[g + i] = v[i];
      if (!(std::fabs(y[i]) <= fast::kTrigMax))
        out[g + i] = in.cosine[in.slot_of(g, i)] ? std::cos(y[i]) : std::sin(y[i]);
    }
  }
}

// ---- identities ---------------------------------------------------------------------------------
/// cos(atan(x)) = 1/√(1+x²), without overflow. (Scalars branch; lanes (mf_lanes.hpp) have their
/// own overload.)
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

}  // namespace tread::mf::detail
