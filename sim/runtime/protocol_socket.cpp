#include "runtime/protocol_socket.hpp"

#include <cerrno>
#include <stdexcept>
#include <vector>

#include "core/status.hpp"

namespace tread::host {

void open_protocol_socket(hal::SocketCanBus& bus, const std::string& interface,
                          proto::Layout layout, proto::Direction incoming,
                          const char* no_socketcan_advice, int receive_buffer_bytes) {
  const bool fd = layout == proto::Layout::fd;
  const Status opened = bus.open(interface, fd);
  if (opened == Status::unsupported && bus.last_errno() == EAFNOSUPPORT) {
    throw std::runtime_error(
        std::string("SocketCAN is not available in this kernel (socket(AF_CAN) refused); ") +
        no_socketcan_advice);
  }
  if (opened != Status::ok) {
    throw std::runtime_error("cannot open CAN interface '" + interface + "' (" + to_string(opened) +
                             ", errno " + std::to_string(bus.last_errno()) +
                             (fd ? "; is its mtu 72 for CAN FD?" : "") + ")");
  }
  std::vector<hal::CanIdFilter> filters;
  for (const proto::MessageSpec& m : proto::messages(layout)) {
    if (m.direction == incoming) {
      filters.push_back({m.id, 0x7FF, false});
    }
  }
  if (bus.set_filters(filters) != Status::ok) {
    throw std::runtime_error("cannot install CAN ID filters on " + interface + " (errno " +
                             std::to_string(bus.last_errno()) + ")");
  }
  if (bus.set_receive_buffer(receive_buffer_bytes) != Status::ok) {
    throw std::runtime_error("cannot set the receive buffer of the socket on " + interface +
                             " (errno " + std::to_string(bus.last_errno()) + ")");
  }
}

}  // namespace tread::host
