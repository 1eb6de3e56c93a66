#pragma once
// Float lanes as a Magic Formula scalar: `evaluate` instantiated with lanes::Lanes<N> computes N
// wheels in one pass. F4 = Lanes<4> (SSE on x86-64, NEON on aarch64; plain scalar code on targets
// without a vector unit, where it is correct but no faster); F8 and F16 for functions compiled for
// AVX2 and AVX-512 (mf_evaluate_batch.cpp), where each lane computes exactly what it computes in
// F4 in a function compiled for the same target. Same parameters and options for all lanes.
//
//   - Lanes<N>: arithmetic with lanes and float (a float broadcasts), comparisons give a Mask<N>
//     (all bits set where true); if_else(mask, a, b) selects per lane, any_lane(mask) tells whether
//     a branch is needed at all.
//   - The elementary functions the evaluation calls, per lane: atan, sin, cos and tan with tread's
//     float polynomials (mf_math.hpp), exp and log as Cephes' float polynomials (relative error a
//     few ulp; errors tested in tests/mf/mf_lanes_test.cpp), pow(x, y) = exp(y·log x) for x > 0
//     (the scalar float path's mf_pow does the same with libm's expf/logf; its fz62 calls powf),
//     sqrt as the vector instruction. Angles beyond the reduction's range and acos (turn slip
//     only) go lane by lane through libm.
//   - MfOutput<Lanes<N>>::status is a LaneStatus<N>: two masks, the lanes whose input left the
//     finite-arithmetic envelope and the lanes with a non-finite output.
//   - Every operator and function takes its lanes and masks by const reference. Passed by value, a
//     Lanes<16> (64 bytes) is an aggregate copy that GCC sometimes leaves stored to memory after
//     inlining, and a product that is also stored is not contracted into an FMA: the 16-lane
//     batch then rounded a few a·b + c differently from the 8- and 4-lane code, depending on how
//     evaluate() happened to be cut into functions. By reference, every width contracts the same
//     expressions, and the batch gives evaluate_four's bits (tests/mf/mf_evaluate_batch_test.cpp).
// Not for the ECU's scalar build (Cortex-M4F): there the node evaluates wheel by wheel.

#include <array>
#include <bit>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>

#include "mf/mf_math.hpp"
#include "mf/mf_types.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#elif defined(__ARM_NEON) && defined(__aarch64__)
#include <arm_neon.h>
#endif

namespace tread::mf::lanes {

// The lane functions below return lanes by value and are always inlined (as are the fast functions
// of mf_math.hpp): an out-of-line copy is compiled for the baseline target, and a wide clone (AVX2,
// AVX-512) calling it would pass 8 or 16 lanes by the baseline's ABI (tests/mf/
// wide_clone_calls.sh). GCC's flatten alone left some out of line (mf_tan, atan_lanes,
// trig_wide_lanes) as unrelated code changed.

/// GCC vector types of N floats and N int32s.
template <int N>
using FloatVec = typename detail::fast::VectorOf<N>::F;
template <int N>
using IntVec = typename detail::fast::VectorOf<N>::I;
using V = FloatVec<4>;
using VI = IntVec<4>;

/// A per-lane truth value: all bits set where true. And, or and not work on the bits as unsigned
/// lanes: on the comparisons' own int32 vectors GCC 12 keeps an and/or of two comparisons as
/// AVX-512 mask (k register) logic it then cannot turn back into a vector, and lowers the
/// comparisons lane by lane (16-lane code: ~3400 scalar vcomiss in mf_evaluate_batch.o).
template <int N>
struct Mask {
  IntVec<N> m{};
  friend Mask operator&&(const Mask& a, const Mask& b) { return {IntVec<N>(bits(a) & bits(b))}; }
  friend Mask operator||(const Mask& a, const Mask& b) { return {IntVec<N>(bits(a) | bits(b))}; }
  friend Mask operator!(const Mask& a) { return {IntVec<N>(~bits(a))}; }
  bool operator[](int i) const { return m[i] != 0; }

 private:
  static typename detail::fast::VectorOf<N>::U bits(const Mask& a) {
    return typename detail::fast::VectorOf<N>::U(a.m);
  }
};
using Mask4 = Mask<4>;

template <int N>
[[gnu::always_inline]] inline bool any_lane(const Mask<N>& a) {
  if constexpr (N == 4) {
#if defined(__SSE2__)
    return _mm_movemask_ps(__m128(a.m)) != 0;
#elif defined(__ARM_NEON) && defined(__aarch64__)
    return vmaxvq_u32(uint32x4_t(a.m)) != 0U;
#else
    return ((a.m[0] | a.m[1]) | (a.m[2] | a.m[3])) != 0;
#endif
  } else {
    // The two halves or-ed, down to four lanes.
    const auto halves = std::bit_cast<std::array<IntVec<N / 2>, 2>>(a.m);
    return any_lane(Mask<N / 2>{halves[0] | halves[1]});
  }
}

/// N floats. Like a float, a default-initialized Lanes is not set (`Lanes<N> x;`), a
/// value-initialized one is zero (`Lanes<N> x{};`): zeroing every default-constructed Lanes (the
/// evaluation's intermediate structs, the cores' arguments) cost the 8-lane batch about 7 % of its
/// time in stores.
template <int N>
struct Lanes {
  FloatVec<N> v;
  Lanes() = default;
  explicit Lanes(FloatVec<N> x) : v(x) {}
  Lanes(float x) : v(broadcast(x)) {}  // NOLINT(google-explicit-constructor): a float broadcasts
  template <typename U>
  requires(std::is_arithmetic_v<U> && !std::same_as<U, float>) explicit Lanes(U x)
      : Lanes(static_cast<float>(x)) {}
  float operator[](int i) const { return v[i]; }

  friend Lanes operator+(const Lanes& a, const Lanes& b) { return Lanes(a.v + b.v); }
  friend Lanes operator-(const Lanes& a, const Lanes& b) { return Lanes(a.v - b.v); }
  friend Lanes operator*(const Lanes& a, const Lanes& b) { return Lanes(a.v * b.v); }
  friend Lanes operator/(const Lanes& a, const Lanes& b) { return Lanes(a.v / b.v); }
  friend Lanes operator-(const Lanes& a) { return Lanes(-a.v); }
  friend Mask<N> operator<(const Lanes& a, const Lanes& b) { return {a.v < b.v}; }
  friend Mask<N> operator>(const Lanes& a, const Lanes& b) { return {a.v > b.v}; }
  friend Mask<N> operator<=(const Lanes& a, const Lanes& b) { return {a.v <= b.v}; }
  friend Mask<N> operator>=(const Lanes& a, const Lanes& b) { return {a.v >= b.v}; }

 private:
  // x in every lane. Four lanes: x in lane 0 shuffled into all (one vbroadcastss / shufps / dup),
  // where the loop of element stores compiled to a chain of four inserts per broadcast in
  // evaluate_four's AVX2 clone (about 6 % of its instructions). Eight and sixteen lanes keep the
  // loop, which compiles to one vbroadcastss there: the shuffle left eight lanes with an insert
  // and a move per broadcast in the AVX2 batch, and GCC's inlining of the batch's AVX2 clone
  // then differed (an out-of-line call, see mf_math.hpp's fast functions); at sixteen GCC 12
  // fails with an internal compiler error on a select in loaded_radius62's AVX-512 code.
  [[gnu::always_inline]] static FloatVec<N> broadcast(float x) {
    if constexpr (N == 4) {
      const FloatVec<N> first = {x};
      return __builtin_shufflevector(first, first, 0, 0, 0, 0);
    } else {
      FloatVec<N> r;
      for (int i = 0; i < N; ++i) r[i] = x;
      return r;
    }
  }
};
using F4 = Lanes<4>;
using F8 = Lanes<8>;
using F16 = Lanes<16>;

/// The select on the mask's sign bit (a Mask's lanes are all ones or all zeros): one (v)blendvps
/// with SSE4.1 and AVX, where `m ? a : b` tested each lane against zero first (a compare with a
/// zeroed register and its inversion: 2–3 more instructions per select, about 50 per block of eight
/// in MF 6.2's solve alone).
/// Where AVX-512VL is there (code compiled for x86-64-v4 as a whole: mf_evaluate_four_v4.cpp),
/// four and eight lanes take it bit by bit, (a & m) | (b & ~m): one vpternlogd. GCC 12 emits
/// vblendvps otherwise, which an Intel Golden Cove core (the Intel VM's Sapphire Rapids Xeon) runs
/// as 3 µops on all three vector ports: measured there, one vblendvps per cycle against three
/// vpternlogd or vblendmps. AVX2 code keeps vblendvps (one µop on the AVX2 VM's AMD Zen 3, where
/// and, andn and or are three), sixteen lanes the mask registers GCC gives them. A select is
/// exact, but its form changes what GCC may fold and so which products it fuses into FMAs
/// (sgn_nz_times in mf_detail_common.hpp): that the v4 code's bits equal the v3 clone's is
/// checked (MfEvaluateFour.X8664V4EqualsV3BitForBit), not given by construction. The elementary
/// functions' own selects (atan_lanes, log, sin_cos_lanes in mf_math.hpp and below) keep GCC's
/// vector conditional: taken bit by bit too, four lanes' results changed in the last bits (the
/// batch no longer equalled them), and MF 6.1 on four lanes measured 370 → 388 ns slower.
/// This is the one inline function of these headers whose body depends on the ISA macros: it
/// must stay inlined into code of one level (always_inline; the wide files are compiled without
/// LTO, src/mf/CMakeLists.txt, and export nothing else, tests/mf/wide_object_symbols.sh).
template <int N>
[[gnu::always_inline]] inline Lanes<N> if_else(const Mask<N>& m, const Lanes<N>& a,
                                               const Lanes<N>& b) {
#if defined(__AVX512VL__)
  if constexpr (N <= 8) {
    using I = IntVec<N>;
    return Lanes<N>(std::bit_cast<FloatVec<N>>(
        I((std::bit_cast<I>(a.v) & m.m) | (std::bit_cast<I>(b.v) & ~m.m))));
  }
#endif
  return Lanes<N>(m.m < 0 ? a.v : b.v);
}

/// The evaluation's max_of/min_of (a < b ? b : a and b < a ? b : a) as single instructions where
/// the target has them (x86 maxps(b, a) is exactly a < b ? b : a, NaN included).
template <int N>
[[gnu::always_inline]] inline Lanes<N> max_of(const Lanes<N>& a, const Lanes<N>& b) {
#if defined(__SSE2__)
  if constexpr (N == 4) return Lanes<N>(V(_mm_max_ps(__m128(b.v), __m128(a.v))));
#endif
  return Lanes<N>(a.v < b.v ? b.v : a.v);
}
template <int N>
[[gnu::always_inline]] inline Lanes<N> min_of(const Lanes<N>& a, const Lanes<N>& b) {
#if defined(__SSE2__)
  if constexpr (N == 4) return Lanes<N>(V(_mm_min_ps(__m128(b.v), __m128(a.v))));
#endif
  return Lanes<N>(b.v < a.v ? b.v : a.v);
}

template <int N>
[[gnu::always_inline]] inline Lanes<N> abs(const Lanes<N>& x) {
  return Lanes<N>(
      std::bit_cast<FloatVec<N>>(IntVec<N>(std::bit_cast<IntVec<N>>(x.v) & 0x7fffffff)));
}

template <int N>
[[gnu::always_inline]] inline Lanes<N> sqrt(const Lanes<N>& x) {
  if constexpr (N == 4) {
#if defined(__SSE2__)
    return Lanes<N>(V(_mm_sqrt_ps(__m128(x.v))));
#elif defined(__ARM_NEON) && defined(__aarch64__)
    return Lanes<N>(V(vsqrtq_f32(float32x4_t(x.v))));
#else
    Lanes<N> r;
    for (int i = 0; i < 4; ++i) r.v[i] = std::sqrt(x.v[i]);
    return r;
#endif
  } else {
    // Lane by lane in the source: GCC turns the loop into one vsqrtps of the caller's width
    // (ymm with AVX2, zmm with AVX-512, two xmm on the baseline). Correctly rounded either way.
    Lanes<N> r;
    for (int i = 0; i < N; ++i) r.v[i] = std::sqrt(x.v[i]);
    return r;
  }
}

/// libm lane by lane (the rare paths).
template <int N, typename F>
[[gnu::always_inline]] inline Lanes<N> per_lane(const Lanes<N>& x, F f) {
  Lanes<N> r;
  for (int i = 0; i < N; ++i) r.v[i] = f(x.v[i]);
  return r;
}

template <int N>
[[gnu::always_inline]] inline Lanes<N> acos(const Lanes<N>& x) {
  return per_lane(x, [](float a) { return std::acos(a); });
}

/// e^x: x = n·ln 2 + r, |r| ≤ ln2/2, Cephes' expf polynomial, 2^n applied in two halves so that
/// results near the overflow and underflow thresholds come out as expf's (inf, denormals, 0). The
/// polynomials here and in log are evaluated by Estrin's scheme: pow lies on the dependent chain
/// of MF 6.2's Rl solve, and Horner's chain of fused steps is about twice as long.
template <int N>
[[gnu::always_inline]] inline Lanes<N> exp(const Lanes<N>& x) {
  using W = FloatVec<N>;
  using WI = IntVec<N>;
  W a = x.v;
  a = a > 89.0f ? W{} + 89.0f : a;
  a = a < -104.0f ? W{} - 104.0f : a;
  const W n = (a * 1.44269504088896341f + 12582912.0f) - 12582912.0f;  // rint(x/ln 2)
  const W r = (a - n * 0.693359375f) - n * -2.12194440e-4f;
  const W z = r * r;
  const W z2 = z * z;
  const W p01 = 5.0000001201e-1f + 1.6666665459e-1f * r;
  const W p23 = 4.1665795894e-2f + 8.3334519073e-3f * r;
  const W p45 = 1.3981999507e-3f + 1.9875691500e-4f * r;
  const W poly = p01 + z * p23 + z2 * p45;
  const W y = r + z * poly + 1.0f;
  const WI ni = __builtin_convertvector(n, WI);
  const WI n1 = ni >> 1;
  const WI n2 = ni - n1;
  const W s1 = std::bit_cast<W>(WI((n1 + 127) << 23));
  const W s2 = std::bit_cast<W>(WI((n2 + 127) << 23));
  return Lanes<N>(y * s1 * s2);
}

/// Natural logarithm for x > 0 (denormals included): Cephes' logf polynomial on the mantissa in
/// [√½, √2). x ≤ 0, inf and NaN give unspecified finite values or NaN: callers select them away.
template <int N>
[[gnu::always_inline]] inline Lanes<N> log(const Lanes<N>& x) {
  using W = FloatVec<N>;
  using WI = IntVec<N>;
  W a = x.v;
  const WI tiny = a < 1.17549435e-38f;
  a = tiny != 0 ? a * 8388608.0f : a;  // denormal → normal (2^23)
  const WI bits = std::bit_cast<WI>(a);
  W e = __builtin_convertvector(WI(((bits >> 23) & 0xff) - 126), W);
  e = tiny != 0 ? e - 23.0f : e;
  W m = std::bit_cast<W>(WI((bits & 0x007fffff) | 0x3f000000));  // [0.5, 1)
  const WI low = m < 0.707106781186547524f;
  e = low != 0 ? e - 1.0f : e;
  m = low != 0 ? m + m - 1.0f : m - 1.0f;
  const W z = m * m;
  const W z2 = z * z;
  const W p01 = 3.3333331174e-1f - 2.4999993993e-1f * m;
  const W p23 = 2.0000714765e-1f - 1.6668057665e-1f * m;
  const W p45 = 1.4249322787e-1f - 1.2420140846e-1f * m;
  const W p67 = 1.1676998740e-1f - 1.1514610310e-1f * m;
  const W q03 = p01 + z * p23;
  const W q47 = p45 + z * p67;
  W y = (q03 + z2 * q47) + (z2 * z2) * 7.0376836292e-2f;
  y = y * (m * z);
  y = y + e * -2.12194440e-4f;
  y = y - 0.5f * z;
  return Lanes<N>((m + y) + e * 0.693359375f);
}

/// x^y for x > 0 as exp(y·log x), like the scalar float path.
template <int N>
[[gnu::always_inline]] inline Lanes<N> pow(const Lanes<N>& x, const Lanes<N>& y) {
  return exp(y * log(x));
}

// The Magic Formula's elementary functions (found by ADL from mf_evaluate.hpp).
/// r[i] = f(x[i]) where which[i]: the rare redo of trig_wide_lanes, out of line and given plain
/// arrays, so that a wide clone's call to it (compiled for its file's target) passes pointers
/// only, never a vector by value. Internal linkage (static): each file has its own copy, compiled
/// for that file's target. As a shared (weak) definition, the linker kept one copy for every file,
/// and the one of the file compiled for x86-64-v3 (mf_evaluate_batch_v3.cpp) could have been the
/// one baseline code called (tests/mf/wide_object_symbols.sh).
template <typename F>
[[gnu::noinline, gnu::cold]] static void redo_lanes(int n, const float* x,
                                                    const std::int32_t* which, float* r, F f) {
  for (int i = 0; i < n; ++i)
    if (which[i] != 0) r[i] = f(x[i]);
}
/// The lanes of x beyond the trig reduction's range, redone in r with libm's f. The range check
/// inline: out of line it was a call (and SSE code) for every tan of the AVX2 batch.
template <int N, typename F>
[[gnu::always_inline]] inline void trig_wide_lanes(const Lanes<N>& x, Lanes<N>& r, F f) {
  const Mask<N> out_of_range = !(abs(x) <= Lanes<N>(detail::fast::kTrigMax));
  if (any_lane(out_of_range)) [[unlikely]] {
    constexpr auto kN = static_cast<std::size_t>(N);
    float xs[kN];
    float rs[kN];
    std::int32_t which[kN];
    std::memcpy(xs, &x.v, sizeof(xs));
    std::memcpy(rs, &r.v, sizeof(rs));
    std::memcpy(which, &out_of_range.m, sizeof(which));
    redo_lanes(N, xs, which, rs, f);
    std::memcpy(&r.v, rs, sizeof(rs));
  }
}
/// sin (cosine false) or cos of lanes; lanes beyond the reduction's range go through libm.
template <int N>
[[gnu::always_inline]] inline Lanes<N> sin_or_cos(const Lanes<N>& y, bool cosine) {
  const IntVec<N> turns = IntVec<N>{} + (cosine ? 1 : 0);
  Lanes<N> r(detail::fast::sin_cos_lanes(y.v, turns));
  trig_wide_lanes(y, r, [=](float a) { return cosine ? std::cos(a) : std::sin(a); });
  return r;
}
template <int N>
[[gnu::always_inline]] inline Lanes<N> mf_sin(const Lanes<N>& x) {
  return sin_or_cos(x, false);
}
template <int N>
[[gnu::always_inline]] inline Lanes<N> mf_cos(const Lanes<N>& x) {
  return sin_or_cos(x, true);
}
template <int N>
[[gnu::always_inline]] inline Lanes<N> mf_atan(const Lanes<N>& x) {
  return Lanes<N>(detail::fast::atan_lanes(x.v));
}
template <int N>
[[gnu::always_inline]] inline Lanes<N> mf_tan(const Lanes<N>& x) {
  Lanes<N> t(detail::fast::tan_lanes(x.v));
  trig_wide_lanes(x, t, [](float a) { return std::tan(a); });
  return t;
}
// Two independent evaluations of a function (mf_math.hpp's *_two): on x86-64, four lanes of each
// side by side in one eight-lane vector (one ymm in evaluate_four's AVX2 and AVX-512 code), each
// lane computing what the eight-lane batch computes for it; elsewhere the two calls.
#if defined(__x86_64__)
inline constexpr bool kTwoInOne = true;
#else
inline constexpr bool kTwoInOne = false;
#endif

}  // namespace tread::mf::lanes
namespace tread::mf::detail {
template <>
inline constexpr bool kTwoForOne<lanes::Lanes<4>> = lanes::kTwoInOne;
}  // namespace tread::mf::detail
namespace tread::mf::lanes {

template <int N>
[[gnu::always_inline]] inline detail::TwoOf<Lanes<N>> mf_atan_two(const Lanes<N>& a,
                                                                  const Lanes<N>& b) {
  if constexpr (N == 4 && kTwoInOne) {
    const FloatVec<8> r =
        detail::fast::atan_lanes(__builtin_shufflevector(a.v, b.v, 0, 1, 2, 3, 4, 5, 6, 7));
    return {Lanes<4>(__builtin_shufflevector(r, r, 0, 1, 2, 3)),
            Lanes<4>(__builtin_shufflevector(r, r, 4, 5, 6, 7))};
  } else {
    return {mf_atan(a), mf_atan(b)};
  }
}
template <int N>
[[gnu::always_inline]] inline detail::TwoOf<Lanes<N>> mf_tan_two(const Lanes<N>& a,
                                                                 const Lanes<N>& b) {
  if constexpr (N == 4 && kTwoInOne) {
    const FloatVec<8> r =
        detail::fast::tan_lanes(__builtin_shufflevector(a.v, b.v, 0, 1, 2, 3, 4, 5, 6, 7));
    detail::TwoOf<Lanes<4>> t{Lanes<4>(__builtin_shufflevector(r, r, 0, 1, 2, 3)),
                              Lanes<4>(__builtin_shufflevector(r, r, 4, 5, 6, 7))};
    trig_wide_lanes(a, t.first, [](float x) { return std::tan(x); });
    trig_wide_lanes(b, t.second, [](float x) { return std::tan(x); });
    return t;
  } else {
    return {mf_tan(a), mf_tan(b)};
  }
}
template <int N>
[[gnu::always_inline]] inline detail::TwoOf<Lanes<N>> mf_pow_two(const Lanes<N>& x,
                                                                 const Lanes<N>& y,
                                                                 const Lanes<N>& u,
                                                                 const Lanes<N>& v) {
  if constexpr (N == 4 && kTwoInOne) {
    const Lanes<8> r = pow(Lanes<8>(__builtin_shufflevector(x.v, u.v, 0, 1, 2, 3, 4, 5, 6, 7)),
                           Lanes<8>(__builtin_shufflevector(y.v, v.v, 0, 1, 2, 3, 4, 5, 6, 7)));
    return {Lanes<4>(__builtin_shufflevector(r.v, r.v, 0, 1, 2, 3)),
            Lanes<4>(__builtin_shufflevector(r.v, r.v, 4, 5, 6, 7))};
  } else {
    return {pow(x, y), pow(u, v)};
  }
}
/// sin or cos of each of two sets of lanes (cosine_a, cosine_b: which), side by side.
template <int N>
[[gnu::always_inline]] inline detail::TwoOf<Lanes<N>> sin_or_cos_two(const Lanes<N>& a,
                                                                     bool cosine_a,
                                                                     const Lanes<N>& b,
                                                                     bool cosine_b) {
  if constexpr (N == 4 && kTwoInOne) {
    const int ta = cosine_a ? 1 : 0;
    const int tb = cosine_b ? 1 : 0;
    const IntVec<8> turns = {ta, ta, ta, ta, tb, tb, tb, tb};
    const FloatVec<8> r = detail::fast::sin_cos_lanes(
        __builtin_shufflevector(a.v, b.v, 0, 1, 2, 3, 4, 5, 6, 7), turns);
    detail::TwoOf<Lanes<4>> t{Lanes<4>(__builtin_shufflevector(r, r, 0, 1, 2, 3)),
                              Lanes<4>(__builtin_shufflevector(r, r, 4, 5, 6, 7))};
    trig_wide_lanes(a, t.first, [=](float x) { return cosine_a ? std::cos(x) : std::sin(x); });
    trig_wide_lanes(b, t.second, [=](float x) { return cosine_b ? std::cos(x) : std::sin(x); });
    return t;
  } else {
    return {sin_or_cos(a, cosine_a), sin_or_cos(b, cosine_b)};
  }
}
template <int N>
[[gnu::always_inline]] inline detail::TwoOf<Lanes<N>> mf_sin_two(const Lanes<N>& a,
                                                                 const Lanes<N>& b) {
  return sin_or_cos_two(a, false, b, false);
}
/// cos a and sin b.
template <int N>
[[gnu::always_inline]] inline detail::TwoOf<Lanes<N>> mf_cos_sin(const Lanes<N>& a,
                                                                 const Lanes<N>& b) {
  return sin_or_cos_two(a, true, b, false);
}

/// Four-lane cores two at a time: cores 2i and 2i+1 side by side in eight lanes, `Pairs` such
/// eight-lane chains interleaved (a slot past `count` repeats core 0). In the four-wheel path's
/// AVX2 and AVX-512 code an eight-lane vector is one ymm register, so the cores (a fifth of
/// evaluate_four's instructions) take half the instructions; every lane computes what the
/// eight-lane batch computes for its wheel (the same templated atan and sin/cos on the same vector
/// type), so the batch and evaluate_four still agree bit for bit.
template <int Pairs, bool kFull>
void mf_core_pairs(const detail::Cores<Lanes<4>>& in, Lanes<4> (&out)[detail::kMaxCores]) {
  using W = FloatVec<8>;
  constexpr auto kPairs = static_cast<std::size_t>(Pairs);
  const auto slot = [&](int k) { return kFull || k < in.count ? k : 0; };
  // The cores' sin/cos choices, one lane each, then spread to four lanes per core (on x86: one
  // widening, then one lane permutation per pair).
  using Bytes = std::uint8_t __attribute__((vector_size(8)));
  Bytes cosine{};
  for (int k = 0; k < 2 * Pairs; ++k) cosine[k] = in.cosine[slot(k)] ? 1 : 0;
  const IntVec<8> each = __builtin_convertvector(cosine, IntVec<8>);
  IntVec<8> turns[kPairs];
  [&]<int... K>(std::integer_sequence<int, K...>) {
    ((turns[K] = __builtin_shufflevector(each, each, 2 * K, 2 * K, 2 * K, 2 * K, 2 * K + 1,
                                         2 * K + 1, 2 * K + 1, 2 * K + 1)),
     ...);
  }
  (std::make_integer_sequence<int, Pairs>{});
  W y[kPairs];
#pragma GCC unroll 4
  for (int k = 0; k < Pairs; ++k) {
    const int a = slot(2 * k);
    const int b = slot(2 * k + 1);
    const W x = __builtin_shufflevector(in.x[a].v, in.x[b].v, 0, 1, 2, 3, 4, 5, 6, 7);
    const W e = __builtin_shufflevector(in.e[a].v, in.e[b].v, 0, 1, 2, 3, 4, 5, 6, 7);
    y[k] = x - e * (x - detail::fast::atan_lanes(x));
  }
#pragma GCC unroll 4
  for (int k = 0; k < Pairs; ++k) {
    const int a = slot(2 * k);
    const int b = slot(2 * k + 1);
    const W c = __builtin_shufflevector(in.c[a].v, in.c[b].v, 0, 1, 2, 3, 4, 5, 6, 7);
    y[k] = c * detail::fast::atan_lanes(y[k]);
  }
  Mask<8> wide;
#pragma GCC unroll 4
  for (int k = 0; k < Pairs; ++k) {
    const W v = detail::fast::sin_cos_lanes(y[k], turns[k]);
    out[2 * k] = Lanes<4>(__builtin_shufflevector(v, v, 0, 1, 2, 3));
    out[2 * k + 1] = Lanes<4>(__builtin_shufflevector(v, v, 4, 5, 6, 7));
    wide = wide || !(abs(Lanes<8>(y[k])) <= Lanes<8>(detail::fast::kTrigMax));
  }
  if (any_lane(wide)) {
    for (int k = 0; k < 2 * Pairs; ++k) {
      const W& yk = y[k / 2];
      const Lanes<4> part(k % 2 == 0 ? __builtin_shufflevector(yk, yk, 0, 1, 2, 3)
                                     : __builtin_shufflevector(yk, yk, 4, 5, 6, 7));
      out[k] = sin_or_cos(part, in.cosine[slot(k)]);
    }
  }
}

/// Cores g … g + G − 1 of an evaluation on N wheels, written side by side so that their long
/// dependent chains (atan, division, atan, sin) overlap (a slot past `count` repeats core g).
/// Angles beyond the reduction's range go through libm.
template <int G, int N>
[[gnu::always_inline]] inline void mf_core_group(const detail::Cores<Lanes<N>>& in, int g,
                                                 Lanes<N> (&out)[detail::kMaxCores]) {
  using W = FloatVec<N>;
  W y[static_cast<std::size_t>(G)];
  int slot[static_cast<std::size_t>(G)];
  for (int k = 0; k < G; ++k) slot[k] = in.slot_of(g, k);
  for (int k = 0; k < G; ++k) {
    const W x = in.x[slot[k]].v;
    y[k] = x - in.e[slot[k]].v * (x - detail::fast::atan_lanes(x));
  }
  for (int k = 0; k < G; ++k) y[k] = in.c[slot[k]].v * detail::fast::atan_lanes(y[k]);
  Mask<N> wide;
  for (int k = 0; k < G; ++k) {
    const IntVec<N> turns = IntVec<N>{} + (in.cosine[slot[k]] ? 1 : 0);
    out[g + k] = Lanes<N>(detail::fast::sin_cos_lanes(y[k], turns));
    wide = wide || !(abs(Lanes<N>(y[k])) <= Lanes<N>(detail::fast::kTrigMax));
  }
  if (any_lane(wide)) {
    for (int k = 0; k < G; ++k) out[g + k] = sin_or_cos(Lanes<N>(y[k]), in.cosine[slot[k]]);
  }
}

/// The Magic Formula cores of an evaluation (mf_math.hpp), each on N wheels. Eight lanes (AVX2):
/// all the cores of an evaluation at once where there are more than four (combined slip), so
/// that eight chains overlap (the 8-lane batch 2–4 % faster than in two passes of four, alternating
/// runs on the AVX2 VM; the same bits); four at a time otherwise.
template <int N>
void mf_cores(const detail::Cores<Lanes<N>>& in, Lanes<N> (&out)[detail::kMaxCores]) {
  if constexpr (N == 4 && kTwoInOne) {
    if (in.count == detail::kMaxCores) {
      mf_core_pairs<4, true>(in, out);
    } else if (in.count <= 4) {
      mf_core_pairs<2, false>(in, out);
    } else {
      mf_core_pairs<4, false>(in, out);
    }
    return;
  }
  if constexpr (N == 8) {
    if (in.count > 4) {
      mf_core_group<8>(in, 0, out);
      return;
    }
  }
  for (int g = 0; g < detail::kMaxCores; g += 4) {
    if (g >= in.count) break;
    mf_core_group<4>(in, g, out);
  }
}

/// cos(atan x) = 1/√(1+x²) (x² = inf gives the limit 0).
template <int N>
[[gnu::always_inline]] inline Lanes<N> cos_atan(const Lanes<N>& x) {
  return Lanes<N>(1.0f) / sqrt(Lanes<N>(1.0f) + x * x);
}
template <int N>
[[gnu::always_inline]] inline Lanes<N> mf_exp(const Lanes<N>& x) {
  return exp(x);
}
template <int N>
[[gnu::always_inline]] inline Lanes<N> mf_pow(const Lanes<N>& x, const Lanes<N>& y) {
  return pow(x, y);
}

}  // namespace tread::mf::lanes

namespace tread::mf {

namespace lanes {
/// MfOutput<Lanes<N>>::status: per lane, whether an input left the finite-arithmetic envelope and
/// whether an output came out non-finite (and was replaced by 0); [i] is lane i's Status.
template <int N>
struct LaneStatus {
  Mask<N> out_of_range{};
  Mask<N> non_finite{};
  Status operator[](int i) const {
    if (non_finite[i]) return Status::non_finite;
    return out_of_range[i] ? Status::out_of_range : Status::ok;
  }
  /// Every lane's operator[] at once: selected as a vector, read out through memory.
  std::array<Status, static_cast<std::size_t>(N)> each() const {
    using I = IntVec<N>;
    const I code = non_finite.m ? I{} + static_cast<int>(Status::non_finite)
                                : (out_of_range.m ? I{} + static_cast<int>(Status::out_of_range)
                                                  : I{} + static_cast<int>(Status::ok));
    std::array<std::int32_t, static_cast<std::size_t>(N)> codes;
    std::memcpy(codes.data(), &code, sizeof(codes));
    std::array<Status, static_cast<std::size_t>(N)> s;
    for (std::size_t i = 0; i < s.size(); ++i) s[i] = static_cast<Status>(codes[i]);
    return s;
  }
};
}  // namespace lanes

template <int N>
struct StatusFor<lanes::Lanes<N>> {
  using type = lanes::LaneStatus<N>;
};
}  // namespace tread::mf
