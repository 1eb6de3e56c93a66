#pragma once
// A double written as the shortest text that reads back to exactly it (std::to_chars), into a
// caller's buffer: the formatting step of large CSV outputs (`tread mf eval`), with no locale, no
// stream and no allocation per value. The same value as "%.17g" when read back, in fewer
// characters ("0.1" rather than "0.10000000000000001"); NaN and infinities as "nan", "inf".

#include <charconv>
#include <cstddef>

namespace tread::host {

/// Characters the longest double takes ("-2.2250738585072014e-308": 24).
inline constexpr std::size_t kShortestNumberMaxChars = 24;

/// Writes `value` at `out`, which must have room for kShortestNumberMaxChars; returns the end.
inline char* write_shortest(char* out, double value) noexcept {
  return std::to_chars(out, out + kShortestNumberMaxChars, value).ptr;
}

}  // namespace tread::host
