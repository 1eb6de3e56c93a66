#pragma once
// The overturning moment Mx (calculateMx, Besselink's form with QSX12…14) and the rolling
// resistance moment My (calculateMy: MF 6.x with the camber and pressure terms, MF 5.2 / PAC2002
// without; MFeval's low-speed reduction).
// The aligning moment Mz (calculateMz0 in pure slip, calculateMz in combined slip): the trail's
// coefficients (Dt, Bt, Ct, Et), the residual moment's (Dr, Br, Cr) and the assembly of Mz from the
// pneumatic trail t, the residual moment Mzr, Fy' and (combined) the arm s of Fx.

#include "mf/mf_detail_common.hpp"
#include "mf/mf_forces.hpp"
#include "mf/mf_math.hpp"
#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"
#include "mf/mf_prepared.hpp"
#include "mf/mf_turn_slip.hpp"

namespace tread::mf::detail {

/// calculateMx.
template <typename T, typename P>
T mx(const MfParameters<P>& p, const Prepared<T>& in, const Basic<T>& b, const T& fy) {
  T fz = in.fz;
  fz = if_else(fz < p.fzmin_n, fz * (fz / p.fzmin_n) * (fz / p.fzmin_n), fz);
  const T fz0 = p.fnomin_n;
  const T g = in.gamma;
  const TwoOf<T> at = mf_atan_two((p.qsx6 * fz / fz0) * (p.qsx6 * fz / fz0), p.qsx9 * fy / fz0);
  const TwoOf<T> cs = mf_cos_sin(p.qsx5 * at.first, p.qsx7 * g + p.qsx8 * at.second);
  return p.unloaded_radius_m * fz * p.lmx *
             (p.qsx1 * p.lvmx - p.qsx2 * g * (T(1) + p.ppmx1 * b.dpi) - p.qsx12 * g * abs(g) +
              p.qsx3 * fy / fz0 + p.qsx4 * cs.first * cs.second +
              p.qsx10 * mf_atan(p.qsx11 * fz / fz0) * g) +
         p.unloaded_radius_m * fy * p.lmx * (p.qsx13 + p.qsx14 * abs(g));
}

/// calculateMy.
template <typename T, typename P>
T my(const MfParameters<P>& p, const Prepared<T>& in, const T& fx) {
  T fz = in.ufz;
  fz = if_else(fz < p.fzmin_n, fz * (fz / p.fzmin_n), fz);
  const T vcx = in.vx;
  const auto stopped = is_zero(vcx);  // My = 0 (the rest is finite there and not used)
  if constexpr (!is_lanes<T>) {
    if (stopped) return T(0);
  }
  const T kappa = in.ukappa;
  const T fz0 = p.fnomin_n;
  const T r0 = p.unloaded_radius_m;
  const T v = vcx / p.longvl_mps;
  const T v2 = v * v;
  T m;
  if (is_mf5x(p)) {
    m = -r0 * fz * p.lmy * (p.qsy1 + p.qsy2 * (fx / fz0) + p.qsy3 * abs(v) + p.qsy4 * v2 * v2);
  } else {
    const T fz_ratio = fz / fz0;
    const T p_ratio = in.p / p.nompres_pa;
    T load;
    T pressure;
    if (is_zero(p.qsy8)) {
      load = if_else(fz_ratio > T(0), mf_pow(fz_ratio, T(p.qsy7)), T(0));
      pressure = T(1);
    } else {
      const TwoOf<T> powers = mf_pow_two(fz_ratio, T(p.qsy7), p_ratio, T(p.qsy8));
      load = if_else(fz_ratio > T(0), powers.first, T(0));
      pressure = powers.second;
    }
    m = -r0 * fz0 * p.lmy *
        (p.qsy1 + p.qsy2 * (fx / fz0) + p.qsy3 * abs(v) + p.qsy4 * v2 * v2 +
         (p.qsy5 + p.qsy6 * fz_ratio) * in.gamma * in.gamma) *
        (load * pressure);
  }
  m = if_else(vcx < T(0), -m, m);
  // Low-speed model ("empirically discovered"): My fades to 0 as the wheel's rotation stops
  // (κ = −1) and reverses beyond it, over the band where the circumferential speed is within
  // VXLOW, κ = −1 ± VXLOW/|Vx|. MFeval writes the lower end as −1 − VXLOW − high_limit, which is
  // this band only where VXLOW is 1 (in m/s; the same bits there); with VXLOW = 0.1 m/s it put
  // the reversal at κ ≈ −0.1 and gave a driving My under ordinary braking at 17 m/s.
  const T high_limit = p.vxlow_mps / abs(vcx) - T(1);
  const T low_limit = T(-2) - high_limit;
  const auto reduced = !(kappa < low_limit) && !(kappa > high_limit);
  if (any_lane(reduced)) {
    // interpolate((−1, 0), (high_limit, π/2)) at κ
    const T reduction = (pi<T>() / T(2)) * (kappa + T(1)) / (high_limit + T(1));
    m = if_else(reduced, m * mf_sin(reduction), m);
  }
  m = if_else(kappa < low_limit, -m, m);
  return if_else(stopped, T(0), m);
}

/// calculateMz0's trail coefficients, from Fy0's Kyα, SHy and SVy (ζ5 with turn slip).
template <typename T, typename P>
MzTrail<T> mz_trail(const MfParameters<P>& p, const Prepared<T>& in, const Basic<T>& b,
                    const MfOptions& options, const Fy0Result<T>& y0) {
  const T r0 = p.unloaded_radius_m;
  const T eps = T(1e-6);
  T fz_mz = in.fz;
  if (options.use_limits) fz_mz = if_else(in.fz > T(0), in.fz_low_limit, T(0));
  const T dfz = b.dfz;
  const T dpi = b.dpi;
  const T gs = b.gamma_star_z;
  const T g = b.gamma_z;
  const T sht = p.qhz1 + p.qhz2 * dfz + (p.qhz3 + p.qhz4 * dfz) * gs;
  const T kya_prime = y0.kya + sgn_nz_times(y0.kya, eps);
  const T shf = y0.shy + y0.svy / kya_prime;
  const T alphar = b.alpha_star + shf;
  const T alphat = b.alpha_star + sht;
  T zeta5 = T(1);
  if (options.use_turn_slip) zeta5 = cos_atan(p.qdtp1 * r0 * in.phi);
  const T dt = (p.qdz1 + p.qdz2 * dfz) * (T(1) - p.ppz1 * dpi) *
               (T(1) + p.qdz3 * g + p.qdz4 * g * g) * fz_mz * (r0 / b.fz0_prime) * p.ltr * zeta5;
  const T bt = (p.qbz1 + p.qbz2 * dfz + p.qbz3 * dfz * dfz) *
               (T(1) + p.qbz4 * g + p.qbz5 * abs(g)) * p.lky / b.lmuy_star;
  const T ct = p.qcz1;
  T et = (p.qez1 + p.qez2 * dfz + p.qez3 * dfz * dfz) *
         (T(1) + (p.qez4 + p.qez5 * gs) * (T(2) / pi<T>()) * mf_atan(bt * ct * alphat));
  if (options.use_limits) et = min_of(et, T(1));
  return {fz_mz, kya_prime, alphar, alphat, dt, bt, ct, et};
}

/// calculateMz's equivalent slip angles αr,eq and αt,eq: combined slip turns κ into an angle with
/// Kxκ/Kyα'.
template <typename T>
struct MzEquivalentSlip {
  T alphar_eq, alphat_eq;
};

template <typename T>
MzEquivalentSlip<T> mz_equivalent_slip(const Prepared<T>& in, const MzTrail<T>& tr, const T& kxk) {
  const T kk = div_or(kxk, tr.kya_prime, T(0)) * in.kappa;
  const TwoOf<T> tans = mf_tan_two(tr.alphar, tr.alphat);
  const TwoOf<T> eq = mf_atan_two(hypot_of(tans.first, kk), hypot_of(tans.second, kk));
  return {eq.first * sgn(tr.alphar), eq.second * sgn(tr.alphat)};
}

/// The residual aligning moment's Dr, Br and Cr (calculateMz0), with the turn-slip factors ζ.
template <typename T>
struct MzResidual {
  T dr, br, cr;
};

template <typename T, typename P>
MzResidual<T> mz_residual(const MfParameters<P>& p, const Prepared<T>& in, const Basic<T>& b,
                          const MzTrail<T>& tr, const Fy0Result<T>& y0, const MzTurnSlip<T>& zeta) {
  const T r0 = p.unloaded_radius_m;
  const T fz_mz = tr.fz_mz;
  const T dfz = b.dfz;
  const T dpi = b.dpi;
  const T gs = b.gamma_star_z;
  const T dr =
      fz_mz * r0 *
          ((p.qdz6 + p.qdz7 * dfz) * p.lres * zeta.zeta2 +
           ((p.qdz8 + p.qdz9 * dfz) * (T(1) + p.ppz2 * dpi) + (p.qdz10 + p.qdz11 * dfz) * abs(gs)) *
               gs * p.lkzc * zeta.zeta0) *
          b.lmuy_star * sgn(in.vx) * mf_cos(b.alpha_star) +
      zeta.zeta8 - T(1);
  const T br = (p.qbz9 * p.lky / b.lmuy_star + p.qbz10 * y0.by * y0.cy) * zeta.zeta6;
  const T cr = zeta.zeta7;
  return {dr, br, cr};
}

/// Mz with its pneumatic trail t and residual moment Mzr.
template <typename T>
struct MzResult {
  T mz, t, mzr;
};

/// Pure slip: calculateMz0's Mz0 = −t0·Fy0(γ = 0, no turn slip) + Mzr0.
template <typename T, typename P>
MzResult<T> mz_pure(const MfParameters<P>& p, const Prepared<T>& in, const Basic<T>& b,
                    const MfOptions& options, const MzTrail<T>& tr, const MzResidual<T>& r) {
  const T bta = tr.bt * tr.alphat;
  const T t =
      tr.dt * mf_cos(tr.ct * mf_atan(bta - tr.et * (bta - mf_atan(bta)))) * b.cos_alpha_prime;
  const T mzr = r.dr * mf_cos(r.cr * mf_atan(r.br * tr.alphar)) * b.cos_alpha_prime;
  const Fy0Result<T> y00_pure = fy0(p, in, b, options, T(0), false);
  return {-t * y00_pure.fy0 + mzr, t, mzr};
}

/// Combined slip (calculateMz): Mz = −t·Fy' + Mzr + s·Fx, from the trail's core at αt,eq, the
/// residual moment at αr,eq, Fy' (MF 5.x: Fy − SVyκ; MF 6.x: Gyκ·Fy0(γ = 0)) and the forces.
template <typename T, typename P>
MzResult<T> mz_combined(const MfParameters<P>& p, const Prepared<T>& in, const Basic<T>& b,
                        const MzTrail<T>& tr, const MzResidual<T>& r, const T& alphar_eq,
                        const T& trail_core, const T& fx, const T& fy, const T& fy_prime) {
  const T r0 = p.unloaded_radius_m;
  const T s =
      r0 * (p.ssz1 + p.ssz2 * (fy / p.fnomin_n) + (p.ssz3 + p.ssz4 * b.dfz) * b.gamma_z) * p.ls;
  T mzr = r.dr * mf_cos(r.cr * mf_atan(r.br * alphar_eq));
  T t = tr.dt * trail_core * b.cos_alpha_prime;
  t = t * p.lfzo;
  t = if_else(in.is_low_speed, t * in.reduction_smooth, t);
  mzr = if_else(in.is_low_speed, mzr * in.reduction_smooth, mzr);
  return {-t * fy_prime + mzr + s * fx, t, mzr};
}

}  // namespace tread::mf::detail
