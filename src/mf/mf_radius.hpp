#pragma once
// The tyre's radii: the effective rolling radius Re and the angular speed ω (calculateRe, by
// MFeval's fixed-point iteration) and doExtras' loaded radius Rl, deflection ρ and vertical
// stiffness Cz: for MF 6.1 the quadratic in ρ/R0 solved in closed form, for MF 6.2, MF 5.2 and
// PAC2002 the root of MF 6.2's vertical force Fz62(Rl) = Fz by a safeguarded Newton iteration.

#include "mf/mf_detail_common.hpp"
#include "mf/mf_math.hpp"
#include "mf/mf_parameters.hpp"
#include "mf/mf_prepared.hpp"
#include "mf/mf_types.hpp"

#include <cmath>
#include <type_traits>

namespace tread::mf::detail {

/// calculateRe: Re by MFeval's fixed-point iteration on omega = (κ·Vx + Vx)/Re (unlimited κ, Fz,
/// Vx).
template <typename T, typename P>
void rolling_radius(const MfParameters<P>& p, Prepared<T>& in) {
  const T r0 = p.unloaded_radius_m;
  const T fz0 = p.fnomin_n;
  const T cz = p.vertical_stiffness_npm * (T(1) + p.pfz1 * in.dpi);
  const T deflection =
      (fz0 / cz) * (p.dreff * mf_atan(p.breff * (in.ufz / fz0)) + p.freff * (in.ufz / fz0));
  T re = r0 * T(0.965);
  T re_old = r0;
  T omega = T(0);
  T romega = r0 * p.q_re0;
  // MFeval: while |Re_old − Re| > 1e-9 (in float and fixed point: 1e-6, the 1e-9 step is at or
  // below their resolution of a radius). The cap only guards against a diverging file.
  // Lanes iterate until all have converged; a converged lane keeps its values.
  const T tolerance = T(std::is_same_v<T, float> || is_lanes<T> || is_fixed_point<T> ? 1e-6 : 1e-9);
  for (int i = 0; i < 100; ++i) {
    const auto active = abs(re_old - re) > tolerance;
    if (!any_lane(active)) break;
    const T omega_next = div_or(in.ukappa * in.vx + in.vx, re, T(0));
    const T speed = (omega_next * r0) / p.longvl_mps;
    const T romega_next = r0 * (p.q_re0 + p.q_v1 * speed * speed);
    re_old = if_else(active, re, re_old);
    omega = if_else(active, omega_next, omega);
    romega = if_else(active, romega_next, romega);
    re = if_else(active, romega_next - deflection, re);
  }
  in.re = re;
  in.omega = omega;
  in.romega = romega;
}

/// MF 6.2's vertical force as a function of the loaded radius, Fz62(Rl) (calculateFz62), at a
/// given γ, ω, Romega, Fx, Fy and pressure. What does not depend on Rl is computed once here
/// (√ of Q_FZ1, tan γ, the speed and Fx corrections, the coefficients times γ), so the root
/// search below pays per step only for the Rl-dependent part.
template <typename T, typename P>
struct Fz62Curve {
  P q_fcy2;
  T r0, fz0, romega, width, inv_r0, inv_romega;
  T q_fz1, q_fz2;
  T q_cam1, q_cam2;
  T camber_scale;            // (rtw/8)·|tan γ|·γ² / den², 0 where den = 0 (MFeval: NaN → 0)
  T free_share;              // 1 − Q_CAM3·|γ|: the free-rolling deflection's share of ρz
  T inv_free_share;          // 1 / max(free_share, 0.1): the start's use of it
  T fys1_g, fys2_g, fys3_g;  // Q_FYS1…3·γ
  T base;                    // 1 + Q_V2·(R0/V0)·|ω| − (Q_FCX·Fx/Fz0)²
  T pressure;                // 1 + PFZ1·dpi
  T fcy_per_force;           // Q_FCY / Fz0
  T fy;
  T pow_c1, pow_c2, pow_c3, pow_c4, pow_c5, pow_c6;  // binomial coefficients C(Q_FCY2, k)
  T pow_c7_abs;                                      // |C(Q_FCY2, 7)|: the series' remainder
  T pow_d2, pow_d3, pow_d4, pow_d5, pow_d6;          // k·C(Q_FCY2, k): the series' derivative
};

template <typename T, typename P>
Fz62Curve<T, P> fz62_curve(const MfParameters<P>& p, const T& gamma, const T& omega,
                           const T& romega, const T& dpi, const T& fx, const T& fy) {
  // What depends on the parameters only is computed in their scalar type P (for the lanes: once,
  // not per lane) and broadcast.
  Fz62Curve<T, P> c;
  const P r0 = p.unloaded_radius_m;
  const P fz0 = p.fnomin_n;
  c.q_fcy2 = p.q_fcy2;
  c.r0 = r0;
  c.fz0 = fz0;
  c.romega = romega;
  c.width = p.width_m;
  c.inv_r0 = T(P(1) / r0);
  c.inv_romega = T(1) / romega;
  const P a = p.vertical_stiffness_npm * r0 / fz0;
  c.q_fz1 = T(sqrt(max_of(P(0), a * a - P(4) * p.q_fz2)));
  c.q_fz2 = p.q_fz2;
  c.q_cam1 = p.q_cam1;
  c.q_cam2 = p.q_cam2;
  const P rtw_8 = (P(1.075) - P(0.5) * p.aspect_ratio) * p.width_m / P(8);
  const T den = (p.q_cam1 * romega + p.q_cam2 * romega * romega) * gamma;
  const auto cambered = !is_zero(den);
  c.camber_scale = T(0);
  if (any_lane(cambered)) {
    c.camber_scale =
        if_else(cambered, (gamma * gamma) * T(rtw_8) * abs(mf_tan(gamma)) / (den * den), T(0));
  }
  c.free_share = T(1) - p.q_cam3 * abs(gamma);
  c.inv_free_share = T(1) / max_of(c.free_share, T(0.1));
  c.fys1_g = p.q_fys1 * gamma;
  c.fys2_g = p.q_fys2 * gamma;
  c.fys3_g = p.q_fys3 * gamma;
  const T fcx = fx * T(p.q_fcx / fz0);
  c.base = T(1) + T(p.q_v2 * (r0 / p.longvl_mps)) * abs(omega) - fcx * fcx;
  c.pressure = T(1) + p.pfz1 * dpi;
  c.fcy_per_force = T(P(p.q_fcy) / fz0);
  c.fy = fy;
  const P q = p.q_fcy2;
  const P c2 = q * (q - P(1)) / P(2);
  const P c3 = c2 * (q - P(2)) / P(3);
  const P c4 = c3 * (q - P(3)) / P(4);
  const P c5 = c4 * (q - P(4)) / P(5);
  const P c6 = c5 * (q - P(5)) / P(6);
  const P c7 = c6 * (q - P(6)) / P(7);
  c.pow_c1 = q;
  c.pow_c2 = c2;
  c.pow_c3 = c3;
  c.pow_c4 = c4;
  c.pow_c5 = c5;
  c.pow_c6 = c6;
  // At least 1e-3: at a whole Q_FCY2 C(q,7) is 0 and the series exact in value, but not its
  // derivative with respect to Q_FCY2 (a fit's Jet), whose truncation this keeps below ε/2e-3.
  c.pow_c7_abs = T(max_of(c7 < P(0) ? -c7 : c7, P(1e-3)));
  c.pow_d2 = T(P(2) * c2);
  c.pow_d3 = T(P(3) * c3);
  c.pow_d4 = T(P(4) * c4);
  c.pow_d5 = T(P(5) * c5);
  c.pow_d6 = T(P(6) * c6);
  return c;
}

/// The deflection ρz at a loaded radius: free-rolling ρ plus the camber part; its slope dρz/dRl.
template <typename T, typename P>
[[gnu::always_inline]] inline T fz62_deflection(const Fz62Curve<T, P>& c, const T& rl, T& slope) {
  const auto compressed = rl < c.romega;
  const T rho_zfr = max_of(c.romega - rl, T(0));
  const T cam = c.q_cam1 * rl + c.q_cam2 * rl * rl;
  const T camber = c.camber_scale * cam;
  const T rho_z = rho_zfr * c.free_share + camber * cam;
  const T drho_z =
      T(2) * camber * (c.q_cam1 + T(2) * c.q_cam2 * rl) - if_else(compressed, c.free_share, T(0));
  const auto positive = rho_z > T(0);
  slope = if_else(positive, drho_z, T(0));
  return if_else(positive, rho_z, T(0));
}

/// (ρz/R0)^Q_FCY2 at the last point where it was computed exactly: the Newton steps near a root
/// move ρz by little, and a Taylor series about that point is exact to the output's resolution
/// there at a fraction of pow's cost.
template <typename T>
struct Fz62PowMemo {
  T base = T(0);  // ρz/R0 where pow was evaluated (0: none yet)
  T inv_base = T(0);
  T value = T(0);
};

/// x^q and its derivative q·x^(q−1) from the memo's base b: (b·(1 + δ))^q = b^q·(1 + C(q,1)δ
/// + … + C(q,6)δ⁶) where the remainder max(|C(q,7)|, 1e-3)·|δ|⁷ is below half of ε (|δ| < ¼), else
/// pow, which becomes the new base.
template <typename T, typename P>
[[gnu::always_inline]] inline T fz62_pow(const Fz62Curve<T, P>& c, const T& x, Fz62PowMemo<T>& memo,
                                         T& derivative) {
  constexpr bool coarse = std::is_same_v<T, float> || is_lanes<T> || is_fixed_point<T>;
  // Without a base in any lane (the first step, as a rule) pow alone, without the series.
  auto near = memo.base > T(0);
  T series = T(0);
  if (any_lane(near)) {
    const T delta = x * memo.inv_base - T(1);
    const T d = abs(delta);
    const T d3 = d * d * d;
    near = near && d < T(0.25) && c.pow_c7_abs * (d3 * d3 * d) < T(coarse ? 6e-8 : 1.1e-16);
    // Estrin's scheme: three independent pairs, then δ² and δ⁴ (a shorter chain than Horner's).
    const T delta2 = delta * delta;
    const T s12 = c.pow_c1 + delta * c.pow_c2;
    const T s34 = c.pow_c3 + delta * c.pow_c4;
    const T s56 = c.pow_c5 + delta * c.pow_c6;
    series = memo.value * (T(1) + delta * (s12 + delta2 * (s34 + delta2 * s56)));
    const T d12 = c.pow_c1 + delta * c.pow_d2;
    const T d34 = c.pow_d3 + delta * c.pow_d4;
    const T d56 = c.pow_d5 + delta * c.pow_d6;
    derivative = memo.value * memo.inv_base * (d12 + delta2 * (d34 + delta2 * d56));
  }
  const auto far = !near;
  if (!any_lane(far)) return series;
  const T exact = T(pow(x, T(c.q_fcy2)));
  const T inv_x = T(1) / x;
  memo.base = if_else(far, x, memo.base);
  memo.inv_base = if_else(far, inv_x, memo.inv_base);
  memo.value = if_else(far, exact, memo.value);
  derivative = if_else(far, c.pow_c1 * exact * inv_x, derivative);
  return if_else(far, exact, series);
}

/// Fz62(Rl) and its slope dFz62/dRl; writes the deflection ρz.
template <typename T, typename P>
[[gnu::always_inline]] inline T fz62(const Fz62Curve<T, P>& c, const T& rl, T& slope, T& rho_z,
                                     Fz62PowMemo<T>& memo) {
  T drho_z = T(0);
  rho_z = fz62_deflection(c, rl, drho_z);
  const T rho_r0 = rho_z * c.inv_r0;
  const T drho_r0 = drho_z * c.inv_r0;
  // Lateral force correction: Fy less the camber's share Sfyg (a polynomial in Rl/Romega).
  const T ratio = rl * c.inv_romega;
  const T sfyg = c.fys1_g + (c.fys2_g + c.fys3_g * ratio) * ratio;
  const T dsfyg = (c.fys2_g + T(2) * c.fys3_g * ratio) * c.inv_romega;
  const auto loaded = rho_r0 > T(0);
  T rho_pow = is_zero(c.q_fcy2) ? T(1) : T(0);
  T drho_pow = T(0);
  if (any_lane(loaded)) {
    T derivative = T(0);
    rho_pow =
        if_else(loaded, fz62_pow(c, if_else(loaded, rho_r0, T(1)), memo, derivative), rho_pow);
    drho_pow = if_else(loaded, derivative * drho_r0, T(0));
  }
  const T lateral = c.fcy_per_force * (c.fy - sfyg);
  const T fcy = rho_pow * lateral;
  const T dfcy = drho_pow * lateral - rho_pow * c.fcy_per_force * dsfyg;
  const T fcorr = (c.base - fcy * fcy) * c.pressure;
  const T stiffness = (c.q_fz1 + c.q_fz2 * rho_r0) * rho_r0 * c.fz0;
  slope = T(-2) * fcy * dfcy * c.pressure * stiffness +
          fcorr * (c.q_fz1 + T(2) * c.q_fz2 * rho_r0) * drho_r0 * c.fz0;
  return fcorr * stiffness;
}

/// x = ρ/R0 with q_fz2·x² + q_fz1·x = Fz / ((base − Fcy²)·(1 + PFZ1·dpi)·Fz0), the positive root
/// written without cancellation; 0 where the right side is not positive.
template <typename T, typename P>
[[gnu::always_inline]] inline T quadratic_deflection(const Fz62Curve<T, P>& c, const T& fz,
                                                     const T& fcy) {
  const T external = (c.base - fcy * fcy) * c.pressure * c.fz0;
  const T q = max_of(div_or(fz, external, T(0)), T(0));
  return div_or(T(2) * q, c.q_fz1 + sqrt(c.q_fz1 * c.q_fz1 + T(4) * c.q_fz2 * q), T(0));
}

template <typename T>
struct LoadedRadius62 {
  T rl_m;
  T rho_m;
  int newton_steps;  // steps of the safeguarded Newton iteration (the most of any lane)
  bool fallback;     // a lane needed the bisection fallback (never in the tested envelope)
};

/// Rl with Fz62(Rl) = Fz: a safeguarded Newton iteration on the branch where the root lies.
/// - The branch: below Romega the tyre is compressed and Fz62 falls steeply with Rl; only where the
///   camber deflection alone carries more than Fz (a light, cambered wheel) does the root lie above
///   Romega. Above Romega Fz62 is a hump (Q_FYS's Sfyg grows with Rl/Romega), and just below it,
///   with Fy ≠ 0, it may dip (ρ^Q_FCY2): the bracket, [0, Romega] or [Romega, Romega + w], keeps
///   the search on the one branch. Romega's end is known (Fz62 evaluated there); the far end is
///   evaluated when a step would leave the bracket towards it: if Fz62 is on the same side of Fz
///   there, the branch has no root (loads beyond a fully squashed tyre, |γ| near 90° with the
///   limits off) and that end is the answer, as bisection gives.
/// - Start: the MF 6.1-style deflection (the quadratic in ρ/R0 with the Rl-independent
///   corrections) less the camber's deflection at Romega. On lanes, where the slowest lane sets
///   the number of steps, the quadratic is solved once more with Fcy's factor (ρz/R0)^Q_FCY2
///   (pow_estimate, within 1e-3·|Q_FCY2| + 2e-4) and Sfyg at the first solution, kept within
///   [0.7, 1.5] of it: on the benchmark's points this takes the groups of four needing 3 steps
///   from 75 % to 13 %. The scalar paths do without it: there it costs about as much as the step
///   it saves (measured).
/// - A step is Newton's where it lands inside the bracket and the slope is negative, else the
///   bracket's midpoint (or its far end, not yet evaluated). Converged when a Newton step is at
///   most R0·ε^(3/4), ε of the output type: the error after it is of order the step² times
///   Fz62''/Fz62' (≲ 1e3 /m at the lightest loads), below ε·R0.
/// tests/mf/mf62_loaded_radius_test.cpp shows over the envelope (every MF 6.2, MF 5.2 and PAC2002
/// test tyre, loads 0 … 10·FZMAX, |γ| to 1.5707, slips, speeds, pressures, limits on and off) that
/// it converges in at most 13 steps (3–5 at most points; MF 5.2 and PAC2002, without the camber
/// and lateral terms, in 1: the start is their root) to the least-deflection root, the one a tyre
/// reaches when loaded from Romega. Should a lane still be unconverged after kNewtonSteps,
/// bisection of its remaining bracket finishes it (lanes: a converged lane keeps its value).
/// Outside the envelope, where 1 + PFZ1·dpi < 0 (a tyre of negative stiffness: PFZ1 > 1 at a low
/// pressure with the limits off), Fz62 below Romega is positive only on a hump near Romega
/// (where Fcy² > 1 + speed − Fx²); where the hump reaches Fz, a step that leaves the bracket
/// evaluates Rl = 0, finds Fz62 below Fz there and answers 0, not the hump's root
/// (Mf62LoadedRadius.PressureFactorAtOrBelowZero counts these points).
template <typename T, typename P>
LoadedRadius62<T> loaded_radius62(const Fz62Curve<T, P>& c, const T& fz_target) {
  constexpr int kNewtonSteps = 16;
  constexpr bool coarse = std::is_same_v<T, float> || is_lanes<T> || is_fixed_point<T>;
  // ε^(3/4): float 6.4e-6, double 1.8e-12 (fixed point Q31.32 as float: its resolution of a
  // radius, 2.3e-10 m, is float's).
  const T tolerance = c.r0 * T(coarse ? 6.4e-6 : 1.8e-12);
  const T settle = c.r0 * T(coarse ? 1.2e-7 : 2.2e-16);  // ε·R0: the error aimed at
  // Fz62(Romega) = (1 + speed − Fx² − Fcy²)(1 + PFZ1·dpi)·stiffness(ρz) is at most the pow-free
  // bound (1 + speed − Fx²)(1 + PFZ1·dpi)·stiffness(ρz) where 1 + PFZ1·dpi > 0: it is evaluated
  // only where that bound exceeds Fz (light, cambered wheels) or where the pressure factor is not
  // positive (PFZ1 > 1 at a low pressure with the limits off, or a pressure below 0), where
  // Fz62(Romega) may exceed Fz with the bound below it.
  Fz62PowMemo<T> memo;
  T slope_romega = T(0);
  const T rho_romega = fz62_deflection(c, c.romega, slope_romega);
  const T rho_romega_r0 = rho_romega / c.r0;
  const T bound = c.base * c.pressure *
                  (c.q_fz1 * rho_romega_r0 + c.q_fz2 * rho_romega_r0 * rho_romega_r0) * c.fz0;
  const auto evaluated = bound > fz_target || !(c.pressure > T(0));
  auto beyond = T(0) > T(0);  // no lane
  if (any_lane(evaluated)) {
    T rho_unused = T(0);
    beyond = evaluated && fz62(c, c.romega, slope_romega, rho_unused, memo) > fz_target;
    // Only those lanes keep the pow's memo (a lane's result must not depend on its neighbours).
    memo.base = if_else(evaluated, memo.base, T(0));
    memo.value = if_else(evaluated, memo.value, T(0));
    memo.inv_base = if_else(evaluated, memo.inv_base, T(0));
  }
  const T lo_end = if_else(beyond, c.romega, T(0));
  const T hi_end = if_else(beyond, c.romega + c.width, c.romega);
  T lo = lo_end;
  T hi = hi_end;
  auto lo_known = beyond;   // Fz62(lo) > Fz is known
  auto hi_known = !beyond;  // Fz62(hi) ≤ Fz is known
  // Start: q_fz2·x² + q_fz1·x = Fz / ((1 + speed − Fx² − Fcy²)(1 + PFZ1·dpi)·Fz0), x = ρ/R0.
  T x0 = quadratic_deflection(c, fz_target, c.fcy_per_force * c.fy);
  if constexpr (is_lanes<T>) {
    const auto ok = x0 > T(0);
    const T factor = if_else(ok, pow_estimate(x0, T(c.q_fcy2)), T(1));
    const T ratio = T(1) - x0 * c.r0 * c.inv_romega;
    const T sfyg = c.fys1_g + (c.fys2_g + c.fys3_g * ratio) * ratio;
    const T x1 = quadratic_deflection(c, fz_target, factor * c.fcy_per_force * (c.fy - sfyg));
    x0 = if_else(x1 > T(0), min_of(max_of(x1, T(0.7) * x0), T(1.5) * x0), x0);
  }
  // The camber's deflection at Romega is carried already; the free-rolling part makes up the rest.
  const T rho_zfr0 = max_of(x0 * c.r0 - rho_romega, T(0)) * c.inv_free_share;
  T rl = min_of(max_of(c.romega - rho_zfr0, lo), hi);
  auto active = !(T(0) > T(0));  // every lane
  auto previous_newton = !active;
  T previous_step = T(0);
  LoadedRadius62<T> result{T(0), T(0), 0, false};
  for (int i = 0; i < kNewtonSteps; ++i) {
    T slope = T(0);
    T rho = T(0);
    const T resid = fz62(c, rl, slope, rho, memo) - fz_target;
    const auto above = resid > T(0);
    lo = if_else(active && above, rl, lo);
    hi = if_else(active && !above, rl, hi);
    lo_known = lo_known || (active && above);
    hi_known = hi_known || (active && !above);
    const T step = -div_or(resid, slope, T(0));
    const T newton = rl + step;
    const auto falling = slope < T(0);
    // Converged: a step at most the tolerance (it may round onto the bracket's end it came
    // from), or a Newton step after a Newton step whose remaining error, C·step² with
    // C ≈ step / previous² (quadratic convergence), is at most ε·R0: |step|³ ≤ ε·R0·previous²
    // (this saves the confirming step).
    // At an end with Fz62 on the far side of Fz, the branch has no root: that end.
    const auto no_root = (above && !(rl < hi_end)) || (!above && !(rl > lo_end));
    const T step_abs = abs(step);
    const auto settled = previous_newton && step_abs < previous_step &&
                         !(step_abs * step_abs * step_abs > settle * previous_step * previous_step);
    const auto converged =
        is_zero(resid) || no_root || (falling && (!(step_abs > tolerance) || settled));
    const auto inside = falling && newton > lo && newton < hi;
    T next = if_else(inside, newton, T(0.5) * (lo + hi));
    next = if_else(!inside && above && !hi_known, hi_end, next);
    next = if_else(!inside && !above && !lo_known, lo_end, next);
    next = if_else(converged, if_else(no_root, rl, min_of(max_of(newton, lo), hi)), next);
    rl = if_else(active, next, rl);
    previous_newton = inside;
    previous_step = step_abs;
    active = active && !converged;
    result.newton_steps = i + 1;
    if (!any_lane(active)) break;
  }
  if (any_lane(active)) {
    result.fallback = true;
    for (int i = 0; i < 80; ++i) {
      const T mid = T(0.5) * (lo + hi);
      T slope = T(0);
      T rho = T(0);
      const auto above = fz62(c, mid, slope, rho, memo) > fz_target;
      lo = if_else(active && above, mid, lo);
      hi = if_else(active && !above, mid, hi);
    }
    rl = if_else(active, T(0.5) * (lo + hi), rl);
  }
  T unused = T(0);
  result.rl_m = rl;
  result.rho_m = fz62_deflection(c, rl, unused);
  return result;
}

/// doExtras: Re, ω, and the loaded radius Rl, deflection ρ and vertical stiffness Cz, from the
/// forces in `out` (after the lifted wheel's zeroing).
template <typename T, typename P>
[[gnu::always_inline]] inline void loaded_radius(const MfParameters<P>& p, const Prepared<T>& in,
                                                 const Basic<T>& b, MfOutput<T>& out) {
  const T r0 = p.unloaded_radius_m;
  const T dpi = b.dpi;
  out.re_m = in.re;
  out.omega_radps = in.omega;
  const T fz0 = p.fnomin_n;
  if (p.fit_type == FitType::mf61) {
    const T fz = in.fz_low_limit;
    const T a_cz = p.vertical_stiffness_npm * r0 / fz0;
    const T q_fz1 = sqrt(max_of(T(0), a_cz * a_cz - T(4) * p.q_fz2));
    const T speed_effect = p.q_v2 * (r0 / p.longvl_mps) * abs(in.omega);
    const T fx_effect = (p.q_fcx * out.fx_n / fz0) * (p.q_fcx * out.fx_n / fz0);
    const T fy_effect = (p.q_fcy * out.fy_n / fz0) * (p.q_fcy * out.fy_n / fz0);
    const T external = (T(1) + speed_effect - fx_effect - fy_effect) * (T(1) + p.pfz1 * dpi) * fz0;
    // Q_FZ2·x² + Q_FZ1·x − Fz/external = 0, positive root, written without cancellation.
    const T c = div_or(fz, external, T(0));
    const T disc = sqrt(max_of(T(0), q_fz1 * q_fz1 + T(4) * p.q_fz2 * c));
    const T x = div_or(T(2) * c, q_fz1 + disc, T(0));
    const T rho_zfr = max_of(x * r0, T(0));
    out.rl_m = max_of(in.romega - rho_zfr, T(0));
    const T rho_z = if_else(is_zero(fz) || !(rho_zfr > T(0)), T(1e-6), rho_zfr);
    out.rho_m = rho_z;
    out.cz_npm = fz / rho_z;
  } else {
    // Rl with Fz62(Rl) = Fz (decreasing in Rl), solved by loaded_radius62. The load: MF 6.2
    // solves for the load as given (MFeval 4.x's calculateRhoRl62 takes uFz, not the Fz limited
    // to FZMAX that the forces see); MF 5.2 / PAC2002 for the limited load.
    const T fz_target = p.fit_type == FitType::mf62 ? in.ufz : in.fz;
    const LoadedRadius62<T> solved = loaded_radius62(
        fz62_curve(p, in.gamma, in.omega, in.romega, dpi, out.fx_n, out.fy_n), fz_target);
    out.rl_m = solved.rl_m;
    T rho_z = solved.rho_m;
    rho_z = if_else(is_zero(in.fz) || !(rho_z > T(0)), T(1e-6), rho_z);
    out.rho_m = rho_z;
    out.cz_npm = in.fz / rho_z;
  }
}

}  // namespace tread::mf::detail
