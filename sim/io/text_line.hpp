#pragma once
// The line and field handling of the host's text readers and writers (profiles, measurements,
// .tir files, column lists, reports): one definition of trimming, splitting, number parsing and
// formatting, the "file:line: message" error and the clean-ups of what spreadsheets write.

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace tread::host::text {

/// Throws std::runtime_error "source:line: message".
[[noreturn]] inline void fail_at(const std::string& source, std::size_t line,
                                 const std::string& message) {
  throw std::runtime_error(source + ":" + std::to_string(line) + ": " + message);
}

/// A file's text as an error message quotes it: at most `max_bytes` bytes (cut at a character
/// boundary) followed by "… (N characters)" when longer, a tab as "\t", other control bytes and
/// bytes that are not well-formed UTF-8 as '?'. A 50 MB line, or a binary file read as text, was
/// echoed whole onto the terminal.
inline std::string excerpt(std::string_view text, std::size_t max_bytes = 80) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    // The length of a well-formed UTF-8 sequence starting at i (RFC 3629: no overlong forms,
    // no surrogates, nothing above U+10FFFF), 0 if there is none.
    std::size_t n = 0;
    if (c < 0x80U) {
      n = 1;
    } else if (c >= 0xC2U && c <= 0xF4U) {
      n = c < 0xE0U ? 2U : c < 0xF0U ? 3U : 4U;
      if (i + n > text.size()) {
        n = 0;
      } else {
        const auto c1 = static_cast<unsigned char>(text[i + 1]);
        const unsigned lo = c == 0xE0U ? 0xA0U : c == 0xF0U ? 0x90U : 0x80U;
        const unsigned hi = c == 0xEDU ? 0x9FU : c == 0xF4U ? 0x8FU : 0xBFU;
        if (c1 < lo || c1 > hi) n = 0;
        for (std::size_t k = 2; k < n; ++k) {
          const auto ck = static_cast<unsigned char>(text[i + k]);
          if (ck < 0x80U || ck > 0xBFU) n = 0;
        }
      }
    }
    const std::size_t width = n == 0 ? 1U : n;
    if (i + width > max_bytes) break;
    if (c == '\t') {
      out += "\\t";
    } else if (n == 0 || (n == 1 && (c < 0x20U || c == 0x7FU))) {
      out += '?';
    } else {
      out.append(text.substr(i, n));
    }
    i += width;
  }
  if (i < text.size()) {
    // Characters, not bytes: UTF-8 continuation bytes are not counted.
    const auto characters = std::count_if(text.begin(), text.end(), [](char b) {
      return (static_cast<unsigned char>(b) & 0xC0U) != 0x80U;
    });
    out += "… (" + std::to_string(characters) + " characters)";
  }
  return out;
}

/// Names from a file as a report lists them: " 'a' 'b'", each an excerpt, at most `max_items`
/// of them and then " … and N more" (a header of a million cells was listed whole).
inline std::string quoted_list(const std::vector<std::string>& names, std::size_t max_items = 12) {
  std::string out;
  for (std::size_t i = 0; i < names.size() && i < max_items; ++i) {
    out += " '" + excerpt(names[i]) + "'";
  }
  if (names.size() > max_items)
    out += " … and " + std::to_string(names.size() - max_items) + " more";
  return out;
}

/// White space: space, tab, CR, LF, form feed, vertical tab (what std::isspace counts in the C
/// locale).
constexpr bool is_blank(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

/// Without leading and trailing white space (is_blank).
inline std::string_view trim_blanks(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) {
    s.remove_prefix(1);
  }
  while (!s.empty() && is_blank(s.back())) {
    s.remove_suffix(1);
  }
  return s;
}

/// The non-empty fields of a line separated by any run of ',', ';', tab, space or CR.
inline std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  const auto is_sep = [](char c) {
    return c == ',' || c == ';' || c == '\t' || c == ' ' || c == '\r';
  };
  std::size_t start = 0;
  while (start < line.size()) {
    while (start < line.size() && is_sep(line[start])) {
      ++start;
    }
    std::size_t end = start;
    while (end < line.size() && !is_sep(line[end])) {
      ++end;
    }
    if (end > start) {
      fields.push_back(line.substr(start, end - start));
    }
    start = end;
  }
  return fields;
}

/// The whole of `text` as a number (an optional leading '+' allowed); false if anything is left
/// over or it is empty. Does not judge finiteness (callers do where it matters).
inline bool parse_number_text(std::string_view text, double& value) {
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+') {
    ++first;
  }
  const auto [ptr, ec] = std::from_chars(first, last, value);
  return ec == std::errc{} && ptr == last && first != last;
}

/// The whole of `text` as a finite number, for option values and spec strings ("h=28"): throws
/// std::invalid_argument "'text' is not a finite number" for an empty value, a trailing word
/// ("28mm"), a value beyond double (1e999) or NaN — where std::stod would take "28mm" as 28 and
/// throw its own "stod" for 1e999.
inline double finite_number(const std::string& text) {
  double value = 0.0;
  if (!parse_number_text(text, value) || !std::isfinite(value)) {
    throw std::invalid_argument("'" + text + "' is not a finite number");
  }
  return value;
}

/// Removes a UTF-8 byte-order mark at the start of the first line of a file (spreadsheet exports
/// write one); without this the first header key or column name would not be recognised.
inline void strip_utf8_bom(std::string& line, std::size_t line_no) {
  if (line_no == 1 && line.starts_with("\xEF\xBB\xBF")) {
    line.erase(0, 3);
  }
}

/// True if `text` is two or more blank-separated numbers each written with one decimal comma
/// between digits and no point ("-70,0 9,519"): a ',' there is a decimal point, not a separator.
inline bool blank_separated_decimal_commas(std::string_view text) {
  std::size_t tokens = 0;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\r')) ++i;
    if (i == text.size()) break;
    std::size_t end = i;
    while (end < text.size() && text[end] != ' ' && text[end] != '\r') ++end;
    const std::string_view token = text.substr(i, end - i);
    const std::size_t comma = token.find(',');
    const auto digit = [](char c) { return c >= '0' && c <= '9'; };
    if (comma == std::string_view::npos || token.find(',', comma + 1) != std::string_view::npos ||
        token.find('.') != std::string_view::npos || comma == 0 || comma + 1 == token.size() ||
        !digit(token[comma - 1]) || !digit(token[comma + 1])) {
      return false;
    }
    ++tokens;
    i = end;
  }
  return tokens >= 2;
}

/// A data line whose fields are separated by ';' or tabs may use decimal commas (European
/// spreadsheets): there a ',' is a decimal point, never a separator; so in a line of blank-
/// separated numbers that each have one decimal comma ("-70,0 9,519", not -70, 0, 9, 519).
/// Returns the line with such commas as points; other lines unchanged.
inline std::string with_decimal_points(std::string_view text) {
  std::string out(text);
  if (out.find_first_of(";\t") != std::string::npos || blank_separated_decimal_commas(text)) {
    std::replace(out.begin(), out.end(), ',', '.');
  }
  return out;
}

/// `value` with `digits` significant digits (as %g), "n/a" when it is not finite: for reports.
inline std::string format_significant(double value, int digits = 6) {
  if (!std::isfinite(value)) {
    return "n/a";
  }
  std::ostringstream s;
  s << std::setprecision(digits) << value;
  return s.str();
}

}  // namespace tread::host::text
