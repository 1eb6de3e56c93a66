#include "node/candump_log.hpp"

#include <charconv>
#include <fstream>
#include <stdexcept>

namespace tread::host {
namespace {

constexpr std::uint32_t kErrFlag = 0x20000000U;
constexpr char kHex[] = "0123456789ABCDEF";

void put_hex(char*& p, std::uint32_t value, int digits) noexcept {
  for (int d = digits - 1; d >= 0; --d) {
    *p++ = kHex[(value >> (4 * d)) & 0xFU];
  }
}

int hex_digit(char c) noexcept {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw std::runtime_error(where + ": " + what);
}

}  // namespace

std::size_t format_candump_line(const proto::CanFrame& frame, std::int64_t time_ns,
                                std::string_view interface, char* out) noexcept {
  char* p = out;
  const std::int64_t us = time_ns / 1000;
  const int n = std::snprintf(p, 40, "(%lld.%06lld) ", static_cast<long long>(us / 1'000'000),
                              static_cast<long long>(us % 1'000'000));
  p += n > 0 ? n : 0;
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
  for (std::size_t i = 0; i < frame.len && i < proto::kFdMaxLen; ++i) {
    put_hex(p, frame.data[i], 2);
  }
  *p = '\0';
  return static_cast<std::size_t>(p - out);
}

LoggedFrame parse_candump_line(std::string_view line, const std::string& where) {
  LoggedFrame logged;
  if (line.size() < 4 || line.front() != '(') {
    fail(where, "expected '(seconds.micros) iface ID#DATA'");
  }
  const auto close = line.find(')');
  const auto dot = line.find('.');
  if (close == std::string_view::npos || dot == std::string_view::npos || dot > close) {
    fail(where, "malformed timestamp");
  }
  long long sec = 0;
  long long usec = 0;
  if (std::from_chars(line.data() + 1, line.data() + dot, sec).ec != std::errc{} ||
      std::from_chars(line.data() + dot + 1, line.data() + close, usec).ec != std::errc{} ||
      close - dot - 1 != 6) {
    fail(where, "malformed timestamp (want seconds.6-digit micros)");
  }
  logged.time_ns = (sec * 1'000'000 + usec) * 1000;
  std::string_view rest = line.substr(close + 1);
  while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
  const auto space = rest.find(' ');
  if (space == std::string_view::npos) {
    fail(where, "missing interface name");
  }
  logged.interface = std::string(rest.substr(0, space));
  rest.remove_prefix(space + 1);
  while (!rest.empty() && rest.back() == ' ') rest.remove_suffix(1);
  // candump may append a direction flag (" R" / " T"): ignore it.
  if (rest.size() > 2 && rest[rest.size() - 2] == ' ') rest.remove_suffix(2);
  const auto hash = rest.find('#');
  if (hash == std::string_view::npos || (hash != 3 && hash != 8)) {
    fail(where, "expected a 3- or 8-digit hex ID followed by '#'");
  }
  std::uint32_t id = 0;
  for (std::size_t i = 0; i < hash; ++i) {
    const int d = hex_digit(rest[i]);
    if (d < 0) fail(where, "ID is not hexadecimal");
    id = (id << 4U) | static_cast<std::uint32_t>(d);
  }
  proto::CanFrame& f = logged.frame;
  if (hash == 8) {
    if ((id & kErrFlag) != 0U) {
      f.error = true;
      id &= ~kErrFlag;
    } else {
      f.extended = true;
    }
  }
  f.id = id;
  std::string_view data = rest.substr(hash + 1);
  if (!data.empty() && data.front() == '#') {
    if (data.size() < 2 || hex_digit(data[1]) < 0)
      fail(where, "FD frame needs a flags digit after '##'");
    f.fd = true;
    f.bit_rate_switch = (hex_digit(data[1]) & 1) != 0;
    data.remove_prefix(2);
  }
  if (data.size() % 2 != 0) fail(where, "odd number of data digits");
  const std::size_t len = data.size() / 2;
  if (len > (f.fd ? proto::kFdMaxLen : proto::kClassicMaxLen) ||
      (f.fd && !proto::is_valid_fd_length(static_cast<std::uint8_t>(len)))) {
    fail(where, "invalid data length " + std::to_string(len));
  }
  f.len = static_cast<std::uint8_t>(len);
  for (std::size_t i = 0; i < len; ++i) {
    const int hi = hex_digit(data[2 * i]);
    const int lo = hex_digit(data[2 * i + 1]);
    if (hi < 0 || lo < 0) fail(where, "data is not hexadecimal");
    f.data[i] = static_cast<std::uint8_t>(hi * 16 + lo);
  }
  f.timestamp_ns = logged.time_ns;
  return logged;
}

std::vector<LoggedFrame> read_candump_log(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) {
    throw std::runtime_error(path.string() + ": cannot open");
  }
  std::vector<LoggedFrame> frames;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    frames.push_back(parse_candump_line(line, path.string() + ":" + std::to_string(line_no)));
  }
  return frames;
}

CandumpWriter::~CandumpWriter() {
  close();
}

void CandumpWriter::open(const std::filesystem::path& path, std::string interface) {
  close();
  file_ = std::fopen(path.c_str(), "w");
  if (file_ == nullptr) {
    throw std::runtime_error(path.string() + ": cannot open for writing");
  }
  buffer_.assign(1U << 20U, '\0');
  std::setvbuf(file_, buffer_.data(), _IOFBF, buffer_.size());
  interface_ = std::move(interface);
}

void CandumpWriter::write(const proto::CanFrame& frame, std::int64_t time_ns) noexcept {
  if (file_ == nullptr) return;
  char line[kCandumpLineMax + 2];
  const std::size_t n = format_candump_line(frame, time_ns, interface_, line);
  line[n] = '\n';
  std::fwrite(line, 1, n + 1, file_);
}

void CandumpWriter::close() noexcept {
  if (file_ != nullptr) {
    std::fclose(file_);
    file_ = nullptr;
  }
}

}  // namespace tread::host
