#pragma once
// Small line-level clean-ups shared by the profile readers (CSV, MiniProf, SIMPACK).

#include <algorithm>
#include <string>
#include <string_view>

namespace tread::profile {

/// Removes a UTF-8 byte-order mark at the start of the first line of a file (spreadsheet exports
/// write one); without this the first header key or column name would not be recognised.
inline void strip_utf8_bom(std::string& line, std::size_t line_no) {
  if (line_no == 1 && line.starts_with("\xEF\xBB\xBF")) {
    line.erase(0, 3);
  }
}

/// A data line whose fields are separated by ';' or tabs may use decimal commas (European
/// spreadsheets): there a ',' is a decimal point, never a separator. Returns the line with such
/// commas as points; other lines unchanged.
inline std::string with_decimal_points(std::string_view text) {
  std::string out(text);
  if (out.find_first_of(";\t") != std::string::npos) {
    std::replace(out.begin(), out.end(), ',', '.');
  }
  return out;
}

}  // namespace tread::profile
