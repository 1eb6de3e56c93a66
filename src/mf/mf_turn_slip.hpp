#pragma once
// Turn slip (path curvature φt): the spin φ and the camber reduction εγ that the turn-slip factors
// ζ of the forces and the aligning moment are computed from (parseInputs with useTurnSlip), and
// the factors of the residual aligning moment (ζ0, ζ2, ζ6, ζ7, ζ8). The other factors stay with
// their equations: ζ1 … ζ4 in mf_forces.hpp, ζ5 with the trail in mf_moments.hpp.

#include "mf/mf_detail_common.hpp"
#include "mf/mf_forces.hpp"
#include "mf/mf_math.hpp"
#include "mf/mf_options.hpp"
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

/// The pneumatic trail's coefficients (calculateMz0; mz_trail in mf_moments.hpp): Dt, Bt, Ct, Et,
/// the slip angles αt of the trail and αr of the residual moment, the load Mz is computed with
/// (FZMIN as its lower limit with the limits on) and Kyα' (Kyα kept away from 0). Here because the
/// turn-slip factors of Mzr use its load.
template <typename T>
struct MzTrail {
  T fz_mz, kya_prime, alphar, alphat, dt, bt, ct, et;
};

/// The turn-slip factors of the residual aligning moment Mzr (calculateMz0): ζ0 (0 with turn slip),
/// ζ2 (Fy0's), ζ6 (of Br), ζ7 (Cr, from the spin moment at full spin Mzp∞ and at 90° slip Mzp90)
/// and ζ8 (1 + Drp, the spin part of Dr). All 1 without turn slip.
template <typename T>
struct MzTurnSlip {
  T zeta0 = T(1), zeta2 = T(1), zeta6 = T(1), zeta7 = T(1), zeta8 = T(1);
};

/// ζ0, ζ2, ζ6, ζ7, ζ8 of Mzr from the trail's load, Fy0's μy and ζ2, and Gyk.
template <typename T, typename P>
MzTurnSlip<T> mz_turn_slip(const MfParameters<P>& p, const Prepared<T>& in, const Basic<T>& b,
                           const MfOptions& options, const MzTrail<T>& tr, const Fy0Result<T>& y0,
                           const T& gyk) {
  MzTurnSlip<T> z;
  if (!options.use_turn_slip) return z;
  const T fz_mz = tr.fz_mz;
  const T muy = y0.muy;
  const T zeta2_fy = y0.zeta2;
  const T r0 = p.unloaded_radius_m;
  const T dfz = b.dfz;
  const T g = b.gamma_z;
  z.zeta0 = T(0);
  z.zeta2 = zeta2_fy;
  z.zeta6 = cos_atan(p.qbrp1 * r0 * in.phi);
  T mzp_inf = p.qcrp1 * abs(muy) * r0 * fz_mz * sqrt(fz_mz / b.fz0_prime) * p.lmp;
  mzp_inf = if_else(mzp_inf < T(0), T(1e-6), mzp_inf);
  const T cdrp = p.qdrp1;
  const T ddrp = div_or(mzp_inf, mf_sin(T(0.5) * pi<T>() * cdrp), T(0));
  const T kzgr0 =
      fz_mz * r0 * (p.qdz8 * p.qdz9 * dfz + (p.qdz10 + p.qdz11 * dfz * abs(g))) * p.lkzc;
  const T bdrp = div_or(kzgr0, cdrp * ddrp * (T(1) - in.epsilong), T(0));
  const T drp = ddrp * mf_sin(cdrp * mf_atan(bdrp * r0 * in.phit));
  const T mzp90 = mzp_inf * (T(2) / pi<T>()) * mf_atan(p.qcrp2 * r0 * abs(in.phit)) * gyk;
  // MFeval: acos(Mzp90/|Drp|), NaN for a ratio above 1 (e.g. 0/0 at φt = 0). Here the ratio
  // is clamped to [−1, 1]; Drp = 0 gives the turn-slip-free Cr = 1 where Mzp90 = 0 too (φt = 0),
  // and otherwise the limit of the clamped ratio, sign(Mzp90) (Cr = 0 or 2): Drp is 0 at φt ≠ 0
  // when Kzγr0 is (e.g. at Fz = FNOMIN for a file without QDZ10/QDZ11), and Cr must not jump
  // there.
  const T ratio = max_of(T(-1), min_of(T(1), div_or(mzp90, abs(drp), sgn(mzp90))));
  z.zeta7 = if_else(is_zero(drp) && is_zero(mzp90), T(1), (T(2) / pi<T>()) * acos(ratio));
  z.zeta8 = T(1) + drp;
  return z;
}

}  // namespace tread::mf::detail
