#pragma once
// A double written as the shortest text that reads back to exactly it, into a caller's buffer:
// the formatting step of large CSV outputs (`tread mf eval`), with no locale, no stream and no
// allocation per value. The same value as "%.17g" when read back, in fewer characters ("0.1"
// rather than "0.10000000000000001"); NaN and infinities as "nan", "inf".
//
// The text is std::to_chars(first, last, value)'s, character for character (tests/sim compares
// them over 1.2 million values chosen to reach every branch and edge): the shortest digits, in
// fixed or scientific notation, whichever is shorter, fixed on a tie. The digits come from
// Dragonbox (libdragonbox-dev), about twice as fast here as libstdc++'s to_chars; the rare values
// it does not cover (zero, subnormal, non-finite, |value| ≥ 2^53) are left to std::to_chars.

#include <cstddef>

namespace tread::host {

/// Characters the longest double takes ("-2.2250738585072014e-308": 24).
inline constexpr std::size_t kShortestNumberMaxChars = 24;
/// Room write_shortest needs at `out`: it writes whole blocks of digits, up to this many bytes,
/// of which the first (returned end − out) ≤ kShortestNumberMaxChars are the number.
inline constexpr std::size_t kShortestNumberRoom = 40;

/// Writes `value` at `out`, which must have room for kShortestNumberRoom; returns the end.
char* write_shortest(char* out, double value) noexcept;

}  // namespace tread::host
