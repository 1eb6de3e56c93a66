#pragma once
// The roles a CAN signal can have: the names of what signals carry. What each role means (where its
// value lives, integer or scaled, its DBC comment) is in role_table.hpp.

#include <cstddef>
#include <cstdint>

namespace tread::proto {

/// What a signal carries, so one table-driven codec serves every layout (in role_table.hpp's order).
enum class Role : std::uint8_t {
  crc,
  counter,
  // rig -> node
  kappa,
  alpha,
  gamma,
  fz,
  vx,
  omega,
  omega_valid,
  ws_lateral,
  ws_yaw,
  ws_yaw_valid,
  rig_cycle,
  cmd_enable,
  cmd_reset,
  cmd_tyre_set,
  cmd_profile_set,
  // node -> rig
  fx,
  fy,
  mz,
  mx,
  my,
  rl,
  wheel_status,
  r_left,
  r_right,
  delta_r,
  gamma_left,
  gamma_right,
  ws_status,
  node_state,
  node_cycle,
  node_overruns,
  node_rejected,
  node_stale_mask,
  node_clamp_mask,
  // rig -> node: a wheelset's motion and wheel loads (for the wheel-rail forces)
  ws_speed,
  ws_lateral_velocity,
  ws_yaw_rate,
  ws_load_left,
  ws_load_right,
  // node -> rig: per rail wheel (instance 2 j + side: wheelset j, side 0 left, 1 right)
  rw_fx,
  rw_y,
  rw_q,
  rw_mz,
  rw_n1,
  rw_n2,
  rw_y_over_q,
  rw_nadal_margin,
  rw_status,
};

/// One past the last role (for tables indexed by role).
inline constexpr std::size_t kRoleCount = static_cast<std::size_t>(Role::rw_status) + 1U;

}  // namespace tread::proto
