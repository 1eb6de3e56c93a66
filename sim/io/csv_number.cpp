#include "io/csv_number.hpp"

#include <array>
#include <cstddef>
#include <cstring>
#include <system_error>

#include <fast_float/fast_float.h>

namespace tread::host {

namespace {

constexpr auto kMaxChars = static_cast<std::size_t>(detail::kMaxNumberChars);

bool is_cell_blank(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f';
}

// A Fortran exponent (1.5D-3), read as `e`: the rare path, apart from the common one.
[[gnu::noinline]] bool read_fortran(const char* first, const char* last, char point,
                                    double& value) noexcept {
  std::array<char, kMaxChars> text{};
  const auto n = static_cast<std::size_t>(last - first);
  for (std::size_t i = 0; i < n; ++i) {
    text[i] = first[i] == 'd' || first[i] == 'D' ? 'e' : first[i];
  }
  const fast_float::from_chars_result r = fast_float::from_chars_advanced(
      text.data(), text.data() + n, value,
      fast_float::parse_options(fast_float::chars_format::general, point));
  return r.ec == std::errc() && r.ptr == text.data() + n;
}

}  // namespace

bool read_csv_number(std::string_view cell, bool decimal_comma, double& value) noexcept {
  const char* first = cell.data();
  const char* last = first + cell.size();
  while (first != last && is_cell_blank(*first)) ++first;
  while (first != last && is_cell_blank(last[-1])) --last;
  if (first != last && *first == '+') ++first;
  const auto n = static_cast<std::size_t>(last - first);
  if (n == 0 || n > kMaxChars) return false;
  const char point = decimal_comma && std::memchr(first, '.', n) == nullptr ? ',' : '.';
  const fast_float::from_chars_result r = fast_float::from_chars_advanced(
      first, last, value, fast_float::parse_options(fast_float::chars_format::general, point));
  if (r.ec != std::errc() || r.ptr != last) {
    const bool fortran =
        std::memchr(first, 'd', n) != nullptr || std::memchr(first, 'D', n) != nullptr;
    if (!fortran || !read_fortran(first, last, point, value)) return false;
  }
  return detail::finite_not_underflow(value, first, last);
}

}  // namespace tread::host
