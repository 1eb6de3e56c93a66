#pragma once
// SocketCAN raw socket: classic and FD frames, non-blocking, kernel receive timestamps.

#include <cstdint>
#include <string_view>

#include "core/status.hpp"
#include "proto/can_frame.hpp"

namespace tread::hal {

class SocketCanBus {
 public:
  SocketCanBus() = default;
  SocketCanBus(const SocketCanBus&) = delete;
  SocketCanBus& operator=(const SocketCanBus&) = delete;
  SocketCanBus(SocketCanBus&& other) noexcept;
  SocketCanBus& operator=(SocketCanBus&& other) noexcept;
  ~SocketCanBus();

  /// Opens a raw CAN socket bound to `interface_name`.
  /// @retval Status::ok            bound and non-blocking
  /// @retval Status::unsupported   the kernel has no CAN (EAFNOSUPPORT) or the link is not
  /// FD-capable
  /// @retval Status::invalid_argument  no such interface
  /// @retval Status::io_error      any other refusal; `last_errno()` tells which
  Status open(std::string_view interface_name, bool enable_fd);

  /// Sends one frame without blocking.
  /// @retval Status::would_block   the socket buffer is full (ENOBUFS/EAGAIN); counted, frame
  /// dropped
  Status send(const proto::CanFrame& frame);

  /// Receives one frame if one is queued.
  /// @retval Status::would_block   nothing queued
  Status receive(proto::CanFrame& frame);

  [[nodiscard]] bool is_open() const noexcept { return fd_ >= 0; }
  [[nodiscard]] int native_handle() const noexcept { return fd_; }
  [[nodiscard]] int last_errno() const noexcept { return last_errno_; }
  [[nodiscard]] std::uint64_t tx_dropped() const noexcept { return tx_dropped_; }

 private:
  void close() noexcept;

  int fd_{-1};
  bool fd_enabled_{false};
  int last_errno_{0};
  std::uint64_t tx_dropped_{0};
};

}  // namespace tread::hal
