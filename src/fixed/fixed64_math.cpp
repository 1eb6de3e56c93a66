#include "fixed/fixed64.hpp"

#include <cstdint>

#include "fixed/q_format.hpp"
#include "fixed/q_math.hpp"

namespace tread::fixed {

namespace {

constexpr std::int64_t kHalfPiRaw = 6746518852;  // π/2·2^32
constexpr std::int64_t kPiRaw = 13493037705;     // π·2^32
constexpr std::int64_t kLog2eRaw = 6196328019;   // log2(e)·2^32
/// ln(2^31)·2^32: e^x beyond it does not fit.
constexpr std::int64_t kExpMaxRaw = 92288378626;

/// The number of significant bits of v (0 for 0): one count-leading-zeros, not a loop (CLZ on
/// ARMv7-M, two of them for 64 bits).
int bit_length(std::uint64_t v) {
  return v == 0 ? 0 : 64 - __builtin_clzll(v);
}

Fixed64 from_unit(Unit u) {
  return Fixed64::from_raw(std::int64_t{u.raw} * 4);
}

/// The Q1.30 sin and cos of x: the binary angle x/(2π)·2^32 mod 2^32 from the 128-bit product
/// |x|·⌊2^64/(2π)⌉ (bits 64…95, with four 32×32-bit products), then the Q1.30 kernel.
void sin_cos_fixed(Fixed64 x, Unit& s, Unit& c) {
  constexpr std::uint64_t kTurnsPerRadQ64 = 2935890503282001226u;  // 2^64/(2π)
  const std::int64_t raw = x.raw();
  const auto ua = static_cast<std::uint64_t>(raw < 0 ? -raw : raw);
  const std::uint64_t ah = ua >> 32;
  const std::uint64_t al = ua & 0xFFFFFFFFu;
  const std::uint64_t kh = kTurnsPerRadQ64 >> 32;
  const std::uint64_t kl = kTurnsPerRadQ64 & 0xFFFFFFFFu;
  const std::uint64_t mid = ah * kl + al * kh;  // each < 2^63: no carry out of 64 bits
  const std::uint64_t low = (al * kl) >> 32;
  const std::uint64_t sum = mid + low;  // a carry out of it is a multiple of 2^64: dropped mod 2^32
  const auto turns = static_cast<std::uint32_t>(ah * kh + (sum >> 32));
  std::int32_t si = 0;
  std::int32_t co = 0;
  kernel::sin_cos_turns(raw < 0 ? 0u - turns : turns, si, co);
  s = Unit{si};
  c = Unit{co};
}

}  // namespace

Fixed64 Fixed64::divide(Fixed64 a, Fixed64 b) {
  if (!a.valid() || !b.valid() || b.raw_ == 0) return invalid();
  const bool negative = (a.raw_ < 0) != (b.raw_ < 0);
  const auto ua = static_cast<std::uint64_t>(a.raw_ < 0 ? -a.raw_ : a.raw_);
  const auto ub = static_cast<std::uint64_t>(b.raw_ < 0 ? -b.raw_ : b.raw_);
  const std::uint64_t whole = ua / ub;
  const std::uint64_t rest = ua % ub;
  if (whole >= (std::uint64_t{1} << 31)) return invalid();
  std::uint64_t fraction = 0;
  if (ub <= 0xFFFFFFFFu) {
    // rest < ub < 2^32: the fraction rest·2^32/ub exactly, rounded to nearest.
    const std::uint64_t num = rest << 32;
    fraction = num / ub;
    if (2 * (num % ub) >= ub) ++fraction;
  } else {
    // ub ≥ 2^32: its low bits dropped (32 significant bits kept), within two steps.
    const int k = bit_length(ub) - 32;
    const std::uint64_t ub_top = ub >> k;
    const std::uint64_t num = rest << (32 - k);  // rest < ub < 2^(32+k)
    fraction = num / ub_top;
  }
  const std::uint64_t magnitude = (whole << 32) + fraction;
  if (magnitude > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
    return invalid();
  }
  const auto r = static_cast<std::int64_t>(magnitude);
  return from_raw(negative ? -r : r);
}

bool isfinite(Fixed64 x) {
  return x.valid();
}

Fixed64 abs(Fixed64 x) {
  return x.raw() < 0 && x.valid() ? -x : x;
}

Fixed64 sqrt(Fixed64 x) {
  if (!x.valid() || x.raw() < 0) return Fixed64::invalid();
  const auto v = static_cast<std::uint64_t>(x.raw());
  // √(v·2^32): for v < 2^32 exactly (rounded down); beyond, √((v >> 2j)·2^32)·2^j with
  // v >> 2j < 2^32.
  if (v <= 0xFFFFFFFFu) {
    return Fixed64::from_raw(kernel::isqrt64(v << 32));
  }
  int j = (bit_length(v) - 32 + 1) / 2;
  return Fixed64::from_raw(std::int64_t{kernel::isqrt64((v >> (2 * j)) << 32)} << j);
}

Fixed64 exp(Fixed64 x) {
  if (!x.valid() || x.raw() >= kExpMaxRaw) return Fixed64::invalid();
  const Fixed64 y = Fixed64::multiply(x, Fixed64::from_raw(kLog2eRaw));  // x·log2 e
  if (!y.valid()) return Fixed64::invalid();
  const std::int64_t n = y.raw() >> 32;  // floor
  const auto f = static_cast<std::uint32_t>(static_cast<std::uint64_t>(y.raw()) & 0xFFFFFFFFu);
  const std::int64_t m = kernel::exp2_fraction_q30(f);  // 2^f in Q30
  const std::int64_t shift = n + 2;                     // Q30 → Q32 and ·2^n
  if (shift >= 0) {
    if (shift > 32) return Fixed64::invalid();
    const std::int64_t r = m << shift;
    return r < 0 ? Fixed64::invalid() : Fixed64::from_raw(r);
  }
  if (shift < -62) return Fixed64::from_raw(0);
  return Fixed64::from_raw(shift_round(m, static_cast<int>(-shift)));
}

Fixed64 log(Fixed64 x) {
  if (!x.valid() || x.raw() <= 0) return Fixed64::invalid();
  const auto v = static_cast<std::uint64_t>(x.raw());
  const int excess = bit_length(v) > 32 ? bit_length(v) - 32 : 0;  // keep 32 significant bits
  const auto m = static_cast<std::uint32_t>(v >> excess);
  return Fixed64::from_raw(kernel::log_q30(m, 32 - excess) * 4);
}

Fixed64 log10(Fixed64 x) {
  return log(x) * Fixed64(0.43429448190325182765);  // 1/ln 10
}

Fixed64 pow(Fixed64 x, Fixed64 y) {
  if (!x.valid() || !y.valid()) return Fixed64::invalid();
  if (y.raw() == 0) return Fixed64(1.0);
  if (x.raw() == 0) return y.raw() > 0 ? Fixed64::from_raw(0) : Fixed64::invalid();
  if (x.raw() < 0) return Fixed64::invalid();
  return exp(y * log(x));
}

namespace {

enum class Trig { sine, cosine, tangent };

Fixed64 trig(Fixed64 x, Trig which) {
  if (!x.valid()) return x;
  Unit s;
  Unit c;
  sin_cos_fixed(x, s, c);
  switch (which) {
    case Trig::sine:
      return from_unit(s);
    case Trig::cosine:
      return from_unit(c);
    case Trig::tangent:
      break;
  }
  return from_unit(s) / from_unit(c);
}

}  // namespace

Fixed64 sin(Fixed64 x) {
  return trig(x, Trig::sine);
}

Fixed64 cos(Fixed64 x) {
  return trig(x, Trig::cosine);
}

Fixed64 tan(Fixed64 x) {
  return trig(x, Trig::tangent);
}

Fixed64 atan(Fixed64 x) {
  if (!x.valid()) return x;
  const std::int64_t raw = x.raw();
  const std::uint64_t a = static_cast<std::uint64_t>(raw < 0 ? -raw : raw);
  std::int64_t r = 0;
  if (a <= (std::uint64_t{1} << 32)) {
    r = std::int64_t{kernel::atan_unit_q30(static_cast<std::int32_t>((a + 2) >> 2))} * 4;
  } else {
    // atan a = π/2 − atan(1/a), 1/a in Q30 (a > 1).
    const auto inv = static_cast<std::int32_t>(((std::uint64_t{1} << 62) + a / 2) / a);
    r = kHalfPiRaw - std::int64_t{kernel::atan_unit_q30(inv)} * 4;
  }
  return Fixed64::from_raw(raw < 0 ? -r : r);
}

Fixed64 acos(Fixed64 x) {
  if (!x.valid()) return x;
  const Fixed64 one(1.0);
  if (x > one || x < -one) return Fixed64::invalid();
  if (x == one) return Fixed64::from_raw(0);
  if (x == -one) return Fixed64::from_raw(kPiRaw);
  // acos x = π/2 − atan(x/√(1 − x²)).
  return Fixed64::from_raw(kHalfPiRaw) - atan(x / sqrt((one - x) * (one + x)));
}

}  // namespace tread::fixed
