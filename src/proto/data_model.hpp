#pragma once
// The protocol's data model: the values the rig sends (RigData: wheel and wheelset inputs, cycle,
// command) and the values the node sends back (NodeData: wheel, wheelset and rail-wheel outputs,
// node status), with the status bits they carry. The codec (codec.hpp) moves them to and from CAN
// frames; role_table.hpp says which signal carries which member.

#include <array>
#include <cstdint>

#include "fixed/fixed64.hpp"
#include "proto/messages.hpp"

namespace tread::proto {

// The physical values are float (the float path), or fixed::Fixed64 (the ...Fixed types: the
// integer-only path for cores without an FPU, through signal_fixed.hpp).

// ---- rig -> node ------------------------------------------------------------------------------
template <typename S>
struct BasicWheelInput {
  S kappa{};
  S alpha_rad{};
  S gamma_rad{};
  S fz_n{};
  S vx_mps{};
  S omega_radps{};
  bool omega_valid{false};
};
using WheelInput = BasicWheelInput<float>;
using WheelInputFixed = BasicWheelInput<fixed::Fixed64>;

template <typename S>
struct BasicWheelsetInput {
  S lateral_mm{};
  S yaw_rad{};
  bool yaw_valid{false};
  // For the wheel-rail forces (WheelsetMotion, WheelsetLoad): track axes, y toward the left rail,
  // yaw counter-clockwise seen from above.
  S speed_mps{};
  S lateral_velocity_mps{};
  S yaw_rate_radps{};
  S load_left_n{};
  S load_right_n{};
};
using WheelsetInput = BasicWheelsetInput<float>;
using WheelsetInputFixed = BasicWheelsetInput<fixed::Fixed64>;

struct Command {
  bool enable{false};
  bool reset{false};
  std::uint8_t tyre_set{0};
  std::uint8_t profile_set{0};
};

template <typename S>
struct BasicRigData {
  std::array<BasicWheelInput<S>, kMaxWheels> wheels{};
  std::array<BasicWheelsetInput<S>, kMaxWheelsets> wheelsets{};
  std::uint32_t rig_cycle{0};
  Command command{};
};
using RigData = BasicRigData<float>;
using RigDataFixed = BasicRigData<fixed::Fixed64>;

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

/// A road wheel's computed values (ISO-W axes): what a tyre channel gives and a wheel output sends.
template <typename S>
struct BasicWheelValues {
  S fx_n{};
  S fy_n{};
  S mz_nm{};
  S mx_nm{};
  S my_nm{};
  S rl_m{};
};

/// A wheelset's contact geometry: what a contact channel gives and a wheelset output sends.
template <typename S>
struct BasicWheelsetValues {
  S r_left_mm{};
  S r_right_mm{};
  S delta_r_mm{};
  S gamma_left_rad{};
  S gamma_right_rad{};
};

/// A rail wheel's contact forces (RailWheelForce, RailWheelContact, RailWheelDerail): wheel
/// 2 j + side of wheelset j. Y is the rail's lateral force on the wheel toward the track centre,
/// Q the vertical; Fx along the track; Mz the spin moment about the contact normal (the wheel's own
/// frame, lateral axis toward its field side); N1, N2 the normal forces of the main and the second
/// contact point; Y/Q and the margin to Nadal's limit.
template <typename S>
struct BasicRailWheelValues {
  S fx_n{};
  S y_n{};
  S q_n{};
  S mz_nm{};
  S n1_n{};
  S n2_n{};
  S y_over_q{};
  S nadal_margin{};
};

/// An output as sent: its values and their status (StatusBits).
template <typename Values>
struct WithStatus : Values {
  std::uint8_t status{0};
};

template <typename S>
using BasicWheelOutput = WithStatus<BasicWheelValues<S>>;
template <typename S>
using BasicWheelsetOutput = WithStatus<BasicWheelsetValues<S>>;
template <typename S>
using BasicRailWheelOutput = WithStatus<BasicRailWheelValues<S>>;
using WheelOutput = BasicWheelOutput<float>;
using WheelsetOutput = BasicWheelsetOutput<float>;
using RailWheelOutput = BasicRailWheelOutput<float>;
using WheelOutputFixed = BasicWheelOutput<fixed::Fixed64>;
using WheelsetOutputFixed = BasicWheelsetOutput<fixed::Fixed64>;
using RailWheelOutputFixed = BasicRailWheelOutput<fixed::Fixed64>;

inline constexpr std::uint8_t kMaxRailWheels = 2 * kMaxWheelsets;

/// NodeStatus.State bits.
inline constexpr std::uint8_t kNodeEnabled = 1U << 0U;
inline constexpr std::uint8_t kNodeSyncMode = 1U << 1U;
inline constexpr std::uint8_t kNodeOverrun = 1U << 2U;  ///< at least one overrun since start
inline constexpr std::uint8_t kNodeFd = 1U << 3U;

/// NodeStatus.Cycle of a node in sync mode before it has received any cycle frame.
inline constexpr std::uint16_t kNoRigCycle = 0xFFFFU;

struct NodeStatusData {
  std::uint8_t state{0};
  std::uint16_t cycle{0};
  std::uint8_t overruns{0};    ///< saturating at 255
  std::uint8_t rejected{0};    ///< saturating at 255
  std::uint8_t stale_mask{0};  ///< bit i: wheel i (0..3), 4+j: wheelset j, 6+j: its forces
  std::uint8_t clamp_mask{0};
};

/// Whether a NodeStatus can be the answer to rig cycle `rig_cycle`. In sync mode NodeStatus.Cycle
/// is the low 16 bits of the RigCycle the node answers (its input-timeout computations repeat the
/// last one): only that cycle's. In periodic mode it is the node's own count: any.
[[nodiscard]] constexpr bool answers_rig_cycle(const NodeStatusData& status,
                                               std::uint32_t rig_cycle) noexcept {
  return (status.state & kNodeSyncMode) == 0U ||
         status.cycle == static_cast<std::uint16_t>(rig_cycle & 0xFFFFU);
}

template <typename S>
struct BasicNodeData {
  std::array<BasicWheelOutput<S>, kMaxWheels> wheels{};
  std::array<BasicWheelsetOutput<S>, kMaxWheelsets> wheelsets{};
  std::array<BasicRailWheelOutput<S>, kMaxRailWheels> rail_wheels{};
  NodeStatusData status{};
};
using NodeData = BasicNodeData<float>;
using NodeDataFixed = BasicNodeData<fixed::Fixed64>;

}  // namespace tread::proto
