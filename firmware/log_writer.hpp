#pragma once
// Writes frames as candump log lines to a host file through semihosting, in one fixed buffer.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/status.hpp"
#include "proto/can_frame.hpp"
#include "proto/candump_line.hpp"
#include "semihost/semihost.hpp"

namespace tread::firmware {

class LogWriter {
 public:
  /// Creates (truncates) `path`; lines name `interface` (cut at 32 characters).
  /// @retval Status::io_error  the host could not create the file
  Status open(std::string_view path, std::string_view interface) noexcept;

  /// Appends one line; the first error is kept and returned by close().
  void write(const proto::CanFrame& frame, std::int64_t time_ns) noexcept;

  /// Flushes and closes.
  /// @retval Status::io_error  a write or the close failed
  Status close() noexcept;

 private:
  void flush() noexcept;

  hal::semihost::Handle file_{0};  // zero-initialised: the object can live in .bss
  bool open_{false};
  std::array<char, 32> interface_{};
  std::size_t interface_len_{0};
  std::array<char, 2048> buffer_{};
  std::size_t used_{0};
  Status status_{Status::ok};
};

}  // namespace tread::firmware
