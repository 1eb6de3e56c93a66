#pragma once
// The helpers every part of the Magic Formula evaluation is written with: per-lane truth values
// and selects (so one source serves the scalars, the float lanes and fixed point), MATLAB's sign,
// min/max, a division with a fallback for a zero denominator, √(a² + b²) and π.

#include "mf/mf_math.hpp"

#include <cmath>
#include <type_traits>
#include <utility>

namespace tread::mf::detail {

using std::abs;
using std::acos;
using std::exp;
using std::pow;
using std::sqrt;

/// Per-lane truth values: bool for the scalars (double, float, ceres::Jet), lanes::Mask4 for
/// lanes::F4. Every branch on an input-dependent value is written as if_else (a select), so the
/// same code runs four wheels at a time; any_lane skips work no lane needs. For the scalars these
/// are the plain `c ? a : b` and `if`, so their results do not change by a bit.
template <typename T>
using MaskOf = decltype(std::declval<const T&>() < std::declval<const T&>());

template <typename T>
constexpr bool is_lanes = !std::is_same_v<MaskOf<T>, bool>;

/// The element of a lanes type (what its operator[] gives), void for the scalars.
template <typename T>
struct LaneElement {
  using type = void;
};
template <typename T>
requires(is_lanes<T>) struct LaneElement<T> {
  using type = std::remove_cvref_t<decltype(std::declval<const T&>()[0])>;
};

/// Float lanes (lanes::Lanes<N>, mf_lanes.hpp): float's precision and tolerances, tread's float
/// polynomials. Double lanes (dlanes::DLanes<N>, mf_double_lanes.hpp) take every choice double
/// takes, so that each lane computes what evaluate<double> computes, bit for bit.
template <typename T>
constexpr bool is_float_lanes = std::is_same_v<typename LaneElement<T>::type, float>;

/// Fixed-point scalars (fixed::Fixed64) mark themselves with a kIsFixedPoint member.
template <typename T>
constexpr bool is_fixed_point = requires {
  T::kIsFixedPoint;
};

/// √(a² + b²). Floating point: as written (so its results do not change by a bit). Fixed point:
/// scaled by the larger magnitude, so squares of large values (a side-slip speed tan α·Vx near
/// α = 90°) do not leave the format.
template <typename T>
T hypot_of(const T& a, const T& b) {
  if constexpr (is_fixed_point<T>) {
    const T x = abs(a);
    const T y = abs(b);
    const T big = x < y ? y : x;
    const T small = x < y ? x : y;
    if (!(big > T(0))) return big;  // 0 (or invalid)
    const T ratio = small / big;
    return big * sqrt(T(1) + ratio * ratio);
  } else {
    return sqrt(a * a + b * b);
  }
}

inline bool any_lane(bool b) {
  return b;
}
template <typename T>
T if_else(bool c, const T& a, const T& b) {
  return c ? a : b;
}

/// x is 0 (either sign) or NaN. float and double: one comparison of |x| (the two-sided form
/// compiled to two compares and a branch; in the MF 6.2 solve, which asks it several times a
/// step, float's MF 6.2 evaluation measured 2–3 ns faster).
template <typename T>
auto is_zero(const T& x) {
  if constexpr (std::is_floating_point_v<T>) {
    return !(std::fabs(x) > T(0));
  } else {
    return !(x < T(0)) && !(x > T(0));
  }
}
/// MATLAB sign(): −1, 0, +1.
template <typename T>
T sgn(const T& x) {
  return if_else(x > T(0), T(1), if_else(x < T(0), T(-1), T(0)));
}
/// sign() with sign(0) = 1, as MFeval writes `s = sign(x); s(s == 0) = 1`.
template <typename T>
T sgn_nz(const T& x) {
  return if_else(x < T(0), T(-1), T(1));
}
/// c·sign(x) with sign(0) = 1, written as the select of −c or c rather than as a product: the same
/// value (a product with ±1 is exact). On lanes the product left GCC a choice: as its vector
/// conditional GCC folds c·(m ? −1 : 1) into m ? −c : c, but a select taken bit by bit
/// (lanes::if_else with AVX-512VL) it cannot see through, and then fused that product, not its
/// neighbour, into an FMA (in a·b + c·sign(x): the x86-64-v4 code's Fx and Fy then differed from
/// the x86-64-v3 code's in the last bits). As a select both compute fma(a, b, ±c).
template <typename T>
T sgn_nz_times(const T& x, const T& c) {
  return if_else(x < T(0), -c, c);
}
template <typename T>
T max_of(const T& a, const T& b) {
  return if_else(a < b, b, a);
}
template <typename T>
T min_of(const T& a, const T& b) {
  return if_else(b < a, b, a);
}
/// num/den, or `fallback` where den is exactly 0 (MFeval: Inf or NaN there).
template <typename T>
T div_or(const T& num, const T& den, const T& fallback) {
  if constexpr (is_lanes<T>) {
    return if_else(is_zero(den), fallback, num / den);
  } else {
    return is_zero(den) ? fallback : num / den;
  }
}

template <typename T>
T pi() {
  return T(3.14159265358979323846);
}

}  // namespace tread::mf::detail
