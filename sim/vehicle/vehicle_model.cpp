#include "vehicle/vehicle_model.hpp"

#include <cmath>

namespace tread::vehicle {

namespace {

double finite_or_zero(double v) {
  return std::isfinite(v) ? v : 0.0;
}

}  // namespace

std::array<double, kWheelCount> wheel_loads(const VehicleParams& p, double ax_mps2,
                                            double ay_mps2) {
  const double l = p.wheelbase_m();
  const double m = p.mass_kg;
  const double h = p.cg_height_m;
  const double front_axle = m * p.gravity_mps2 * p.cg_to_rear_axle_m / l - m * ax_mps2 * h / l;
  const double rear_axle = m * p.gravity_mps2 * p.cg_to_front_axle_m / l + m * ax_mps2 * h / l;
  // Left minus right load on an axle: −2·share·m·ay·h/track (a left turn loads the right side).
  const double lateral = m * ay_mps2 * h / p.track_m;
  const double front_shift = p.roll_stiffness_front_share * lateral;
  const double rear_shift = (1.0 - p.roll_stiffness_front_share) * lateral;
  std::array<double, kWheelCount> fz{};
  fz[kFrontLeft] = 0.5 * front_axle - front_shift;
  fz[kFrontRight] = 0.5 * front_axle + front_shift;
  fz[kRearLeft] = 0.5 * rear_axle - rear_shift;
  fz[kRearRight] = 0.5 * rear_axle + rear_shift;
  for (double& f : fz) {
    if (!(f > 0.0)) f = 0.0;  // lifted wheel
  }
  return fz;
}

VehicleState straight_running_state(const VehicleParams& p, double vx_mps) {
  VehicleState s;
  s.vx_mps = vx_mps;
  for (double& w : s.omega_radps) w = vx_mps / p.wheel_radius_m;
  s.fz_n = wheel_loads(p, 0.0, 0.0);
  return s;
}

std::array<double, 2> VehicleModel::wheel_velocity(std::size_t i) const {
  // Wheel centre velocity in body axes, then rotated into the (steered) wheel's axes.
  const double vxb = s_.vx_mps - s_.yaw_rate_radps * p_.wheel_y_m(i);
  const double vyb = s_.vy_mps + s_.yaw_rate_radps * p_.wheel_x_m(i);
  const double delta = i < 2 ? s_.steer_rad : 0.0;
  const double c = std::cos(delta);
  const double sn = std::sin(delta);
  return {vxb * c + vyb * sn, -vxb * sn + vyb * c};
}

std::array<WheelKinematics, kWheelCount> VehicleModel::wheel_inputs() const {
  std::array<WheelKinematics, kWheelCount> out{};
  for (std::size_t i = 0; i < kWheelCount; ++i) {
    const std::array<double, 2> v = wheel_velocity(i);
    WheelKinematics& w = out[i];
    w.vx_mps = v[0];
    w.omega_radps = s_.omega_radps[i];
    w.fz_n = s_.fz_n[i];
    w.gamma_rad = 0.0;
    if (p_.relaxation_length_kappa_m > 0.0) {
      w.kappa = s_.kappa[i];
    } else {
      // Kinematic slip (no relaxation); the speed floor only avoids 0/0 at standstill.
      w.kappa = (s_.omega_radps[i] * p_.wheel_radius_m - v[0]) / std::fmax(std::fabs(v[0]), 0.1);
    }
    if (p_.relaxation_length_alpha_m > 0.0) {
      w.alpha_rad = std::atan(s_.tan_alpha[i]);
    } else {
      w.alpha_rad = std::atan2(v[1], std::fmax(std::fabs(v[0]), 0.1));
    }
  }
  return out;
}

void VehicleModel::step(const std::array<WheelForces, kWheelCount>& forces,
                        const Controls& controls, double dt_s) {
  const double m = p_.mass_kg;
  const double radius = p_.wheel_radius_m;
  const double inertia = p_.wheel_spin_inertia_kgm2;

  // Body forces and yaw moment from the wheel forces (wheel axes → body axes with the steer
  // angle the forces were computed for).
  double fx_sum = 0.0;
  double fy_sum = 0.0;
  double mz_sum = 0.0;
  std::array<double, kWheelCount> fx_wheel{};
  for (std::size_t i = 0; i < kWheelCount; ++i) {
    const double fx = finite_or_zero(forces[i].fx_n);
    const double fy = finite_or_zero(forces[i].fy_n);
    const double mz = finite_or_zero(forces[i].mz_nm);
    fx_wheel[i] = fx;
    const double delta = i < 2 ? s_.steer_rad : 0.0;
    const double c = std::cos(delta);
    const double sn = std::sin(delta);
    const double fxb = fx * c - fy * sn;
    const double fyb = fx * sn + fy * c;
    fx_sum += fxb;
    fy_sum += fyb;
    mz_sum += p_.wheel_x_m(i) * fyb - p_.wheel_y_m(i) * fxb + mz;
  }
  const double ax = fx_sum / m;
  const double ay = fy_sum / m;
  const double yaw_acc = mz_sum / p_.yaw_inertia_kgm2;

  // Velocities. The body axes turn by r·dt over the step: the velocity vector is rotated exactly
  // by −r·dt (r at the middle of the step), which keeps its magnitude (an explicit r·v term would
  // grow it by (r·dt)²/2 per step), then the accelerations are added.
  const double r = s_.yaw_rate_radps + dt_s * yaw_acc;
  const double turn = 0.5 * (s_.yaw_rate_radps + r) * dt_s;
  const double ct = std::cos(turn);
  const double st = std::sin(turn);
  const double vx = ct * s_.vx_mps + st * s_.vy_mps + dt_s * ax;
  const double vy = -st * s_.vx_mps + ct * s_.vy_mps + dt_s * ay;

  // Wheel spin: drive torque and the tyre's reaction, then the brake as a friction torque.
  for (std::size_t i = 0; i < kWheelCount; ++i) {
    const double drive = finite_or_zero(controls.drive_torque_nm[i]);
    const double brake = std::fmax(finite_or_zero(controls.brake_torque_nm[i]), 0.0);
    const double omega = s_.omega_radps[i] + dt_s * (drive - radius * fx_wheel[i]) / inertia;
    const double brake_step = dt_s * brake / inertia;
    if (std::fabs(omega) <= brake_step) {
      s_.omega_radps[i] = 0.0;  // held by the brake
    } else {
      s_.omega_radps[i] = omega - std::copysign(brake_step, omega);
    }
  }

  s_.vx_mps = vx;
  s_.vy_mps = vy;
  s_.yaw_rate_radps = r;
  s_.steer_wheel_rad = finite_or_zero(controls.steer_wheel_rad);
  s_.steer_rad = s_.steer_wheel_rad / p_.steering_ratio;

  // Transient slips from the new velocities, decay implicit (stable for any |vx_w|·dt/σ).
  for (std::size_t i = 0; i < kWheelCount; ++i) {
    const std::array<double, 2> v = wheel_velocity(i);
    const double speed = std::fabs(v[0]);
    if (p_.relaxation_length_kappa_m > 0.0) {
      const double g = dt_s / p_.relaxation_length_kappa_m;
      const double slip_speed = s_.omega_radps[i] * radius - v[0];
      s_.kappa[i] = (s_.kappa[i] + g * slip_speed) / (1.0 + g * speed);
    }
    if (p_.relaxation_length_alpha_m > 0.0) {
      const double g = dt_s / p_.relaxation_length_alpha_m;
      s_.tan_alpha[i] = (s_.tan_alpha[i] + g * v[1]) / (1.0 + g * speed);
    }
  }

  // Position with the new velocities (heading at the middle of the step).
  const double yaw_new = s_.yaw_rad + dt_s * r;
  const double yaw_mid = 0.5 * (s_.yaw_rad + yaw_new);
  s_.x_m += dt_s * (vx * std::cos(yaw_mid) - vy * std::sin(yaw_mid));
  s_.y_m += dt_s * (vx * std::sin(yaw_mid) + vy * std::cos(yaw_mid));
  s_.yaw_rad = yaw_new;

  s_.ax_mps2 = ax;
  s_.ay_mps2 = ay;
  s_.fz_n = wheel_loads(p_, ax, ay);
  s_.t_s += dt_s;
}

}  // namespace tread::vehicle
