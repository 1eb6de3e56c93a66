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
      tx_dropped_(other.tx_dropped_) {}

SocketCanBus& SocketCanBus::operator=(SocketCanBus&& other) noexcept {
  if (this != &other) {
    close();
    fd_ = std::exchange(other.fd_, -1);
    fd_enabled_ = other.fd_enabled_;
    last_errno_ = other.last_errno_;
    tx_dropped_ = other.tx_dropped_;
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

Status SocketCanBus::send(const proto::CanFrame& frame) {
  if (fd_ < 0) {
    return Status::io_error;
  }
  canfd_frame raw{};
  raw.can_id = frame.id & (frame.extended ? CAN_EFF_MASK : CAN_SFF_MASK);
  if (frame.extended) {
    raw.can_id |= CAN_EFF_FLAG;
  }
  if (frame.error) {  // error-frame injection (vcan echoes it to every reader, like canerrsim)
    raw.can_id = CAN_ERR_FLAG | (frame.id & CAN_ERR_MASK);
  }
  std::size_t size = CAN_MTU;
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

Status SocketCanBus::receive(proto::CanFrame& frame) {
  if (fd_ < 0) {
    return Status::io_error;
  }
  canfd_frame raw{};
  iovec iov{&raw, sizeof(raw)};
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(timespec)) + CMSG_SPACE(sizeof(std::uint32_t))];
  msghdr message{};
  message.msg_iov = &iov;
  message.msg_iovlen = 1;
  message.msg_control = control;
  message.msg_controllen = sizeof(control);

  const ssize_t got = ::recvmsg(fd_, &message, MSG_DONTWAIT);
  if (got < 0) {
    last_errno_ = errno;
    return (last_errno_ == EAGAIN || last_errno_ == EWOULDBLOCK) ? Status::would_block
                                                                 : Status::io_error;
  }
  if (static_cast<std::size_t>(got) != CAN_MTU && static_cast<std::size_t>(got) != CANFD_MTU) {
    return Status::invalid_argument;
  }
  frame = proto::CanFrame{};
  frame.fd = static_cast<std::size_t>(got) == CANFD_MTU;
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

}  // namespace tread::hal
