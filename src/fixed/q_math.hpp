#pragma once
// Elementary functions in Q formats, integer arithmetic only (no table, no floating point).
// Internally everything is Q1.30 (step 2^−30 ≈ 9.3e-10) with 64-bit products; the polynomials are
// least-squares/minimax fits made for this file (scripts/fixed-point-fits.py) on the reduced
// intervals, their own error far below one Q30 step. Error bounds (absolute, in the result's
// units, measured over dense grids and 10^6 random arguments by tests/fixed/q_math_test.cpp; the
// bound a test asserts is the one given here):
//
//   atan(x)          x any Q<F> (F ≤ 30)     → Q2.29 rad         |error| ≤ 4e-9
//   sin, cos(a)      a Q2.29 rad or Q<F>      → Q1.30             |error| ≤ 4e-9
//   exp(x)           x any Q<F>               → Q<Fr>             relative ≤ 1e-8 + one step of Fr
//   log(x)           x > 0 any Q<F>           → Q<Fr>             |error| ≤ 1e-8 + one step of Fr
//   sqrt(x)          x ≥ 0 Q<F>               → Q<F>              exactly rounded down
//   pow(x, y)        x > 0, y any             → Q<Fr>             exp(y·log x): relative ≤
//                                                                  |y·log x|·2e-9 + 1e-8
//
// Arguments outside a function's domain (log of x ≤ 0, sqrt of x < 0) give 0 and set the
// Saturation flag; results outside the result format saturate and set it.

#include <cstdint>

#include "fixed/q_format.hpp"

namespace tread::fixed {

using Angle = Q<29>;  ///< radians, Q2.29: ±4 rad
using Unit = Q<30>;   ///< Q1.30: ±2

namespace kernel {

/// Value of an unsigned Q30 in [0, 1] polynomial kernels; defined in q_math.cpp.
/// atan(t) for t ∈ [0, 2^30] (i.e. [0, 1]) in Q30, result in Q30 (≤ π/4).
std::int32_t atan_unit_q30(std::int32_t t_q30);
/// sin and cos of r ∈ [−π/4, π/4] (Q30 radians), results Q30.
void sin_cos_q30(std::int32_t r_q30, std::int32_t& sin_q30, std::int32_t& cos_q30);
/// sin/cos of a binary angle (2^32 = one turn).
void sin_cos_turns(std::uint32_t turns, std::int32_t& sin_q30, std::int32_t& cos_q30);
/// 2^f for f ∈ [0, 1) given as a Q32 fraction, result Q30 in [2^30, 2^31).
std::int64_t exp2_fraction_q30(std::uint32_t f_q32);
/// ln(x) for x = raw·2^−frac > 0, result in Q(30) as 64 bits.
std::int64_t log_q30(std::uint32_t raw, int frac);
/// ⌊√v⌋ for 64-bit v.
std::uint32_t isqrt64(std::uint64_t v);

}  // namespace kernel

/// atan(raw·2^−frac) in Q2.29 radians, for a format chosen at run time (0 ≤ frac ≤ 30).
inline Angle atan_of(std::int32_t raw, int frac) {
  if (raw == 0) {
    return Angle{0};
  }
  const bool negative = raw < 0;
  const std::uint64_t a =
      negative ? static_cast<std::uint64_t>(-std::int64_t{raw}) : static_cast<std::uint64_t>(raw);
  const std::uint64_t one = std::uint64_t{1} << frac;
  std::int64_t result_q30 = 0;
  if (a <= one) {
    result_q30 = kernel::atan_unit_q30(static_cast<std::int32_t>(a << (30 - frac)));
  } else {
    // atan(a) = π/2 − atan(1/a), 1/a in Q30 rounded.
    const std::uint64_t num = std::uint64_t{1} << (30 + frac);
    const auto inv = static_cast<std::int32_t>((num + a / 2) / a);
    constexpr std::int64_t kHalfPiQ30 = 1686629713;  // π/2·2^30
    result_q30 = kHalfPiQ30 - kernel::atan_unit_q30(inv);
  }
  const auto r = static_cast<std::int32_t>((result_q30 + 1) >> 1);  // Q30 → Q29
  return Angle{negative ? -r : r};
}

/// atan(x) in Q2.29 radians (|x| any; atan(±max) is ±π/2 to within a step).
template <int F>
Angle atan(Q<F> x) {
  static_assert(F <= 30, "atan: at most 30 fraction bits");
  return atan_of(x.raw, F);
}

/// sin and cos of raw·2^−frac radians (0 ≤ frac ≤ 31), Q1.30 results.
inline void sin_cos_of(std::int32_t raw, int frac, Unit& sin_out, Unit& cos_out) {
  // Binary angle: turns = angle/(2π)·2^32 mod 2^32. The factor 2^32/(2π) is used with 64
  // fraction bits (integer part and a 32-bit fraction), so even a Q15.16 angle of 32768 rad is
  // converted to within a fraction of a step; only the low 32 bits (the angle mod one turn) are
  // kept.
  constexpr std::int64_t kTurnsPerRadInt = 683565275;    // ⌊2^32/(2π)⌋
  constexpr std::int64_t kTurnsPerRadFrac = 2475754826;  // the fraction·2^32
  const std::int64_t whole = std::int64_t{raw} * kTurnsPerRadInt;
  const std::int64_t part = (std::int64_t{raw} * kTurnsPerRadFrac) >> 32;
  const std::int64_t turns = shift_round(whole + part, frac);
  std::int32_t s = 0;
  std::int32_t c = 0;
  kernel::sin_cos_turns(static_cast<std::uint32_t>(static_cast<std::uint64_t>(turns)), s, c);
  sin_out = Unit{s};
  cos_out = Unit{c};
}

/// sin and cos of an angle in radians, Q1.30 results.
template <int F>
void sin_cos(Q<F> angle, Unit& sin_out, Unit& cos_out) {
  sin_cos_of(angle.raw, F, sin_out, cos_out);
}
template <int F>
Unit sin(Q<F> angle) {
  Unit s;
  Unit c;
  sin_cos(angle, s, c);
  return s;
}
template <int F>
Unit cos(Q<F> angle) {
  Unit s;
  Unit c;
  sin_cos(angle, s, c);
  return c;
}
/// tan in Q<Fr>; saturates near ±π/2.
template <int Fr, int F>
Q<Fr> tan(Q<F> angle, Saturation& sat) {
  Unit s;
  Unit c;
  sin_cos(angle, s, c);
  return div<Fr>(s, c, sat);
}

/// e^x in Q<Fr>.
template <int Fr, int F>
Q<Fr> exp(Q<F> x, Saturation& sat) {
  static_assert(F <= 30 && Fr <= 30, "exp: formats");
  // y = x·log2(e) in Q(F+30): n = ⌊y⌋, f = y − n ∈ [0, 1).
  constexpr std::int64_t kLog2eQ30 = 1549082005;  // log2(e)·2^30
  const std::int64_t y = std::int64_t{x.raw} * kLog2eQ30;
  const int frac_bits = F + 30;
  const std::int64_t n = y >> frac_bits;  // floor
  const std::uint64_t f = static_cast<std::uint64_t>(y - (n << frac_bits));
  const auto f_q32 =
      static_cast<std::uint32_t>(frac_bits >= 32 ? f >> (frac_bits - 32) : f << (32 - frac_bits));
  const std::int64_t m = kernel::exp2_fraction_q30(f_q32);  // 2^f in Q30
  // result = m·2^n in Q(Fr): shift m (Q30) by n + Fr − 30.
  const std::int64_t up = n + Fr - 30;
  if (up >= 1) {
    if (up > 31) {
      sat.hit = true;
      return Q<Fr>{kRawMax};
    }
    return Q<Fr>{saturate(m << up, sat)};
  }
  if (up < -62) {
    return Q<Fr>{0};
  }
  return Q<Fr>{saturate(shift_round(m, static_cast<int>(-up)), sat)};
}

/// ln(x) in Q<Fr>, x > 0.
template <int Fr, int F>
Q<Fr> log(Q<F> x, Saturation& sat) {
  static_assert(Fr <= 30, "log: result format");
  if (x.raw <= 0) {
    sat.hit = true;
    return Q<Fr>{0};
  }
  const std::int64_t l = kernel::log_q30(static_cast<std::uint32_t>(x.raw), F);
  return Q<Fr>{saturate(shift_round(l, 30 - Fr), sat)};
}

/// x^y = e^(y·ln x) in Q<Fr>, x > 0 (x ≤ 0 gives 0 and sets the flag).
template <int Fr, int Fx, int Fy>
Q<Fr> pow(Q<Fx> x, Q<Fy> y, Saturation& sat) {
  if (x.raw <= 0) {
    sat.hit = true;
    return Q<Fr>{0};
  }
  // ln x in Q30 (64 bits, |ln x| ≤ 22, so below 2^35) times y = hi·2^16 + lo in two products
  // below 2^51 each, to Q26 (|y·ln x| must stay below 32: e^32 is beyond any Q format).
  const std::int64_t l = kernel::log_q30(static_cast<std::uint32_t>(x.raw), Fx);
  const std::int64_t hi = y.raw >> 16;  // floor
  const std::int64_t lo = y.raw - hi * 65536;
  constexpr int kShiftLo = Fy + 4;  // Q(30+Fy) → Q26
  constexpr int kShiftHi = Fy - 12;
  std::int64_t p_hi = 0;
  if constexpr (kShiftHi >= 0) {
    p_hi = shift_round(l * hi, kShiftHi);
  } else {
    const std::int64_t prod = l * hi;
    constexpr std::int64_t kLimit = std::int64_t{1} << (40 + kShiftHi);
    p_hi = prod > kLimit ? (std::int64_t{1} << 40)
                         : (prod < -kLimit ? -(std::int64_t{1} << 40) : prod * (1 << -kShiftHi));
  }
  const std::int64_t p = p_hi + shift_round(l * lo, kShiftLo);
  if (p > kRawMax || p < kRawMin) {
    if (p < 0) {
      return Q<Fr>{0};
    }
    sat.hit = true;
    return Q<Fr>{kRawMax};
  }
  return exp<Fr>(Q<26>{static_cast<std::int32_t>(p)}, sat);
}

/// √x in Q<F>, rounded down; x < 0 gives 0 and sets the flag.
template <int F>
Q<F> sqrt(Q<F> x, Saturation& sat) {
  if (x.raw < 0) {
    sat.hit = true;
    return Q<F>{0};
  }
  return Q<F>{static_cast<std::int32_t>(kernel::isqrt64(static_cast<std::uint64_t>(x.raw) << F))};
}

}  // namespace tread::fixed
