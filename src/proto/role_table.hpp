#pragma once
// What each signal role means, written once: the member of the data model (data_model.hpp) that
// holds its value, the object that member belongs to (a wheel, a wheelset, a rail wheel, the rig's
// data, its command, the node's status), and its DBC comment. Whether a role is scaled or an
// integer follows from the member's type: the scalar (float, fixed::Fixed64) is scaled, a flag,
// counter or mask is not. The codec, the node, the frame comparison and the DBC writer read it.
//
// A member pointer's type names its struct and field type, so the rows differ in type: the table
// is a std::tuple per scalar, built at compile time. visit_role() hands the row of a role to a
// function; role_scope(), is_integer_role() and role_comment() are constexpr lookups made from the
// same rows. No heap, no RTTI, no exceptions.

#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>

#include "fixed/fixed64.hpp"
#include "proto/data_model.hpp"
#include "proto/signal_role.hpp"

namespace tread::proto {

/// The object of the data model a role's member belongs to, and so the channel it concerns.
enum class RoleScope : std::uint8_t {
  e2e,              ///< the E2E header (CRC, counter): written by e2e_protect, in no data model
  wheel,            ///< wheels[i], i the signal's instance
  wheelset,         ///< wheelsets[j]: geometry inputs (both of its channels use them) and outputs
  wheelset_motion,  ///< wheelsets[j]: motion and wheel loads, inputs of its wheel-rail forces only
  rail_wheel,       ///< rail_wheels[2 j + side]
  rig,              ///< the rig's data itself
  command,          ///< the rig's command
  node_status,      ///< the node's status
};

/// One role: `member` points into the scope's object (std::nullptr_t for the E2E header).
template <RoleScope Scope, typename Member>
struct RoleRow {
  static constexpr RoleScope scope = Scope;
  Role role;
  Member member;
  const char* comment;  ///< the DBC comment of its signals
};

template <RoleScope Scope, typename Member>
constexpr RoleRow<Scope, Member> role_row(Role role, Member member, const char* comment) noexcept {
  return {role, member, comment};
}

/// The field type a member pointer points to (std::nullptr_t for none).
template <typename Member>
struct member_value {
  using type = std::nullptr_t;
};
template <typename T, typename C>
struct member_value<T C::*> {
  using type = T;
};

/// Every role in the order of the Role enum, for the data model of scalar S.
template <typename S>
constexpr auto make_role_table() noexcept {
  using RoleScope::command;
  using RoleScope::e2e;
  using RoleScope::node_status;
  using RoleScope::rail_wheel;
  using RoleScope::rig;
  using RoleScope::wheel;
  using RoleScope::wheelset;
  using RoleScope::wheelset_motion;
  using WheelIn = BasicWheelInput<S>;
  using WheelsetIn = BasicWheelsetInput<S>;
  using WheelOut = BasicWheelOutput<S>;
  using WheelsetOut = BasicWheelsetOutput<S>;
  using RailWheelOut = BasicRailWheelOutput<S>;
  constexpr const char* kStatusBits =
      "bit0 stale, bit1 input clamped (outside table), bit2 disabled, bit3 saturated";
  return std::tuple{
      role_row<e2e>(Role::crc, nullptr,
                    "E2E CRC-8/SAE-J1850 over data ID (low, high byte) and bytes 1..n-1"),
      role_row<e2e>(Role::counter, nullptr, "E2E alive counter 0..14"),
      // rig -> node
      role_row<wheel>(Role::kappa, &WheelIn::kappa, "longitudinal slip ratio"),
      role_row<wheel>(Role::alpha, &WheelIn::alpha_rad, "slip angle (ISO-W)"),
      role_row<wheel>(Role::gamma, &WheelIn::gamma_rad, "inclination (camber) angle"),
      role_row<wheel>(Role::fz, &WheelIn::fz_n, "vertical load"),
      role_row<wheel>(Role::vx, &WheelIn::vx_mps, "longitudinal speed of the wheel centre"),
      role_row<wheel>(Role::omega, &WheelIn::omega_radps, "wheel spin rate (valid if OmegaValid)"),
      role_row<wheel>(Role::omega_valid, &WheelIn::omega_valid, "1: Omega carries a value"),
      role_row<wheelset>(Role::ws_lateral, &WheelsetIn::lateral_mm,
                         "wheelset lateral displacement, + toward the left rail"),
      role_row<wheelset>(Role::ws_yaw, &WheelsetIn::yaw_rad,
                         "wheelset yaw angle (valid if YawValid)"),
      role_row<wheelset>(Role::ws_yaw_valid, &WheelsetIn::yaw_valid, "1: Yaw carries a value"),
      role_row<rig>(Role::rig_cycle, &BasicRigData<S>::rig_cycle,
                    "rig cycle number; in sync mode the node computes when this arrives"),
      role_row<command>(Role::cmd_enable, &Command::enable, "1: node computes and sends outputs"),
      role_row<command>(Role::cmd_reset, &Command::reset, "1: reset transient states and counters"),
      role_row<command>(Role::cmd_tyre_set, &Command::tyre_set, "tyre parameter set to use"),
      role_row<command>(Role::cmd_profile_set, &Command::profile_set,
                        "wheel/rail profile set to use"),
      // node -> rig
      role_row<wheel>(Role::fx, &WheelOut::fx_n, "longitudinal force (ISO-W)"),
      role_row<wheel>(Role::fy, &WheelOut::fy_n, "lateral force (ISO-W)"),
      role_row<wheel>(Role::mz, &WheelOut::mz_nm, "self-aligning moment"),
      role_row<wheel>(Role::mx, &WheelOut::mx_nm, "overturning moment"),
      role_row<wheel>(Role::my, &WheelOut::my_nm, "rolling resistance moment"),
      role_row<wheel>(Role::rl, &WheelOut::rl_m, "loaded radius"),
      role_row<wheel>(Role::wheel_status, &WheelOut::status,
                      "bit0 stale, bit1 input clamped, bit2 disabled, bit3 output saturated"),
      role_row<wheelset>(Role::r_left, &WheelsetOut::r_left_mm,
                         "rolling radius of the left wheel at its contact point"),
      role_row<wheelset>(Role::r_right, &WheelsetOut::r_right_mm,
                         "rolling radius of the right wheel at its contact point"),
      role_row<wheelset>(Role::delta_r, &WheelsetOut::delta_r_mm,
                         "rolling radius difference r_left - r_right"),
      role_row<wheelset>(Role::gamma_left, &WheelsetOut::gamma_left_rad,
                         "contact angle, left wheel"),
      role_row<wheelset>(Role::gamma_right, &WheelsetOut::gamma_right_rad,
                         "contact angle, right wheel"),
      role_row<wheelset>(Role::ws_status, &WheelsetOut::status, kStatusBits),
      role_row<node_status>(Role::node_state, &NodeStatusData::state,
                            "bit0 enabled, bit1 sync mode, bit2 overrun seen, bit3 FD layout"),
      role_row<node_status>(Role::node_cycle, &NodeStatusData::cycle,
                            "periodic mode: node cycle number (wraps); sync mode: the RigCycle "
                            "answered, low 16 bits (an input-timeout computation repeats the last; "
                            "65535 before any)"),
      role_row<node_status>(Role::node_overruns, &NodeStatusData::overruns,
                            "missed deadlines since start (saturating)"),
      role_row<node_status>(Role::node_rejected, &NodeStatusData::rejected,
                            "rejected frames since start (saturating)"),
      role_row<node_status>(
          Role::node_stale_mask, &NodeStatusData::stale_mask,
          "bit i: wheel i stale, bit 4+j: wheelset j stale, bit 6+j: its forces stale"),
      role_row<node_status>(
          Role::node_clamp_mask, &NodeStatusData::clamp_mask,
          "bit i: wheel i clamped, bit 4+j: wheelset j clamped, bit 6+j: its forces clamped"),
      // rig -> node: a wheelset's motion and wheel loads
      role_row<wheelset_motion>(Role::ws_speed, &WheelsetIn::speed_mps, "wheelset forward speed"),
      role_row<wheelset_motion>(Role::ws_lateral_velocity, &WheelsetIn::lateral_velocity_mps,
                                "wheelset lateral velocity, + toward the left rail"),
      role_row<wheelset_motion>(Role::ws_yaw_rate, &WheelsetIn::yaw_rate_radps,
                                "wheelset yaw rate, counter-clockwise seen from above"),
      role_row<wheelset_motion>(Role::ws_load_left, &WheelsetIn::load_left_n,
                                "vertical wheel load, left wheel"),
      role_row<wheelset_motion>(Role::ws_load_right, &WheelsetIn::load_right_n,
                                "vertical wheel load, right wheel"),
      // node -> rig: per rail wheel
      role_row<rail_wheel>(Role::rw_fx, &RailWheelOut::fx_n,
                           "longitudinal creep force on the wheel (sum of its contact points)"),
      role_row<rail_wheel>(Role::rw_y, &RailWheelOut::y_n,
                           "lateral force of the rail on the wheel, + toward the track centre"),
      role_row<rail_wheel>(Role::rw_q, &RailWheelOut::q_n,
                           "vertical force of the rail on the wheel"),
      role_row<rail_wheel>(
          Role::rw_mz, &RailWheelOut::mz_nm,
          "spin moment about the contact normal (wheel frame, y toward its field side)"),
      role_row<rail_wheel>(Role::rw_n1, &RailWheelOut::n1_n,
                           "normal force at the main contact point"),
      role_row<rail_wheel>(Role::rw_n2, &RailWheelOut::n2_n,
                           "normal force at the second contact point (two-point contact), else 0"),
      role_row<rail_wheel>(Role::rw_y_over_q, &RailWheelOut::y_over_q,
                           "derailment quotient Y/Q (0 when the wheel has lifted)"),
      role_row<rail_wheel>(Role::rw_nadal_margin, &RailWheelOut::nadal_margin,
                           "Nadal's limit minus Y/Q (> 0: below the limit)"),
      role_row<rail_wheel>(Role::rw_status, &RailWheelOut::status, kStatusBits),
  };
}

template <typename S>
inline constexpr auto kRoleTable = make_role_table<S>();

/// Row k of the table is role k: visit_role and the lookups index by the enum's value.
template <typename S>
constexpr bool rows_in_role_order() noexcept {
  if (std::tuple_size_v<decltype(kRoleTable<S>)> != kRoleCount) {
    return false;
  }
  return std::apply(
      [](const auto&... row) {
        std::size_t k = 0;
        return ((static_cast<std::size_t>(row.role) == k++) && ...);
      },
      kRoleTable<S>);
}
static_assert(rows_in_role_order<float>() && rows_in_role_order<fixed::Fixed64>());

/// Calls `visit(row)` with the row of `role` in the table of scalar S.
template <typename S, typename Visit>
constexpr void visit_role(Role role, Visit&& visit) noexcept {
  const auto k = static_cast<std::size_t>(role);
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    static_cast<void>(((k == I && (visit(std::get<I>(kRoleTable<S>)), true)) || ...));
  }
  (std::make_index_sequence<kRoleCount>{});
}

/// What a role means without its member: for code that needs no data model.
struct RoleInfo {
  RoleScope scope;
  bool integer;  ///< a flag, counter or mask: the raw value, no scaling
  const char* comment;
};

inline constexpr std::array<RoleInfo, kRoleCount> kRoleInfo = std::apply(
    [](const auto&... row) {
      return std::array<RoleInfo, kRoleCount>{RoleInfo{
          row.scope, !std::is_same_v<typename member_value<decltype(row.member)>::type, float>,
          row.comment}...};
    },
    kRoleTable<float>);

[[nodiscard]] constexpr RoleScope role_scope(Role role) noexcept {
  return kRoleInfo[static_cast<std::size_t>(role)].scope;
}
/// Roles whose values are integers (flags, counters, masks) rather than scaled physical values.
[[nodiscard]] constexpr bool is_integer_role(Role role) noexcept {
  return kRoleInfo[static_cast<std::size_t>(role)].integer;
}
/// The DBC comment of the role's signals.
[[nodiscard]] constexpr const char* role_comment(Role role) noexcept {
  return kRoleInfo[static_cast<std::size_t>(role)].comment;
}

}  // namespace tread::proto
