#include "io/shortest_number.hpp"

#include <dragonbox/dragonbox.h>

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>

namespace tread::host {

namespace {

constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

constexpr std::uint64_t kPowersOfTen[] = {1ULL,
                                          10ULL,
                                          100ULL,
                                          1000ULL,
                                          10000ULL,
                                          100000ULL,
                                          1000000ULL,
                                          10000000ULL,
                                          100000000ULL,
                                          1000000000ULL,
                                          10000000000ULL,
                                          100000000000ULL,
                                          1000000000000ULL,
                                          10000000000000ULL,
                                          100000000000000ULL,
                                          1000000000000000ULL,
                                          10000000000000000ULL,
                                          100000000000000000ULL};

// Decimal digits of 1 ≤ v < 10^17, without a loop: log10(2) ≈ 1233 / 4096 gives the count of
// the largest power of two below v, one less than v's or equal to it.
int digit_count(std::uint64_t v) {
  const auto guess = static_cast<std::size_t>(((64 - std::countl_zero(v)) * 1233) >> 12);
  return static_cast<int>(guess) + (v >= kPowersOfTen[guess] ? 1 : 0);
}

// The 8 digits of v < 10^8, zero-padded, at p.
[[gnu::always_inline]] inline void put_eight_digits(char* p, std::uint32_t v) {
  const std::uint32_t high = v / 10000;
  const std::uint32_t low = v % 10000;
  std::memcpy(p, kDigitPairs + 2 * (high / 100), 2);
  std::memcpy(p + 2, kDigitPairs + 2 * (high % 100), 2);
  std::memcpy(p + 4, kDigitPairs + 2 * (low / 100), 2);
  std::memcpy(p + 6, kDigitPairs + 2 * (low % 100), 2);
}

}  // namespace

char* write_shortest(char* out, double value) noexcept {
  const auto bits = std::bit_cast<std::uint64_t>(value);
  const std::uint64_t biased_exponent = (bits >> 52) & 0x7ff;
  // Zero and subnormals (0), NaN and infinities (0x7ff), and |value| ≥ 2^53, where to_chars's
  // fixed notation writes the integer's exact digits rather than the shortest ones.
  if (biased_exponent == 0 || biased_exponent == 0x7ff || biased_exponent >= 1023 + 53) {
    return std::to_chars(out, out + kShortestNumberMaxChars, value).ptr;
  }
  const auto decimal = jkj::dragonbox::to_decimal(value, jkj::dragonbox::policy::sign::ignore,
                                                  jkj::dragonbox::policy::trailing_zero::remove);
  *out = '-';
  out += bits >> 63;
  // value = significand × 10^exponent, with n digits; the first is at 10^first_exponent.
  const std::uint64_t significand = decimal.significand;
  const int n = digit_count(significand);
  const int exponent = decimal.exponent;
  const int first_exponent = exponent + n - 1;

  // The 17 digits of the significand, zero-padded, then 16 zeros: its n digits at t + 17 − n,
  // and the blocks copied below (at most 16 bytes after its first digit, or 17 from it) carry
  // zeros, never stale bytes, past them; none reads beyond t + 33.
  char t[17 + 16];
  std::memset(t + 16, '0', 17);
  const std::uint64_t high = significand / 100000000;
  put_eight_digits(t + 9, static_cast<std::uint32_t>(significand % 100000000));
  put_eight_digits(t + 1, static_cast<std::uint32_t>(high % 100000000));
  t[0] = static_cast<char>('0' + high / 100000000);
  const char* digits = t + 17 - n;

  const int exponent_abs = first_exponent < 0 ? -first_exponent : first_exponent;
  // d.ddde+XX (one digit: de+XX; three-digit exponents: e+XXX) against fixed notation.
  const int scientific_chars = n + (n > 1 ? 1 : 0) + 4 + (exponent_abs >= 100 ? 1 : 0);
  const int fixed_chars = exponent >= 0         ? n + exponent             // ddd000
                          : first_exponent >= 0 ? n + 1                    // dd.ddd
                                                : n + 1 - first_exponent;  // 0.00ddd
  if (fixed_chars <= scientific_chars) {
    if (exponent >= 0) {  // an integer below 2^53: at most 16 characters, digits then zeros
      std::memcpy(out, digits, 16);
    } else if (first_exponent >= 0) {  // at most 16 digits on either side of the point
      std::memcpy(out, digits, 16);
      out[first_exponent + 1] = '.';
      std::memcpy(out + first_exponent + 2, digits + first_exponent + 1, 16);
    } else {  // fixed wins down to 0.000dd at most ("0." and 3 zeros); 8 bytes cover that
      std::memcpy(out, "0.000000", 8);
      std::memcpy(out + 1 - first_exponent, digits, 17);
    }
    return out + fixed_chars;
  }
  out[0] = digits[0];
  out[1] = '.';
  std::memcpy(out + 2, digits + 1, 16);
  char* p = out + 1 + (n > 1 ? n : 0);
  *p++ = 'e';
  *p++ = first_exponent < 0 ? '-' : '+';
  if (exponent_abs >= 100) *p++ = static_cast<char>('0' + exponent_abs / 100);
  std::memcpy(p, kDigitPairs + 2 * (exponent_abs % 100), 2);
  return p + 2;
}

}  // namespace tread::host
