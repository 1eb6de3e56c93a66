#pragma once
// A suspended wheelset on straight track: lateral displacement y and yaw angle psi, held to a frame
// that runs straight at the speed V by lateral and yaw springs and dampers (the primary
// suspension), driven by the wheel-rail contact forces (the classic two-degree-of-freedom model of
// wheelset hunting, e.g. Wickens):
//     m y''   = F_y(contact) - k_y y - c_y y'
//     I psi'' = M_z(contact) - k_psi psi - c_psi psi'
// with the contact's generalised forces from each wheel's Y (rail on wheel, toward the track
// centre), longitudinal creep force Fx and spin moment (rail/wheel_contact.hpp, the node's
// RailWheel outputs):
//     F_y = Y_right - Y_left,   M_z = -e0 (Fx_left - Fx_right) + Mz_left - Mz_right.
// (The left wheel sits at +e0, toward +y; the right wheel's spin moment is in its mirrored frame.)
//
// The step (wheelset_step) is linearly implicit with the linearised system's matrix: the creep
// damping grows as 1/V and makes an explicit step unstable at low speed, and a first-order step
// shifts the critical speed by several per cent at 1 kHz. The forces are those of this step (the
// node's answer); the matrix only steadies the step.
//
// Fixed-size Eigen types, no heap: every function here holds an EigenHeapForbidden while it runs,
// so a debug build asserts on any Eigen allocation (the build defines EIGEN_RUNTIME_NO_MALLOC, the
// run-time form of EIGEN_NO_MALLOC: see CMakeLists.txt), and tests/loop/no_allocation_test.cpp
// counts every allocation through the step and the eigen-analysis in any build.

#include <Eigen/Dense>

namespace tread::rail {

/// Forbids Eigen heap allocations while alive (with EIGEN_RUNTIME_NO_MALLOC; else nothing).
class EigenHeapForbidden {
 public:
#ifdef EIGEN_RUNTIME_NO_MALLOC
  EigenHeapForbidden() noexcept : allowed_before_(Eigen::internal::set_is_malloc_allowed(false)) {}
  ~EigenHeapForbidden() {
    Eigen::internal::set_is_malloc_allowed(allowed_before_);
  }
#else
  EigenHeapForbidden() noexcept = default;
#endif
  EigenHeapForbidden(const EigenHeapForbidden&) = delete;
  EigenHeapForbidden& operator=(const EigenHeapForbidden&) = delete;

 private:
#ifdef EIGEN_RUNTIME_NO_MALLOC
  bool allowed_before_;
#endif
};

template <typename T>
using Vector2 = Eigen::Matrix<T, 2, 1>;
template <typename T>
using Matrix2 = Eigen::Matrix<T, 2, 2>;

template <typename T>
struct WheelsetParams {
  T mass_kg{1500};
  T yaw_inertia_kgm2{800};
  T lateral_stiffness_n_per_m{1.0e6};           ///< k_y (both sides together)
  T yaw_stiffness_nm_per_rad{1.0e6};            ///< k_psi = 2 k_x b^2 (k_x 0.5 MN/m at b = 1 m)
  T lateral_damping_ns_per_m{0};                ///< c_y
  T yaw_damping_nms_per_rad{0};                 ///< c_psi
  T half_contact_base_m{static_cast<T>(0.75)};  ///< e0
  T wheel_load_n{80000};                        ///< static vertical load per wheel (16.3 t axle)
};

/// Wheelset state: q = (y [m], psi [rad]), v = (y', psi').
template <typename T>
struct WheelsetState {
  Vector2<T> q = Vector2<T>::Zero();
  Vector2<T> v = Vector2<T>::Zero();
};

/// One wheel's contact forces as the node answers them (N, N m).
template <typename T>
struct WheelContactForces {
  T y_n{};    ///< rail on wheel, toward the track centre
  T fx_n{};   ///< longitudinal creep force, forward
  T mz_nm{};  ///< spin moment in the wheel's own frame
};

/// The generalised contact forces (F_y [N], M_z [N m]) on the wheelset.
template <typename T>
Vector2<T> contact_generalised_force(const WheelContactForces<T>& left,
                                     const WheelContactForces<T>& right,
                                     T half_contact_base_m) noexcept {
  return Vector2<T>(right.y_n - left.y_n,
                    -half_contact_base_m * (left.fx_n - right.fx_n) + left.mz_nm - right.mz_nm);
}

template <typename T>
Matrix2<T> mass_matrix(const WheelsetParams<T>& p) noexcept {
  return Vector2<T>(p.mass_kg, p.yaw_inertia_kgm2).asDiagonal();
}
template <typename T>
Matrix2<T> suspension_stiffness(const WheelsetParams<T>& p) noexcept {
  return Vector2<T>(p.lateral_stiffness_n_per_m, p.yaw_stiffness_nm_per_rad).asDiagonal();
}
template <typename T>
Matrix2<T> suspension_damping(const WheelsetParams<T>& p) noexcept {
  return Vector2<T>(p.lateral_damping_ns_per_m, p.yaw_damping_nms_per_rad).asDiagonal();
}

/// The state derivative (y', psi', y'', psi'') under the contact force F.
template <typename T>
Eigen::Matrix<T, 4, 1> state_derivative(const WheelsetState<T>& s, const Vector2<T>& contact_force,
                                        const WheelsetParams<T>& p) noexcept {
  Eigen::Matrix<T, 4, 1> d;
  d.template head<2>() = s.v;
  d.template tail<2>() = mass_matrix(p).inverse() * (contact_force - suspension_stiffness(p) * s.q -
                                                     suspension_damping(p) * s.v);
  return d;
}

/// Advances the state by dt under the contact force F of this step, linearly implicit with the
/// system matrix J (system_matrix() at the equilibrium: the contact's stiffness and creep
/// damping):
///     (I - dt/2 J) dx = dt f(x_n),   x_n+1 = x_n + dx
/// (the trapezoidal rule with one force evaluation a step: second order while the motion stays
/// near the linearisation, A-stable whatever the creep damping at low speed, no numerical
/// damping of the hunting mode).
template <typename T>
void wheelset_step(WheelsetState<T>& s, const Vector2<T>& contact_force,
                   const Eigen::Matrix<T, 4, 4>& jacobian, const WheelsetParams<T>& p,
                   T dt) noexcept {
  const EigenHeapForbidden no_heap;
  const Eigen::Matrix<T, 4, 4> lhs = Eigen::Matrix<T, 4, 4>::Identity() - (dt / T{2}) * jacobian;
  const Eigen::Matrix<T, 4, 1> dx =
      lhs.partialPivLu().solve(dt * state_derivative(s, contact_force, p));
  s.q += dx.template head<2>();
  s.v += dx.template tail<2>();
}

/// The first-order system matrix of the linearised wheelset, state (y, psi, y', psi'):
///     A = [[0, I], [M^-1 (K_c - K), M^-1 (D_c - C)]]
/// with K_c, D_c the contact forces' derivatives with respect to q and v at the equilibrium.
template <typename T>
Eigen::Matrix<T, 4, 4> system_matrix(const WheelsetParams<T>& p,
                                     const Matrix2<T>& contact_stiffness,
                                     const Matrix2<T>& contact_damping) noexcept {
  const EigenHeapForbidden no_heap;
  const Matrix2<T> m_inv = mass_matrix(p).inverse();
  Eigen::Matrix<T, 4, 4> a = Eigen::Matrix<T, 4, 4>::Zero();
  a.template block<2, 2>(0, 2) = Matrix2<T>::Identity();
  a.template block<2, 2>(2, 0) = m_inv * (contact_stiffness - suspension_stiffness(p));
  a.template block<2, 2>(2, 2) = m_inv * (contact_damping - suspension_damping(p));
  return a;
}

}  // namespace tread::rail
