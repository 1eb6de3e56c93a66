#pragma once
// The inputs as the equations see them: MFeval's parseInputs (the finite-arithmetic envelope, the
// low-speed reductions, the limits of useMode, then Re and ω and the turn-slip spin where needed)
// and calculateBasic (α*, γ*, PAC2002's camber scalings, dfz, dpi, cos α').

#include "mf/mf_detail_common.hpp"
#include "mf/mf_math.hpp"
#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"
#include "mf/mf_prepared.hpp"
#include "mf/mf_radius.hpp"
#include "mf/mf_turn_slip.hpp"
#include "mf/mf_types.hpp"

namespace tread::mf::detail {

template <typename T>
T clamp_envelope(const T& x, const T& lo, const T& hi, MaskOf<T>& out_of_range) {
  const auto below = x < lo;
  const auto above = x > hi;
  out_of_range = out_of_range || below || above;
  return if_else(below, lo, if_else(above, hi, x));
}

/// parseInputs.
template <typename T, typename P>
Prepared<T> prepare(const MfParameters<P>& p, const MfInput<T>& input, const MfOptions& options) {
  Prepared<T> in;
  MaskOf<T>& status = in.out_of_range;
  // The finite-arithmetic envelope (not in MFeval; see the header comment). Fz < 0 is 0 (no
  // contact), not out of range.
  const T fz_env = T(10) * max_of(p.fzmax_n, p.fnomin_n);
  T fz = clamp_envelope(max_of(input.fz_n, T(0)), T(0), fz_env, status);
  T kappa = clamp_envelope(input.kappa, T(-100), T(100), status);
  T alpha = clamp_envelope(input.alpha_rad, T(-1.5707), T(1.5707), status);
  T gamma = clamp_envelope(input.gamma_rad, T(-1.5707), T(1.5707), status);
  T phit = clamp_envelope(input.phit_1pm, T(-100), T(100), status);
  const T vx = clamp_envelope(input.vx_mps, T(-1000), T(1000), status);
  T pressure = if_else(input.p_pa > T(0), input.p_pa, T(p.inflpres_pa));
  pressure = clamp_envelope(pressure, T(1e-6) * p.nompres_pa, T(100) * p.nompres_pa, status);

  in.ufz = fz;
  in.ukappa = kappa;
  in.ukappa_low = kappa;
  in.ualpha = alpha;
  in.ugamma = gamma;
  in.vx = vx;
  in.fz_low_limit = fz;

  if (options.use_limits) {
    // "empirically discovered"
    const auto turning = !is_zero(phit);
    if (any_lane(turning)) phit = if_else(turning, phit * mf_cos(alpha), phit);
    const T vxlow = p.vxlow_mps;
    const auto low = abs(vx) <= vxlow;
    in.is_low_speed = low;
    T reduction_linear = T(1);
    if (any_lane(low)) {
      const T wvlow = T(0.5) * (T(1) + mf_cos(pi<T>() * div_or(vx, vxlow, T(0))));
      in.reduction_smooth = if_else(low, T(1) - wvlow, T(1));
      reduction_linear = if_else(low, abs(div_or(vx, vxlow, T(0))), T(1));
      in.ukappa_low = if_else(low, in.ukappa_low * reduction_linear, in.ukappa_low);
      phit = if_else(low, phit * reduction_linear, phit);
    }
    // |Vx| + |tan α·Vx| < VXLOW needs |Vx| < VXLOW: skip the tan otherwise.
    const auto slow = abs(vx) < vxlow;
    const T vsy = any_lane(slow) ? if_else(slow, mf_tan(alpha) * vx, T(0)) : T(0);
    phit = if_else(vx < T(0), -phit, phit);
    const T speed_sum = abs(vx) + abs(vsy);
    kappa = if_else(low, kappa * reduction_linear, kappa);
    alpha = if_else(speed_sum < vxlow, alpha * (speed_sum / vxlow), alpha);

    alpha = max_of(alpha, T(p.alpmin_rad));
    alpha = min_of(alpha, T(p.alpmax_rad));
    gamma = max_of(gamma, T(p.cammin_rad));
    gamma = min_of(gamma, T(p.cammax_rad));
    fz = min_of(fz, T(p.fzmax_n));
    in.fz_low_limit = max_of(fz, T(p.fzmin_n));
    pressure = max_of(pressure, T(p.presmin_pa));
    pressure = min_of(pressure, T(p.presmax_pa));
    kappa = max_of(kappa, T(p.kpumin));
    kappa = min_of(kappa, T(p.kpumax));
  }
  in.ualpha = if_else(is_zero(vx), T(0), in.ualpha);  // "zero speed (empirically discovered)"

  in.fz = fz;
  in.kappa = kappa;
  in.alpha = alpha;
  in.gamma = gamma;
  in.phit = phit;
  in.p = pressure;
  in.dpi = (pressure - p.nompres_pa) / p.nompres_pa;

  if (options.use_turn_slip || options.extras) rolling_radius(p, in);
  if (options.use_turn_slip) turn_slip_spin(p, in);
  return in;
}

/// calculateBasic. With `tan_gamma`, where two tangents cost about one (kTwoForOne), also tan γ
/// beside tan α, for MF 6.2's loaded radius (its camber deflection).
template <typename T, typename P>
Basic<T> basic(const MfParameters<P>& p, const Prepared<T>& in, const MfOptions& options,
               T* tan_gamma = nullptr) {
  Basic<T> b;
  const T vcx = in.vx;
  // A lambda, not a helper function: written as a function (or as an if/else here) it changed how
  // GCC contracted the 8-lane batch's tan α into FMAs, and the batch no longer gave evaluate_four's
  // bits in 3 % of the evaluations of a random set (MfEvaluateBatch.EqualsEvaluateFour).
  const auto tan_of_alpha = [&]() __attribute__((always_inline)) {
    if constexpr (kTwoForOne<T>) {
      if (tan_gamma != nullptr) {
        const TwoOf<T> both = mf_tan_two(in.alpha, in.gamma);
        *tan_gamma = both.second;
        return both.first;
      }
    }
    return mf_tan(in.alpha);
  };
  const T tan_alpha = tan_of_alpha();
  const T vsy = tan_alpha * abs(vcx);
  const T vc = hypot_of(vcx, vsy);
  b.fz0_prime = p.lfzo * p.fnomin_n;
  b.dfz = (in.fz - b.fz0_prime) / b.fz0_prime;
  b.dpi = (in.p - p.nompres_pa) / p.nompres_pa;
  if (options.use_alpha_star) {
    b.alpha_star = tan_alpha * sgn(vcx);
    b.gamma_star = mf_sin(in.gamma);
  } else {
    b.alpha_star = in.alpha;
    b.gamma_star = in.gamma;
  }
  b.gamma_x = in.gamma;
  b.gamma_star_x = b.gamma_star;
  b.gamma_z = in.gamma;
  b.gamma_star_z = b.gamma_star;
  if (p.fit_type == FitType::pac2002) {
    b.gamma_x = in.gamma * p.lgax;
    b.gamma_star_x = b.gamma_star * p.lgax;
    b.gamma_z = in.gamma * p.lgaz;
    b.gamma_star_z = b.gamma_star * p.lgaz;
    b.gamma_star = b.gamma_star * p.lgay;
  }
  const T vc_prime = vc + sgn_nz_times(vc, T(1e-6));
  // |Vcx/Vc'| < 1 mathematically; the clamp only absorbs rounding. α' itself is only used as cos
  // α'.
  b.cos_alpha_prime = max_of(T(-1), min_of(T(1), vcx / vc_prime));
  // LMUV = 0 → LMU*_star = LMU*; A_mu = 1 → LMU*_prime = LMU*_star.
  b.lmux_star = p.lmux;
  b.lmuy_star = p.lmuy;
  b.lmux_prime = b.lmux_star;
  b.lmuy_prime = b.lmuy_star;
  return b;
}

}  // namespace tread::mf::detail
