#pragma once
// A SocketCAN socket for one end of the protocol (the node or the rig), set up the one way both
// use: opened (FD if the layout is), kernel ID filters that pass only the frames this end receives
// (every other frame — a flood, foreign traffic — is dropped before it reaches this socket's
// queue), and an explicit receive buffer, so how much a burst may queue is known, not whatever the
// system default is. Overflows of that queue are counted by the kernel (SO_RXQ_OVFL) and read
// with SocketCanBus::rx_overflows().

#include <string>

#include "proto/messages.hpp"
#include "socketcan/socketcan_bus.hpp"

namespace tread::host {

/// The receive buffer both ends ask for (the kernel doubles it for its bookkeeping and caps the
/// request at net.core.rmem_max; receive_buffer_bytes() reports what it granted).
inline constexpr int kProtocolReceiveBufferBytes = 1 << 20;

/// What to do without SocketCAN, for the commands that have an in-process bus (node, demo).
inline constexpr const char* kNoSocketCanAdvice =
    "use --can stub, or run in the VM harness (scripts/vm/run-in-vm.sh)";

/// Opens `interface` for the end that receives `incoming` frames. Throws std::runtime_error naming
/// the interface: no SocketCAN in the kernel (with `no_socketcan_advice`), no such interface (or no
/// FD on it), filters or buffer refused.
void open_protocol_socket(hal::SocketCanBus& bus, const std::string& interface,
                          proto::Layout layout, proto::Direction incoming,
                          const char* no_socketcan_advice = kNoSocketCanAdvice,
                          int receive_buffer_bytes = kProtocolReceiveBufferBytes);

}  // namespace tread::host
