#pragma once
// The overturning moment Mx (calculateMx, Besselink's form with QSX12…14) and the rolling
// resistance moment My (calculateMy: MF 6.x with the camber and pressure terms, MF 5.2 / PAC2002
// without; MFeval's low-speed reduction).
// The aligning moment's trail coefficients (calculateMz0's Dt, Bt, Ct, Et); the rest of Mz is
// assembled in mf_evaluate.hpp.

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
  return p.unloaded_radius_m * fz * p.lmx *
             (p.qsx1 * p.lvmx - p.qsx2 * g * (T(1) + p.ppmx1 * b.dpi) - p.qsx12 * g * abs(g) +
              p.qsx3 * fy / fz0 +
              p.qsx4 * mf_cos(p.qsx5 * mf_atan((p.qsx6 * fz / fz0) * (p.qsx6 * fz / fz0))) *
                  mf_sin(p.qsx7 * g + p.qsx8 * mf_atan(p.qsx9 * fy / fz0)) +
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
    const T load = if_else(fz_ratio > T(0), mf_pow(fz_ratio, T(p.qsy7)), T(0));
    const T p_ratio = in.p / p.nompres_pa;
    const T pressure = is_zero(p.qsy8) ? T(1) : mf_pow(p_ratio, T(p.qsy8));
    m = -r0 * fz0 * p.lmy *
        (p.qsy1 + p.qsy2 * (fx / fz0) + p.qsy3 * abs(v) + p.qsy4 * v2 * v2 +
         (p.qsy5 + p.qsy6 * fz_ratio) * in.gamma * in.gamma) *
        (load * pressure);
  }
  m = if_else(vcx < T(0), -m, m);
  // Low-speed model ("empirically discovered").
  const T high_limit = p.vxlow_mps / abs(vcx) - T(1);
  const T low_limit = T(-1) - p.vxlow_mps - high_limit;
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
  const T kya_prime = y0.kya + eps * sgn_nz(y0.kya);
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

}  // namespace tread::mf::detail
