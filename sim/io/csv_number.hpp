#pragma once
// A number cell of a CSV table as a finite double (host side), read with fast_float.
//
// The same numbers as tir::parse_number (sim/tir/tir_file.hpp) accepts, to the same double (both
// round correctly): blanks (' ', tab, CR, FF) around the number are ignored, one leading '+' is
// allowed, then a decimal number with optional sign and exponent (`e`, `E` and Fortran `d`, `D`).
// Refused: an empty cell, more than 64 characters, anything after the number, inf and nan, and a
// value too large for a double or so small that it rounds to zero ("1e-400": as std::from_chars).
// With `decimal_comma` a cell without a '.' takes ',' as its decimal point ("0,05" = 0.05), as
// spreadsheets in many locales write with ';' or tab separators.

#include <cmath>
#include <cstddef>
#include <string_view>
#include <system_error>

#include <fast_float/fast_float.h>

namespace tread::host {

/// True with the number in `value`; false (`value` unspecified) if `cell` is not one.
bool read_csv_number(std::string_view cell, bool decimal_comma, double& value) noexcept;

namespace detail {

/// True if the digits before the exponent are not all zero: a zero result then is an underflow,
/// which std::from_chars (and so tir::parse_number) refuses as out of range.
inline bool nonzero_mantissa(const char* first, const char* last) noexcept {
  for (; first != last; ++first) {
    const char c = *first;
    if (c == 'e' || c == 'E' || c == 'd' || c == 'D') break;
    if (c >= '1' && c <= '9') return true;
  }
  return false;
}

/// The rules once a number is read from [first, last): finite, and not an underflow to zero
/// ("1e-400", which std::from_chars, and so tir::parse_number, refuses as out of range).
inline bool finite_not_underflow(double value, const char* first, const char* last) noexcept {
  return std::isfinite(value) && (std::fabs(value) > 0.0 || !nonzero_mantissa(first, last));
}

/// The most characters a number may take (as tir::parse_number).
inline constexpr std::ptrdiff_t kMaxNumberChars = 64;

}  // namespace detail

/// The one-pass path of a row read in place: the number that starts at `first` (after a '+', if
/// any) in a line that ends at `last`, with '.' as its decimal point. Returns the end of the
/// number, or nullptr wherever read_csv_number's other rules decide: no number, more than 64
/// characters, inf or nan, too large, an underflow to zero. A Fortran exponent ends the number
/// at its `d`. If only blanks (text::is_blank) follow the returned end up to the cell's separator
/// (or the line's end), read_csv_number of that cell, trimmed by text::trim_blanks, with a '.'
/// point gives the same value: the caller checks that, and reads any other cell with
/// read_csv_number.
/// (Defined here so that a row's reader, InputTable::read_comma_row, inlines it and fast_float's
/// parse with it: cmake/TreadHotSources.cmake.)
inline const char* read_csv_number_at(const char* first, const char* last, double& value) noexcept {
  if (first != last && *first == '+') ++first;
  const fast_float::from_chars_result r = fast_float::from_chars_advanced(
      first, last, value, fast_float::parse_options(fast_float::chars_format::general, '.'));
  if (r.ec != std::errc() || r.ptr == first || r.ptr - first > detail::kMaxNumberChars ||
      !detail::finite_not_underflow(value, first, r.ptr)) {
    return nullptr;
  }
  return r.ptr;
}

}  // namespace tread::host
