#pragma once
// The codec's internals, shared by codec.cpp (which looks up each signal's field per frame) and
// field_map.cpp (which looks them up once, at init): the field of a data model that a signal
// carries (the role table's look-up, role_table.hpp) and the float or integer-only scaling.

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

#include "proto/can_frame.hpp"
#include "proto/data_model.hpp"
#include "proto/messages.hpp"
#include "proto/role_table.hpp"
#include "proto/signal.hpp"
#include "proto/signal_fixed.hpp"

namespace tread::proto::detail {

/// The wheel / wheelset / rail wheel index of signal `s` in message `m`, within [0, count).
inline std::size_t index_of(const MessageSpec& m, const SignalSpec& s, std::size_t count) noexcept {
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

/// Calls fn(field) with the field of `d` that signal `s` of message `m` carries, if `d` has one.
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

/// `frame` cleared and given the message's identifier, length and FD flags; its payload bytes.
inline std::span<std::uint8_t> start_frame(const MessageSpec& message, CanFrame& frame) noexcept {
  frame = CanFrame{};
  frame.id = message.id;
  frame.fd = message.fd;
  frame.bit_rate_switch = message.fd;
  frame.len = message.len;
  return {frame.data.data(), frame.len};
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

}  // namespace tread::proto::detail
