#include "proto/codec.hpp"

#include <concepts>
#include <cstdint>
#include <type_traits>

#include "proto/e2e_profile1.hpp"
#include "proto/role_table.hpp"
#include "proto/signal_fixed.hpp"

namespace tread::proto {
namespace {

std::size_t index_of(const MessageSpec& m, const SignalSpec& s, std::size_t count) noexcept {
  const std::int8_t i = m.instance_of(s);
  const auto idx = static_cast<std::size_t>(i < 0 ? 0 : i);
  return idx < count ? idx : count - 1U;
}

/// The scalar of a data model (float or fixed::Fixed64).
template <typename D>
struct scalar_of;
template <typename S>
struct scalar_of<BasicRigData<S>> {
  using type = S;
};
template <typename S>
struct scalar_of<BasicNodeData<S>> {
  using type = S;
};
template <typename D>
using ScalarOf = typename scalar_of<std::remove_const_t<D>>::type;

/// Calls fn(field) when `member` is a member of `object` (a row of the other direction is not).
template <typename Object, typename Member, typename Fn>
void apply_member(Object& object, Member member, Fn& fn) noexcept {
  if constexpr (requires { object.*member; }) {
    fn(object.*member);
  }
}

/// Calls fn(field) with the field of `d` that signal `s` of message `m` carries (role_table.hpp),
/// if `d` has one.
template <typename D, typename Fn>
void with_field(D& d, const MessageSpec& m, const SignalSpec& s, Fn&& fn) noexcept {
  visit_role<ScalarOf<D>>(s.role, [&](const auto& row) {
    constexpr RoleScope scope = std::remove_cvref_t<decltype(row)>::scope;
    if constexpr (scope == RoleScope::wheel) {
      apply_member(d.wheels[index_of(m, s, kMaxWheels)], row.member, fn);
    } else if constexpr (scope == RoleScope::wheelset || scope == RoleScope::wheelset_motion) {
      apply_member(d.wheelsets[index_of(m, s, kMaxWheelsets)], row.member, fn);
    } else if constexpr (scope == RoleScope::rail_wheel) {
      if constexpr (requires { d.rail_wheels; }) {
        apply_member(d.rail_wheels[index_of(m, s, kMaxRailWheels)], row.member, fn);
      }
    } else if constexpr (scope == RoleScope::rig) {
      apply_member(d, row.member, fn);
    } else if constexpr (scope == RoleScope::command) {
      if constexpr (requires { d.command; }) {
        apply_member(d.command, row.member, fn);
      }
    } else if constexpr (scope == RoleScope::node_status) {
      if constexpr (requires { d.status; }) {
        apply_member(d.status, row.member, fn);
      }
    }
  });
}

// The float or the integer-only route, by the data model's scalar.
inline Status encode_physical(const SignalSpec& s, float v, std::span<std::uint8_t> b) noexcept {
  return encode_signal(s, v, b);
}
inline Status encode_physical(const SignalSpec& s, fixed::Fixed64 v,
                              std::span<std::uint8_t> b) noexcept {
  return encode_signal_fixed(s, v, b);
}
template <typename S>
S decode_physical(const SignalSpec& s, std::span<const std::uint8_t> b) noexcept {
  if constexpr (std::same_as<S, fixed::Fixed64>) {
    return decode_signal_fixed(s, b);
  } else {
    return decode_signal(s, b);
  }
}

template <typename Data>
Status encode_impl(const MessageSpec& message, const Data& data, std::uint8_t counter,
                   CanFrame& frame) noexcept {
  frame = CanFrame{};
  frame.id = message.id;
  frame.fd = message.fd;
  frame.bit_rate_switch = message.fd;
  frame.len = message.len;
  const std::span<std::uint8_t> bytes(frame.data.data(), frame.len);
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
