#pragma once
// Q-format fixed-point numbers for cores without an FPU (Cortex-M0+/M3): a value is a signed
// 32-bit integer `raw` standing for raw / 2^F. Q<F> covers [−2^(31−F), 2^(31−F) − 2^−F] in steps
// of 2^−F; e.g. Q<16> is Q15.16 (±32768, step 1.5e-5), Q<29> is Q2.29 (±4, step 1.9e-9), Q<30>
// is Q1.30 (±2, step 9.3e-10).
//
// Every operation rounds to nearest (ties up) and saturates to the result format's range; a
// saturation sets the caller's Saturation flag, so a chain of operations tells at its end whether
// any step left its format (a Magic Formula evaluation reports it as its status). Products and
// quotients are formed in 64 bits. Integer arithmetic only: on a core without an FPU nothing here
// calls a soft-float routine (64-bit multiply/divide are integer helpers, __aeabi_lmul/ldivmod).
// Constants are converted from double at compile time (`q<F>(1.5)` in a constant expression).

#include <cstdint>
#include <limits>

namespace tread::fixed {

template <int F>
struct Q {
  static_assert(F >= 0 && F <= 31, "Q<F>: 0..31 fraction bits in 32 bits");
  static constexpr int kFraction = F;
  std::int32_t raw = 0;

  friend constexpr bool operator==(Q a, Q b) { return a.raw == b.raw; }
  friend constexpr bool operator<(Q a, Q b) { return a.raw < b.raw; }
  friend constexpr bool operator>(Q a, Q b) { return a.raw > b.raw; }
  friend constexpr bool operator<=(Q a, Q b) { return a.raw <= b.raw; }
  friend constexpr bool operator>=(Q a, Q b) { return a.raw >= b.raw; }
};

/// Sticky: set by any operation whose exact result lay outside its format (and was saturated).
struct Saturation {
  bool hit = false;
};

inline constexpr std::int32_t kRawMax = std::numeric_limits<std::int32_t>::max();
inline constexpr std::int32_t kRawMin = std::numeric_limits<std::int32_t>::min();

/// The 64-bit value clamped into 32 bits.
constexpr std::int32_t saturate(std::int64_t v, Saturation& sat) {
  if (v > kRawMax) {
    sat.hit = true;
    return kRawMax;
  }
  if (v < kRawMin) {
    sat.hit = true;
    return kRawMin;
  }
  return static_cast<std::int32_t>(v);
}

/// v · 2^−shift rounded to nearest (ties toward +inf); shift may be negative (then exact, unless
/// the value leaves 64 bits: callers keep |v| < 2^62 / 2^−shift).
constexpr std::int64_t shift_round(std::int64_t v, int shift) {
  if (shift <= 0) {
    return v * (std::int64_t{1} << -shift);
  }
  if (shift >= 63) {
    return 0;
  }
  return (v + (std::int64_t{1} << (shift - 1))) >> shift;
}

/// Called only by a constant outside its format; not constexpr, so such a constant does not
/// compile.
inline void constant_outside_the_format() {}

/// A constant: consteval so that no floating point reaches an image.
template <int F>
consteval Q<F> q(double value) {
  const double scaled = value * static_cast<double>(std::int64_t{1} << F);
  const double rounded = scaled < 0.0 ? scaled - 0.5 : scaled + 0.5;
  if (!(rounded < 2147483647.5) || !(rounded > -2147483648.5)) {
    constant_outside_the_format();  // not constexpr: a compile error in a constant expression
  }
  return Q<F>{static_cast<std::int32_t>(rounded)};
}

/// For host code and tests only (uses floating point).
template <int F>
constexpr double to_double(Q<F> x) {
  return static_cast<double>(x.raw) / static_cast<double>(std::int64_t{1} << F);
}
/// For host code and tests only: nearest Q<F>, saturated.
template <int F>
constexpr Q<F> from_double(double value, Saturation& sat) {
  const double scaled = value * static_cast<double>(std::int64_t{1} << F);
  if (!(scaled <= 0.0 || scaled > 0.0)) {  // NaN
    sat.hit = true;
    return Q<F>{0};
  }
  if (scaled >= 2147483647.0) {
    sat.hit = scaled >= 2147483647.5 || sat.hit;
    return Q<F>{kRawMax};
  }
  if (scaled <= -2147483648.0) {
    sat.hit = scaled < -2147483648.5 || sat.hit;
    return Q<F>{kRawMin};
  }
  const double rounded = scaled < 0.0 ? scaled - 0.5 : scaled + 0.5;
  return Q<F>{static_cast<std::int32_t>(static_cast<std::int64_t>(rounded))};
}

/// The same value in another format (rounded, saturated).
template <int Fr, int Fa>
constexpr Q<Fr> to(Q<Fa> a, Saturation& sat) {
  return Q<Fr>{saturate(shift_round(a.raw, Fa - Fr), sat)};
}

template <int F>
constexpr Q<F> add(Q<F> a, Q<F> b, Saturation& sat) {
  return Q<F>{saturate(std::int64_t{a.raw} + b.raw, sat)};
}
template <int F>
constexpr Q<F> sub(Q<F> a, Q<F> b, Saturation& sat) {
  return Q<F>{saturate(std::int64_t{a.raw} - b.raw, sat)};
}
template <int F>
constexpr Q<F> neg(Q<F> a, Saturation& sat) {
  return Q<F>{saturate(-std::int64_t{a.raw}, sat)};
}
template <int F>
constexpr Q<F> abs(Q<F> a, Saturation& sat) {
  return a.raw < 0 ? neg(a, sat) : a;
}

/// a·b in Q<Fr>.
template <int Fr, int Fa, int Fb>
constexpr Q<Fr> mul(Q<Fa> a, Q<Fb> b, Saturation& sat) {
  static_assert(Fa + Fb - Fr <= 62, "mul: result format too coarse");
  return Q<Fr>{saturate(shift_round(std::int64_t{a.raw} * b.raw, Fa + Fb - Fr), sat)};
}

/// a/b in Q<Fr>, rounded to nearest. b = 0 gives the format's extreme with the sign of a (0 for
/// a = 0) and sets the flag.
template <int Fr, int Fa, int Fb>
constexpr Q<Fr> div(Q<Fa> a, Q<Fb> b, Saturation& sat) {
  static_assert(Fr + Fb - Fa >= -32 && Fr + Fb - Fa <= 60, "div: formats too far apart");
  if (b.raw == 0) {
    if (a.raw == 0) {
      return Q<Fr>{0};
    }
    sat.hit = true;
    return Q<Fr>{a.raw > 0 ? kRawMax : kRawMin};
  }
  // q = a·2^(Fr+Fb−Fa) / b. The numerator is formed with one guard bit for the rounding; when
  // it would leave 63 bits the quotient certainly saturates.
  const int shift = Fr + Fb - Fa + 1;
  std::int64_t num = a.raw;
  std::int64_t den = b.raw;
  if (shift >= 0) {
    if (num > (std::int64_t{1} << (62 - shift)) || num < -(std::int64_t{1} << (62 - shift))) {
      // |a|·2^shift ≥ 2^62 and |b| < 2^31: the quotient is beyond 2^31.
      sat.hit = true;
      return Q<Fr>{(num < 0) != (den < 0) ? kRawMin : kRawMax};
    }
    num *= std::int64_t{1} << shift;
  } else {
    den *= std::int64_t{1} << -shift;
  }
  std::int64_t quotient2 = num / den;  // 2·q, truncated toward zero
  // Round the doubled quotient to nearest: q = (2q + sign) / 2, ties away from zero.
  quotient2 += quotient2 < 0 ? -1 : 1;
  return Q<Fr>{saturate(quotient2 / 2, sat)};
}

/// Minimum / maximum / clamp in one format.
template <int F>
constexpr Q<F> min(Q<F> a, Q<F> b) {
  return b.raw < a.raw ? b : a;
}
template <int F>
constexpr Q<F> max(Q<F> a, Q<F> b) {
  return a.raw < b.raw ? b : a;
}
template <int F>
constexpr Q<F> clamp(Q<F> x, Q<F> lo, Q<F> hi) {
  return x.raw < lo.raw ? lo : (hi.raw < x.raw ? hi : x);
}
/// −1, 0 or +1 in Q<F> (F ≤ 30).
template <int F>
constexpr Q<F> sign(Q<F> x) {
  static_assert(F <= 30, "sign: 1 must fit");
  return Q<F>{x.raw > 0 ? (std::int32_t{1} << F) : (x.raw < 0 ? -(std::int32_t{1} << F) : 0)};
}

}  // namespace tread::fixed
