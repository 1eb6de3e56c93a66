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

}  // namespace

namespace {

/// sin and the (clamped) cos of a point's contact angle, computed once per cycle.
template <typename T>
struct Trig {
  T s{};
  T c{1};
};

template <typename T>
Creepage<T> creepage_at(const WheelKinematics<T>& k, T r_mm, const Trig<T>& t) noexcept {
  Creepage<T> out;
  const T v = k.speed_m_s;
  if (!(v > T{0}) || !std::isfinite(v)) {
    return out;
  }
  constexpr T kMmToM = static_cast<T>(1e-3);
  out.xi =
      (v - k.axle_spin_rad_s * r_mm * kMmToM - k.yaw_rate_rad_s * k.half_contact_base_mm * kMmToM) /
      v;
  out.eta = (k.lateral_velocity_m_s - v * k.yaw_rad) / (v * t.c);
  // rad/s over m/s is rad/m; the creep laws take rad/mm.
  out.phi_per_mm = (k.yaw_rate_rad_s * t.c - k.axle_spin_rad_s * t.s) / v * kMmToM;
  return out;
}

/// The load split (see split_wheel_load), with the cube root of the main point's load when it
/// carries the wheel alone (so its patch needs no second one).
template <typename T>
NormalSplit<T> split(const ContactPointData<T> (&points)[2], const Trig<T> (&trig)[2], T q_n,
                     T& cbrt_alone) noexcept {
  NormalSplit<T> out;
  cbrt_alone = T{0};
  if (!(q_n > T{0}) || !points[0].present) {
    return out;
  }
  const T n_alone = q_n / trig[0].c;
  const T cb = cube_root(n_alone);
  const T d_alone =
      points[0].shape.approach_unit_mm * cb * cb / trig[0].c + points[0].vertical_gap_mm;
  if (!points[1].present || d_alone <= points[1].vertical_gap_mm) {
    out.normal_n[0] = n_alone;
    out.vertical_approach_mm = d_alone;
    cbrt_alone = cb;
    return out;
  }
  // Both carry. The vertical load f(d) = sum N_i(d) cos(gamma_i), N_i = ((d - g_i) cos / u)^1.5,
  // is convex and increasing in the vertical approach d: Newton from d_alone (where f > q)
  // descends monotonically onto the root.
  const T tolerance = q_n * static_cast<T>(sizeof(T) == 4 ? 2e-6 : 1e-12);
  T d = d_alone;
  T normal[2]{};
  for (int iteration = 0; iteration < 30; ++iteration) {
    T f = -q_n;
    T slope{};
    for (int i = 0; i < 2; ++i) {
      const T x = (d - points[i].vertical_gap_mm) * trig[i].c;
      normal[i] = hertz_load_for_approach(points[i].shape, x);
      if (normal[i] > T{0}) {
        f += normal[i] * trig[i].c;
        slope += T{1.5} * normal[i] / (d - points[i].vertical_gap_mm) * trig[i].c;
      }
    }
    if (std::abs(f) <= tolerance || !(slope > T{0})) {
      break;
    }
    d -= f / slope;
  }
  out.normal_n[0] = normal[0];
  out.normal_n[1] = normal[1];
  out.vertical_approach_mm = d;
  return out;
}

template <typename T>
Trig<T> trig_of(const ContactPointData<T>& p) noexcept {
  if (!p.present) {
    return {};
  }
  const T c = std::cos(p.gamma_rad);
  return {std::sin(p.gamma_rad), c > kMinCos<T> ? c : kMinCos<T>};
}

}  // namespace

template <typename T>
Creepage<T> point_creepage(const WheelKinematics<T>& k, T r_mm, T gamma_rad) noexcept {
  const T c = std::cos(gamma_rad);
  return creepage_at(k, r_mm, Trig<T>{std::sin(gamma_rad), c > kMinCos<T> ? c : kMinCos<T>});
}

template <typename T>
NormalSplit<T> split_wheel_load(const ContactPointData<T> (&points)[2], T q_n) noexcept {
  const Trig<T> trig[2] = {trig_of(points[0]), trig_of(points[1])};
  T unused{};
  return split(points, trig, q_n, unused);
}

template <typename T>
NadalReference<T> nadal_reference(T flange_angle_rad, T mu) noexcept {
  const Result<T> limit = nadal_limit(flange_angle_rad, mu);
  return {flange_angle_rad, mu, limit.value, limit.status};
}

template <typename T>
WheelForces<T> wheel_contact(const ContactPointData<T> (&points)[2], T q_n,
                             const WheelKinematics<T>& kinematics) noexcept {
  WheelForces<T> out;
  const Trig<T> trig[2] = {trig_of(points[0]), trig_of(points[1])};
  T cbrt_alone{};
  const NormalSplit<T> normals = split(points, trig, q_n, cbrt_alone);
  for (int i = 0; i < 2; ++i) {
    PointForces<T>& p = out.point[i];
    p.normal_n = normals.normal_n[i];
    p.sin_gamma = trig[i].s;
    p.cos_gamma = trig[i].c;
    if (!points[i].present || !(p.normal_n > T{0})) {
      continue;
    }
    if (i == 0 && cbrt_alone > T{0}) {
      const HertzShape<T>& sh = points[0].shape;
      p.patch.a_mm = sh.a_unit_mm * cbrt_alone;
      p.patch.b_mm = sh.b_unit_mm * cbrt_alone;
      p.patch.approach_mm = sh.approach_unit_mm * cbrt_alone * cbrt_alone;
      constexpr T kPi = static_cast<T>(3.14159265358979323846);
      p.patch.p_mean_mpa = p.normal_n / (kPi * p.patch.a_mm * p.patch.b_mm);
      p.patch.p_max_mpa = T{1.5} * p.patch.p_mean_mpa;
    } else {
      p.patch = hertz_patch(points[i].shape, p.normal_n);
    }
    p.creepage = creepage_at(kinematics, points[i].r_mm, trig[i]);
  }
  return out;
}

template <typename T>
void wheel_derailment(WheelForces<T>& w, const ContactPointData<T> (&points)[2],
                      const NadalReference<T>& nadal) noexcept {
  w.yq = {};
  int steepest = -1;  // a loaded point steeper than the flange angle
  T steepest_angle = nadal.angle_rad;
  for (int i = 0; i < 2; ++i) {
    const PointForces<T>& p = w.point[i];
    if (!points[i].present || !(p.normal_n > T{0})) {
      continue;
    }
    w.yq.y_n += p.normal_n * p.sin_gamma - p.creep.fy_n * p.cos_gamma;
    w.yq.q_n += p.normal_n * p.cos_gamma + p.creep.fy_n * p.sin_gamma;
    if (points[i].gamma_rad > steepest_angle) {
      steepest_angle = points[i].gamma_rad;
      steepest = i;
    }
  }
  // Nadal's limit at the steepest angle: the reference's, or (rarely) a steeper loaded point's,
  // from its sin and cos: (sin - mu cos) / (cos + mu sin).
  T limit = nadal.limit;
  if (nadal.status == Status::ok && steepest >= 0 &&
      steepest_angle < static_cast<T>(1.57079632679489661923)) {
    const T mu = nadal.mu;
    const T c = std::cos(steepest_angle);
    const T sn = w.point[steepest].sin_gamma;
    limit = (sn - mu * c) / (c + mu * sn);
  }
  w.derailment = {};
  w.derailment_status = Status::ok;
  if (nadal.status != Status::ok) {
    w.derailment_status = nadal.status;
    return;
  }
  w.derailment.limit = limit;
  if (!(w.yq.q_n > T{0}) || !std::isfinite(w.yq.y_n)) {
    w.derailment.margin = limit;
    w.derailment_status = Status::out_of_range;
    return;
  }
  w.derailment.y_over_q = w.yq.y_n / w.yq.q_n;
  w.derailment.margin = limit - w.derailment.y_over_q;
}

template <typename T>
WheelForces<T> wheel_forces(const ContactPointData<T> (&points)[2], T q_n,
                            const WheelKinematics<T>& kinematics, T g_mpa,
                            const NadalReference<T>& nadal,
                            const PolachParameters<T>& polach) noexcept {
  WheelForces<T> out = wheel_contact(points, q_n, kinematics);
  for (int i = 0; i < 2; ++i) {
    PointForces<T>& p = out.point[i];
    if (points[i].present && p.normal_n > T{0}) {
      const CreepContact<T> contact{p.patch.a_mm, p.patch.b_mm, p.normal_n, g_mpa, points[i].c};
      p.creep = polach_creep(contact, p.creepage, kinematics.speed_m_s, polach);
    }
  }
  wheel_derailment(out, points, nadal);
  return out;
}

template <typename T>
WheelContactTotals<T> wheel_totals(const WheelForces<T>& w) noexcept {
  return {w.point[0].creep.fx_n + w.point[1].creep.fx_n,
          (w.point[0].creep.mz_nmm + w.point[1].creep.mz_nmm) * static_cast<T>(1e-3)};
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
                                                const WheelKinematics<float>&, float,
                                                const NadalReference<float>&,
                                                const PolachParameters<float>&) noexcept;
template WheelForces<double> wheel_forces<double>(const ContactPointData<double> (&)[2], double,
                                                  const WheelKinematics<double>&, double,
                                                  const NadalReference<double>&,
                                                  const PolachParameters<double>&) noexcept;
template WheelForces<float> wheel_contact<float>(const ContactPointData<float> (&)[2], float,
                                                 const WheelKinematics<float>&) noexcept;
template WheelForces<double> wheel_contact<double>(const ContactPointData<double> (&)[2], double,
                                                   const WheelKinematics<double>&) noexcept;
template void wheel_derailment<float>(WheelForces<float>&, const ContactPointData<float> (&)[2],
                                      const NadalReference<float>&) noexcept;
template void wheel_derailment<double>(WheelForces<double>&, const ContactPointData<double> (&)[2],
                                       const NadalReference<double>&) noexcept;
template WheelContactTotals<float> wheel_totals<float>(const WheelForces<float>&) noexcept;
template WheelContactTotals<double> wheel_totals<double>(const WheelForces<double>&) noexcept;
template NadalReference<float> nadal_reference<float>(float, float) noexcept;
template NadalReference<double> nadal_reference<double>(double, double) noexcept;

}  // namespace tread::rail
