#include "proto/codec.hpp"

#include <array>
#include <concepts>
#include <type_traits>
#include <utility>

#include "proto/e2e_profile1.hpp"
#include "proto/signal_fixed.hpp"

namespace tread::proto {
namespace {

std::size_t index_of(const MessageSpec& m, const SignalSpec& s, std::size_t count) noexcept {
  const std::int8_t i = m.instance_of(s);
  const auto idx = static_cast<std::size_t>(i < 0 ? 0 : i);
  return idx < count ? idx : count - 1U;
}

// Where each role's physical (float) value lives in the data model: a member of a wheel, of a
// wheelset or of a rail wheel (or none: an integer-valued role). Tables indexed by role, built at
// compile time, so the per-signal lookup is a load instead of a switch.
template <typename S, typename Wheel, typename Wheelset, typename RailWheel>
struct FloatMember {
  S Wheel::*wheel = nullptr;
  S Wheelset::*wheelset = nullptr;
  S RailWheel::*rail_wheel = nullptr;
};

/// The rig's data has no rail-wheel outputs: a placeholder type for the unused member.
template <typename S>
struct NoRailWheel {
  S unused{};
};

template <typename S>
using RigMember = FloatMember<S, BasicWheelInput<S>, BasicWheelsetInput<S>, NoRailWheel<S>>;
template <typename S>
using NodeMember =
    FloatMember<S, BasicWheelOutput<S>, BasicWheelsetOutput<S>, BasicRailWheelOutput<S>>;

template <typename S>
constexpr RigMember<S> rig_member(Role role) noexcept {
  using WheelInput = BasicWheelInput<S>;
  using WheelsetInput = BasicWheelsetInput<S>;
  switch (role) {
    case Role::kappa:
      return {&WheelInput::kappa, nullptr};
    case Role::alpha:
      return {&WheelInput::alpha_rad, nullptr};
    case Role::gamma:
      return {&WheelInput::gamma_rad, nullptr};
    case Role::fz:
      return {&WheelInput::fz_n, nullptr};
    case Role::vx:
      return {&WheelInput::vx_mps, nullptr};
    case Role::omega:
      return {&WheelInput::omega_radps, nullptr};
    case Role::ws_lateral:
      return {nullptr, &WheelsetInput::lateral_mm};
    case Role::ws_yaw:
      return {nullptr, &WheelsetInput::yaw_rad};
    case Role::ws_speed:
      return {nullptr, &WheelsetInput::speed_mps};
    case Role::ws_lateral_velocity:
      return {nullptr, &WheelsetInput::lateral_velocity_mps};
    case Role::ws_yaw_rate:
      return {nullptr, &WheelsetInput::yaw_rate_radps};
    case Role::ws_load_left:
      return {nullptr, &WheelsetInput::load_left_n};
    case Role::ws_load_right:
      return {nullptr, &WheelsetInput::load_right_n};
    default:
      return {};
  }
}

template <typename S>
constexpr NodeMember<S> node_member(Role role) noexcept {
  using WheelOutput = BasicWheelOutput<S>;
  using WheelsetOutput = BasicWheelsetOutput<S>;
  using RailWheelOutput = BasicRailWheelOutput<S>;
  switch (role) {
    case Role::fx:
      return {&WheelOutput::fx_n, nullptr};
    case Role::fy:
      return {&WheelOutput::fy_n, nullptr};
    case Role::mz:
      return {&WheelOutput::mz_nm, nullptr};
    case Role::mx:
      return {&WheelOutput::mx_nm, nullptr};
    case Role::my:
      return {&WheelOutput::my_nm, nullptr};
    case Role::rl:
      return {&WheelOutput::rl_m, nullptr};
    case Role::r_left:
      return {nullptr, &WheelsetOutput::r_left_mm};
    case Role::r_right:
      return {nullptr, &WheelsetOutput::r_right_mm};
    case Role::delta_r:
      return {nullptr, &WheelsetOutput::delta_r_mm};
    case Role::gamma_left:
      return {nullptr, &WheelsetOutput::gamma_left_rad};
    case Role::gamma_right:
      return {nullptr, &WheelsetOutput::gamma_right_rad};
    case Role::rw_fx:
      return {nullptr, nullptr, &RailWheelOutput::fx_n};
    case Role::rw_y:
      return {nullptr, nullptr, &RailWheelOutput::y_n};
    case Role::rw_q:
      return {nullptr, nullptr, &RailWheelOutput::q_n};
    case Role::rw_mz:
      return {nullptr, nullptr, &RailWheelOutput::mz_nm};
    case Role::rw_n1:
      return {nullptr, nullptr, &RailWheelOutput::n1_n};
    case Role::rw_n2:
      return {nullptr, nullptr, &RailWheelOutput::n2_n};
    case Role::rw_y_over_q:
      return {nullptr, nullptr, &RailWheelOutput::y_over_q};
    case Role::rw_nadal_margin:
      return {nullptr, nullptr, &RailWheelOutput::nadal_margin};
    default:
      return {};
  }
}

template <typename Member, Member (*member_of)(Role)>
constexpr std::array<Member, kRoleCount> make_members() noexcept {
  std::array<Member, kRoleCount> table{};
  for (std::size_t r = 0; r < kRoleCount; ++r) table[r] = member_of(static_cast<Role>(r));
  return table;
}

template <typename S>
constexpr auto kRigMembers = make_members<RigMember<S>, rig_member<S>>();
template <typename S>
constexpr auto kNodeMembers = make_members<NodeMember<S>, node_member<S>>();

template <typename D>
inline constexpr bool kIsRigData = std::same_as<std::remove_const_t<D>, RigData> ||
                                   std::same_as<std::remove_const_t<D>, RigDataFixed>;
template <typename D>
inline constexpr bool kIsNodeData = std::same_as<std::remove_const_t<D>, NodeData> ||
                                    std::same_as<std::remove_const_t<D>, NodeDataFixed>;

/// The scalar of a data model (float or fixed::Fixed64).
template <typename D>
using ScalarOf = std::remove_cvref_t<decltype(std::declval<D&>().wheels[0].fx_n)>;

template <typename D>
constexpr const auto& members_for() noexcept {
  if constexpr (kIsRigData<D>) {
    return kRigMembers<std::remove_cvref_t<decltype(std::declval<D&>().wheels[0].kappa)>>;
  } else {
    return kNodeMembers<ScalarOf<D>>;
  }
}

// A physical (float) field of the data model, or nullptr for integer-valued roles.
template <typename D>
requires kIsRigData<D> || kIsNodeData<D>
auto float_field(D& d, const MessageSpec& m, const SignalSpec& s) noexcept
    -> decltype(&(d.wheels[0].*members_for<D>()[0].wheel)) {
  const auto& member = members_for<D>()[static_cast<std::size_t>(s.role)];
  if (member.wheel != nullptr) {
    return &(d.wheels[index_of(m, s, kMaxWheels)].*member.wheel);
  }
  if (member.wheelset != nullptr) {
    return &(d.wheelsets[index_of(m, s, kMaxWheelsets)].*member.wheelset);
  }
  if constexpr (kIsNodeData<D>) {
    if (member.rail_wheel != nullptr) {
      return &(d.rail_wheels[index_of(m, s, kMaxRailWheels)].*member.rail_wheel);
    }
  }
  return nullptr;
}

// Integer-valued roles: read (get) or write (set) through one accessor.
template <typename D, typename Visit>
requires kIsRigData<D>
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
requires kIsNodeData<D>
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
    case Role::rw_status:
      visit(d.rail_wheels[index_of(m, s, kMaxRailWheels)].status);
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
    if (const auto* f = float_field(data, message, s); f != nullptr) {
      if (encode_physical(s, *f, bytes) != Status::ok) {
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
    if (auto* f = float_field(data, message, s); f != nullptr) {
      *f = decode_physical<std::remove_cvref_t<decltype(*f)>>(s, bytes);
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
