#pragma once
// Writes the protocol's message catalogue (src/proto/messages.hpp) as a DBC file.

#include <string>

#include "proto/messages.hpp"

namespace tread::host {

/// The DBC text of `layout`: nodes Rig and Node, every message and signal with its scaling, range,
/// unit and comment, and for the FD layout the VFrameFormat/BusType attributes.
std::string write_dbc(proto::Layout layout);

/// "Kappa_2" for instanced signals, "Kappa" otherwise.
std::string signal_name(const proto::SignalSpec& signal);
/// "WheelSlip_2" for instanced messages, "Command" otherwise.
std::string message_name(const proto::MessageSpec& message);

}  // namespace tread::host
