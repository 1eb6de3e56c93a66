#pragma once
// Fixed64: a Q31.32 fixed-point scalar (a signed 64-bit integer counting 2^−32) with the
// arithmetic operators and elementary functions of a floating-point type, so the templated Magic
// Formula (mf/mf_evaluate.hpp) runs on it unchanged — the same source as the double and float
// paths — with integer instructions only, on cores without an FPU (Cortex-M0+/M3) and bit for bit
// the same on the host (`tread mf eval --fixed`).
//
// One format for every intermediate: range ±2^31 (2.1e9: forces in N, stiffnesses in N/rad and
// N/m, pressures in Pa and their products all fit for any tyre inside its FZMAX), resolution
// 2^−32 (2.3e-10: slips, angles and coefficients keep 9 or more significant digits).
//
// Invalid values, like IEEE NaN: the most negative raw value stands for "no number". It is the
// result of any operation whose exact result leaves the range (overflow), of a division by zero,
// of log/sqrt/pow/acos outside their domain, and of any operation on an invalid operand; every
// comparison with it is false and isfinite() says no. So an overflow anywhere in an evaluation
// reaches the outputs it affects, where the Magic Formula reports it (MfOutput::status
// non_finite, the output set to 0) exactly as it reports a NaN in floating point — nothing
// saturates silently.
//
// Rounding: + and − are exact; × rounds to nearest (ties up); ÷ rounds to nearest when |divisor| <
// 1 and is within two steps otherwise. The elementary functions (fixed64_math.cpp, from the Q1.30
// kernels of q_math.hpp) have absolute errors of a few 1e-9 (relative for exp/pow); the bounds are
// asserted by tests/fixed/fixed64_test.cpp.
//
// Constants: `Fixed64(0.5)` is consteval — a literal becomes its Q31.32 value at compile time and
// a run-time double cannot reach it, so no soft-float routine can be called from core code.
// Fixed64::from_double / to_double convert at run time, for host code and tests only.

#include <cstdint>
#include <limits>

#include "fixed/q_format.hpp"

namespace tread::fixed {

class Fixed64 {
 public:
  static constexpr int kFractionBits = 32;
  static constexpr std::int64_t kInvalidRaw = std::numeric_limits<std::int64_t>::min();
  static constexpr std::int64_t kOneRaw = std::int64_t{1} << 32;
  /// Marks the type for code that must tell fixed from floating point (e.g. an iteration's
  /// tolerance).
  static constexpr bool kIsFixedPoint = true;

  constexpr Fixed64() = default;
  /// A constant, rounded to nearest at compile time.
  consteval explicit Fixed64(double value) : raw_(round_constant(value)) {}

  static constexpr Fixed64 from_raw(std::int64_t raw) {
    Fixed64 f;
    f.raw_ = raw;
    return f;
  }
  static constexpr Fixed64 invalid() { return from_raw(kInvalidRaw); }
  /// Host and tests only: nearest value; NaN, ±inf and values outside the range are invalid.
  static Fixed64 from_double(double value);
  /// Host and tests only: NaN for an invalid value.
  double to_double() const;

  constexpr std::int64_t raw() const { return raw_; }
  constexpr bool valid() const { return raw_ != kInvalidRaw; }

  friend constexpr Fixed64 operator+(Fixed64 a, Fixed64 b) {
    std::int64_t r = 0;
    if (!a.valid() || !b.valid() || __builtin_add_overflow(a.raw_, b.raw_, &r)) return invalid();
    return from_raw(r);
  }
  friend constexpr Fixed64 operator-(Fixed64 a, Fixed64 b) {
    std::int64_t r = 0;
    if (!a.valid() || !b.valid() || __builtin_sub_overflow(a.raw_, b.raw_, &r)) return invalid();
    return from_raw(r);
  }
  friend constexpr Fixed64 operator-(Fixed64 a) { return a.valid() ? from_raw(-a.raw_) : a; }
  friend constexpr Fixed64 operator+(Fixed64 a) { return a; }
  friend constexpr Fixed64 operator*(Fixed64 a, Fixed64 b) { return multiply(a, b); }
  friend Fixed64 operator/(Fixed64 a, Fixed64 b) { return divide(a, b); }
  Fixed64& operator+=(Fixed64 b) { return *this = *this + b; }
  Fixed64& operator-=(Fixed64 b) { return *this = *this - b; }
  Fixed64& operator*=(Fixed64 b) { return *this = *this * b; }
  Fixed64& operator/=(Fixed64 b) { return *this = *this / b; }

  // Like NaN: every comparison with an invalid value is false (and != true).
  friend constexpr bool operator<(Fixed64 a, Fixed64 b) {
    return a.valid() && b.valid() && a.raw_ < b.raw_;
  }
  friend constexpr bool operator>(Fixed64 a, Fixed64 b) { return b < a; }
  friend constexpr bool operator<=(Fixed64 a, Fixed64 b) {
    return a.valid() && b.valid() && a.raw_ <= b.raw_;
  }
  friend constexpr bool operator>=(Fixed64 a, Fixed64 b) { return b <= a; }
  friend constexpr bool operator==(Fixed64 a, Fixed64 b) {
    return a.valid() && b.valid() && a.raw_ == b.raw_;
  }
  friend constexpr bool operator!=(Fixed64 a, Fixed64 b) { return !(a == b); }

  /// a·b rounded to nearest (ties up): the middle 64 bits of the 128-bit product of the
  /// magnitudes, from four 32×32-bit products (no 128-bit type: the same code and bits on 32-bit
  /// cores).
  static constexpr Fixed64 multiply(Fixed64 a, Fixed64 b) {
    if (!a.valid() || !b.valid()) return invalid();
    const bool negative = (a.raw_ < 0) != (b.raw_ < 0);
    const auto ua = static_cast<std::uint64_t>(a.raw_ < 0 ? -a.raw_ : a.raw_);  // < 2^63
    const auto ub = static_cast<std::uint64_t>(b.raw_ < 0 ? -b.raw_ : b.raw_);
    // 32-bit halves, so each product is one 32×32→64-bit multiply (UMULL) on a 32-bit core.
    const auto ah = static_cast<std::uint32_t>(ua >> 32);  // < 2^31
    const auto bh = static_cast<std::uint32_t>(ub >> 32);
    const auto al = static_cast<std::uint32_t>(ua);
    const auto bl = static_cast<std::uint32_t>(ub);
    // For P = ±M: ⌊(P + 2^31)/2^32⌋ = ⌊(M + 2^31)/2^32⌋ for P ≥ 0 and −⌊(M + 2^31 − 1)/2^32⌋
    // for P < 0; M = ah·bh·2^64 + (ah·bl + al·bh)·2^32 + al·bl, every term non-negative.
    const std::uint64_t bias = negative ? (std::uint64_t{1} << 31) - 1 : std::uint64_t{1} << 31;
    const std::uint64_t top = std::uint64_t{ah} * bh;  // < 2^62
    if (top >= (std::uint64_t{1} << 31)) return invalid();
    const std::uint64_t mid = std::uint64_t{ah} * bl + std::uint64_t{al} * bh;  // each < 2^63
    const std::uint64_t low = (std::uint64_t{al} * bl + bias) >> 32;
    std::uint64_t m = 0;
    if (__builtin_add_overflow(top << 32, mid, &m) || __builtin_add_overflow(m, low, &m) ||
        m > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
      return invalid();
    }
    const auto r = static_cast<std::int64_t>(m);
    return from_raw(negative ? -r : r);
  }

  static Fixed64 divide(Fixed64 a, Fixed64 b);

 private:
  static consteval std::int64_t round_constant(double value) {
    const double scaled = value * 4294967296.0;
    if (!(scaled < 9.2233720368547748e18) || !(scaled > -9.2233720368547748e18)) {
      constant_outside_the_format();  // not constexpr: a compile error in a constant expression
    }
    return static_cast<std::int64_t>(scaled < 0.0 ? scaled - 0.5 : scaled + 0.5);
  }

  std::int64_t raw_ = 0;
};

// ---- the functions the templated core finds by argument-dependent lookup (fixed64_math.cpp) ----
bool isfinite(Fixed64 x);
Fixed64 abs(Fixed64 x);
Fixed64 sqrt(Fixed64 x);
Fixed64 exp(Fixed64 x);
Fixed64 log(Fixed64 x);
Fixed64 log10(Fixed64 x);
Fixed64 pow(Fixed64 x, Fixed64 y);
Fixed64 sin(Fixed64 x);
Fixed64 cos(Fixed64 x);
Fixed64 tan(Fixed64 x);
Fixed64 atan(Fixed64 x);
Fixed64 acos(Fixed64 x);

}  // namespace tread::fixed
