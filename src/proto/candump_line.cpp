#include "proto/candump_line.hpp"

namespace tread::proto {
namespace {

constexpr std::uint32_t kErrFlag = 0x20000000U;
constexpr char kHex[] = "0123456789ABCDEF";

void put_hex(char*& p, std::uint32_t value, int digits) noexcept {
  for (int d = digits - 1; d >= 0; --d) {
    *p++ = kHex[(value >> (4 * d)) & 0xFU];
  }
}

/// `value` in decimal, at least `min_digits` digits (zero-padded).
void put_decimal(char*& p, std::uint64_t value, int min_digits) noexcept {
  char digits[20];
  int n = 0;
  do {
    digits[n++] = static_cast<char>('0' + value % 10U);
    value /= 10U;
  } while (value != 0U);
  while (n < min_digits) {
    digits[n++] = '0';
  }
  while (n > 0) {
    *p++ = digits[--n];
  }
}

int hex_digit(char c) noexcept {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

/// s.substr() without its exception path (libstdc++ would link abort() into a bare-metal image):
/// `pos` is clamped to the end.
std::string_view slice(std::string_view s, std::size_t pos,
                       std::size_t len = std::string_view::npos) noexcept {
  pos = pos < s.size() ? pos : s.size();
  const std::size_t rest = s.size() - pos;
  return {s.data() + pos, len < rest ? len : rest};
}

/// A non-empty run of decimal digits; false for anything else or more than 18 digits.
bool parse_decimal(std::string_view text, std::int64_t& value) noexcept {
  if (text.empty() || text.size() > 18U) return false;
  value = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return false;
    value = value * 10 + (c - '0');
  }
  return true;
}

}  // namespace

std::size_t format_candump_line(const CanFrame& frame, std::int64_t time_ns,
                                std::string_view interface, char* out) noexcept {
  char* p = out;
  std::int64_t us = time_ns / 1000;
  *p++ = '(';
  if (us < 0) {
    *p++ = '-';
    us = -us;
  }
  put_decimal(p, static_cast<std::uint64_t>(us / 1'000'000), 1);
  *p++ = '.';
  put_decimal(p, static_cast<std::uint64_t>(us % 1'000'000), 6);
  *p++ = ')';
  *p++ = ' ';
  const std::size_t iface_len = interface.size() < 32U ? interface.size() : 32U;
  for (std::size_t i = 0; i < iface_len; ++i) {
    *p++ = interface[i];
  }
  *p++ = ' ';
  if (frame.error) {
    put_hex(p, kErrFlag | frame.id, 8);
  } else if (frame.extended) {
    put_hex(p, frame.id, 8);
  } else {
    put_hex(p, frame.id, 3);
  }
  *p++ = '#';
  if (frame.fd) {
    *p++ = '#';
    *p++ = kHex[frame.bit_rate_switch ? 1 : 0];
  }
  for (std::size_t i = 0; i < frame.len && i < kFdMaxLen; ++i) {
    put_hex(p, frame.data[i], 2);
  }
  *p = '\0';
  return static_cast<std::size_t>(p - out);
}

const char* describe(CandumpError error) noexcept {
  switch (error) {
    case CandumpError::none:
      return "ok";
    case CandumpError::not_a_frame:
      return "expected '(seconds.micros) iface ID#DATA'";
    case CandumpError::bad_timestamp:
      return "malformed timestamp, or later than 9223372035 s";
    case CandumpError::bad_micros:
      return "malformed timestamp (want seconds.6-digit micros)";
    case CandumpError::no_interface:
      return "missing interface name";
    case CandumpError::bad_id_length:
      return "expected a 3- or 8-digit hex ID followed by '#'";
    case CandumpError::id_not_hex:
      return "ID is not hexadecimal";
    case CandumpError::no_fd_flags:
      return "FD frame needs a flags digit after '##'";
    case CandumpError::odd_data:
      return "odd number of data digits";
    case CandumpError::bad_data_length:
      return "invalid data length";
    case CandumpError::data_not_hex:
      return "data is not hexadecimal";
  }
  return "unknown candump error";
}

CandumpError parse_candump_line(std::string_view line, CandumpLine& out) noexcept {
  out = CandumpLine{};
  if (line.size() < 4 || line.front() != '(') {
    return CandumpError::not_a_frame;
  }
  const auto close = line.find(')');
  const auto dot = line.find('.');
  if (close == std::string_view::npos || dot == std::string_view::npos || dot > close) {
    return CandumpError::bad_timestamp;
  }
  std::int64_t sec = 0;
  std::int64_t usec = 0;
  if (!parse_decimal(slice(line, 1, dot - 1), sec) ||
      !parse_decimal(slice(line, dot + 1, close - dot - 1), usec) || close - dot - 1 != 6) {
    return CandumpError::bad_micros;
  }
  // The time in int64 nanoseconds: up to 9 223 372 035 s (the year 2262); beyond, the product
  // would overflow (found by fuzzing: tests/fuzz/regressions/candump_replay).
  constexpr std::int64_t kMaxSeconds = 9'223'372'035;
  if (sec > kMaxSeconds) {
    return CandumpError::bad_timestamp;
  }
  out.time_ns = (sec * 1'000'000 + usec) * 1000;
  std::string_view rest = slice(line, close + 1);
  while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
  const auto space = rest.find(' ');
  if (space == std::string_view::npos) {
    return CandumpError::no_interface;
  }
  out.interface = slice(rest, 0, space);
  rest.remove_prefix(space + 1);
  while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\r')) rest.remove_suffix(1);
  // candump may append a direction flag (" R" / " T"): ignore it.
  if (rest.size() > 2 && rest[rest.size() - 2] == ' ') rest.remove_suffix(2);
  const auto hash = rest.find('#');
  if (hash == std::string_view::npos || (hash != 3 && hash != 8)) {
    return CandumpError::bad_id_length;
  }
  std::uint32_t id = 0;
  for (std::size_t i = 0; i < hash; ++i) {
    const int d = hex_digit(rest[i]);
    if (d < 0) return CandumpError::id_not_hex;
    id = (id << 4U) | static_cast<std::uint32_t>(d);
  }
  CanFrame& f = out.frame;
  if (hash == 8) {
    if ((id & kErrFlag) != 0U) {
      f.error = true;
      id &= ~kErrFlag;
    } else {
      f.extended = true;
    }
  }
  f.id = id;
  std::string_view data = slice(rest, hash + 1);
  if (!data.empty() && data.front() == '#') {
    if (data.size() < 2 || hex_digit(data[1]) < 0) return CandumpError::no_fd_flags;
    f.fd = true;
    f.bit_rate_switch = (hex_digit(data[1]) & 1) != 0;
    data.remove_prefix(2);
  }
  if (data.size() % 2 != 0) return CandumpError::odd_data;
  const std::size_t len = data.size() / 2;
  out.data_len = len;
  if (len > (f.fd ? kFdMaxLen : kClassicMaxLen) ||
      (f.fd && !is_valid_fd_length(static_cast<std::uint8_t>(len)))) {
    return CandumpError::bad_data_length;
  }
  f.len = static_cast<std::uint8_t>(len);
  for (std::size_t i = 0; i < len; ++i) {
    const int hi = hex_digit(data[2 * i]);
    const int lo = hex_digit(data[2 * i + 1]);
    if (hi < 0 || lo < 0) return CandumpError::data_not_hex;
    f.data[i] = static_cast<std::uint8_t>(hi * 16 + lo);
  }
  f.timestamp_ns = out.time_ns;
  return CandumpError::none;
}

}  // namespace tread::proto
