#pragma once
// SocketCAN raw socket: classic and FD frames, non-blocking, kernel receive timestamps; a cycle's
// frames sent and received in one system call each (sendmmsg, recvmmsg).

#include <linux/can.h>
#include <sys/socket.h>

#include <cstddef>
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

/// SocketCAN raw socket. Satisfies hal::WaitableCanBus, hal::BatchCanBus and
/// hal::BatchReceiveCanBus. Error frames (bus-off, controller problems,
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

  /// Sends `frames` in order, up to kBatchFrames of them in one system call (sendmmsg), without
  /// blocking. Returns how many were queued: the first ones of `frames`. It stops at the first
  /// frame it cannot send: one send() would refuse as invalid (an FD frame on a classic socket, a
  /// length the frame cannot have; not counted), one refused because the socket's queue is full
  /// (ENOBUFS/EAGAIN: that frame and every one after it counted in tx_dropped(), as send() counts
  /// a refused frame), or an I/O error (`last_errno()`; not counted). A signal (EINTR) is retried.
  std::size_t send_batch(std::span<const proto::CanFrame> frames);

  /// Receives one frame if one is queued.
  /// @retval Status::would_block   nothing queued
  /// @retval Status::invalid_argument  the message was no CAN frame (counted in rx_malformed())
  Status receive(proto::CanFrame& frame);

  /// Receives up to `frames.size()` queued frames, up to kBatchFrames of them in one system call
  /// (recvmmsg), without blocking, each as receive() gives it (kernel timestamp, error frames).
  /// Returns how many it wrote to the front of `frames`: fewer than asked for when no more were
  /// queued, 0 when none was (or on an I/O error: `last_errno()`). A message that is no CAN frame
  /// is skipped and counted in rx_malformed().
  std::size_t receive_batch(std::span<proto::CanFrame> frames);

  /// The most frames one sendmmsg or recvmmsg call of send_batch() / receive_batch() carries.
  static constexpr std::size_t kBatchFrames = 32;

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
  /// Messages received that were no CAN frame (a size other than CAN_MTU or CANFD_MTU): skipped.
  [[nodiscard]] std::uint64_t rx_malformed() const noexcept { return rx_malformed_; }
  [[nodiscard]] bool bus_off() const noexcept { return bus_off_; }

 private:
  void close() noexcept;
  /// `frame` as the kernel's frame; `size` CAN_MTU or CANFD_MTU. invalid_argument where send()
  /// refuses it.
  Status to_raw(const proto::CanFrame& frame, canfd_frame& raw, std::size_t& size) const;
  /// The received message (`got` bytes, its control messages in `message`) as `frame`: error-frame
  /// state, overflow count and timestamp taken. invalid_argument (counted) if it is no CAN frame.
  Status from_raw(const canfd_frame& raw, std::size_t got, msghdr& message, proto::CanFrame& frame);

  int fd_{-1};
  bool fd_enabled_{false};
  int last_errno_{0};
  std::uint64_t tx_dropped_{0};
  std::uint32_t rx_overflows_{0};
  std::uint64_t error_frames_{0};
  std::uint64_t rx_malformed_{0};
  bool bus_off_{false};
};

static_assert(WaitableCanBus<SocketCanBus>);
static_assert(BatchCanBus<SocketCanBus>);
static_assert(BatchReceiveCanBus<SocketCanBus>);

}  // namespace tread::hal
