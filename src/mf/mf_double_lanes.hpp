#pragma once
// Double lanes as a Magic Formula scalar: `evaluate` instantiated with dlanes::DLanes<N> computes N
// operating points in one pass and gives each exactly what evaluate<double> gives it, bit for bit.
// Unlike the float lanes (mf_lanes.hpp, tread's own polynomials), every elementary function is
// libm's, called lane by lane (atan, sin, cos, tan, exp, pow, acos, log), and the arithmetic is
// IEEE double per lane (+ − × ÷ and √ are correctly rounded, so a vector instruction gives the
// scalar's bits). What the lanes gain: the arithmetic in vector registers, and N independent libm
// calls next to each other, which the CPU overlaps (a dependent chain of glibc atan calls measured
// 27 ns a call on the AVX2 VM, independent calls 10–11 ns).
//
// The bits equal evaluate<double>'s only where neither is contracted into FMAs: the file that
// instantiates it is compiled -ffp-contract=off, and it is used where evaluate<double> has no FMA
// either (x86-64 without __FMA__: mf_evaluate_rows.cpp). tests/mf/mf_evaluate_rows_test.cpp
// compares them over every shipped tyre, use mode and option.
//
// Where the shared code chooses by precision (the MF 6.2 solve's tolerances and approximants,
// mf_radius.hpp), detail::is_float_lanes tells float lanes from these.

#include <array>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <type_traits>

#include "mf/mf_math.hpp"
#include "mf/mf_types.hpp"

namespace tread::mf::dlanes {

/// Two lanes (one SSE2 register): four measured slower on the AVX2 VM (two registers a value,
/// spilled around each libm call), so only two are defined.
template <int N>
struct VectorOf;
template <>
struct VectorOf<2> {
  using D = double __attribute__((vector_size(16)));
  using I = std::int64_t __attribute__((vector_size(16)));
};

/// A per-lane truth value: all bits set where true.
template <int N>
struct DMask {
  using I = typename VectorOf<N>::I;
  I m{};
  friend DMask operator&&(const DMask& a, const DMask& b) { return {a.m & b.m}; }
  friend DMask operator||(const DMask& a, const DMask& b) { return {a.m | b.m}; }
  friend DMask operator!(const DMask& a) { return {~a.m}; }
  bool operator[](int i) const { return m[i] != 0; }
};

template <int N>
inline bool any_lane(const DMask<N>& a) {
  bool any = false;
  for (int i = 0; i < N; ++i) any = any || a.m[i] != 0;
  return any;
}

/// N doubles. A default-initialized DLanes is not set, a value-initialized one is zero.
template <int N>
struct DLanes {
  using D = typename VectorOf<N>::D;
  D v;
  DLanes() = default;
  explicit DLanes(D x) : v(x) {}
  // NOLINTNEXTLINE(google-explicit-constructor): a double broadcasts (lane by lane: D{} + x would
  // turn −0 into +0).
  DLanes(double x) {
    for (int i = 0; i < N; ++i) v[i] = x;
  }
  template <typename U>
  requires(std::is_arithmetic_v<U> && !std::same_as<U, double>) explicit DLanes(U x)
      : DLanes(static_cast<double>(x)) {}
  double operator[](int i) const { return v[i]; }

  friend DLanes operator+(const DLanes& a, const DLanes& b) { return DLanes(a.v + b.v); }
  friend DLanes operator-(const DLanes& a, const DLanes& b) { return DLanes(a.v - b.v); }
  friend DLanes operator*(const DLanes& a, const DLanes& b) { return DLanes(a.v * b.v); }
  friend DLanes operator/(const DLanes& a, const DLanes& b) { return DLanes(a.v / b.v); }
  friend DLanes operator-(const DLanes& a) { return DLanes(-a.v); }
  friend DMask<N> operator<(const DLanes& a, const DLanes& b) { return {a.v < b.v}; }
  friend DMask<N> operator>(const DLanes& a, const DLanes& b) { return {a.v > b.v}; }
  friend DMask<N> operator<=(const DLanes& a, const DLanes& b) { return {a.v <= b.v}; }
  friend DMask<N> operator>=(const DLanes& a, const DLanes& b) { return {a.v >= b.v}; }
};

template <int N>
inline DLanes<N> if_else(const DMask<N>& m, const DLanes<N>& a, const DLanes<N>& b) {
  return DLanes<N>(m.m ? a.v : b.v);
}

/// libm lane by lane.
template <int N, typename F>
inline DLanes<N> per_lane(const DLanes<N>& x, F f) {
  DLanes<N> r;
  for (int i = 0; i < N; ++i) r.v[i] = f(x.v[i]);
  return r;
}

template <int N>
inline DLanes<N> abs(const DLanes<N>& x) {
  return per_lane(x, [](double a) { return std::fabs(a); });
}
template <int N>
inline DLanes<N> sqrt(const DLanes<N>& x) {
  return per_lane(x, [](double a) { return std::sqrt(a); });
}
template <int N>
inline DLanes<N> atan(const DLanes<N>& x) {
  return per_lane(x, [](double a) { return std::atan(a); });
}
template <int N>
inline DLanes<N> sin(const DLanes<N>& x) {
  return per_lane(x, [](double a) { return std::sin(a); });
}
template <int N>
inline DLanes<N> cos(const DLanes<N>& x) {
  return per_lane(x, [](double a) { return std::cos(a); });
}
template <int N>
inline DLanes<N> tan(const DLanes<N>& x) {
  return per_lane(x, [](double a) { return std::tan(a); });
}
template <int N>
inline DLanes<N> exp(const DLanes<N>& x) {
  return per_lane(x, [](double a) { return std::exp(a); });
}
template <int N>
inline DLanes<N> log(const DLanes<N>& x) {
  return per_lane(x, [](double a) { return std::log(a); });
}
template <int N>
inline DLanes<N> acos(const DLanes<N>& x) {
  return per_lane(x, [](double a) { return std::acos(a); });
}
template <int N>
inline DLanes<N> pow(const DLanes<N>& x, const DLanes<N>& y) {
  DLanes<N> r;
  for (int i = 0; i < N; ++i) r.v[i] = std::pow(x.v[i], y.v[i]);
  return r;
}

/// cos(atan x) as the scalars compute it (mf_math.hpp), both branches per lane, then selected.
template <int N>
inline DLanes<N> cos_atan(const DLanes<N>& x) {
  const DLanes<N> a = abs(x);
  const DLanes<N> inv = DLanes<N>(1.0) / a;
  return if_else(a > DLanes<N>(1.0), inv / sqrt(DLanes<N>(1.0) + inv * inv),
                 DLanes<N>(1.0) / sqrt(DLanes<N>(1.0) + x * x));
}

/// MfOutput<DLanes<N>>::status: per lane, whether an input left the finite-arithmetic envelope and
/// whether an output came out non-finite (and was replaced by 0); [i] is lane i's Status.
template <int N>
struct DLaneStatus {
  DMask<N> out_of_range{};
  DMask<N> non_finite{};
  Status operator[](int i) const {
    if (non_finite[i]) return Status::non_finite;
    return out_of_range[i] ? Status::out_of_range : Status::ok;
  }
};

}  // namespace tread::mf::dlanes

namespace tread::mf {
template <int N>
struct StatusFor<dlanes::DLanes<N>> {
  using type = dlanes::DLaneStatus<N>;
};
}  // namespace tread::mf
