#include "fixed/q_math.hpp"

#include <array>
#include <cstddef>

namespace tread::fixed::kernel {

namespace {

// Coefficients in Q1.30, printed by scripts/fixed-point-fits.py (the fit and its own error).
// atan(u) = u·P(u²), |u| ≤ tan(π/8); fit error 4.03e-12
constexpr std::array<std::int64_t, 7> kAtan{1073741824, -357913906, 214746106, -153327278,
                                            118351766,  -89893412,  48927583};
// sin(r) = r·P(r²), |r| ≤ π/4; fit error 1.70e-12
constexpr std::array<std::int64_t, 5> kSin{1073741824, -178956970, 8947841, -213016, 2914};
// cos(r) = P(r²), |r| ≤ π/4; fit error 4.74e-11
constexpr std::array<std::int64_t, 5> kCos{1073741824, -536870908, 44739189, -1491064, 26178};
// 2^f = P(f), f ∈ [0, 1); fit error 5.72e-11
constexpr std::array<std::int64_t, 8> kExp2{1073741824, 744261126, 257941086, 59598365,
                                            10322424,   1442062,   153505,    23258};
// atanh(s) = s·P(s²), |s| ≤ 3 − 2√2; fit error 2.39e-15
constexpr std::array<std::int64_t, 6> kAtanh{1073741824, 357913942, 214748317,
                                             153397255,  118992506, 105944750};

constexpr std::int64_t kOneQ30 = std::int64_t{1} << 30;
constexpr std::int64_t kQuarterPiQ30 = 843314857;    // π/4·2^30
constexpr std::int64_t kTanEighthPiQ30 = 444758426;  // tan(π/8)·2^30
constexpr std::int64_t kHalfPiQ30 = 1686629713;      // π/2·2^30
constexpr std::int64_t kLn2Q32 = 2977044472;         // ln 2·2^32
constexpr std::int64_t kSqrt2Q30 = 1518500250;       // √2·2^30

/// (a·b)·2^−30 rounded, for Q30 values (|a|, |b| < 2^33).
constexpr std::int64_t mul30(std::int64_t a, std::int64_t b) {
  return (a * b + (std::int64_t{1} << 29)) >> 30;
}

/// P(z) by Horner's rule in Q30.
template <std::size_t N>
constexpr std::int64_t horner(const std::array<std::int64_t, N>& c, std::int64_t z) {
  std::int64_t p = c[N - 1];
  for (std::size_t k = N - 1; k-- > 0;) {
    p = c[k] + mul30(p, z);
  }
  return p;
}

}  // namespace

std::int32_t atan_unit_q30(std::int32_t t_q30) {
  std::int64_t u = t_q30;
  std::int64_t base = 0;
  if (u > kTanEighthPiQ30) {
    // atan t = π/4 + atan((t − 1)/(t + 1)), |(t − 1)/(t + 1)| ≤ tan(π/8) for t ∈ [tan π/8, 1].
    const std::int64_t num = (u - kOneQ30) * kOneQ30;  // ≤ 0
    const std::int64_t den = u + kOneQ30;
    u = (num - den / 2) / den;  // rounded (num ≤ 0)
    base = kQuarterPiQ30;
  }
  return static_cast<std::int32_t>(base + mul30(u, horner(kAtan, mul30(u, u))));
}

void sin_cos_q30(std::int32_t r_q30, std::int32_t& sin_q30, std::int32_t& cos_q30) {
  const std::int64_t r = r_q30;
  const std::int64_t z = mul30(r, r);
  sin_q30 = static_cast<std::int32_t>(mul30(r, horner(kSin, z)));
  cos_q30 = static_cast<std::int32_t>(horner(kCos, z));
}

void sin_cos_turns(std::uint32_t turns, std::int32_t& sin_q30, std::int32_t& cos_q30) {
  // The nearest quarter turn q and the rest r ∈ [−1/8, 1/8) turn.
  const std::uint32_t quadrant = ((turns + (std::uint32_t{1} << 29)) >> 30) & 3u;
  const auto rest = static_cast<std::int32_t>(turns - (quadrant << 30));
  // rest·2π/2^32 rad in Q30 = rest·(π/2)·2^30 / 2^30.
  const auto r = static_cast<std::int32_t>(mul30(rest, kHalfPiQ30));
  std::int32_t s = 0;
  std::int32_t c = 0;
  sin_cos_q30(r, s, c);
  switch (quadrant) {
    case 0:
      sin_q30 = s;
      cos_q30 = c;
      break;
    case 1:
      sin_q30 = c;
      cos_q30 = -s;
      break;
    case 2:
      sin_q30 = -s;
      cos_q30 = -c;
      break;
    default:
      sin_q30 = -c;
      cos_q30 = s;
      break;
  }
}

std::int64_t exp2_fraction_q30(std::uint32_t f_q32) {
  const std::int64_t f = (std::int64_t{f_q32} + 2) >> 2;  // Q30
  return horner(kExp2, f);
}

std::int64_t log_q30(std::uint32_t raw, int frac) {
  // raw = m·2^k with m ∈ [1/√2, √2) in Q30.
  int msb = 31;
  while (((raw >> msb) & 1u) == 0u) {
    --msb;
  }
  std::int64_t m = msb <= 30 ? std::int64_t{raw} << (30 - msb) : std::int64_t{raw} >> (msb - 30);
  int k = msb - frac;
  if (m > kSqrt2Q30) {
    m = (m + 1) >> 1;
    ++k;
  }
  // ln m = 2·atanh(s), s = (m − 1)/(m + 1), |s| ≤ 3 − 2√2.
  const std::int64_t num = (m - kOneQ30) * kOneQ30;
  const std::int64_t den = m + kOneQ30;
  const std::int64_t s = (num + (num < 0 ? -den / 2 : den / 2)) / den;
  const std::int64_t ln_m = 2 * mul30(s, horner(kAtanh, mul30(s, s)));
  return ((k * kLn2Q32 + 2) >> 2) + ln_m;
}

std::uint32_t isqrt64(std::uint64_t v) {
  std::uint64_t result = 0;
  std::uint64_t bit = std::uint64_t{1} << 62;
  while (bit > v) {
    bit >>= 2;
  }
  while (bit != 0) {
    if (v >= result + bit) {
      v -= result + bit;
      result = (result >> 1) + bit;
    } else {
      result >>= 1;
    }
    bit >>= 2;
  }
  return static_cast<std::uint32_t>(result);
}

}  // namespace tread::fixed::kernel
