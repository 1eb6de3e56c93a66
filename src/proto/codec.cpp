#include "proto/codec.hpp"

#include <concepts>
#include <type_traits>

#include "proto/e2e_profile1.hpp"

namespace tread::proto {
namespace {

std::size_t index_of(const MessageSpec& m, const SignalSpec& s, std::size_t count) noexcept {
  const std::int8_t i = m.instance_of(s);
  const auto idx = static_cast<std::size_t>(i < 0 ? 0 : i);
  return idx < count ? idx : count - 1U;
}

// A physical (float) field of the data model, or nullptr for integer-valued roles.
template <typename D>
requires std::same_as<std::remove_const_t<D>, RigData>
auto float_field(D& d, const MessageSpec& m, const SignalSpec& s) noexcept
    -> decltype(&d.wheels[0].kappa) {
  auto& w = d.wheels[index_of(m, s, kMaxWheels)];
  auto& ws = d.wheelsets[index_of(m, s, kMaxWheelsets)];
  switch (s.role) {
    case Role::kappa:
      return &w.kappa;
    case Role::alpha:
      return &w.alpha_rad;
    case Role::gamma:
      return &w.gamma_rad;
    case Role::fz:
      return &w.fz_n;
    case Role::vx:
      return &w.vx_mps;
    case Role::omega:
      return &w.omega_radps;
    case Role::ws_lateral:
      return &ws.lateral_mm;
    case Role::ws_yaw:
      return &ws.yaw_rad;
    default:
      return nullptr;
  }
}

template <typename D>
requires std::same_as<std::remove_const_t<D>, NodeData>
auto float_field(D& d, const MessageSpec& m, const SignalSpec& s) noexcept
    -> decltype(&d.wheels[0].fx_n) {
  auto& w = d.wheels[index_of(m, s, kMaxWheels)];
  auto& ws = d.wheelsets[index_of(m, s, kMaxWheelsets)];
  switch (s.role) {
    case Role::fx:
      return &w.fx_n;
    case Role::fy:
      return &w.fy_n;
    case Role::mz:
      return &w.mz_nm;
    case Role::mx:
      return &w.mx_nm;
    case Role::my:
      return &w.my_nm;
    case Role::rl:
      return &w.rl_m;
    case Role::r_left:
      return &ws.r_left_mm;
    case Role::r_right:
      return &ws.r_right_mm;
    case Role::delta_r:
      return &ws.delta_r_mm;
    case Role::gamma_left:
      return &ws.gamma_left_rad;
    case Role::gamma_right:
      return &ws.gamma_right_rad;
    default:
      return nullptr;
  }
}

// Integer-valued roles: read (get) or write (set) through one accessor.
template <typename D, typename Visit>
requires std::same_as<std::remove_const_t<D>, RigData>
void int_field(D& d, const MessageSpec& m, const SignalSpec& s, Visit&& visit) noexcept {
  auto& w = d.wheels[index_of(m, s, kMaxWheels)];
  auto& ws = d.wheelsets[index_of(m, s, kMaxWheelsets)];
  switch (s.role) {
    case Role::omega_valid:
      visit(w.omega_valid);
      break;
    case Role::ws_yaw_valid:
      visit(ws.yaw_valid);
      break;
    case Role::rig_cycle:
      visit(d.rig_cycle);
      break;
    case Role::cmd_enable:
      visit(d.command.enable);
      break;
    case Role::cmd_reset:
      visit(d.command.reset);
      break;
    case Role::cmd_tyre_set:
      visit(d.command.tyre_set);
      break;
    case Role::cmd_profile_set:
      visit(d.command.profile_set);
      break;
    default:
      break;
  }
}

template <typename D, typename Visit>
requires std::same_as<std::remove_const_t<D>, NodeData>
void int_field(D& d, const MessageSpec& m, const SignalSpec& s, Visit&& visit) noexcept {
  auto& w = d.wheels[index_of(m, s, kMaxWheels)];
  auto& ws = d.wheelsets[index_of(m, s, kMaxWheelsets)];
  switch (s.role) {
    case Role::wheel_status:
      visit(w.status);
      break;
    case Role::ws_status:
      visit(ws.status);
      break;
    case Role::node_state:
      visit(d.status.state);
      break;
    case Role::node_cycle:
      visit(d.status.cycle);
      break;
    case Role::node_overruns:
      visit(d.status.overruns);
      break;
    case Role::node_rejected:
      visit(d.status.rejected);
      break;
    case Role::node_stale_mask:
      visit(d.status.stale_mask);
      break;
    case Role::node_clamp_mask:
      visit(d.status.clamp_mask);
      break;
    default:
      break;
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
    if (const float* f = float_field(data, message, s); f != nullptr) {
      if (encode_signal(s, *f, bytes) != Status::ok) {
        status = Status::out_of_range;
      }
      continue;
    }
    std::int64_t raw = 0;
    int_field(data, message, s, [&raw](auto& field) { raw = static_cast<std::int64_t>(field); });
    if (encode_raw_signal(s, raw, bytes) != Status::ok) {
      status = Status::out_of_range;
    }
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
    if (float* f = float_field(data, message, s); f != nullptr) {
      *f = decode_signal(s, bytes);
      continue;
    }
    const std::int64_t raw = decode_raw_signal(s, bytes);
    int_field(data, message, s, [raw](auto& field) {
      field = static_cast<std::remove_reference_t<decltype(field)>>(raw);
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

}  // namespace tread::proto
