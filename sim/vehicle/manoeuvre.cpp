#include "vehicle/manoeuvre.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "vehicle/manoeuvre_runner.hpp"

namespace tread::vehicle {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double clamp01(double x) {
  return std::clamp(x, 0.0, 1.0);
}

/// Linear interpolation of `value(sample)` at time t_s over the trace (NaN outside it).
template <typename F>
double value_at(const Trace& trace, double t_s, F value) {
  if (trace.empty() || !(t_s >= trace.front().t_s && t_s <= trace.back().t_s)) return kNaN;
  const auto it = std::lower_bound(trace.begin(), trace.end(), t_s,
                                   [](const TraceSample& s, double t) { return s.t_s < t; });
  if (it == trace.begin()) return value(*it);
  const TraceSample& b = *it;
  const TraceSample& a = *(it - 1);
  const double w = (t_s - a.t_s) / (b.t_s - a.t_s);
  return (1.0 - w) * value(a) + w * value(b);
}

/// The first time `value` crosses `level` in the direction of `rising` at or after t_from
/// (interpolated), NaN if never.
template <typename F>
double crossing_time(const Trace& trace, double t_from, double level, bool rising, F value) {
  for (std::size_t i = 1; i < trace.size(); ++i) {
    if (trace[i].t_s < t_from) continue;
    const double a = value(trace[i - 1]);
    const double b = value(trace[i]);
    const bool crossed = rising ? (a < level && b >= level) : (a > level && b <= level);
    if (crossed) {
      const double w = (level - a) / (b - a);
      return trace[i - 1].t_s + w * (trace[i].t_s - trace[i - 1].t_s);
    }
  }
  return kNaN;
}

/// Cornering stiffness of one wheel at load fz_n (N/rad, positive), by a central difference.
double cornering_stiffness(const TyreFunction& tyre, std::size_t wheel, double fz_n,
                           double vx_mps) {
  WheelKinematics k;
  k.fz_n = fz_n;
  k.vx_mps = vx_mps;
  constexpr double kStep = 0.002;
  k.alpha_rad = kStep;
  const double fy_plus = tyre(wheel, k).fy_n;
  k.alpha_rad = -kStep;
  const double fy_minus = tyre(wheel, k).fy_n;
  return std::fabs(fy_plus - fy_minus) / (2.0 * kStep);
}

}  // namespace

double result_value(const std::vector<ManoeuvreResult>& results, std::string_view name) {
  for (const ManoeuvreResult& r : results) {
    if (r.name == name) return r.value;
  }
  return kNaN;
}

// ----------------------------------------------------------------------------------------------
// Braking

BrakingManoeuvre::BrakingManoeuvre(const VehicleParams& params, const TyreFunction& tyre,
                                   const BrakingOptions& options)
    : p_(params), o_(options) {
  const double v0 = o_.initial_speed_mps;
  const double fz_front = p_.static_front_wheel_load_n();
  const double fz_rear = p_.static_rear_wheel_load_n();
  // Peak friction at the static loads → the expected deceleration → the expected braking loads.
  const auto peak_mu = [&](std::size_t wheel, double fz) {
    const double kappa = peak_braking_slip(tyre, wheel, fz, v0);
    WheelKinematics k;
    k.fz_n = fz;
    k.vx_mps = v0;
    k.kappa = kappa;
    return std::fabs(tyre(wheel, k).fx_n) / fz;
  };
  const double mu = 0.5 * (peak_mu(kFrontLeft, fz_front) + peak_mu(kRearLeft, fz_rear));
  const double transfer =
      0.5 * p_.mass_kg * mu * p_.gravity_mps2 * p_.cg_height_m / p_.wheelbase_m();
  const double fz_front_braking = fz_front + transfer;
  const double fz_rear_braking = std::fmax(fz_rear - transfer, 0.1 * fz_rear);
  if (!(o_.abs_target_slip_front < 0.0)) {
    o_.abs_target_slip_front = peak_braking_slip(tyre, kFrontLeft, fz_front_braking, v0);
  }
  if (!(o_.abs_target_slip_rear < 0.0)) {
    o_.abs_target_slip_rear = peak_braking_slip(tyre, kRearLeft, fz_rear_braking, v0);
  }
  if (!(o_.brake_torque_total_nm > 0.0)) {
    o_.brake_torque_total_nm = 2.0 * mu * p_.mass_kg * p_.gravity_mps2 * p_.wheel_radius_m;
  }
}

VehicleState BrakingManoeuvre::initial_state() const {
  return straight_running_state(p_, o_.initial_speed_mps);
}

void BrakingManoeuvre::reset() {
  abs_integral_nm_.fill(0.0);
  abs_output_nm_.fill(0.0);
}

Controls BrakingManoeuvre::controls(double t_s, double dt_s, const VehicleState& state) {
  Controls c;
  const double pedal = clamp01((t_s - o_.brake_start_s) / o_.pedal_ramp_s);
  const double total = pedal * o_.brake_torque_total_nm;
  for (std::size_t i = 0; i < kWheelCount; ++i) {
    const bool front = i < 2;
    const double share = front ? p_.brake_front_share : 1.0 - p_.brake_front_share;
    const double pedal_torque = 0.5 * share * total;
    if (!o_.abs) {
      c.brake_torque_nm[i] = pedal_torque;
      continue;
    }
    if (state.vx_mps < o_.abs_min_speed_mps) {
      c.brake_torque_nm[i] = std::fmin(abs_output_nm_[i], pedal_torque);
      continue;
    }
    // Wheel-slip controller on the slip speed from wheel speed and vehicle speed (straight
    // line), PI with the integrator clamped to the pedal's torque.
    const double target = front ? o_.abs_target_slip_front : o_.abs_target_slip_rear;
    const double slip_speed = state.omega_radps[i] * p_.wheel_radius_m - state.vx_mps;
    const double error = slip_speed - target * state.vx_mps;  // < 0: too much slip → release
    abs_integral_nm_[i] =
        std::clamp(abs_integral_nm_[i] + o_.abs_ki_nm * error * dt_s, 0.0, pedal_torque);
    c.brake_torque_nm[i] =
        std::clamp(abs_integral_nm_[i] + o_.abs_kp_nms * error, 0.0, pedal_torque);
    abs_output_nm_[i] = c.brake_torque_nm[i];
  }
  return c;
}

bool BrakingManoeuvre::finished(double t_s, const VehicleState& state) const {
  return t_s >= o_.time_limit_s || !(state.vx_mps >= o_.stop_speed_mps);
}

std::vector<ManoeuvreResult> BrakingManoeuvre::results(const Trace& trace) const {
  std::vector<ManoeuvreResult> out;
  if (trace.empty()) return out;
  const double v0 = trace.front().state.vx_mps;
  const auto speed = [](const TraceSample& s) { return s.state.vx_mps; };
  // Distance travelled: the trapezoid of the speed over time (exact for a speed linear within a
  // step; the position of the symplectic step lags it by dt·Δv/2).
  std::vector<double> travelled(trace.size(), 0.0);
  for (std::size_t i = 1; i < trace.size(); ++i) {
    travelled[i] = travelled[i - 1] + 0.5 * (trace[i].state.vx_mps + trace[i - 1].state.vx_mps) *
                                          (trace[i].t_s - trace[i - 1].t_s);
  }
  const auto distance = [&trace, &travelled](const TraceSample& s) {
    return travelled[static_cast<std::size_t>(&s - trace.data())];
  };
  const double t80 = crossing_time(trace, 0.0, 0.8 * v0, false, speed);
  const double t10 = crossing_time(trace, 0.0, 0.1 * v0, false, speed);
  const double s80 = value_at(trace, t80, distance);
  const double s10 = value_at(trace, t10, distance);
  const double v80 = 0.8 * v0;
  const double v10 = 0.1 * v0;
  const double mean_decel = (v80 * v80 - v10 * v10) / (2.0 * (s10 - s80));
  // The end: where the speed crosses the stop speed, or the last sample if the trace ends
  // before (e.g. a rig's trace without the final state); extrapolated to standstill at the mean
  // deceleration.
  double t_stop = crossing_time(trace, 0.0, o_.stop_speed_mps, false, speed);
  double v_stop = o_.stop_speed_mps;
  if (!std::isfinite(t_stop)) {
    t_stop = trace.back().t_s;
    v_stop = std::fmax(trace.back().state.vx_mps, 0.0);
  }
  const double x_start = value_at(trace, o_.brake_start_s, distance);
  const double stopping_distance =
      value_at(trace, t_stop, distance) - x_start + v_stop * v_stop / (2.0 * mean_decel);
  const double stopping_time = t_stop - o_.brake_start_s + v_stop / mean_decel;
  out.push_back({"initial_speed", v0, "m/s"});
  out.push_back({"mean_deceleration", mean_decel, "m/s^2"});
  out.push_back({"stopping_distance", stopping_distance, "m"});
  out.push_back({"stopping_time", stopping_time, "s"});
  out.push_back({"abs", o_.abs ? 1.0 : 0.0, "1"});
  out.push_back({"abs_target_slip_front", o_.abs_target_slip_front, "1"});
  out.push_back({"abs_target_slip_rear", o_.abs_target_slip_rear, "1"});
  out.push_back({"brake_torque_total", o_.brake_torque_total_nm, "N m"});
  return out;
}

// ----------------------------------------------------------------------------------------------
// Step steer

StepSteerManoeuvre::StepSteerManoeuvre(const VehicleParams& params, const TyreFunction& tyre,
                                       const StepSteerOptions& options)
    : p_(params), o_(options) {
  if (!(std::fabs(o_.steer_wheel_rad) > 0.0)) {
    o_.steer_wheel_rad =
        steer_wheel_angle_for_lateral_acceleration(p_, tyre, o_.speed_mps, o_.target_ay_mps2);
  }
}

VehicleState StepSteerManoeuvre::initial_state() const {
  return straight_running_state(p_, o_.speed_mps);
}

Controls StepSteerManoeuvre::controls(double t_s, double dt_s, const VehicleState& state) {
  Controls c;
  const double ramp = o_.steer_rise_s > 0.0 ? clamp01((t_s - o_.steer_start_s) / o_.steer_rise_s)
                                            : (t_s >= o_.steer_start_s ? 1.0 : 0.0);
  c.steer_wheel_rad = ramp * o_.steer_wheel_rad;
  const double error = o_.speed_mps - state.vx_mps;
  speed_integral_m_ += error * dt_s;
  const double torque = o_.speed_kp_nms * error + o_.speed_ki_nm * speed_integral_m_;
  const double front = 0.5 * o_.drive_front_share * torque;
  const double rear = 0.5 * (1.0 - o_.drive_front_share) * torque;
  c.drive_torque_nm = {front, front, rear, rear};
  return c;
}

std::vector<ManoeuvreResult> StepSteerManoeuvre::results(const Trace& trace) const {
  std::vector<ManoeuvreResult> out;
  if (trace.empty()) return out;
  const double t_end = trace.back().t_s;
  double ay_sum = 0.0;
  double r_sum = 0.0;
  double beta_sum = 0.0;
  int n = 0;
  double r_peak = 0.0;
  double t_peak = kNaN;
  const double sign = o_.steer_wheel_rad < 0.0 ? -1.0 : 1.0;
  for (const TraceSample& s : trace) {
    if (s.t_s >= t_end - 0.5) {
      ay_sum += s.state.ay_mps2;
      r_sum += s.state.yaw_rate_radps;
      beta_sum += std::atan2(s.state.vy_mps, s.state.vx_mps);
      ++n;
    }
    if (s.t_s >= o_.steer_start_s && sign * s.state.yaw_rate_radps > sign * r_peak) {
      r_peak = s.state.yaw_rate_radps;
      t_peak = s.t_s;
    }
  }
  const double ay_ss = n > 0 ? ay_sum / n : kNaN;
  const double r_ss = n > 0 ? r_sum / n : kNaN;
  const double t50 = o_.steer_start_s + 0.5 * o_.steer_rise_s;
  const auto yaw = [sign](const TraceSample& s) { return sign * s.state.yaw_rate_radps; };
  const double t90 = crossing_time(trace, o_.steer_start_s, 0.9 * sign * r_ss, true, yaw);
  out.push_back({"steer_wheel_angle", o_.steer_wheel_rad, "rad"});
  out.push_back({"speed", o_.speed_mps, "m/s"});
  out.push_back({"ay_steady", ay_ss, "m/s^2"});
  out.push_back({"yaw_rate_steady", r_ss, "rad/s"});
  out.push_back({"sideslip_steady", n > 0 ? beta_sum / n : kNaN, "rad"});
  out.push_back({"yaw_rate_response_time", t90 - t50, "s"});
  out.push_back({"yaw_rate_peak_time", t_peak - t50, "s"});
  out.push_back({"yaw_rate_overshoot", 100.0 * (r_peak - r_ss) / r_ss, "%"});
  return out;
}

// ----------------------------------------------------------------------------------------------
// Sine with dwell

SineDwellManoeuvre::SineDwellManoeuvre(const VehicleParams& params, const TyreFunction& tyre,
                                       const SineDwellOptions& options)
    : p_(params), o_(options) {
  if (!(o_.amplitude_rad > 0.0)) {
    const double delta_03g =
        steer_wheel_angle_for_lateral_acceleration(p_, tyre, o_.speed_mps, 0.3 * p_.gravity_mps2);
    o_.amplitude_rad = o_.amplitude_factor * std::fabs(delta_03g);
  }
}

double SineDwellManoeuvre::end_of_steer_s() const {
  return o_.steer_start_s + 1.0 / o_.frequency_hz + o_.dwell_s;
}

double SineDwellManoeuvre::duration_s() const {
  return end_of_steer_s() + 1.8;  // just past the last metric (1.75 s)
}

VehicleState SineDwellManoeuvre::initial_state() const {
  return straight_running_state(p_, o_.speed_mps);
}

double SineDwellManoeuvre::steer_wheel_rad(double t_s) const {
  const double t = t_s - o_.steer_start_s;
  const double period = 1.0 / o_.frequency_hz;
  const double w = 2.0 * std::numbers::pi * o_.frequency_hz;
  const double a = o_.left_first ? o_.amplitude_rad : -o_.amplitude_rad;
  if (t < 0.0) return 0.0;
  if (t < 0.75 * period) return a * std::sin(w * t);
  if (t < 0.75 * period + o_.dwell_s) return -a;
  if (t < period + o_.dwell_s) return a * std::sin(w * (t - o_.dwell_s));
  return 0.0;
}

Controls SineDwellManoeuvre::controls(double t_s, double /*dt_s*/, const VehicleState& /*state*/) {
  Controls c;
  c.steer_wheel_rad = steer_wheel_rad(t_s);
  return c;
}

std::vector<ManoeuvreResult> SineDwellManoeuvre::results(const Trace& trace) const {
  std::vector<ManoeuvreResult> out;
  if (trace.empty()) return out;
  const double period = 1.0 / o_.frequency_hz;
  // The reversal lobe's yaw rate has the sign opposite to the first steer.
  const double sign = o_.left_first ? -1.0 : 1.0;
  double peak = 0.0;
  for (const TraceSample& s : trace) {
    if (s.t_s >= o_.steer_start_s + 0.5 * period) {
      peak = std::fmax(peak, sign * s.state.yaw_rate_radps);
    }
  }
  const auto yaw = [](const TraceSample& s) { return s.state.yaw_rate_radps; };
  const double cos_t = end_of_steer_s();
  const double r100 = value_at(trace, cos_t + 1.0, yaw);
  const double r175 = value_at(trace, cos_t + 1.75, yaw);
  const auto lateral = [](const TraceSample& s) { return s.state.y_m; };
  const double y0 = value_at(trace, o_.steer_start_s, lateral);
  const double y107 = value_at(trace, o_.steer_start_s + 1.07, lateral);
  const double first = o_.left_first ? 1.0 : -1.0;
  out.push_back({"amplitude", o_.amplitude_rad, "rad"});
  out.push_back({"speed", o_.speed_mps, "m/s"});
  out.push_back({"end_of_steer", cos_t, "s"});
  out.push_back({"peak_yaw_rate", sign * peak, "rad/s"});
  out.push_back({"yaw_rate_ratio_1_00", 100.0 * sign * r100 / peak, "%"});
  out.push_back({"yaw_rate_ratio_1_75", 100.0 * sign * r175 / peak, "%"});
  out.push_back({"lateral_displacement_1_07", first * (y107 - y0), "m"});
  return out;
}

// ----------------------------------------------------------------------------------------------

double steer_wheel_angle_for_lateral_acceleration(const VehicleParams& params,
                                                  const TyreFunction& tyre, double speed_mps,
                                                  double ay_mps2, double dt_s) {
  // Linear single-track estimate: δ = L/R + (m_f/C_f − m_r/C_r)·ay, R = v²/ay.
  const double l = params.wheelbase_m();
  const double c_front =
      2.0 * cornering_stiffness(tyre, kFrontLeft, params.static_front_wheel_load_n(), speed_mps);
  const double c_rear =
      2.0 * cornering_stiffness(tyre, kRearLeft, params.static_rear_wheel_load_n(), speed_mps);
  const double m_front = params.mass_kg * params.cg_to_rear_axle_m / l;
  const double m_rear = params.mass_kg * params.cg_to_front_axle_m / l;
  const double delta =
      l * ay_mps2 / (speed_mps * speed_mps) + (m_front / c_front - m_rear / c_rear) * ay_mps2;
  const auto steady_ay = [&](double steer_wheel_rad) {
    StepSteerOptions o;
    o.speed_mps = speed_mps;
    o.steer_wheel_rad = steer_wheel_rad;
    o.steer_start_s = 0.1;
    o.duration_s = 3.0;
    StepSteerManoeuvre m(params, tyre, o);
    return result_value(run_manoeuvre(m, params, tyre, dt_s).results, "ay_steady");
  };
  // Secant steps (starting with a proportional one) to 0.5 % of the target.
  double x0 = delta * params.steering_ratio;
  double y0 = steady_ay(x0);
  if (!std::isfinite(y0) || std::fabs(y0) <= 0.0) return x0;
  double x1 = x0 * ay_mps2 / y0;
  for (int i = 0; i < 8; ++i) {
    const double y1 = steady_ay(x1);
    if (!std::isfinite(y1)) break;
    if (std::fabs(y1 - ay_mps2) <= 0.005 * std::fabs(ay_mps2)) break;
    const double slope = (y1 - y0) / (x1 - x0);
    x0 = x1;
    y0 = y1;
    x1 = std::isfinite(slope) && std::fabs(slope) > 0.0 ? x1 + (ay_mps2 - y1) / slope
                                                        : x1 * ay_mps2 / y1;
  }
  return x1;
}

std::unique_ptr<Manoeuvre> make_manoeuvre(std::string_view name, const VehicleParams& params,
                                          const TyreFunction& tyre) {
  if (name == "braking") return std::make_unique<BrakingManoeuvre>(params, tyre);
  if (name == "step-steer") return std::make_unique<StepSteerManoeuvre>(params, tyre);
  if (name == "sine-dwell") return std::make_unique<SineDwellManoeuvre>(params, tyre);
  return nullptr;
}

}  // namespace tread::vehicle
