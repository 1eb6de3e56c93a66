#pragma once
// The rig's manoeuvres for the road vehicle: each is a driver (controls from time and state), an
// initial state, an end condition and the evaluation of its results from the trace.
//   "braking"     straight-line braking from 100 km/h, pedal ramp to well above the lock torque,
//                 with or without a wheel-slip ABS; mean deceleration between 80 % and 10 % of the
//                 initial speed (as the MFDD of ECE R13), stopping distance and time.
//   "step-steer"  ISO 7401 step steer at 80 km/h to the steering-wheel angle of a steady lateral
//                 acceleration (4 m/s²), speed held by a drive-torque controller; steady ay and r,
//                 yaw-rate response time (50 % steer → 90 % r), overshoot.
//   "sine-dwell"  FMVSS 126 / UN R140 sine with dwell at 80 km/h, coasting: 0.7 Hz, 500 ms dwell at
//                 the second peak; yaw-rate ratios 1.00 s and 1.75 s after the end of steer (the
//                 standard asks < 35 % / < 20 %), lateral displacement 1.07 s after the start.
// Time t_s is the model's time (0 at the manoeuvre's initial state).

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "vehicle/tyre_function.hpp"
#include "vehicle/vehicle_model.hpp"
#include "vehicle/vehicle_params.hpp"
#include "vehicle/vehicle_trace.hpp"

namespace tread::vehicle {

struct ManoeuvreResult {
  std::string name;  ///< e.g. "mean_deceleration"
  double value{0.0};
  std::string unit;  ///< e.g. "m/s^2"
};

class Manoeuvre {
 public:
  virtual ~Manoeuvre() = default;
  [[nodiscard]] virtual std::string_view name() const = 0;
  /// The time limit of the run, s.
  [[nodiscard]] virtual double duration_s() const = 0;
  [[nodiscard]] virtual VehicleState initial_state() const = 0;
  /// Resets the controllers (ABS, speed control) to the start of the manoeuvre.
  virtual void reset() = 0;
  /// The driver's controls for the step from t_s to t_s + dt_s. Called once per step, in order.
  [[nodiscard]] virtual Controls controls(double t_s, double dt_s, const VehicleState& state) = 0;
  /// True when the run is over (the time limit, or an end condition such as standstill).
  [[nodiscard]] virtual bool finished(double t_s, const VehicleState& state) const {
    return t_s >= duration_s() || !(state.vx_mps > 0.5);
  }
  /// The manoeuvre's results from its trace (named, with units).
  [[nodiscard]] virtual std::vector<ManoeuvreResult> results(const Trace& trace) const = 0;
};

/// The value of result `name`, or NaN if there is none.
double result_value(const std::vector<ManoeuvreResult>& results, std::string_view name);

// ----------------------------------------------------------------------------------------------
struct BrakingOptions {
  double initial_speed_mps{100.0 / 3.6};
  double brake_start_s{0.1};  ///< rolling before the pedal
  double pedal_ramp_s{0.2};   ///< pedal ramp time to the full brake torque
  /// Full total brake torque (all wheels), N·m; 0: twice the lock torque μ_peak·m·g·R.
  double brake_torque_total_nm{0.0};
  bool abs{true};
  /// ABS slip targets per axle; 0: the tyre's peak-Fx slip at the expected braking loads.
  double abs_target_slip_front{0.0};
  double abs_target_slip_rear{0.0};
  /// The ABS works on the slip speed error (ω·R − vx) − κ_target·vx, so its loop gain does not
  /// grow as the car slows down (on the slip ratio it would, as 1/vx).
  double abs_kp_nms{1000.0};  ///< proportional gain, N·m per m/s of slip-speed error
  double abs_ki_nm{20000.0};  ///< integral gain, N·m/s per m/s of slip-speed error
  /// Below this speed the ABS stops regulating and holds each wheel's last torque (real ABS
  /// hands over near standstill; the tyre's relaxation is barely damped there).
  double abs_min_speed_mps{3.0};
  double stop_speed_mps{1.0};  ///< the run ends below this speed
  double time_limit_s{6.0};
};

/// Straight-line braking. The tyre function is used once, at construction, for the peak friction
/// and the ABS's peak slips.
/// Results: initial_speed (m/s), mean_deceleration (m/s^2, between 80 % and 10 % of the initial
/// speed over distance: (v80² − v10²)/(2·s), distance as the trapezoid of the speed),
/// stopping_distance and stopping_time (m, s: from the pedal onset to the stop speed — or the
/// trace's last sample — then extrapolated to standstill at the mean deceleration),
/// abs (1 or 0), abs_target_slip_front/rear (1), brake_torque_total (N·m).
class BrakingManoeuvre final : public Manoeuvre {
 public:
  BrakingManoeuvre(const VehicleParams& params, const TyreFunction& tyre,
                   const BrakingOptions& options = {});
  [[nodiscard]] std::string_view name() const override { return "braking"; }
  [[nodiscard]] double duration_s() const override { return o_.time_limit_s; }
  [[nodiscard]] VehicleState initial_state() const override;
  void reset() override;
  [[nodiscard]] Controls controls(double t_s, double dt_s, const VehicleState& state) override;
  [[nodiscard]] bool finished(double t_s, const VehicleState& state) const override;
  [[nodiscard]] std::vector<ManoeuvreResult> results(const Trace& trace) const override;
  [[nodiscard]] const BrakingOptions& options() const { return o_; }

 private:
  VehicleParams p_;
  BrakingOptions o_;
  std::array<double, kWheelCount> abs_integral_nm_{};
  std::array<double, kWheelCount> abs_output_nm_{};
};

// ----------------------------------------------------------------------------------------------
struct StepSteerOptions {
  double speed_mps{80.0 / 3.6};
  /// Steering-wheel angle of the step, rad; 0: the angle that gives target_ay_mps2 at steady state
  /// (steer_wheel_angle_for_lateral_acceleration, with the tyre function).
  double steer_wheel_rad{0.0};
  double target_ay_mps2{4.0};
  double steer_start_s{0.5};
  double steer_rise_s{0.15};  ///< 0 → 100 % of the step (linear)
  double duration_s{4.0};
  double drive_front_share{1.0};  ///< share of the speed controller's torque on the front axle
  double speed_kp_nms{3000.0};    ///< N·m per m/s of speed error (total)
  double speed_ki_nm{6000.0};     ///< N·m per m of integrated speed error
};

/// ISO 7401 step steer. Results: steer_wheel_angle (rad), ay_steady (m/s^2), yaw_rate_steady
/// (rad/s), sideslip_steady (rad), yaw_rate_response_time (s, from 50 % of the steering step to
/// 90 % of the steady yaw rate), yaw_rate_peak_time (s, from 50 % steer), yaw_rate_overshoot (%,
/// (r_peak − r_steady)/r_steady). Steady values: the mean over the last 0.5 s.
class StepSteerManoeuvre final : public Manoeuvre {
 public:
  /// `tyre` is used only when options.steer_wheel_rad is 0 (to find the angle).
  StepSteerManoeuvre(const VehicleParams& params, const TyreFunction& tyre,
                     const StepSteerOptions& options = {});
  [[nodiscard]] std::string_view name() const override { return "step-steer"; }
  [[nodiscard]] double duration_s() const override { return o_.duration_s; }
  [[nodiscard]] VehicleState initial_state() const override;
  void reset() override { speed_integral_m_ = 0.0; }
  [[nodiscard]] Controls controls(double t_s, double dt_s, const VehicleState& state) override;
  [[nodiscard]] std::vector<ManoeuvreResult> results(const Trace& trace) const override;
  [[nodiscard]] const StepSteerOptions& options() const { return o_; }

 private:
  VehicleParams p_;
  StepSteerOptions o_;
  double speed_integral_m_{0.0};
};

// ----------------------------------------------------------------------------------------------
struct SineDwellOptions {
  double speed_mps{80.0 / 3.6};
  double frequency_hz{0.7};
  double dwell_s{0.5};
  /// Steering-wheel amplitude, rad; 0: amplitude_factor × the steering-wheel angle that gives
  /// 0.3 g at steady state at speed_mps (the standard's δ0.3g from its slowly increasing steer,
  /// here found by steady-state runs with the tyre function).
  double amplitude_rad{0.0};
  double amplitude_factor{6.5};
  double steer_start_s{0.5};
  bool left_first{true};  ///< first half-wave to the left (positive)
};

/// Sine with dwell, coasting (no drive, no brake). Results: amplitude (rad), peak_yaw_rate (rad/s,
/// the first peak after the steering reversal), yaw_rate_ratio_1_00 and _1_75 (%, r at 1.00 s /
/// 1.75 s after the end of steer over the peak), lateral_displacement_1_07 (m, of the CG
/// perpendicular to the initial heading, 1.07 s after the start of steer), end_of_steer (s).
/// The run ends 1.8 s after the end of steer (4.2 s). With the default vehicle and
/// MagicFormula61_Parameters.tir the car (no ESC) spins at 6.5 × δ0.3g: yaw-rate ratios near
/// 100 %, rear slip angles up to 0.74 rad from 3.9 s on (beyond the CAN α range of ±0.655 rad,
/// which saturates); at 1.5 × δ0.3g it settles (ratios ≈ 0 %).
class SineDwellManoeuvre final : public Manoeuvre {
 public:
  /// `tyre` is used only when options.amplitude_rad is 0 (to find δ0.3g).
  SineDwellManoeuvre(const VehicleParams& params, const TyreFunction& tyre,
                     const SineDwellOptions& options = {});
  [[nodiscard]] std::string_view name() const override { return "sine-dwell"; }
  [[nodiscard]] double duration_s() const override;
  [[nodiscard]] VehicleState initial_state() const override;
  void reset() override {}
  [[nodiscard]] Controls controls(double t_s, double dt_s, const VehicleState& state) override;
  [[nodiscard]] std::vector<ManoeuvreResult> results(const Trace& trace) const override;
  [[nodiscard]] const SineDwellOptions& options() const { return o_; }
  /// The steering-wheel angle at t_s.
  [[nodiscard]] double steer_wheel_rad(double t_s) const;
  /// The end of steer (start + 1/f + dwell), s.
  [[nodiscard]] double end_of_steer_s() const;

 private:
  VehicleParams p_;
  SineDwellOptions o_;
};

/// The steering-wheel angle (rad) whose steady state at `speed_mps` (held by the step steer's
/// speed controller) has the lateral acceleration `ay_mps2`: a linear single-track estimate from
/// the tyre's cornering stiffness at the static loads, refined by secant steps on step-steer runs
/// of the model with `tyre` (to 0.5 % of ay_mps2).
double steer_wheel_angle_for_lateral_acceleration(const VehicleParams& params,
                                                  const TyreFunction& tyre, double speed_mps,
                                                  double ay_mps2, double dt_s = 1e-3);

/// "braking", "step-steer" or "sine-dwell" with default options; nullptr for another name.
std::unique_ptr<Manoeuvre> make_manoeuvre(std::string_view name, const VehicleParams& params,
                                          const TyreFunction& tyre);

}  // namespace tread::vehicle
