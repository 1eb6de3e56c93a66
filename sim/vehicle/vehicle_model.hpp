#pragma once
// The rig's road vehicle: a planar 4-wheel model whose slip comes from the wheel speeds and the
// body motion (not prescribed), to be driven against a tread node at the rig's period.
//
// States: body velocities vx, vy (body axes at the CG) and yaw rate r; position X, Y and yaw ψ;
// four wheel spin speeds ω_i; four transient slips κ'_i and tan α'_i (first order, relaxation
// lengths σκ, σα of VehicleParams):
//     dκ'/dt     = ((ω·R − vx_w) − |vx_w|·κ')     / σκ
//     d(tanα')/dt = ( vy_w       − |vx_w|·tanα')  / σα
// where (vx_w, vy_w) is the wheel centre's velocity in the wheel's axes. At steady state κ' is the
// kinematic slip (ω·R − vx_w)/|vx_w| and tan α' = vy_w/|vx_w|: ISO-W as the tyre core (κ < 0
// braking; α > 0 when the wheel moves to its left, which gives Fy < 0 with a TNO .tir).
// The relaxation is what keeps the stiff wheel spin stable at a 1 ms step with forces that arrive
// once per step: without it the wheel's time constant Iω·|vx|/(Cκ·R²) is below 1 ms under about
// 15 m/s; with it the wheel + tyre form an oscillator of about sqrt(Cκ·R²/(Iω·σκ)) ≈ 300 rad/s,
// which symplectic Euler integrates stably at 1 ms.
//
// Loads: quasi-static transfer from the previous step's body accelerations (explicit):
//     front axle  m·g·b/L − m·ax·h/L,  rear axle  m·g·a/L + m·ax·h/L,
//     left − right on axle k = −2·share_k·m·ay·h/track (share_front = roll-stiffness share),
// so ΣFz = m·g (a wheel load below 0 is taken as 0: lifted wheel).
//
// Integration: semi-implicit (symplectic) Euler at the rig's period, forces held over the step:
// body and wheel velocities first (the body-axis velocity turned exactly by −r·dt, then ΣF/m·dt
// added; a brake is a friction torque: it stops a wheel and holds it at ω = 0, never reverses
// it), then the transient slips (their decay implicit) and the position from the new velocities.
// The forces must be the answers to this state's wheel_inputs(): answers one cycle late make the
// wheel spin loop unstable at 1 ms (see delay_compensation.hpp).
// The model never divides by a speed: it stays finite down to and through standstill (the
// manoeuvres stop below about 1 m/s, where the tyre model's own low-speed reduction takes over).
// Wheel order and axes: vehicle_params.hpp. Host code (double); step() never allocates.

#include <array>
#include <cstddef>

#include "vehicle/vehicle_params.hpp"

namespace tread::vehicle {

/// What goes to the node for one wheel (WheelSlip_i / WheelLoad_i).
struct WheelKinematics {
  double kappa{0.0};      ///< transient longitudinal slip κ'
  double alpha_rad{0.0};  ///< transient slip angle atan(tan α')
  double gamma_rad{0.0};  ///< inclination (0: the model has no camber)
  double fz_n{0.0};       ///< vertical load
  double vx_mps{0.0};     ///< wheel centre speed along the wheel's x axis
  double omega_radps{0.0};
};

/// What comes back from the node for one wheel (WheelForce_i), in the wheel's (ISO-W) axes.
struct WheelForces {
  double fx_n{0.0};
  double fy_n{0.0};
  double mz_nm{0.0};
};

/// The driver's inputs for one step.
struct Controls {
  double steer_wheel_rad{0.0};  ///< steering-wheel angle (road wheels: / steering_ratio)
  std::array<double, kWheelCount> drive_torque_nm{};  ///< on the wheel, positive forward
  std::array<double, kWheelCount> brake_torque_nm{};  ///< magnitude (≥ 0; negative taken as 0)
};

struct VehicleState {
  double t_s{0.0};
  double vx_mps{0.0};          ///< body x velocity of the CG
  double vy_mps{0.0};          ///< body y velocity of the CG
  double yaw_rate_radps{0.0};  ///< r
  /// Body-axis acceleration of the CG over the last step, ΣF/m (ax = dvx/dt − r·vy, ay = dvy/dt
  /// + r·vx). These drive the load transfer of the next step.
  double ax_mps2{0.0};
  double ay_mps2{0.0};
  double x_m{0.0};  ///< X, earth-fixed
  double y_m{0.0};  ///< Y, earth-fixed (left of the initial heading)
  double yaw_rad{0.0};
  double steer_wheel_rad{0.0};  ///< steering-wheel angle of the last step
  double steer_rad{0.0};        ///< front road-wheel angle
  std::array<double, kWheelCount> omega_radps{};
  std::array<double, kWheelCount> fz_n{};
  std::array<double, kWheelCount> kappa{};      ///< transient κ'
  std::array<double, kWheelCount> tan_alpha{};  ///< transient tan α'
};

/// Wheel loads for body accelerations ax, ay (the quasi-static transfer above).
std::array<double, kWheelCount> wheel_loads(const VehicleParams& p, double ax_mps2, double ay_mps2);

/// Straight running at `vx_mps`: free-rolling wheels (ω = vx/R), static loads, zero slip.
VehicleState straight_running_state(const VehicleParams& p, double vx_mps);

class VehicleModel {
 public:
  VehicleModel(const VehicleParams& params, const VehicleState& initial)
      : p_(params), s_(initial) {}

  /// The four wheels' inputs for the node from the current state (wheel order 0 FL, 1 FR, 2 RL,
  /// 3 RR).
  [[nodiscard]] std::array<WheelKinematics, kWheelCount> wheel_inputs() const;

  /// Advance by dt_s with the tyre forces the node returned for wheel_inputs() (held over the
  /// step) and the driver's controls. A non-finite force component is taken as 0.
  void step(const std::array<WheelForces, kWheelCount>& forces, const Controls& controls,
            double dt_s);

  [[nodiscard]] const VehicleState& state() const { return s_; }
  [[nodiscard]] const VehicleParams& params() const { return p_; }

  /// Velocity of wheel i's centre in the wheel's axes {vx_w, vy_w} for the current state.
  [[nodiscard]] std::array<double, 2> wheel_velocity(std::size_t i) const;

 private:
  VehicleParams p_;
  VehicleState s_;
};

}  // namespace tread::vehicle
