#include "proto/codec.hpp"

#include <concepts>
#include <cstdint>
#include <type_traits>

#include "proto/codec_detail.hpp"
#include "proto/e2e_profile1.hpp"

namespace tread::proto {
namespace {

using detail::decode_physical;
using detail::encode_physical;
using detail::ScalarOf;
using detail::with_field;

template <typename Data>
Status encode_impl(const MessageSpec& message, const Data& data, std::uint8_t counter,
                   CanFrame& frame) noexcept {
  const std::span<std::uint8_t> bytes = detail::start_frame(message, frame);
  Status status = Status::ok;
  for (const SignalSpec& s : message.signals) {
    if (s.role == Role::crc || s.role == Role::counter) {
      continue;
    }
    with_field(data, message, s, [&](const auto& field) {
      Status fitted = Status::ok;
      if constexpr (std::same_as<std::remove_cvref_t<decltype(field)>, ScalarOf<Data>>) {
        fitted = encode_physical(s, field, bytes);
      } else {
        fitted = encode_raw_signal(s, static_cast<std::int64_t>(field), bytes);
      }
      if (fitted != Status::ok) {
        status = Status::out_of_range;
      }
    });
  }
  e2e_protect(frame, message.data_id(), counter);
  return status;
}

template <typename Data>
Status decode_impl(const MessageSpec& message, const CanFrame& frame, Data& data) noexcept {
  if (frame.len != message.len || frame.fd != message.fd) {
    return Status::invalid_argument;
  }
  const std::span<const std::uint8_t> bytes(frame.data.data(), frame.len);
  for (const SignalSpec& s : message.signals) {
    if (s.role == Role::crc || s.role == Role::counter) {
      continue;
    }
    with_field(data, message, s, [&](auto& field) {
      using Field = std::remove_reference_t<decltype(field)>;
      if constexpr (std::same_as<Field, ScalarOf<Data>>) {
        field = decode_physical<Field>(s, bytes);
      } else {
        field = static_cast<Field>(decode_raw_signal(s, bytes));
      }
    });
  }
  return Status::ok;
}

}  // namespace

Status encode(const MessageSpec& message, const RigData& data, std::uint8_t counter,
              CanFrame& frame) noexcept {
  if (message.direction != Direction::rig_to_node) {
    return Status::invalid_argument;
  }
  return encode_impl(message, data, counter, frame);
}

Status encode(const MessageSpec& message, const NodeData& data, std::uint8_t counter,
              CanFrame& frame) noexcept {
  if (message.direction != Direction::node_to_rig) {
    return Status::invalid_argument;
  }
  return encode_impl(message, data, counter, frame);
}

Status decode(const MessageSpec& message, const CanFrame& frame, RigData& data) noexcept {
  if (message.direction != Direction::rig_to_node) {
    return Status::invalid_argument;
  }
  return decode_impl(message, frame, data);
}

Status decode(const MessageSpec& message, const CanFrame& frame, NodeData& data) noexcept {
  if (message.direction != Direction::node_to_rig) {
    return Status::invalid_argument;
  }
  return decode_impl(message, frame, data);
}

Status encode(const MessageSpec& message, const RigDataFixed& data, std::uint8_t counter,
              CanFrame& frame) noexcept {
  if (message.direction != Direction::rig_to_node) {
    return Status::invalid_argument;
  }
  return encode_impl(message, data, counter, frame);
}

Status encode(const MessageSpec& message, const NodeDataFixed& data, std::uint8_t counter,
              CanFrame& frame) noexcept {
  if (message.direction != Direction::node_to_rig) {
    return Status::invalid_argument;
  }
  return encode_impl(message, data, counter, frame);
}

Status decode(const MessageSpec& message, const CanFrame& frame, RigDataFixed& data) noexcept {
  if (message.direction != Direction::rig_to_node) {
    return Status::invalid_argument;
  }
  return decode_impl(message, frame, data);
}

Status decode(const MessageSpec& message, const CanFrame& frame, NodeDataFixed& data) noexcept {
  if (message.direction != Direction::node_to_rig) {
    return Status::invalid_argument;
  }
  return decode_impl(message, frame, data);
}

}  // namespace tread::proto
