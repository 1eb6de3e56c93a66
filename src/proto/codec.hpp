#pragma once
// Table-driven codec: moves values between the protocol's data model and CAN frames, for any
// message of either layout (messages.hpp), and applies the E2E protection (e2e_profile1.hpp).

#include <array>
#include <cstdint>

#include "core/status.hpp"
#include "proto/can_frame.hpp"
#include "proto/messages.hpp"

namespace tread::proto {

// ---- rig -> node ------------------------------------------------------------------------------
struct WheelInput {
  float kappa{0.0F};
  float alpha_rad{0.0F};
  float gamma_rad{0.0F};
  float fz_n{0.0F};
  float vx_mps{0.0F};
  float omega_radps{0.0F};
  bool omega_valid{false};
};

struct WheelsetInput {
  float lateral_mm{0.0F};
  float yaw_rad{0.0F};
  bool yaw_valid{false};
};

struct Command {
  bool enable{false};
  bool reset{false};
  std::uint8_t tyre_set{0};
  std::uint8_t profile_set{0};
};

struct RigData {
  std::array<WheelInput, kMaxWheels> wheels{};
  std::array<WheelsetInput, kMaxWheelsets> wheelsets{};
  std::uint32_t rig_cycle{0};
  Command command{};
};

// ---- node -> rig ------------------------------------------------------------------------------
/// Status bits of a wheel / wheelset output.
enum StatusBits : std::uint8_t {
  kStatusStale = 1U << 0U,     ///< no valid input within the timeout: outputs are zero
  kStatusClamped = 1U << 1U,   ///< an input was outside the model's limits and was clamped
  kStatusDisabled = 1U << 2U,  ///< the node is not enabled (Command.Enable = 0)
  /// an output did not fit its signal and was saturated, or the model's output was not finite
  /// (then every output of the channel is 0)
  kStatusOutOfRange = 1U << 3U,
};

struct WheelOutput {
  float fx_n{0.0F};
  float fy_n{0.0F};
  float mz_nm{0.0F};
  float mx_nm{0.0F};
  float my_nm{0.0F};
  float rl_m{0.0F};
  std::uint8_t status{0};
};

struct WheelsetOutput {
  float r_left_mm{0.0F};
  float r_right_mm{0.0F};
  float delta_r_mm{0.0F};
  float gamma_left_rad{0.0F};
  float gamma_right_rad{0.0F};
  std::uint8_t status{0};
};

/// NodeStatus.State bits.
inline constexpr std::uint8_t kNodeEnabled = 1U << 0U;
inline constexpr std::uint8_t kNodeSyncMode = 1U << 1U;
inline constexpr std::uint8_t kNodeOverrun = 1U << 2U;  ///< at least one overrun since start
inline constexpr std::uint8_t kNodeFd = 1U << 3U;

struct NodeStatusData {
  std::uint8_t state{0};
  std::uint16_t cycle{0};
  std::uint8_t overruns{0};    ///< saturating at 255
  std::uint8_t rejected{0};    ///< saturating at 255
  std::uint8_t stale_mask{0};  ///< bit i: wheel i (0..3), bit 4+j: wheelset j
  std::uint8_t clamp_mask{0};
};

struct NodeData {
  std::array<WheelOutput, kMaxWheels> wheels{};
  std::array<WheelsetOutput, kMaxWheelsets> wheelsets{};
  NodeStatusData status{};
};

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

}  // namespace tread::proto
