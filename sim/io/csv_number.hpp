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

#include <string_view>

namespace tread::host {

/// True with the number in `value`; false (`value` unspecified) if `cell` is not one.
bool read_csv_number(std::string_view cell, bool decimal_comma, double& value) noexcept;

}  // namespace tread::host
