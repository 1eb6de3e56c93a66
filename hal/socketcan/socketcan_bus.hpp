#pragma once
// SocketCAN raw socket: classic and FD frames, non-blocking, kernel receive timestamps.

#include <cstdint>
#include <span>
#include <string_view>

#include "core/status.hpp"
#include "hal_concepts.hpp"
#include "proto/can_frame.hpp"

namespace tread::hal {

/// A kernel receive filter: a frame passes when (received_id & mask) == (id & mask).
struct CanIdFilter {
  std::uint32_t id;
  std::uint32_t mask;
  bool extended{false};
};

/// SocketCAN raw socket. Satisfies hal::CanBus. Error frames (bus-off, controller problems,
/// restarted, TX timeout) are delivered as frames with `error = true` and the error class in `id`.
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

  /// Installs kernel ID filters (CAN_RAW_FILTER); an empty span receives nothing but error frames.
  /// @retval Status::io_error  setsockopt refused
  Status set_filters(std::span<const CanIdFilter> filters);

  /// Sends one frame without blocking.
  /// @retval Status::would_block   the socket buffer is full (ENOBUFS/EAGAIN); counted, frame
  /// dropped
  Status send(const proto::CanFrame& frame);

  /// Receives one frame if one is queued.
  /// @retval Status::would_block   nothing queued
  Status receive(proto::CanFrame& frame);

  /// Blocks until a frame (or error frame) is queued or the absolute CLOCK_MONOTONIC
  /// `deadline_ns` passes (ppoll). Satisfies hal::WaitableCanBus.
  /// @retval Status::ok           something is queued
  /// @retval Status::would_block  the deadline passed
  /// @retval Status::io_error     the socket is not open, or ppoll failed (`last_errno()`)
  Status wait_until_ns(std::int64_t deadline_ns);

  /// Sets SO_RCVBUF (bytes); small values make receive-overflow counting observable in tests.
  Status set_receive_buffer(int bytes);
  /// The receive buffer the kernel granted (SO_RCVBUF read back: twice the request, capped at
  /// net.core.rmem_max × 2), or -1 if it cannot be read.
  [[nodiscard]] int receive_buffer_bytes() const noexcept;

  [[nodiscard]] bool is_open() const noexcept { return fd_ >= 0; }
  [[nodiscard]] int native_handle() const noexcept { return fd_; }
  [[nodiscard]] int last_errno() const noexcept { return last_errno_; }
  [[nodiscard]] std::uint64_t tx_dropped() const noexcept { return tx_dropped_; }
  /// Frames the kernel dropped because this socket's receive queue was full (SO_RXQ_OVFL).
  [[nodiscard]] std::uint32_t rx_overflows() const noexcept { return rx_overflows_; }
  [[nodiscard]] std::uint64_t error_frames() const noexcept { return error_frames_; }
  [[nodiscard]] bool bus_off() const noexcept { return bus_off_; }

 private:
  void close() noexcept;

  int fd_{-1};
  bool fd_enabled_{false};
  int last_errno_{0};
  std::uint64_t tx_dropped_{0};
  std::uint32_t rx_overflows_{0};
  std::uint64_t error_frames_{0};
  bool bus_off_{false};
};

static_assert(WaitableCanBus<SocketCanBus>);

}  // namespace tread::hal
