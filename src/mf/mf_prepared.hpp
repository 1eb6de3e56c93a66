#pragma once
// What the effects of one evaluation share: the inputs as MFeval's parseInputs leaves them
// (limited, low-speed reduced, with the rolling radius and the turn-slip spin) and calculateBasic's
// quantities (α*, γ*, the load and pressure increments, the friction scalings). Filled by
// mf_inputs.hpp; read by the forces, moments, radii, contact patch and relaxation lengths.

#include "mf/mf_detail_common.hpp"

namespace tread::mf::detail {

/// Inputs after MFeval's parseInputs (one row, userDynamics = 0).
template <typename T>
struct Prepared {
  T fz, kappa, alpha, gamma, phit, vx, p;  // limited
  T ufz, ukappa, ukappa_low, ualpha, ugamma;
  T fz_low_limit;
  MaskOf<T> is_low_speed{};
  T reduction_smooth = T(1);
  T dpi;
  T omega, re, romega;
  T phi = T(0), epsilong = T(0);
  MaskOf<T> out_of_range{};  // an input lay outside the finite-arithmetic envelope
};

/// Shared intermediate quantities (calculateBasic).
template <typename T>
struct Basic {
  T alpha_star, gamma_star, lmux_star, lmuy_star, lmux_prime, lmuy_prime;
  // Camber as seen by Fx and Mz: γ (and γ*) except for PAC2002, which scales it by LGAX / LGAZ
  // (and γ* = γ·LGAY for Fy).
  T gamma_x, gamma_star_x, gamma_z, gamma_star_z;
  T fz0_prime, cos_alpha_prime, dfz, dpi;  // cos α' = Vcx/Vc' (MFeval: cos(acos(Vcx/Vc')))
};

}  // namespace tread::mf::detail
