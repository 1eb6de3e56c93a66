#pragma once
// Polach's creep-force method: a closed form for the tangential force of an elliptic Hertz contact
// with a linear growth of the tangential stress in the adhesion area and Coulomb friction in the
// slip area (Polach, Vehicle System Dynamics 33 suppl., 1999: the method and its spin term; Wear
// 258, 2005: the adhesion-reduction factors and friction falling with slip velocity).
//
// With the creepage magnitude s_c = |(xi, eta_c)|, eta_c = eta + phi a when that is larger in
// magnitude than eta (else eta), and Kalker's coefficients weighted by the direction of the
// creepage without spin, c = |(C11 xi, C22 eta)| / |(xi, eta)|, the gradient of tangential stress
// in the adhesion area is
//     eps = (pi / 4) G a b c s_c / (mu Q),
// and the force magnitude
//     F = (2 mu Q / pi) (kA eps / (1 + (kA eps)^2) + atan(kS eps)),
// directed against (xi, eta) (so for C11 != C22 the linear-range direction is (xi, eta), not
// Kalker's (C11 xi, C22 eta); the magnitude is his). With kA = kS = 1 its slope at s -> 0 is
// Kalker's linear force, and F -> mu Q as s grows. Friction falls with the slip velocity w = s V:
//     mu = mu0 ((1 - A) exp(-B w) + A).
// Spin adds a lateral force F_yS (Polach 1999; sign of its bracket checked by these limits), with
// the same two limits: Kalker's -G c^3 C23 phi
// at small spin, and zero at full sliding (a pure spin in full slip has no net force).
//
// The spin moment is not part of Polach's method. Here it is Kalker's linear moment scaled by the
// ratio of the saturated to the linear tangential force (an approximation; FASTSIM computes it from
// the traction field, see fastsim.hpp).

#include "rail/creep_force.hpp"

namespace tread::rail {

template <typename T>
struct PolachParameters {
  T mu0{static_cast<T>(0.36)};  ///< maximum (static) friction coefficient
  T a_ratio{1};                 ///< A = mu_infinity / mu0 (1: no fall with slip velocity)
  T b_s_per_m{0};               ///< B, exponential rate of the fall (s/m)
  T k_adhesion{1};  ///< kA: reduction of the stress gradient in the adhesion area (0 < kA <= 1)
  T k_slip{1};      ///< kS: reduction in the slip area (0 < kS <= kA)
};

/// Creep force on the wheel. speed_m_s is the rolling speed V (for the slip velocity s V).
/// Normal force <= 0 gives zero force. Never NaN or infinite for finite inputs.
template <typename T>
CreepForce<T> polach_creep(const CreepContact<T>& contact, const Creepage<T>& creepage, T speed_m_s,
                           const PolachParameters<T>& p) noexcept;

/// The friction coefficient Polach's law gives at slip velocity w (m/s).
template <typename T>
T polach_friction(const PolachParameters<T>& p, T slip_velocity_m_s) noexcept;

extern template CreepForce<float> polach_creep<float>(const CreepContact<float>&,
                                                      const Creepage<float>&, float,
                                                      const PolachParameters<float>&) noexcept;
extern template CreepForce<double> polach_creep<double>(const CreepContact<double>&,
                                                        const Creepage<double>&, double,
                                                        const PolachParameters<double>&) noexcept;
extern template float polach_friction<float>(const PolachParameters<float>&, float) noexcept;
extern template double polach_friction<double>(const PolachParameters<double>&, double) noexcept;

}  // namespace tread::rail
