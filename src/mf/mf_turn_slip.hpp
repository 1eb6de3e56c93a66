#pragma once
// Turn slip (path curvature φt): the spin φ and the camber reduction εγ that the turn-slip factors
// ζ of the forces and the aligning moment are computed from (parseInputs with useTurnSlip). The
// factors themselves stay with their equations: ζ1 … ζ4 in mf_forces.hpp, ζ0, ζ2, ζ5 … ζ8 of Mz in
// mf_evaluate.hpp.

#include "mf/mf_detail_common.hpp"
#include "mf/mf_math.hpp"
#include "mf/mf_parameters.hpp"
#include "mf/mf_prepared.hpp"

namespace tread::mf::detail {

/// parseInputs with useTurnSlip: the spin φ = (ψ̇ − (1 − εγ)·ω·sin γ)/Vc' and εγ, from the limited
/// inputs and ω (rolling_radius).
template <typename T, typename P>
[[gnu::always_inline]] inline void turn_slip_spin(const MfParameters<P>& p, Prepared<T>& in) {
  const T fz = in.fz;
  const T alpha = in.alpha;
  const T gamma = in.gamma;
  const T phit = in.phit;
  const T vx = in.vx;
  const T fz0_prime = p.lfzo * p.fnomin_n;
  const T dfz = (fz - fz0_prime) / fz0_prime;
  const T vsy = -mf_tan(alpha) * abs(vx);
  T vc_prime = hypot_of(vx, vsy);
  in.epsilong = p.pecp1 * (T(1) + p.pecp2 * dfz);
  vc_prime = if_else(abs(vx) < p.vxlow_mps, p.vxlow_mps * sgn_nz(vx), vc_prime);
  const T psi_dot = -phit * vc_prime;
  in.phi = div_or(psi_dot - (T(1) - in.epsilong) * in.omega * mf_sin(gamma), vc_prime, T(0));
}

}  // namespace tread::mf::detail
