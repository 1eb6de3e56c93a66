#pragma once
// Table-driven codec: moves values between the protocol's data model and CAN frames, for any
// message of either layout (messages.hpp), and applies the E2E protection (e2e_profile1.hpp).

#include <cstdint>

#include "core/status.hpp"
#include "proto/can_frame.hpp"
#include "proto/data_model.hpp"
#include "proto/messages.hpp"

namespace tread::proto {

/// Fills `frame` (id, length, FD flag, payload) from `data`, then writes counter and CRC.
/// @retval Status::ok            every signal fitted
/// @retval Status::out_of_range  at least one signal saturated (or was not finite); still encoded
/// @retval Status::invalid_argument  the message is not rig_to_node
Status encode(const MessageSpec& message, const RigData& data, std::uint8_t counter,
              CanFrame& frame) noexcept;
/// As above for node_to_rig messages.
Status encode(const MessageSpec& message, const NodeData& data, std::uint8_t counter,
              CanFrame& frame) noexcept;

/// Copies the signals `message` carries from `frame` into `data` (other fields untouched).
/// No E2E check here: see e2e_check.
/// @retval Status::invalid_argument  wrong length or direction
Status decode(const MessageSpec& message, const CanFrame& frame, RigData& data) noexcept;
Status decode(const MessageSpec& message, const CanFrame& frame, NodeData& data) noexcept;

/// The same on the fixed-point data model (no float on the way).
Status encode(const MessageSpec& message, const RigDataFixed& data, std::uint8_t counter,
              CanFrame& frame) noexcept;
Status encode(const MessageSpec& message, const NodeDataFixed& data, std::uint8_t counter,
              CanFrame& frame) noexcept;
Status decode(const MessageSpec& message, const CanFrame& frame, RigDataFixed& data) noexcept;
Status decode(const MessageSpec& message, const CanFrame& frame, NodeDataFixed& data) noexcept;

}  // namespace tread::proto
