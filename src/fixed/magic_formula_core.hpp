#pragma once
// The Magic Formula's core in fixed point: y = trig(C·atan(x − E·(x − atan x))), trig = sin (the
// force and moment curves) or cos (the weighting functions and the pneumatic trail), for
// x = B·slip.
//
// Formats: x Q15.16 (|B·slip| < 32768), C Q3.28 (|C| < 8), E Q7.24 (|E| < 128), y Q1.30.
// x − atan x is formed in Q29 with 64 bits and E·(x − atan x) with a split product, so the
// argument of the outer atan keeps 29 fraction bits while |x − E·(x − atan x)| < 4 and as many as
// fit beyond. The outer angle C·atan(·) is Q3.28 (Q4.27 for |C| > 5). Error against double
// evaluation of the same inputs: tests/fixed/ magic_formula_core_test.cpp (≤ 1e-8·(1 + |C|·(1 +
// |E|)) over the formats' ranges).

#include <cstdint>

#include "fixed/q_format.hpp"
#include "fixed/q_math.hpp"

namespace tread::fixed {

using Slip16 = Q<16>;  ///< B·slip, Q15.16
using ShapeC = Q<28>;  ///< C, Q3.28
using CurveE = Q<24>;  ///< E, Q7.24

inline Unit magic_formula_core(Slip16 x, ShapeC c, CurveE e, bool cosine) {
  const std::int64_t x_q29 = std::int64_t{x.raw} * 8192;  // exact: |x| < 2^15 → < 2^44
  const std::int64_t diff = x_q29 - atan(x).raw;          // x − atan x, Q29
  // E·diff in Q29: diff = hi·2^16 + lo, E·hi < 2^60, E·lo < 2^47.
  const std::int64_t hi = diff >> 16;
  const std::int64_t lo = diff - hi * 65536;
  const std::int64_t e_diff = shift_round(e.raw * hi, 8) + shift_round(e.raw * lo, 24);
  const std::int64_t u_q29 = x_q29 - e_diff;  // |u| < 2^53
  // The outer atan's argument in the finest format it fits: Q29 while |u| < 4, fewer fraction
  // bits beyond (|u| < 2^24).
  std::int64_t u = u_q29;
  int frac = 29;
  while (u > kRawMax || u < kRawMin) {
    u = shift_round(u, 1);
    --frac;
  }
  const Angle outer = atan_of(static_cast<std::int32_t>(u), frac);
  // C·atan in Q28: |C| < 8 and |atan| ≤ π/2, so |angle| < 12.6 would not fit for |C| > 5; the
  // product is formed in 64 bits and reduced modulo the turn by sin_cos on a Q<27> angle there.
  const std::int64_t angle_q28 = shift_round(std::int64_t{c.raw} * outer.raw, 29);
  Unit s;
  Unit co;
  if (angle_q28 >= kRawMin && angle_q28 <= kRawMax) {
    sin_cos(Q<28>{static_cast<std::int32_t>(angle_q28)}, s, co);
  } else {
    sin_cos(Q<27>{static_cast<std::int32_t>(shift_round(angle_q28, 1))}, s, co);
  }
  return cosine ? co : s;
}

}  // namespace tread::fixed
