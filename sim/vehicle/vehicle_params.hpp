#pragma once
// Parameters of the 4-wheel road-vehicle model the rig drives (sim/vehicle/vehicle_model.hpp):
// a mid-size passenger car. SI units, the unit in every name.
//
// Wheel order (the protocol's channel i = WheelSlip_i / WheelLoad_i / WheelForce_i):
//   0 front left, 1 front right, 2 rear left, 3 rear right.
// Body axes (ISO 8855, as the tyre's ISO-W): x forward, y left, z up; yaw rate positive for a
// left-hand turn; positive steering angle steers left.

#include <cstddef>

namespace tread::vehicle {

inline constexpr std::size_t kWheelCount = 4;
inline constexpr std::size_t kFrontLeft = 0;
inline constexpr std::size_t kFrontRight = 1;
inline constexpr std::size_t kRearLeft = 2;
inline constexpr std::size_t kRearRight = 3;

struct VehicleParams {
  double mass_kg{1500.0};
  double yaw_inertia_kgm2{2500.0};
  double cg_to_front_axle_m{1.2};  ///< a
  double cg_to_rear_axle_m{1.4};   ///< b (wheelbase L = a + b)
  double track_m{1.55};            ///< same track front and rear
  double cg_height_m{0.55};
  /// Share of the roll stiffness (and so of the lateral load transfer) on the front axle.
  double roll_stiffness_front_share{0.55};
  double wheel_spin_inertia_kgm2{1.0};  ///< per wheel, wheel + brake disc + driveline share
  /// Radius relating wheel speed to slip: κ = (ω·R − vx)/|vx|. Take the tyre file's
  /// UNLOADED_RADIUS (the node evaluates the same κ); 0.31 m when no file is given.
  double wheel_radius_m{0.31};
  /// Steering-wheel angle / road-wheel angle (front wheels, parallel steer, no Ackermann).
  double steering_ratio{15.0};
  /// Share of a total brake torque that a manoeuvre puts on the front axle.
  double brake_front_share{0.65};
  /// Relaxation length of the longitudinal transient slip κ' (σκ). 0 or less: no relaxation,
  /// the kinematic slip is used directly (unstable at a 1 ms step at low speed; see the tests).
  double relaxation_length_kappa_m{0.2};
  /// Relaxation length of the lateral transient slip tan α' (σα). 0 or less: kinematic slip.
  double relaxation_length_alpha_m{0.4};
  double gravity_mps2{9.81};

  [[nodiscard]] double wheelbase_m() const { return cg_to_front_axle_m + cg_to_rear_axle_m; }
  /// Static load of one front / rear wheel, N.
  [[nodiscard]] double static_front_wheel_load_n() const {
    return 0.5 * mass_kg * gravity_mps2 * cg_to_rear_axle_m / wheelbase_m();
  }
  [[nodiscard]] double static_rear_wheel_load_n() const {
    return 0.5 * mass_kg * gravity_mps2 * cg_to_front_axle_m / wheelbase_m();
  }
  /// Position of wheel i's centre relative to the CG in body axes, m.
  [[nodiscard]] double wheel_x_m(std::size_t i) const {
    return i < 2 ? cg_to_front_axle_m : -cg_to_rear_axle_m;
  }
  [[nodiscard]] double wheel_y_m(std::size_t i) const {
    return (i % 2 == 0) ? 0.5 * track_m : -0.5 * track_m;
  }
};

}  // namespace tread::vehicle
