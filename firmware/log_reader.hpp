#pragma once
// Reads a host file line by line through semihosting, in fixed buffers (no heap): the firmware's
// way into a candump log.

#include <array>
#include <cstddef>
#include <string_view>

#include "core/status.hpp"
#include "semihost/semihost.hpp"

namespace tread::firmware {

class LogReader {
 public:
  /// Longest line accepted (a candump line of a 64-byte FD frame is about 200 characters).
  static constexpr std::size_t kMaxLine = 256;

  /// @retval Status::io_error  the host could not open the file
  Status open(std::string_view path) noexcept;

  /// The next line without its newline (and without a '\r' before it).
  /// @retval Status::ok            `line` holds it (valid until the next call)
  /// @retval Status::would_block   the end of the file: no more lines
  /// @retval Status::out_of_range  a line longer than kMaxLine
  /// @retval Status::io_error      the host could not read
  Status next(std::string_view& line) noexcept;

  void close() noexcept;

 private:
  Status fill() noexcept;

  hal::semihost::Handle file_{0};  // zero-initialised: the object can live in .bss
  bool open_{false};
  std::array<char, 1024> buffer_{};
  std::size_t begin_{0};
  std::size_t end_{0};
  bool eof_{false};
};

}  // namespace tread::firmware
