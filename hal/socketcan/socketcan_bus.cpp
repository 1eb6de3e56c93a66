#include "socketcan/socketcan_bus.hpp"

#include <fcntl.h>
#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/uio.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <string>
#include <utility>

namespace tread::hal {

SocketCanBus::SocketCanBus(SocketCanBus&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)),
      fd_enabled_(other.fd_enabled_),
      last_errno_(other.last_errno_),
      tx_dropped_(other.tx_dropped_),
      rx_overflows_(other.rx_overflows_),
      error_frames_(other.error_frames_),
      rx_malformed_(other.rx_malformed_),
      bus_off_(other.bus_off_) {}

SocketCanBus& SocketCanBus::operator=(SocketCanBus&& other) noexcept {
  if (this != &other) {
    close();
    fd_ = std::exchange(other.fd_, -1);
    fd_enabled_ = other.fd_enabled_;
    last_errno_ = other.last_errno_;
    tx_dropped_ = other.tx_dropped_;
    rx_overflows_ = other.rx_overflows_;
    error_frames_ = other.error_frames_;
    rx_malformed_ = other.rx_malformed_;
    bus_off_ = other.bus_off_;
  }
  return *this;
}

SocketCanBus::~SocketCanBus() {
  close();
}

void SocketCanBus::close() noexcept {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
}

Status SocketCanBus::open(std::string_view interface_name, bool enable_fd) {
  close();
  const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) {
    last_errno_ = errno;
    return last_errno_ == EAFNOSUPPORT ? Status::unsupported : Status::io_error;
  }
  fd_ = fd;

  const std::string name(interface_name);
  const unsigned int index = ::if_nametoindex(name.c_str());
  if (index == 0U) {
    last_errno_ = errno;
    close();
    return Status::invalid_argument;
  }

  if (enable_fd) {
    const int on = 1;
    if (::setsockopt(fd_, SOL_CAN_RAW, CAN_RAW_FD_FRAMES, &on, sizeof(on)) != 0) {
      last_errno_ = errno;
      close();
      return Status::unsupported;
    }
  }
  const int on = 1;
  const can_err_mask_t err_mask = CAN_ERR_BUSOFF | CAN_ERR_CRTL | CAN_ERR_RESTARTED |
                                  CAN_ERR_TX_TIMEOUT | CAN_ERR_PROT | CAN_ERR_ACK;
  if (::setsockopt(fd_, SOL_SOCKET, SO_TIMESTAMPNS, &on, sizeof(on)) != 0 ||
      ::setsockopt(fd_, SOL_SOCKET, SO_RXQ_OVFL, &on, sizeof(on)) != 0 ||
      ::setsockopt(fd_, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &err_mask, sizeof(err_mask)) != 0) {
    last_errno_ = errno;
    close();
    return Status::io_error;
  }

  sockaddr_can address{};
  address.can_family = AF_CAN;
  address.can_ifindex = static_cast<int>(index);
  if (::bind(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) != 0) {
    last_errno_ = errno;
    close();
    return Status::io_error;
  }
  fd_enabled_ = enable_fd;
  return Status::ok;
}

Status SocketCanBus::set_receive_buffer(int bytes) {
  if (fd_ < 0 || ::setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &bytes, sizeof(bytes)) != 0) {
    last_errno_ = errno;
    return Status::io_error;
  }
  return Status::ok;
}

int SocketCanBus::receive_buffer_bytes() const noexcept {
  int bytes = 0;
  socklen_t size = sizeof(bytes);
  if (fd_ < 0 || ::getsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &bytes, &size) != 0) {
    return -1;
  }
  return bytes;
}

Status SocketCanBus::set_filters(std::span<const CanIdFilter> filters) {
  if (fd_ < 0) {
    return Status::io_error;
  }
  constexpr std::size_t kMaxFilters = 64;
  if (filters.size() > kMaxFilters) {
    return Status::invalid_argument;
  }
  can_filter raw[kMaxFilters]{};
  for (std::size_t i = 0; i < filters.size(); ++i) {
    const std::uint32_t flag = filters[i].extended ? CAN_EFF_FLAG : 0U;
    raw[i].can_id = filters[i].id | flag;
    // Match the frame format too, so an 11-bit filter does not pass 29-bit frames.
    raw[i].can_mask = filters[i].mask | CAN_EFF_FLAG | CAN_RTR_FLAG;
  }
  const auto size = static_cast<socklen_t>(filters.size() * sizeof(can_filter));
  if (::setsockopt(fd_, SOL_CAN_RAW, CAN_RAW_FILTER, filters.empty() ? nullptr : raw, size) != 0) {
    last_errno_ = errno;
    return Status::io_error;
  }
  return Status::ok;
}

Status SocketCanBus::to_raw(const proto::CanFrame& frame, canfd_frame& raw,
                            std::size_t& size) const {
  raw = canfd_frame{};
  raw.can_id = frame.id & (frame.extended ? CAN_EFF_MASK : CAN_SFF_MASK);
  if (frame.extended) {
    raw.can_id |= CAN_EFF_FLAG;
  }
  if (frame.error) {  // error-frame injection (vcan echoes it to every reader, like canerrsim)
    raw.can_id = CAN_ERR_FLAG | (frame.id & CAN_ERR_MASK);
  }
  size = CAN_MTU;
  if (frame.fd) {
    if (!fd_enabled_ || !proto::is_valid_fd_length(frame.len)) {
      return Status::invalid_argument;
    }
    size = CANFD_MTU;
    raw.flags = frame.bit_rate_switch ? CANFD_BRS : 0U;
  } else if (frame.len > proto::kClassicMaxLen) {
    return Status::invalid_argument;
  }
  raw.len = frame.len;
  std::copy_n(frame.data.begin(), frame.len, raw.data);
  return Status::ok;
}

Status SocketCanBus::send(const proto::CanFrame& frame) {
  if (fd_ < 0) {
    return Status::io_error;
  }
  canfd_frame raw{};
  std::size_t size = 0;
  if (const Status s = to_raw(frame, raw, size); s != Status::ok) {
    return s;
  }
  const ssize_t written = ::write(fd_, &raw, size);
  if (written < 0) {
    last_errno_ = errno;
    if (last_errno_ == ENOBUFS || last_errno_ == EAGAIN) {
      ++tx_dropped_;
      return Status::would_block;
    }
    return Status::io_error;
  }
  return static_cast<std::size_t>(written) == size ? Status::ok : Status::io_error;
}

std::size_t SocketCanBus::send_batch(std::span<const proto::CanFrame> frames) {
  if (fd_ < 0) {
    return 0;
  }
  std::array<canfd_frame, kBatchFrames> raw;
  std::array<iovec, kBatchFrames> iov{};
  std::array<mmsghdr, kBatchFrames> messages{};
  std::size_t sent = 0;
  while (sent < frames.size()) {
    // The next system call's frames: up to the batch's size, up to the first invalid frame.
    std::size_t count = 0;
    bool invalid = false;
    while (count < kBatchFrames && sent + count < frames.size()) {
      std::size_t size = 0;
      if (to_raw(frames[sent + count], raw[count], size) != Status::ok) {
        invalid = true;
        break;
      }
      iov[count] = iovec{&raw[count], size};
      messages[count] = mmsghdr{};
      messages[count].msg_hdr.msg_iov = &iov[count];
      messages[count].msg_hdr.msg_iovlen = 1;
      ++count;
    }
    // sendmmsg stops at the first message the socket refuses and reports how many went before
    // it; the refusal's errno comes from the call that starts with the refused message.
    std::size_t done = 0;
    while (done < count) {
      const int rc =
          ::sendmmsg(fd_, messages.data() + done, static_cast<unsigned int>(count - done), 0);
      if (rc < 0 && errno == EINTR) {
        continue;
      }
      if (rc <= 0) {
        last_errno_ = rc < 0 ? errno : EIO;
        if (last_errno_ == ENOBUFS || last_errno_ == EAGAIN) {
          tx_dropped_ += frames.size() - (sent + done);  // the refused frame and all after it
        }
        return sent + done;
      }
      for (std::size_t k = done; k < done + static_cast<std::size_t>(rc); ++k) {
        if (messages[k].msg_len != iov[k].iov_len) {  // a raw CAN socket takes all or nothing
          last_errno_ = EIO;
          return sent + k;
        }
      }
      done += static_cast<std::size_t>(rc);
    }
    sent += count;
    if (invalid) {
      return sent;
    }
  }
  return sent;
}

Status SocketCanBus::wait_until_ns(std::int64_t deadline_ns) {
  if (fd_ < 0) {
    return Status::io_error;
  }
  for (;;) {
    timespec now{};
    ::clock_gettime(CLOCK_MONOTONIC, &now);
    const std::int64_t left_ns =
        deadline_ns - (static_cast<std::int64_t>(now.tv_sec) * 1'000'000'000 + now.tv_nsec);
    const std::int64_t wait_ns = left_ns > 0 ? left_ns : 0;
    const timespec timeout{static_cast<time_t>(wait_ns / 1'000'000'000),
                           static_cast<long>(wait_ns % 1'000'000'000)};
    pollfd p{fd_, POLLIN, 0};
    const int rc = ::ppoll(&p, 1, &timeout, nullptr);
    if (rc > 0) {
      return Status::ok;
    }
    if (rc == 0) {
      return Status::would_block;
    }
    if (errno != EINTR) {
      last_errno_ = errno;
      return Status::io_error;
    }
  }
}

Status SocketCanBus::from_raw(const canfd_frame& raw, std::size_t got, msghdr& message,
                              proto::CanFrame& frame) {
  if (got != CAN_MTU && got != CANFD_MTU) {
    ++rx_malformed_;
    return Status::invalid_argument;
  }
  frame = proto::CanFrame{};
  frame.fd = got == CANFD_MTU;
  frame.extended = (raw.can_id & CAN_EFF_FLAG) != 0U;
  frame.error = (raw.can_id & CAN_ERR_FLAG) != 0U;
  frame.id = raw.can_id & (frame.extended || frame.error ? CAN_EFF_MASK : CAN_SFF_MASK);
  if (frame.error) {
    frame.extended = false;
    frame.id = raw.can_id & CAN_ERR_MASK;
    ++error_frames_;
    if ((frame.id & CAN_ERR_BUSOFF) != 0U) {
      bus_off_ = true;
    }
    if ((frame.id & CAN_ERR_RESTARTED) != 0U) {
      bus_off_ = false;
    }
  }
  frame.bit_rate_switch = frame.fd && (raw.flags & CANFD_BRS) != 0U;
  frame.len = std::min<std::uint8_t>(raw.len, frame.fd ? proto::kFdMaxLen : proto::kClassicMaxLen);
  std::copy_n(raw.data, frame.len, frame.data.begin());

  for (cmsghdr* c = CMSG_FIRSTHDR(&message); c != nullptr; c = CMSG_NXTHDR(&message, c)) {
    if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SO_RXQ_OVFL) {
      std::memcpy(&rx_overflows_, CMSG_DATA(c), sizeof(rx_overflows_));
    }
    if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SO_TIMESTAMPNS) {
      timespec ts{};
      std::memcpy(&ts, CMSG_DATA(c), sizeof(ts));
      frame.timestamp_ns = static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
    }
  }
  return Status::ok;
}

namespace {

// Room for a message's control data: its receive timestamp and the overflow count.
constexpr std::size_t kControlBytes =
    CMSG_SPACE(sizeof(timespec)) + CMSG_SPACE(sizeof(std::uint32_t));
struct alignas(cmsghdr) ControlBuffer {
  char bytes[kControlBytes];
};

}  // namespace

Status SocketCanBus::receive(proto::CanFrame& frame) {
  if (fd_ < 0) {
    return Status::io_error;
  }
  canfd_frame raw{};
  iovec iov{&raw, sizeof(raw)};
  ControlBuffer control;
  msghdr message{};
  message.msg_iov = &iov;
  message.msg_iovlen = 1;
  message.msg_control = control.bytes;
  message.msg_controllen = sizeof(control.bytes);

  const ssize_t got = ::recvmsg(fd_, &message, MSG_DONTWAIT);
  if (got < 0) {
    last_errno_ = errno;
    return (last_errno_ == EAGAIN || last_errno_ == EWOULDBLOCK) ? Status::would_block
                                                                 : Status::io_error;
  }
  return from_raw(raw, static_cast<std::size_t>(got), message, frame);
}

std::size_t SocketCanBus::receive_batch(std::span<proto::CanFrame> frames) {
  if (fd_ < 0) {
    return 0;
  }
  std::array<canfd_frame, kBatchFrames> raw;
  std::array<iovec, kBatchFrames> iov{};
  std::array<ControlBuffer, kBatchFrames> control;
  std::array<mmsghdr, kBatchFrames> messages{};
  std::size_t taken = 0;
  while (taken < frames.size()) {
    const std::size_t ask = std::min(kBatchFrames, frames.size() - taken);
    for (std::size_t k = 0; k < ask; ++k) {
      iov[k] = iovec{&raw[k], sizeof(canfd_frame)};
      messages[k] = mmsghdr{};
      messages[k].msg_hdr.msg_iov = &iov[k];
      messages[k].msg_hdr.msg_iovlen = 1;
      messages[k].msg_hdr.msg_control = control[k].bytes;
      messages[k].msg_hdr.msg_controllen = sizeof(control[k].bytes);
    }
    const int rc =
        ::recvmmsg(fd_, messages.data(), static_cast<unsigned int>(ask), MSG_DONTWAIT, nullptr);
    if (rc < 0) {
      if (errno == EINTR) {
        continue;
      }
      if (errno != EAGAIN && errno != EWOULDBLOCK) {
        last_errno_ = errno;
      }
      return taken;
    }
    for (std::size_t k = 0; k < static_cast<std::size_t>(rc); ++k) {
      if (from_raw(raw[k], messages[k].msg_len, messages[k].msg_hdr, frames[taken]) == Status::ok) {
        ++taken;
      }
    }
    if (static_cast<std::size_t>(rc) < ask) {
      return taken;  // the queue is empty
    }
  }
  return taken;
}

}  // namespace tread::hal
