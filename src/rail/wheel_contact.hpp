#pragma once
// One wheel on its rail: the creepages of each contact point from the wheelset's motion, the
// split of the wheel load between a tread and a flange point (two-point contact), the creep forces
// at each point by Polach's method, and the wheel's Y, Q and Nadal margin. Pure, no heap, float
// on the node and double on the host.
//
// Each wheel works in its own frame: x forward, y toward its field side (away from the track
// centre: the track's +y for the left wheel, -y for the right), z up. The right wheel's motion is
// mirrored into that frame (mirrored()), its lateral forces and moments mirrored back by the
// caller. A contact point has rolling radius r and contact angle gamma (> 0 where the radius grows
// toward the flange); its contact frame is x, the tangent t = (cos gamma, sin gamma) in (y, z) and
// the normal.
//
// Creepages at a point of a wheel rolling at axle spin Omega, wheelset speed V, lateral velocity
// v_y, yaw angle psi, yaw rate psi_dot, wheel at e from the wheelset centre:
//     xi  = (V - Omega r - psi_dot e) / V
//     eta = (v_y - V psi) / (V cos gamma)
//     phi = (psi_dot cos gamma - Omega sin gamma) / V
// (the linearised kinematics of the classical wheelset models, e.g. Wickens; the spin term
// -sin(gamma)/r0 is what makes the flange's lateral force point toward the field side).
//
// Two-point contact: a rigid wheel sinking by the vertical approach d closes a point with vertical
// gap g by (d - g) cos(gamma) along its normal; each point carries the Hertz load of that approach
// and the vertical components add up to the wheel load Q. Tangential forces are left out of that
// balance (they are small against N at the tread, and Y/Q carries them).

#include "rail/derailment.hpp"
#include "rail/hertz_ellipse.hpp"
#include "rail/polach_creep.hpp"

namespace tread::rail {

template <typename T>
struct WheelKinematics {
  T speed_m_s{};             ///< V (> 0)
  T lateral_velocity_m_s{};  ///< toward the field side
  T yaw_rad{};               ///< heading toward the field side positive
  T yaw_rate_rad_s{};
  T axle_spin_rad_s{};          ///< Omega
  T half_contact_base_mm{750};  ///< e: wheel contact point from the wheelset centre
};

/// The right wheel's view of the wheelset motion given in track axes (y left, yaw counter-
/// clockwise seen from above): lateral velocity, yaw angle and yaw rate change sign.
template <typename T>
WheelKinematics<T> mirrored(WheelKinematics<T> k) noexcept {
  k.lateral_velocity_m_s = -k.lateral_velocity_m_s;
  k.yaw_rad = -k.yaw_rad;
  k.yaw_rate_rad_s = -k.yaw_rate_rad_s;
  return k;
}

/// Creepages at a point with rolling radius r (mm) and contact angle gamma. Speed <= 0 (or not
/// finite): zero creepage (a standing wheelset has no creep).
template <typename T>
Creepage<T> point_creepage(const WheelKinematics<T>& k, T r_mm, T gamma_rad) noexcept;

/// What the contact table holds for one contact point (all load-independent).
template <typename T>
struct ContactPointData {
  bool present = false;
  T r_mm{};
  T gamma_rad{};
  T vertical_gap_mm{};  ///< 0 for the main point
  HertzShape<T> shape{};
  KalkerCoefficients<T> c{};
};

/// Normal forces of the (up to) two points for wheel load q_n (> 0; <= 0 gives zero forces).
template <typename T>
struct NormalSplit {
  T normal_n[2]{};
  T vertical_approach_mm{};
};

template <typename T>
NormalSplit<T> split_wheel_load(const ContactPointData<T> (&points)[2], T q_n) noexcept;

template <typename T>
struct PointForces {
  T normal_n{};
  T sin_gamma{};   ///< of the point's contact angle
  T cos_gamma{1};  ///< (held at >= 0.05: angles beyond ~87 deg are not a wheel's)
  Creepage<T> creepage{};
  CreepForce<T> creep{};  ///< on the wheel, in the point's contact frame
  HertzPatch<T> patch{};
};

template <typename T>
struct WheelForces {
  PointForces<T> point[2]{};
  WheelYQ<T> yq{};
  DerailmentCheck<T> derailment{};
  Status derailment_status = Status::ok;  ///< of derailment_check (out_of_range: wheel lifted)
};

/// Nadal's limit at the profile's flange angle, computed once (at init): a wheel on its tread
/// would have to climb its flange.
template <typename T>
struct NadalReference {
  T angle_rad{};
  T mu{};
  T limit{};
  Status status{Status::invalid_argument};
};
template <typename T>
NadalReference<T> nadal_reference(T flange_angle_rad, T mu) noexcept;

/// The steps of wheel_forces, for other creep laws (the host's FASTSIM): the load split, Hertz
/// patches and creepages of the points (creep forces left zero) ...
template <typename T>
WheelForces<T> wheel_contact(const ContactPointData<T> (&points)[2], T q_n,
                             const WheelKinematics<T>& kinematics) noexcept;
/// ... and, once the points' creep forces are in, Y, Q and the check against Nadal's limit.
template <typename T>
void wheel_derailment(WheelForces<T>& wheel, const ContactPointData<T> (&points)[2],
                      const NadalReference<T>& nadal) noexcept;

/// A wheel's longitudinal creep force and spin moment summed over its points (N, N m).
template <typename T>
struct WheelContactTotals {
  T fx_n{};
  T mz_nm{};
};
template <typename T>
WheelContactTotals<T> wheel_totals(const WheelForces<T>& wheel) noexcept;

/// The whole wheel: split, creepages, Polach at each loaded point, Y/Q against Nadal's limit at
/// the larger of the reference's flange angle and the contact angles that carry load.
/// g_mpa: combined shear modulus.
template <typename T>
WheelForces<T> wheel_forces(const ContactPointData<T> (&points)[2], T q_n,
                            const WheelKinematics<T>& kinematics, T g_mpa,
                            const NadalReference<T>& nadal,
                            const PolachParameters<T>& polach) noexcept;

extern template Creepage<float> point_creepage<float>(const WheelKinematics<float>&, float,
                                                      float) noexcept;
extern template Creepage<double> point_creepage<double>(const WheelKinematics<double>&, double,
                                                        double) noexcept;
extern template NormalSplit<float> split_wheel_load<float>(const ContactPointData<float> (&)[2],
                                                           float) noexcept;
extern template NormalSplit<double> split_wheel_load<double>(const ContactPointData<double> (&)[2],
                                                             double) noexcept;
extern template WheelForces<float> wheel_forces<float>(const ContactPointData<float> (&)[2], float,
                                                       const WheelKinematics<float>&, float,
                                                       const NadalReference<float>&,
                                                       const PolachParameters<float>&) noexcept;
extern template WheelForces<double> wheel_forces<double>(const ContactPointData<double> (&)[2],
                                                         double, const WheelKinematics<double>&,
                                                         double, const NadalReference<double>&,
                                                         const PolachParameters<double>&) noexcept;
extern template WheelForces<float> wheel_contact<float>(const ContactPointData<float> (&)[2], float,
                                                        const WheelKinematics<float>&) noexcept;
extern template WheelForces<double> wheel_contact<double>(const ContactPointData<double> (&)[2],
                                                          double,
                                                          const WheelKinematics<double>&) noexcept;
extern template void wheel_derailment<float>(WheelForces<float>&,
                                             const ContactPointData<float> (&)[2],
                                             const NadalReference<float>&) noexcept;
extern template void wheel_derailment<double>(WheelForces<double>&,
                                              const ContactPointData<double> (&)[2],
                                              const NadalReference<double>&) noexcept;
extern template WheelContactTotals<float> wheel_totals<float>(const WheelForces<float>&) noexcept;
extern template WheelContactTotals<double> wheel_totals<double>(
    const WheelForces<double>&) noexcept;
extern template NadalReference<float> nadal_reference<float>(float, float) noexcept;
extern template NadalReference<double> nadal_reference<double>(double, double) noexcept;

}  // namespace tread::rail
