#pragma once
// Tangential contact: the quantities every creep-force law here shares.
//
// Conventions (those of Kalker and his CONTACT program): x is the rolling direction, y lateral, z
// the contact normal; the creepages are the rigid slip velocities of the wheel relative to the rail
// divided by the rolling speed V:
//     xi  = longitudinal creepage,  eta = lateral creepage  (dimensionless),
//     phi = spin creepage (rad/mm: spin angular velocity about the normal over V).
// Forces and moment are those acting on the wheel: a positive creepage gives a negative force.
// Units: N, mm, MPa (N/mm^2), N mm.

#include <cmath>

#include "rail/kalker_coefficients.hpp"

namespace tread::rail {

template <typename T>
struct Creepage {
  T xi{};
  T eta{};
  T phi_per_mm{};
};

/// The elastic contact the creep laws act on: a Hertz ellipse and its load, the combined shear
/// modulus and Kalker's coefficients for its a/b and Poisson ratio.
template <typename T>
struct CreepContact {
  T a_mm{};      ///< semi-axis along x
  T b_mm{};      ///< semi-axis along y
  T normal_n{};  ///< normal force N (> 0)
  T g_mpa{};     ///< combined shear modulus G = 2 G1 G2 / (G1 + G2)
  KalkerCoefficients<T> c{};
};

template <typename T>
struct CreepForce {
  T fx_n{};
  T fy_n{};
  T mz_nmm{};  ///< spin moment about the contact normal
};

/// Kalker's linear theory (no saturation): the exact small-creepage limit of every law here.
template <typename T>
CreepForce<T> kalker_linear(const CreepContact<T>& k, const Creepage<T>& s) noexcept {
  const T c2 = k.a_mm * k.b_mm;
  const T c1 = c2 > T{0} ? std::sqrt(c2) : T{0};
  const T g = k.g_mpa;
  return {-g * c2 * k.c.c11 * s.xi,
          -g * c2 * k.c.c22 * s.eta - g * c2 * c1 * k.c.c23 * s.phi_per_mm,
          g * c2 * c1 * k.c.c23 * s.eta - g * c2 * c2 * k.c.c33 * s.phi_per_mm};
}

}  // namespace tread::rail
