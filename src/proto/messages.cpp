#include "proto/messages.hpp"

#include <array>

namespace tread::proto {
namespace {

using R = Role;
constexpr bool kSigned = true;
constexpr bool kUnsigned = false;

// ---- signal groups (start bits relative to `base`)
// ------------------------------------------------
constexpr SignalSpec crc() {
  return {R::crc, "CRC", -1, 0, 8, kUnsigned, 1.0, 0.0, ""};
}
constexpr SignalSpec counter() {
  return {R::counter, "Counter", -1, 8, 4, kUnsigned, 1.0, 0.0, ""};
}

// Scalings (quantisation = factor / 2, stated in the README's protocol section):
//   kappa 5e-5 (range ±1.638), alpha 2e-5 rad (±0.655), gamma 1e-5 rad (±0.328), Fz 1 N (0..65535),
//   Vx 0.01 m/s (±327), omega 0.01 rad/s (±327), lateral 1e-3 mm (±32.8), yaw 1e-5 rad;
//   Fx/Fy 1 N (±32767), Mz/Mx/My 0.05 N m (±1638), Rl 1e-5 m (0..0.655), r 1e-4 mm (0..1677),
//   delta_r 1e-3 mm (±32.8), contact angles 1e-4 rad (±3.28).
constexpr SignalSpec kappa(std::int8_t i, std::uint16_t b) {
  return {R::kappa, "Kappa", i, b, 16, kSigned, 5e-5, 0.0, "1"};
}
constexpr SignalSpec alpha(std::int8_t i, std::uint16_t b) {
  return {R::alpha, "Alpha", i, b, 16, kSigned, 2e-5, 0.0, "rad"};
}
constexpr SignalSpec gamma(std::int8_t i, std::uint16_t b) {
  return {R::gamma, "Gamma", i, b, 16, kSigned, 1e-5, 0.0, "rad"};
}
constexpr SignalSpec fz(std::int8_t i, std::uint16_t b) {
  return {R::fz, "Fz", i, b, 16, kUnsigned, 1.0, 0.0, "N"};
}
constexpr SignalSpec vx(std::int8_t i, std::uint16_t b) {
  return {R::vx, "Vx", i, b, 16, kSigned, 0.01, 0.0, "m/s"};
}
constexpr SignalSpec omega(std::int8_t i, std::uint16_t b) {
  return {R::omega, "Omega", i, b, 16, kSigned, 0.01, 0.0, "rad/s"};
}
constexpr SignalSpec omega_valid(std::int8_t i, std::uint16_t b) {
  return {R::omega_valid, "OmegaValid", i, b, 1, kUnsigned, 1.0, 0.0, ""};
}
constexpr SignalSpec lateral(std::int8_t i, std::uint16_t b) {
  return {R::ws_lateral, "Lateral", i, b, 16, kSigned, 1e-3, 0.0, "mm"};
}
constexpr SignalSpec yaw(std::int8_t i, std::uint16_t b) {
  return {R::ws_yaw, "Yaw", i, b, 16, kSigned, 1e-5, 0.0, "rad"};
}
constexpr SignalSpec yaw_valid(std::int8_t i, std::uint16_t b) {
  return {R::ws_yaw_valid, "YawValid", i, b, 1, kUnsigned, 1.0, 0.0, ""};
}
constexpr SignalSpec fx(std::int8_t i, std::uint16_t b) {
  return {R::fx, "Fx", i, b, 16, kSigned, 1.0, 0.0, "N"};
}
constexpr SignalSpec fy(std::int8_t i, std::uint16_t b) {
  return {R::fy, "Fy", i, b, 16, kSigned, 1.0, 0.0, "N"};
}
constexpr SignalSpec mz(std::int8_t i, std::uint16_t b) {
  return {R::mz, "Mz", i, b, 16, kSigned, 0.05, 0.0, "N.m"};
}
constexpr SignalSpec mx(std::int8_t i, std::uint16_t b) {
  return {R::mx, "Mx", i, b, 16, kSigned, 0.05, 0.0, "N.m"};
}
constexpr SignalSpec my(std::int8_t i, std::uint16_t b) {
  return {R::my, "My", i, b, 16, kSigned, 0.05, 0.0, "N.m"};
}
constexpr SignalSpec rl(std::int8_t i, std::uint16_t b) {
  return {R::rl, "Rl", i, b, 16, kUnsigned, 1e-5, 0.0, "m"};
}
constexpr SignalSpec wheel_status(std::int8_t i, std::uint16_t b) {
  return {R::wheel_status, "Status", i, b, 4, kUnsigned, 1.0, 0.0, ""};
}
constexpr SignalSpec r_left(std::int8_t i, std::uint16_t b) {
  return {R::r_left, "RLeft", i, b, 24, kUnsigned, 1e-4, 0.0, "mm"};
}
constexpr SignalSpec r_right(std::int8_t i, std::uint16_t b) {
  return {R::r_right, "RRight", i, b, 24, kUnsigned, 1e-4, 0.0, "mm"};
}
constexpr SignalSpec delta_r(std::int8_t i, std::uint16_t b) {
  return {R::delta_r, "DeltaR", i, b, 16, kSigned, 1e-3, 0.0, "mm"};
}
constexpr SignalSpec gamma_left(std::int8_t i, std::uint16_t b) {
  return {R::gamma_left, "GammaLeft", i, b, 16, kSigned, 1e-4, 0.0, "rad"};
}
constexpr SignalSpec gamma_right(std::int8_t i, std::uint16_t b) {
  return {R::gamma_right, "GammaRight", i, b, 16, kSigned, 1e-4, 0.0, "rad"};
}
constexpr SignalSpec ws_status(std::int8_t i, std::uint16_t b) {
  return {R::ws_status, "Status", i, b, 4, kUnsigned, 1.0, 0.0, ""};
}

// Wheel-rail forces. In: speed 0.01 m/s (0..655), lateral velocity 1e-4 m/s (±3.28), yaw rate
// 1e-4 rad/s (±3.28), wheel loads 4 N (0..262 kN). Out, per rail wheel: Fx, Y, Q 8 N (±262 kN:
// a flange carrying the whole load at 70 deg gives Y ~ 2.7 Q), spin moment 0.05 N m (±1638),
// normal forces 8 N (0..524 kN), Y/Q and Nadal margin 1e-4 (±3.28).
constexpr SignalSpec ws_speed(std::int8_t i, std::uint16_t b) {
  return {R::ws_speed, "Speed", i, b, 16, kUnsigned, 0.01, 0.0, "m/s"};
}
constexpr SignalSpec ws_lateral_velocity(std::int8_t i, std::uint16_t b) {
  return {R::ws_lateral_velocity, "LateralVelocity", i, b, 16, kSigned, 1e-4, 0.0, "m/s"};
}
constexpr SignalSpec ws_yaw_rate(std::int8_t i, std::uint16_t b) {
  return {R::ws_yaw_rate, "YawRate", i, b, 16, kSigned, 1e-4, 0.0, "rad/s"};
}
constexpr SignalSpec ws_load_left(std::int8_t i, std::uint16_t b) {
  return {R::ws_load_left, "LoadLeft", i, b, 16, kUnsigned, 4.0, 0.0, "N"};
}
constexpr SignalSpec ws_load_right(std::int8_t i, std::uint16_t b) {
  return {R::ws_load_right, "LoadRight", i, b, 16, kUnsigned, 4.0, 0.0, "N"};
}
constexpr SignalSpec rw_fx(std::int8_t i, std::uint16_t b) {
  return {R::rw_fx, "Fx", i, b, 16, kSigned, 8.0, 0.0, "N"};
}
constexpr SignalSpec rw_y(std::int8_t i, std::uint16_t b) {
  return {R::rw_y, "Y", i, b, 16, kSigned, 8.0, 0.0, "N"};
}
constexpr SignalSpec rw_q(std::int8_t i, std::uint16_t b) {
  return {R::rw_q, "Q", i, b, 16, kSigned, 8.0, 0.0, "N"};
}
constexpr SignalSpec rw_mz(std::int8_t i, std::uint16_t b) {
  return {R::rw_mz, "SpinMoment", i, b, 16, kSigned, 0.05, 0.0, "N.m"};
}
constexpr SignalSpec rw_n1(std::int8_t i, std::uint16_t b) {
  return {R::rw_n1, "N1", i, b, 16, kUnsigned, 8.0, 0.0, "N"};
}
constexpr SignalSpec rw_n2(std::int8_t i, std::uint16_t b) {
  return {R::rw_n2, "N2", i, b, 16, kUnsigned, 8.0, 0.0, "N"};
}
constexpr SignalSpec rw_y_over_q(std::int8_t i, std::uint16_t b) {
  return {R::rw_y_over_q, "YOverQ", i, b, 16, kSigned, 1e-4, 0.0, "1"};
}
constexpr SignalSpec rw_nadal_margin(std::int8_t i, std::uint16_t b) {
  return {R::rw_nadal_margin, "NadalMargin", i, b, 16, kSigned, 1e-4, 0.0, "1"};
}
constexpr SignalSpec rw_status(std::int8_t i, std::uint16_t b) {
  return {R::rw_status, "Status", i, b, 4, kUnsigned, 1.0, 0.0, ""};
}

// ---- messages shared by both layouts
// --------------------------------------------------------------
constexpr std::array kCommand{
    crc(),
    counter(),
    SignalSpec{R::cmd_enable, "Enable", -1, 12, 1, kUnsigned, 1.0, 0.0, ""},
    SignalSpec{R::cmd_reset, "Reset", -1, 13, 1, kUnsigned, 1.0, 0.0, ""},
    SignalSpec{R::cmd_tyre_set, "TyreSet", -1, 16, 8, kUnsigned, 1.0, 0.0, ""},
    SignalSpec{R::cmd_profile_set, "ProfileSet", -1, 24, 8, kUnsigned, 1.0, 0.0, ""}};
constexpr std::array kNodeStatus{
    crc(),
    counter(),
    SignalSpec{R::node_state, "State", -1, 12, 4, kUnsigned, 1.0, 0.0, ""},
    SignalSpec{R::node_cycle, "Cycle", -1, 16, 16, kUnsigned, 1.0, 0.0, ""},
    SignalSpec{R::node_overruns, "Overruns", -1, 32, 8, kUnsigned, 1.0, 0.0, ""},
    SignalSpec{R::node_rejected, "Rejected", -1, 40, 8, kUnsigned, 1.0, 0.0, ""},
    SignalSpec{R::node_stale_mask, "StaleMask", -1, 48, 8, kUnsigned, 1.0, 0.0, ""},
    SignalSpec{R::node_clamp_mask, "ClampMask", -1, 56, 8, kUnsigned, 1.0, 0.0, ""}};

// ---- classic layout (8-byte frames)
// ---------------------------------------------------------------
constexpr std::array kRigCycle{
    crc(), counter(), SignalSpec{R::rig_cycle, "RigCycle", -1, 16, 32, kUnsigned, 1.0, 0.0, ""}};
constexpr std::array kWheelSlip{crc(), counter(), kappa(-1, 16), alpha(-1, 32), gamma(-1, 48)};
constexpr std::array kWheelLoad{crc(),      counter(),  omega_valid(-1, 12),
                                fz(-1, 16), vx(-1, 32), omega(-1, 48)};
constexpr std::array kWheelsetIn{crc(), counter(), yaw_valid(-1, 12), lateral(-1, 16), yaw(-1, 32)};
constexpr std::array kWheelForce{crc(),      counter(),  wheel_status(-1, 12),
                                 fx(-1, 16), fy(-1, 32), mz(-1, 48)};
constexpr std::array kWheelMoment{crc(), counter(), mx(-1, 16), my(-1, 32), rl(-1, 48)};
constexpr std::array kWheelsetRadius{crc(), counter(), ws_status(-1, 12), r_left(-1, 16),
                                     r_right(-1, 40)};
constexpr std::array kWheelsetAngle{crc(), counter(), delta_r(-1, 16), gamma_left(-1, 32),
                                    gamma_right(-1, 48)};

constexpr std::array kWheelsetMotion{crc(), counter(), ws_speed(-1, 16),
                                     ws_lateral_velocity(-1, 32), ws_yaw_rate(-1, 48)};
constexpr std::array kWheelsetLoad{crc(), counter(), ws_load_left(-1, 16), ws_load_right(-1, 32)};
constexpr std::array kRailWheelForce{crc(),         counter(),    rw_status(-1, 12),
                                     rw_fx(-1, 16), rw_y(-1, 32), rw_q(-1, 48)};
constexpr std::array kRailWheelContact{crc(), counter(), rw_n1(-1, 16), rw_n2(-1, 32),
                                       rw_mz(-1, 48)};
constexpr std::array kRailWheelDerail{crc(), counter(), rw_y_over_q(-1, 16),
                                      rw_nadal_margin(-1, 32)};

constexpr MessageSpec msg(const char* name, std::int8_t instance, std::uint32_t id, Direction dir,
                          std::span<const SignalSpec> signals, std::uint8_t len = 8,
                          bool fd = false) {
  return {name, instance, id, len, fd, dir, signals};
}
constexpr Direction kIn = Direction::rig_to_node;
constexpr Direction kOut = Direction::node_to_rig;

constexpr std::array kClassic{
    msg("Command", -1, kCommandId, kIn, kCommand),
    msg("RigCycle", -1, kRigCycleId, kIn, kRigCycle),
    msg("NodeStatus", -1, kNodeStatusId, kOut, kNodeStatus),
    msg("WheelSlip", 0, 0x100, kIn, kWheelSlip),
    msg("WheelSlip", 1, 0x101, kIn, kWheelSlip),
    msg("WheelSlip", 2, 0x102, kIn, kWheelSlip),
    msg("WheelSlip", 3, 0x103, kIn, kWheelSlip),
    msg("WheelLoad", 0, 0x110, kIn, kWheelLoad),
    msg("WheelLoad", 1, 0x111, kIn, kWheelLoad),
    msg("WheelLoad", 2, 0x112, kIn, kWheelLoad),
    msg("WheelLoad", 3, 0x113, kIn, kWheelLoad),
    msg("WheelsetIn", 0, 0x120, kIn, kWheelsetIn),
    msg("WheelsetIn", 1, 0x121, kIn, kWheelsetIn),
    msg("WheelForce", 0, 0x180, kOut, kWheelForce),
    msg("WheelForce", 1, 0x181, kOut, kWheelForce),
    msg("WheelForce", 2, 0x182, kOut, kWheelForce),
    msg("WheelForce", 3, 0x183, kOut, kWheelForce),
    msg("WheelMoment", 0, 0x190, kOut, kWheelMoment),
    msg("WheelMoment", 1, 0x191, kOut, kWheelMoment),
    msg("WheelMoment", 2, 0x192, kOut, kWheelMoment),
    msg("WheelMoment", 3, 0x193, kOut, kWheelMoment),
    msg("WheelsetRadius", 0, 0x1A0, kOut, kWheelsetRadius),
    msg("WheelsetRadius", 1, 0x1A1, kOut, kWheelsetRadius),
    msg("WheelsetAngle", 0, 0x1B0, kOut, kWheelsetAngle),
    msg("WheelsetAngle", 1, 0x1B1, kOut, kWheelsetAngle),
    msg("WheelsetMotion", 0, 0x130, kIn, kWheelsetMotion),
    msg("WheelsetMotion", 1, 0x131, kIn, kWheelsetMotion),
    msg("WheelsetLoad", 0, 0x140, kIn, kWheelsetLoad),
    msg("WheelsetLoad", 1, 0x141, kIn, kWheelsetLoad),
    msg("RailWheelForce", 0, 0x1E0, kOut, kRailWheelForce),
    msg("RailWheelForce", 1, 0x1E1, kOut, kRailWheelForce),
    msg("RailWheelForce", 2, 0x1E2, kOut, kRailWheelForce),
    msg("RailWheelForce", 3, 0x1E3, kOut, kRailWheelForce),
    msg("RailWheelContact", 0, 0x1F0, kOut, kRailWheelContact),
    msg("RailWheelContact", 1, 0x1F1, kOut, kRailWheelContact),
    msg("RailWheelContact", 2, 0x1F2, kOut, kRailWheelContact),
    msg("RailWheelContact", 3, 0x1F3, kOut, kRailWheelContact),
    msg("RailWheelDerail", 0, 0x150, kOut, kRailWheelDerail),
    msg("RailWheelDerail", 1, 0x151, kOut, kRailWheelDerail),
    msg("RailWheelDerail", 2, 0x152, kOut, kRailWheelDerail),
    msg("RailWheelDerail", 3, 0x153, kOut, kRailWheelDerail),
};

// ---- CAN FD layout: one input frame, two output frames
// ---------------------------------------------
constexpr std::size_t kRigInputsCount =
    2 + 6 * kMaxWheels + 2 * kMaxWheelsets + kMaxWheels + kMaxWheelsets + 1;
constexpr std::array<SignalSpec, kRigInputsCount> make_rig_inputs() {
  std::array<SignalSpec, kRigInputsCount> s{};
  std::size_t n = 0;
  s[n++] = crc();
  s[n++] = counter();
  for (std::int8_t i = 0; i < static_cast<std::int8_t>(kMaxWheels); ++i) {
    const auto b = static_cast<std::uint16_t>(16 + 96 * i);
    s[n++] = kappa(i, b);
    s[n++] = alpha(i, static_cast<std::uint16_t>(b + 16));
    s[n++] = gamma(i, static_cast<std::uint16_t>(b + 32));
    s[n++] = fz(i, static_cast<std::uint16_t>(b + 48));
    s[n++] = vx(i, static_cast<std::uint16_t>(b + 64));
    s[n++] = omega(i, static_cast<std::uint16_t>(b + 80));
  }
  for (std::int8_t j = 0; j < static_cast<std::int8_t>(kMaxWheelsets); ++j) {
    const auto b = static_cast<std::uint16_t>(400 + 32 * j);
    s[n++] = lateral(j, b);
    s[n++] = yaw(j, static_cast<std::uint16_t>(b + 16));
  }
  for (std::int8_t i = 0; i < static_cast<std::int8_t>(kMaxWheels); ++i) {
    s[n++] = omega_valid(i, static_cast<std::uint16_t>(464 + i));
  }
  for (std::int8_t j = 0; j < static_cast<std::int8_t>(kMaxWheelsets); ++j) {
    s[n++] = yaw_valid(j, static_cast<std::uint16_t>(468 + j));
  }
  s[n++] = SignalSpec{R::rig_cycle, "RigCycle", -1, 472, 32, kUnsigned, 1.0, 0.0, ""};
  return s;
}

constexpr std::size_t kWheelOutCount = 2 + kMaxWheels + 6 * kMaxWheels;
constexpr std::array<SignalSpec, kWheelOutCount> make_wheel_out() {
  std::array<SignalSpec, kWheelOutCount> s{};
  std::size_t n = 0;
  s[n++] = crc();
  s[n++] = counter();
  for (std::int8_t i = 0; i < static_cast<std::int8_t>(kMaxWheels); ++i) {
    s[n++] = wheel_status(i, static_cast<std::uint16_t>(16 + 4 * i));
  }
  for (std::int8_t i = 0; i < static_cast<std::int8_t>(kMaxWheels); ++i) {
    const auto b = static_cast<std::uint16_t>(32 + 96 * i);
    s[n++] = fx(i, b);
    s[n++] = fy(i, static_cast<std::uint16_t>(b + 16));
    s[n++] = mz(i, static_cast<std::uint16_t>(b + 32));
    s[n++] = mx(i, static_cast<std::uint16_t>(b + 48));
    s[n++] = my(i, static_cast<std::uint16_t>(b + 64));
    s[n++] = rl(i, static_cast<std::uint16_t>(b + 80));
  }
  return s;
}

constexpr std::size_t kWheelsetOutCount = 2 + kMaxWheelsets + 5 * kMaxWheelsets;
constexpr std::array<SignalSpec, kWheelsetOutCount> make_wheelset_out() {
  std::array<SignalSpec, kWheelsetOutCount> s{};
  std::size_t n = 0;
  s[n++] = crc();
  s[n++] = counter();
  for (std::int8_t j = 0; j < static_cast<std::int8_t>(kMaxWheelsets); ++j) {
    s[n++] = ws_status(j, static_cast<std::uint16_t>(16 + 4 * j));
  }
  for (std::int8_t j = 0; j < static_cast<std::int8_t>(kMaxWheelsets); ++j) {
    const auto b = static_cast<std::uint16_t>(24 + 96 * j);
    s[n++] = r_left(j, b);
    s[n++] = r_right(j, static_cast<std::uint16_t>(b + 24));
    s[n++] = delta_r(j, static_cast<std::uint16_t>(b + 48));
    s[n++] = gamma_left(j, static_cast<std::uint16_t>(b + 64));
    s[n++] = gamma_right(j, static_cast<std::uint16_t>(b + 80));
  }
  return s;
}

// Wheel-rail forces on FD: one input frame for both wheelsets' motion and loads, one output frame
// per wheelset for its two rail wheels (signals numbered by rail wheel, 2 j + side).
constexpr std::size_t kWheelsetMotionFdCount = 2 + 5 * kMaxWheelsets;
constexpr std::array<SignalSpec, kWheelsetMotionFdCount> make_wheelset_motion_fd() {
  std::array<SignalSpec, kWheelsetMotionFdCount> s{};
  std::size_t n = 0;
  s[n++] = crc();
  s[n++] = counter();
  for (std::int8_t j = 0; j < static_cast<std::int8_t>(kMaxWheelsets); ++j) {
    const auto b = static_cast<std::uint16_t>(16 + 80 * j);
    s[n++] = ws_speed(j, b);
    s[n++] = ws_lateral_velocity(j, static_cast<std::uint16_t>(b + 16));
    s[n++] = ws_yaw_rate(j, static_cast<std::uint16_t>(b + 32));
    s[n++] = ws_load_left(j, static_cast<std::uint16_t>(b + 48));
    s[n++] = ws_load_right(j, static_cast<std::uint16_t>(b + 64));
  }
  return s;
}

constexpr std::size_t kRailWheelsFdCount = 2 + 2 * 9;
constexpr std::array<SignalSpec, kRailWheelsFdCount> make_rail_wheels_fd(std::int8_t wheelset) {
  std::array<SignalSpec, kRailWheelsFdCount> s{};
  std::size_t n = 0;
  s[n++] = crc();
  s[n++] = counter();
  for (std::int8_t side = 0; side < 2; ++side) {
    const auto w = static_cast<std::int8_t>(2 * wheelset + side);
    s[n++] = rw_status(w, static_cast<std::uint16_t>(16 + 4 * side));
    const auto b = static_cast<std::uint16_t>(32 + 128 * side);
    s[n++] = rw_fx(w, b);
    s[n++] = rw_y(w, static_cast<std::uint16_t>(b + 16));
    s[n++] = rw_q(w, static_cast<std::uint16_t>(b + 32));
    s[n++] = rw_mz(w, static_cast<std::uint16_t>(b + 48));
    s[n++] = rw_n1(w, static_cast<std::uint16_t>(b + 64));
    s[n++] = rw_n2(w, static_cast<std::uint16_t>(b + 80));
    s[n++] = rw_y_over_q(w, static_cast<std::uint16_t>(b + 96));
    s[n++] = rw_nadal_margin(w, static_cast<std::uint16_t>(b + 112));
  }
  return s;
}

constexpr auto kRigInputsFd = make_rig_inputs();
constexpr auto kWheelOutFd = make_wheel_out();
constexpr auto kWheelsetOutFd = make_wheelset_out();
constexpr auto kWheelsetMotionFd = make_wheelset_motion_fd();
constexpr auto kRailWheelsFd0 = make_rail_wheels_fd(0);
constexpr auto kRailWheelsFd1 = make_rail_wheels_fd(1);

constexpr std::array kFd{
    msg("Command", -1, kCommandId, kIn, kCommand),
    msg("NodeStatus", -1, kNodeStatusId, kOut, kNodeStatus),
    msg("RigInputsFD", -1, kRigInputsFdId, kIn, kRigInputsFd, 64, true),
    msg("WheelOutFD", -1, 0x1C0, kOut, kWheelOutFd, 64, true),
    msg("WheelsetOutFD", -1, 0x1D0, kOut, kWheelsetOutFd, 32, true),
    msg("WheelsetMotionFD", -1, 0x0B0, kIn, kWheelsetMotionFd, 24, true),
    msg("RailWheelsOutFD", 0, 0x1E0, kOut, kRailWheelsFd0, 48, true),
    msg("RailWheelsOutFD", 1, 0x1E1, kOut, kRailWheelsFd1, 48, true),
};

static_assert(kClassic.size() <= kMaxMessages && kFd.size() <= kMaxMessages);

constexpr std::size_t signal_count(std::span<const MessageSpec> all) {
  std::size_t n = 0;
  for (const MessageSpec& m : all) {
    n += m.signals.size();
  }
  return n;
}
static_assert(signal_count(kClassic) <= kMaxLayoutSignals && signal_count(kFd) <= kMaxLayoutSignals,
              "a layout's signals must fit kMaxLayoutSignals (field_map.hpp)");

// Every signal lies inside its frame and no two signals of a message overlap.
constexpr bool layout_is_sound(std::span<const MessageSpec> all) {
  for (const MessageSpec& m : all) {
    std::array<bool, 512> used{};
    for (const SignalSpec& s : m.signals) {
      if (s.length == 0U || s.length > 32U || s.start_bit + s.length > m.len * 8U) {
        return false;
      }
      for (std::uint32_t bit = s.start_bit; bit < s.start_bit + s.length; ++bit) {
        if (used[bit]) {
          return false;
        }
        used[bit] = true;
      }
    }
  }
  return true;
}
static_assert(layout_is_sound(kClassic), "classic layout: a signal overlaps or leaves its frame");
static_assert(layout_is_sound(kFd), "FD layout: a signal overlaps or leaves its frame");

// O(1) identifier lookup: index + 1 of the message with each 11-bit identifier below 0x200 (0:
// none).
constexpr std::size_t kIdTableSize = 0x200;
template <std::size_t N>
constexpr std::array<std::uint8_t, kIdTableSize> make_id_table(
    const std::array<MessageSpec, N>& all) {
  std::array<std::uint8_t, kIdTableSize> table{};
  for (std::size_t i = 0; i < N; ++i) {
    table[all[i].id] = static_cast<std::uint8_t>(i + 1U);
  }
  return table;
}
constexpr auto kClassicIds = make_id_table(kClassic);
constexpr auto kFdIds = make_id_table(kFd);

constexpr bool ids_fit(std::span<const MessageSpec> all) {
  for (const MessageSpec& m : all) {
    if (m.id >= kIdTableSize) {
      return false;
    }
  }
  return true;
}
static_assert(ids_fit(kClassic) && ids_fit(kFd), "message identifiers must stay below 0x200");

}  // namespace

std::span<const MessageSpec> messages(Layout layout) noexcept {
  return layout == Layout::classic ? std::span<const MessageSpec>(kClassic)
                                   : std::span<const MessageSpec>(kFd);
}

const MessageSpec* find_message(Layout layout, std::uint32_t id) noexcept {
  if (id >= kIdTableSize) {
    return nullptr;
  }
  const std::uint8_t slot = layout == Layout::classic ? kClassicIds[id] : kFdIds[id];
  return slot == 0U ? nullptr : &messages(layout)[slot - 1U];
}

std::size_t message_index(Layout layout, const MessageSpec& message) noexcept {
  return static_cast<std::size_t>(&message - messages(layout).data());
}

}  // namespace tread::proto
