#include "rail/wheel_contact.hpp"

#include <cmath>

namespace tread::rail {
namespace {

template <typename T>
constexpr T kMinCos = static_cast<T>(0.05);  // contact angles beyond ~87 deg are not a wheel

template <typename T>
T clamped_cos(T gamma_rad) noexcept {
  const T c = std::cos(gamma_rad);
  return c > kMinCos<T> ? c : kMinCos<T>;
}

/// Vertical load carried by the points at vertical approach d, and their normal forces.
template <typename T>
T vertical_load(const ContactPointData<T> (&points)[2], T d, T (&normal)[2]) noexcept {
  T sum{};
  for (int i = 0; i < 2; ++i) {
    normal[i] = T{0};
    if (!points[i].present) {
      continue;
    }
    const T c = clamped_cos(points[i].gamma_rad);
    normal[i] = hertz_load_for_approach(points[i].shape, (d - points[i].vertical_gap_mm) * c);
    sum += normal[i] * c;
  }
  return sum;
}

}  // namespace

template <typename T>
Creepage<T> point_creepage(const WheelKinematics<T>& k, T r_mm, T gamma_rad) noexcept {
  Creepage<T> s;
  const T v = k.speed_m_s;
  if (!(v > T{0}) || !std::isfinite(v)) {
    return s;
  }
  constexpr T kMmToM = static_cast<T>(1e-3);
  const T c = clamped_cos(gamma_rad);
  const T sn = std::sin(gamma_rad);
  s.xi =
      (v - k.axle_spin_rad_s * r_mm * kMmToM - k.yaw_rate_rad_s * k.half_contact_base_mm * kMmToM) /
      v;
  s.eta = (k.lateral_velocity_m_s - v * k.yaw_rad) / (v * c);
  // rad/s over m/s is rad/m; the creep laws take rad/mm.
  s.phi_per_mm = (k.yaw_rate_rad_s * c - k.axle_spin_rad_s * sn) / v * kMmToM;
  return s;
}

template <typename T>
NormalSplit<T> split_wheel_load(const ContactPointData<T> (&points)[2], T q_n) noexcept {
  NormalSplit<T> out;
  if (!(q_n > T{0}) || !points[0].present) {
    return out;
  }
  // The main point alone first.
  const T c0 = clamped_cos(points[0].gamma_rad);
  const HertzPatch<T> alone = hertz_patch(points[0].shape, q_n / c0);
  T d_hi = alone.approach_mm / c0 + points[0].vertical_gap_mm;
  T normal[2];
  if (!points[1].present || d_hi <= points[1].vertical_gap_mm) {
    out.normal_n[0] = q_n / c0;
    out.vertical_approach_mm = d_hi;
    return out;
  }
  // Both carry: the vertical load grows monotonically with d; Illinois on [0, d_hi].
  T d_lo{0};
  T f_lo = -q_n;
  T f_hi = vertical_load(points, d_hi, normal) - q_n;
  const T tolerance = q_n * static_cast<T>(sizeof(T) == 4 ? 1e-6 : 1e-12);
  T d = d_hi;
  int side = 0;
  for (int i = 0; i < 60; ++i) {
    d = (d_lo * f_hi - d_hi * f_lo) / (f_hi - f_lo);
    if (!(d > d_lo && d < d_hi)) {
      d = (d_lo + d_hi) / T{2};
    }
    const T f = vertical_load(points, d, normal) - q_n;
    if (std::abs(f) <= tolerance) {
      break;
    }
    if (f > T{0}) {
      d_hi = d;
      f_hi = f;
      if (side == 1) {
        f_lo /= T{2};
      }
      side = 1;
    } else {
      d_lo = d;
      f_lo = f;
      if (side == -1) {
        f_hi /= T{2};
      }
      side = -1;
    }
  }
  (void)vertical_load(points, d, normal);
  out.normal_n[0] = normal[0];
  out.normal_n[1] = normal[1];
  out.vertical_approach_mm = d;
  return out;
}

template <typename T>
WheelForces<T> wheel_forces(const ContactPointData<T> (&points)[2], T q_n,
                            const WheelKinematics<T>& kinematics, T g_mpa, T flange_angle_rad,
                            const PolachParameters<T>& polach) noexcept {
  WheelForces<T> out;
  const NormalSplit<T> split = split_wheel_load(points, q_n);
  T flange_angle = flange_angle_rad;
  for (int i = 0; i < 2; ++i) {
    PointForces<T>& p = out.point[i];
    p.normal_n = split.normal_n[i];
    if (!points[i].present || !(p.normal_n > T{0})) {
      continue;
    }
    p.patch = hertz_patch(points[i].shape, p.normal_n);
    p.creepage = point_creepage(kinematics, points[i].r_mm, points[i].gamma_rad);
    const CreepContact<T> contact{p.patch.a_mm, p.patch.b_mm, p.normal_n, g_mpa, points[i].c};
    p.creep = polach_creep(contact, p.creepage, kinematics.speed_m_s, polach);
    add_contact_point(out.yq, p.normal_n, points[i].gamma_rad, p.creep.fy_n);
    if (points[i].gamma_rad > flange_angle) {
      flange_angle = points[i].gamma_rad;
    }
  }
  const Result<DerailmentCheck<T>> check =
      derailment_check(out.yq, flange_angle, polach_friction(polach, T{0}));
  out.derailment = check.value;
  out.derailment_status = check.status;
  return out;
}

template Creepage<float> point_creepage<float>(const WheelKinematics<float>&, float,
                                               float) noexcept;
template Creepage<double> point_creepage<double>(const WheelKinematics<double>&, double,
                                                 double) noexcept;
template NormalSplit<float> split_wheel_load<float>(const ContactPointData<float> (&)[2],
                                                    float) noexcept;
template NormalSplit<double> split_wheel_load<double>(const ContactPointData<double> (&)[2],
                                                      double) noexcept;
template WheelForces<float> wheel_forces<float>(const ContactPointData<float> (&)[2], float,
                                                const WheelKinematics<float>&, float, float,
                                                const PolachParameters<float>&) noexcept;
template WheelForces<double> wheel_forces<double>(const ContactPointData<double> (&)[2], double,
                                                  const WheelKinematics<double>&, double, double,
                                                  const PolachParameters<double>&) noexcept;

}  // namespace tread::rail
