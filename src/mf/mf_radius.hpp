#pragma once
// The tyre's radii: the effective rolling radius Re and the angular speed ω (calculateRe, by
// MFeval's fixed-point iteration) and doExtras' loaded radius Rl, deflection ρ and vertical
// stiffness Cz: for MF 6.1 the quadratic in ρ/R0 solved in closed form, for MF 6.2, MF 5.2 and
// PAC2002 the root of MF 6.2's vertical force Fz62(Rl) = Fz by a safeguarded Newton iteration
// (Halley's steps in double and on lanes).

#include "mf/mf_detail_common.hpp"
#include "mf/mf_free_radius.hpp"
#include "mf/mf_math.hpp"
#include "mf/mf_parameters.hpp"
#include "mf/mf_prepared.hpp"
#include "mf/mf_types.hpp"

#include <cmath>
#include <type_traits>

namespace tread::mf::detail {

/// calculateRe: Re by MFeval's fixed-point iteration on omega = (κ·Vx + Vx)/Re (unlimited κ, Fz,
/// Vx). Returns the steps taken (on lanes, the most of any lane).
template <typename T, typename P>
[[gnu::always_inline]] inline int rolling_radius(const MfParameters<P>& p, Prepared<T>& in) {
  const T r0 = p.unloaded_radius_m;
  const T fz0 = p.fnomin_n;
  const T cz = p.vertical_stiffness_npm * (T(1) + p.pfz1 * in.dpi);
  const T deflection =
      (fz0 / cz) * (p.dreff * mf_atan(p.breff * (in.ufz / fz0)) + p.freff * (in.ufz / fz0));
  T re = r0 * T(0.965);
  T re_old = r0;
  T omega = T(0);
  T romega = r0 * p.q_re0;
  if constexpr (std::is_same_v<T, float> || is_float_lanes<T>) {
    // Float and float lanes start the iteration at its fixed point, from a series, instead of at
    // MFeval's 0.965·R0. The iteration is Re ← A + B/Re² with A = R0·Q_RE0 − deflection,
    // B = R0·Q_V1·(v·R0/V0)², v = κ·Vx + Vx. Its fixed point is A·(1 + u), where u + 2u² + u³ =
    // ε = B/A³, so u = ε − 2ε² + 7ε³ − 30ε⁴ + 143ε⁵ − …; cut after ε⁴, the start is within about
    // 143·ε⁵·A of it (1e-9 m at ε = 0.007, Vx = 40 m/s and κ = 0.3 on MagicFormula61; 2e-7 m at
    // |ε| = 0.02, the most taken). The first step then moves Re by less than the tolerance, 1e-6 m
    // (for A up to about 1.5 m; a larger tyre takes a second), and is the last, where from
    // 0.965·R0 it took three, each waiting for the previous one's division (on lanes the slowest
    // lane sets the count, on a branch that waits for the chain). The answer is the same map's
    // iterate, within float's resolution of MFeval's. Taken where |ε| < 0.02 and A > R0/2;
    // elsewhere the old start.
    // Not in double: there tread gives MFeval's iterates themselves (ω is the step before the
    // last's, up to 2.6e-9 relative off the fixed point, and the golden test asks 1e-9), nor in
    // fixed point (no FPU: the division would only add to the steps).
    const T a = r0 * p.q_re0 - deflection;
    const T v = in.ukappa * in.vx + in.vx;
    const T s = v * (r0 / p.longvl_mps);
    const T b = (r0 * p.q_v1) * s * s;
    const T a3 = a * a * a;
    const auto series = a > T(0.5) * r0 && abs(b) < T(0.02) * a3;
    const T eps = div_or(b, if_else(series, a3, T(1)), T(0));
    const T u = eps * (T(1) - eps * (T(2) - eps * (T(7) - eps * T(30))));
    re = if_else(series, a + a * u, re);
  }
  // MFeval: while |Re_old − Re| > 1e-9 (in float and fixed point: 1e-6, the 1e-9 step is at or
  // below their resolution of a radius). The cap only guards against a diverging file.
  // Lanes iterate until all have converged; a converged lane keeps its values. The first step is
  // always taken (it gives ω and Romega).
  const T tolerance =
      T(std::is_same_v<T, float> || is_float_lanes<T> || is_fixed_point<T> ? 1e-6 : 1e-9);
  const auto every = !(T(0) > T(0));
  int steps = 0;
  for (; steps < 100; ++steps) {
    const auto active = steps == 0 ? every : abs(re_old - re) > tolerance;
    if (!any_lane(active)) break;
    const T omega_next = div_or(in.ukappa * in.vx + in.vx, re, T(0));
    const T romega_next = free_radius_m(p, omega_next);
    re_old = if_else(active, re, re_old);
    omega = if_else(active, omega_next, omega);
    romega = if_else(active, romega_next, romega);
    re = if_else(active, romega_next - deflection, re);
  }
  in.re = re;
  in.omega = omega;
  in.romega = romega;
  return steps;
}

/// How fz62_pow_ratio takes (1 + δ)^q near its memo: the [3/3] Padé approximant (kPowPade: float,
/// double, double lanes, Jets), the [5/5] one (kPowPade55: float lanes) or the binomial series to
/// δ⁶ (fixed point).
template <typename T>
inline constexpr bool kPowPade = !is_float_lanes<T> && !is_fixed_point<T>;
template <typename T>
inline constexpr bool kPowPade55 = is_float_lanes<T>;

/// MF 6.2's vertical force as a function of the loaded radius, Fz62(Rl) (calculateFz62), at a
/// given γ, ω, Romega, Fx, Fy and pressure. What does not depend on Rl is computed once here
/// (√ of Q_FZ1, tan γ, the speed and Fx corrections, the coefficients times γ), so the root
/// search below pays per step only for the Rl-dependent part.
template <typename T, typename P>
struct Fz62Curve {
  P q_fcy2;
  P pow_q;  // 2·Q_FCY2: Fcy² takes (ρz/R0)^(2·Q_FCY2)
  T r0, fz0, romega, width, inv_r0, inv_romega;
  T q_fz1, q_fz2;
  // The camber deflection (rtw/8)·|tan γ|·(num/den)², num = (Q_CAM1·Rl + Q_CAM2·Rl²)·γ and den
  // num's value at Romega, written with γ cancelled as camber_scale·cam², cam = num/den (≈ 1 near
  // Romega): in fixed point γ²·(rtw/8)·|tan γ| alone is below Q31.32's resolution at small γ.
  // With Q = den/γ = Q_CAM1·Romega + Q_CAM2·Romega²:
  T cam1, cam2;              // Q_CAM1 / Q, Q_CAM2 / Q, 0 where den = 0
  T camber_scale;            // (rtw/8)·|tan γ|, 0 where den = 0 (MFeval: 0/0 = NaN → 0)
  T free_share;              // 1 − Q_CAM3·|γ|: the free-rolling deflection's share of ρz
  T inv_free_share;          // 1 / max(free_share, 0.1): the start's use of it
  T fys1_g, fys2_g, fys3_g;  // Q_FYS1…3·γ
  T speed_base;              // 1 + Q_V2·(R0/V0)·|ω|
  T base;                    // speed_base − (Q_FCX·Fx/Fz0)² (fz62_set_forces)
  T pressure;                // 1 + PFZ1·dpi
  T stiffness_scale;         // (1 + PFZ1·dpi)·Fz0
  T fcy_per_force;           // Q_FCY / Fz0
  T fy;
  // Fcy² = (ρz/R0)^q·(Q_FCY·(Fy − Sfyg)/Fz0)², q = 2·Q_FCY2; near a point where the power is
  // known, (1 + δ)^q (see fz62_pow_ratio) by
  //   - float, double, double lanes, Jets: its [3/3] Padé approximant N(δ)/D(δ),
  //     N/D − (1 + δ)^q ≈ e7·δ⁷
  //     with e7 = (q − 3)(q − 2)(q − 1)q(q + 1)(q + 2)(q + 3)/100800;
  //   - float lanes: its [5/5] Padé approximant, N/D − (1 + δ)^q ≈ e11·δ¹¹ with
  //     e11 = q(q² − 1)(q² − 4)(q² − 9)(q² − 16)(q² − 25)·(5!)²/(10!·11!);
  //   - fixed point: its binomial series to δ⁶ (no division), remainder C(q, 7)·δ⁷.
  T pow_n1, pow_n2, pow_n3;  // N(δ) = 1 + n1·δ + n2·δ² + n3·δ³ (+ n4·δ⁴ + n5·δ⁵; series: C(q, 1…3))
  T pow_d1, pow_d2, pow_d3;  // D(δ) = 1 + d1·δ + d2·δ² + d3·δ³ (+ d4·δ⁴ + d5·δ⁵; series: C(q, 4…6))
  T pow_n4 = T(0), pow_n5 = T(0), pow_d4 = T(0), pow_d5 = T(0);  // float lanes only
  T pow_remainder;     // the bound's factor on |δ|⁷ (float lanes: on t¹¹; see fz62_pow_ratio)
  T pow_floor = T(0);  // float lanes: the least δ the approximant takes (see fz62_pow_ratio)
};

/// The [5/5] Padé approximant of (1 + δ)^q (float lanes' fz62_pow_ratio): N's and D's
/// coefficients, the bound's factor on t¹¹ and the least δ taken, functions of q alone.
template <typename P>
struct Pade55 {
  P q;
  P n1, n2, n3, n4, n5, d1, d2, d3, d4, d5;
  P remainder, floor;
};
template <typename P>
[[gnu::always_inline]] inline Pade55<P> pade55(const P& q) {
  Pade55<P> k;
  k.q = q;
  // N = ₂F₁(−5, −5 − q; −10; −δ), D = ₂F₁(−5, q − 5; −10; −δ): the term in δ^k is the one in
  // δ^(k−1) times (6 − k)(6 ± q − k)/((11 − k)·k)·δ.
  k.n1 = (P(5) + q) * P(0.5);
  k.n2 = k.n1 * (P(4) + q) * P(4.0 / 18.0);
  k.n3 = k.n2 * (P(3) + q) * P(3.0 / 24.0);
  k.n4 = k.n3 * (P(2) + q) * P(2.0 / 28.0);
  k.n5 = k.n4 * (P(1) + q) * P(1.0 / 30.0);
  k.d1 = (P(5) - q) * P(0.5);
  k.d2 = k.d1 * (P(4) - q) * P(4.0 / 18.0);
  k.d3 = k.d2 * (P(3) - q) * P(3.0 / 24.0);
  k.d4 = k.d3 * (P(2) - q) * P(2.0 / 28.0);
  k.d5 = k.d4 * (P(1) - q) * P(1.0 / 30.0);
  const P q2 = q * q;
  // e11 = (5!)²/(10!·11!)·q(q² − 1)(q² − 4)(q² − 9)(q² − 16)(q² − 25).
  const P e11 = (q2 - P(1)) * (q2 - P(4)) * (q2 - P(9)) * (q2 - P(16)) * (q2 - P(25)) * q *
                P(9.941312851e-11);
  // At least 1e-20 (fz62_pow_ratio's bound accepts the same δ: 1e-20·1.5¹¹ is far below 6e-8), so
  // that the bound's product never underflows.
  k.remainder = max_of(P(8) * (e11 < P(0) ? -e11 : e11), P(1e-20));
  // Below δ = −0.5/(1 + (|q| − 1)/2) (−0.5 for |q| ≤ 1) N's or D's terms cancel enough for
  // float's rounding to exceed (8 + |q|)·ε near whole |q| of 4 or 5, where e11 is about 0.
  const P magnitude = q < P(0) ? -q : q;
  k.floor = P(-0.5) / (P(1) + P(0.5) * max_of(magnitude - P(1), P(0)));
  return k;
}
/// What pade55_kept keeps: internal linkage, as pade55_kept's, so that each object has its own
/// (the x86-64-v4 file's code must share nothing with baseline code: tests/mf/
/// wide_object_symbols.sh).
template <typename P>
struct Pade55Kept {
  bool valid;
  Pade55<P> k;
};
template <typename P>
[[gnu::tls_model("initial-exec")]] static thread_local constinit Pade55Kept<P> pade55_kept_value{};
/// Whether pade55_kept is used: on Linux targets (a thread pointer for the thread-local).
#if defined(__linux__)
inline constexpr bool kKeepPade55 = true;
#else
inline constexpr bool kKeepPade55 = false;
#endif
/// pade55 for the q of the last call on this thread, kept: the coefficients take about forty
/// scalar operations, a division among them, which four lanes' evaluate_four paid in every call
/// (it builds the curve per call) beside a solve whose chain sets its time. Four lanes on the
/// Intel VM: MF 6.2's extra time over MF 6.1 1 870 → 1 747 ns per block of 64 wheels, the paired
/// MF 6.2 / MF 6.1 1.302 → 1.288 (five alternating runs). Keyed on q's value (a fit changes
/// Q_FCY2 in place), per thread (`tread mf eval` evaluates on every core); a constant-initialised
/// thread-local of the initial-exec model: no guard, no __tls_get_addr, no allocation on a
/// thread's first use, also where tread is linked into a shared object (which then needs its 56
/// bytes of static TLS). Hosted targets only (kKeepPade55): on bare metal there is no thread
/// pointer. Not async-signal-safe (nothing evaluates in a signal handler). The values are
/// pade55's (Mf62LoadedRadius.KeptPadeCoefficientsAreTheComputedOnes).
template <typename P>
[[gnu::always_inline]] static inline Pade55<P> pade55_kept(const P& q) {
  Pade55Kept<P>& kept = pade55_kept_value<P>;
  // Recomputed unless q equals the kept one (a NaN q: every time).
  if (!(kept.valid && kept.k.q <= q && kept.k.q >= q)) kept = {true, pade55(q)};
  return kept.k;
}

/// Fz62Curve but for what the forces Fx and Fy set (fz62_set_forces): four lanes build it before
/// the forces are known, so that it is off the solve's chain. `tan_gamma`: tan γ where the caller
/// has it (computed beside tan α), else null.
template <typename T, typename P>
Fz62Curve<T, P> fz62_curve_without_forces(const MfParameters<P>& p, const T& gamma, const T& omega,
                                          const T& romega, const T& dpi,
                                          const T* tan_gamma = nullptr) {
  // What depends on the parameters only is computed in their scalar type P (for the lanes: once,
  // not per lane) and broadcast.
  Fz62Curve<T, P> c;
  const P r0 = p.unloaded_radius_m;
  const P fz0 = p.fnomin_n;
  c.q_fcy2 = p.q_fcy2;
  c.pow_q = P(2) * p.q_fcy2;
  c.r0 = r0;
  c.fz0 = fz0;
  c.romega = romega;
  c.width = p.width_m;
  c.inv_r0 = T(P(1) / r0);
  c.inv_romega = T(1) / romega;
  const P a = p.vertical_stiffness_npm * r0 / fz0;
  c.q_fz1 = T(sqrt(max_of(P(0), a * a - P(4) * p.q_fz2)));
  c.q_fz2 = p.q_fz2;
  const P rtw_8 = (P(1.075) - P(0.5) * p.aspect_ratio) * p.width_m / P(8);
  const T at_romega = p.q_cam1 * romega + p.q_cam2 * romega * romega;
  const auto cambered = !is_zero(at_romega * gamma);
  c.cam1 = T(0);
  c.cam2 = T(0);
  c.camber_scale = T(0);
  if (any_lane(cambered)) {
    const T inv = div_or(T(1), if_else(cambered, at_romega, T(1)), T(0));
    c.cam1 = if_else(cambered, p.q_cam1 * inv, T(0));
    c.cam2 = if_else(cambered, p.q_cam2 * inv, T(0));
    c.camber_scale =
        if_else(cambered, T(rtw_8) * abs(tan_gamma != nullptr ? *tan_gamma : mf_tan(gamma)), T(0));
  }
  c.free_share = T(1) - p.q_cam3 * abs(gamma);
  c.inv_free_share = T(1) / max_of(c.free_share, T(0.1));
  c.fys1_g = p.q_fys1 * gamma;
  c.fys2_g = p.q_fys2 * gamma;
  c.fys3_g = p.q_fys3 * gamma;
  c.speed_base = T(1) + T(p.q_v2 * (r0 / p.longvl_mps)) * abs(omega);
  c.pressure = T(1) + p.pfz1 * dpi;
  c.stiffness_scale = c.pressure * fz0;
  c.fcy_per_force = T(P(p.q_fcy) / fz0);
  const P q = c.pow_q;
  if constexpr (kPowPade55<T>) {
    // evaluate_four builds the curve in every call, the 8- and 16-lane batch once per block in a
    // loop GCC hoists it out of (mf_evaluate_batch.cpp): four lanes keep the last q's
    // coefficients (pade55_kept; also the batch's blocks where it runs four lanes: NEON, and
    // builds without the x86-64 wide files).
    constexpr bool kKept = kKeepPade55 && is_float_lanes<T> && sizeof(T) == 4 * sizeof(float);
    const Pade55<P> k = [&] {
      if constexpr (kKept) {
        return pade55_kept(q);
      } else {
        return pade55(q);
      }
    }();
    c.pow_n1 = k.n1;
    c.pow_n2 = k.n2;
    c.pow_n3 = k.n3;
    c.pow_n4 = k.n4;
    c.pow_n5 = k.n5;
    c.pow_d1 = k.d1;
    c.pow_d2 = k.d2;
    c.pow_d3 = k.d3;
    c.pow_d4 = k.d4;
    c.pow_d5 = k.d5;
    c.pow_remainder = k.remainder;
    c.pow_floor = k.floor;
  } else if constexpr (!kPowPade<T>) {
    const P c2 = q * (q - P(1)) / P(2);
    const P c3 = c2 * (q - P(2)) / P(3);
    const P c4 = c3 * (q - P(3)) / P(4);
    const P c5 = c4 * (q - P(4)) / P(5);
    const P c6 = c5 * (q - P(5)) / P(6);
    const P c7 = c6 * (q - P(6)) / P(7);
    c.pow_n1 = q;
    c.pow_n2 = c2;
    c.pow_n3 = c3;
    c.pow_d1 = c4;
    c.pow_d2 = c5;
    c.pow_d3 = c6;
    // At least 1e-3, as when a fit's Jets took the series too: fixed point's results do not
    // change.
    c.pow_remainder = T(max_of(c7 < P(0) ? -c7 : c7, P(1e-3)));
  } else {
    // N's and D's coefficients (the Padé approximant of (1 + δ)^q: ₂F₁(−3, −3 − q; −6; −δ) over
    // ₂F₁(−3, q − 3; −6; −δ)), no division on the parameters' path.
    const P up1 = (P(3) + q) * P(0.5);
    const P up2 = up1 * (P(2) + q) * P(0.2);
    const P down1 = (P(3) - q) * P(0.5);
    const P down2 = down1 * (P(2) - q) * P(0.2);
    c.pow_n1 = up1;
    c.pow_n2 = up2;
    c.pow_n3 = up2 * (P(1) + q) * P(1.0 / 12.0);
    c.pow_d1 = down1;
    c.pow_d2 = down2;
    c.pow_d3 = down2 * (P(1) - q) * P(1.0 / 12.0);
    const P e7 = (q * q - P(9)) * (q * q - P(4)) * (q * q - P(1)) * q * P(1.0 / 100800.0);
    // 4·|e7|: wherever fz62_pow_ratio accepts the approximant (4·|e7|·|δ|⁷ below half of ε,
    // |δ| < 0.3) its error relative to (1 + δ)^q is at most 3.4·|e7|·|δ|⁷ over q ∈ [−10, 10]
    // (a grid of q and δ; a helper's review found the accepted results within 0.86·ε/2 of x^q
    // in float and 0.28·ε/2 in double, also near every whole q and for |q| up to 1e10). The
    // asymptotic form alone is no bound where it is not accepted: at δ = −0.3 the error is
    // 4.6·|e7|·|δ|⁷ for q = −0.95 and 206× for q = −10. Where Q_FCY2 is a fit's Jet, at least
    // 1e-3: at a whole q in [−3, 3] e7 is 0 and the approximant exact in value, but not in its
    // derivative with respect to Q_FCY2 (|de7/dq| ≤ 1.2e-3 for |q| ≤ 2, 7.1e-3 at ±3, where that
    // derivative's truncation can reach 7–9× the bound, as it could with the series).
    const P bound = P(4) * (e7 < P(0) ? -e7 : e7);
    if constexpr (std::is_arithmetic_v<P>) {
      c.pow_remainder = T(bound);
    } else {
      c.pow_remainder = T(max_of(bound, P(1e-3)));
    }
  }
  return c;
}

/// Completes a curve with the forces Fx and Fy.
template <typename T, typename P>
[[gnu::always_inline]] inline void fz62_set_forces(Fz62Curve<T, P>& c, const MfParameters<P>& p,
                                                   const T& fx, const T& fy) {
  const T fcx = fx * T(p.q_fcx / p.fnomin_n);
  c.base = c.speed_base - fcx * fcx;
  c.fy = fy;
}

template <typename T, typename P>
Fz62Curve<T, P> fz62_curve(const MfParameters<P>& p, const T& gamma, const T& omega,
                           const T& romega, const T& dpi, const T& fx, const T& fy) {
  Fz62Curve<T, P> c = fz62_curve_without_forces(p, gamma, omega, romega, dpi);
  fz62_set_forces(c, p, fx, fy);
  return c;
}

/// The deflection ρz at a loaded radius: free-rolling ρ plus the camber part; its slope dρz/dRl
/// and curvature d²ρz/dRl².
template <typename T, typename P>
[[gnu::always_inline]] inline T fz62_deflection(const Fz62Curve<T, P>& c, const T& rl, T& slope,
                                                T& curvature) {
  const auto compressed = rl < c.romega;
  const T rho_zfr = max_of(c.romega - rl, T(0));
  const T cam = c.cam1 * rl + c.cam2 * rl * rl;
  const T dcam = c.cam1 + T(2) * c.cam2 * rl;
  const T camber = c.camber_scale * cam;
  const T rho_z = rho_zfr * c.free_share + camber * cam;
  const T drho_z = T(2) * camber * dcam - if_else(compressed, c.free_share, T(0));
  const T d2rho_z = T(2) * c.camber_scale * (dcam * dcam + T(2) * c.cam2 * cam);
  const auto positive = rho_z > T(0);
  // At Romega itself with no deflection (an upright wheel, where the lightest loads' start lands:
  // its free deflection is below the spacing of Rl's values) the compressed side's slope, so that
  // Newton steps into the tyre instead of seeing a flat Fz62.
  const auto at_romega = !(rl < c.romega) && !(rl > c.romega);
  slope = if_else(positive, drho_z, if_else(at_romega, -c.free_share, T(0)));
  curvature = if_else(positive, d2rho_z, T(0));
  return if_else(positive, rho_z, T(0));
}

template <typename T, typename P>
[[gnu::always_inline]] inline T fz62_deflection(const Fz62Curve<T, P>& c, const T& rl, T& slope) {
  T curvature = T(0);
  return fz62_deflection(c, rl, slope, curvature);
}

/// (ρz/R0)^(2·Q_FCY2) at the last point where it was computed exactly (or at the start's
/// deflection, before the first evaluation): the steps near a root move ρz by little, and an
/// approximation of (1 + δ)^q about that point is exact to the output's resolution there at a
/// fraction of pow's cost.
template <typename T>
struct Fz62PowMemo {
  T base = T(0);  // ρz/R0 where pow was evaluated (0: none yet)
  T inv_base = T(0);
  T value = T(0);
};

/// x^q as fz62_pow_ratio gives it: num/den, den the Padé approximant's denominator D(δ) or 1
/// (pow's value, the fixed-point series), so that the quotient need not be formed on the solve's
/// chain (see fz62). D is positive wherever the approximant is taken: D(0) = 1, and D has no zero
/// on the interval of δ about 0 where the approximant stays within its bound of (1 + δ)^q.
template <typename T>
struct Fz62Power {
  T num;
  T den;
};

/// x^q from the memo's base b, (b·(1 + δ))^q = b^q·(1 + δ)^q, where a bound on the
/// approximation's relative error (Fz62Curve's pow_remainder) is below half of ε, else pow, which
/// becomes the new base:
///   - float, double, Jets: b^q·N(δ)/D(δ), the [3/3] Padé approximant, for |δ| < 0.3, where
///     4·|e7|·|δ|⁷ is below half of ε. It is far closer than the binomial series to δ⁶ (q = −0.95,
///     δ = 0.3: 2e-9 against 1.9e-4), so that the step after a start a few mm off need not wait
///     for pow: on the benchmark's points float's pows inside the loop went from 0.69 to 0.33 per
///     solve, those left where the second evaluation's deflection is 1.3 to 2.3 times the
///     start's (Fcy²'s power, which the start leaves out, matters most there). The [5/5] one in
///     float measured 10 ns slower per evaluation (the portable scalar build has no FMA).
///   - float lanes: the [5/5] Padé approximant where 8·|e11|·t¹¹ (t = δ/(1 + δ/2)) is below half of
///     ε, tested without a division, for pow_floor < δ < 1.5: for the sample tyre's q = −0.95
///     −0.5 < δ < 1.34. The t form held as a bound wherever it accepts over q ∈ [−20, 20] and
///     δ ∈ (−0.9, 2] (a long double grid, step 0.01 in q and 0.001 in δ; the asymptotic e11·δ¹¹
///     is no bound). On four lanes one lane beyond reach makes the group take pow, and the second
///     evaluation's deflection lies up to twice the start's (the start leaves Fcy²'s power out):
///     with the binomial series (reach |δ| < 0.095 there) 12 822 of 12 800 groups of four of the
///     benchmark's points took a pow inside the loop, with the [5/5] approximant 133. The
///     instructions per evaluate_four stay about the same (5 757 → 5 747 under callgrind), but pow
///     was on the second evaluation's chain: evaluate_four on MF 6.2 measured 18 ns per group of
///     four faster (p10 of 400 passes, 10 alternating runs: 806–825 → 788–805 ns). In the bound
///     |δ| is taken as at least 1/32 (which rejects no δ it accepted for |q| up to about 46) and
///     8·|e11| as at least 1e-20, so that its product stays a normal float (see below).
///   - fixed point: b^q·(1 + C(q,1)δ + … + C(q,6)δ⁶) for |δ| < ¼, without a division (no FPU
///     to overlap one with).
/// Its derivatives are not needed: fz62 takes them as the power times q·x'/x (exact for x^q, and
/// for the approximation to its accuracy).
///
/// `used`: the lanes whose result is used (for the scalars, true: they call it only then). Only
/// those lanes take the exact power and update their memo, so that a lane's later steps do not
/// depend on whether a neighbour made this call where its own result was not needed (an unloaded
/// lane: the scalars do not call it there).
template <typename T, typename P>
[[gnu::always_inline]] inline Fz62Power<T> fz62_pow_ratio(const Fz62Curve<T, P>& c, const T& x,
                                                          Fz62PowMemo<T>& memo,
                                                          const MaskOf<T>& used) {
  constexpr bool coarse = std::is_same_v<T, float> || is_float_lanes<T> || is_fixed_point<T>;
  // Without a base in any lane, pow alone, without the approximation.
  auto near = memo.base > T(0);
  T approx = T(0);
  T approx_den = T(1);
  if (any_lane(near)) {
    const T delta = x * memo.inv_base - T(1);
    const T delta2 = delta * delta;
    if constexpr (kPowPade55<T>) {
      // pow_remainder·|δ|¹¹ ≤ (ε/2)·(1 + δ/2)¹¹, the bound in t = δ/(1 + δ/2) without its
      // division (off the chain: it only feeds the branch to pow). N and D side by side.
      const T h = T(1) + T(0.5) * delta;
      const T h2 = h * h;
      const T h4 = h2 * h2;
      // |δ| taken as at least 1/32 here, which rejects no δ it accepted for |q| up to about 46
      // (there pow_remainder·(1/32)¹¹ ≤ 6e-8·(1 − 1/64)¹¹): near a converging root
      // pow_remainder·|δ|¹¹ underflowed into denormals (7e-40 at δ = 1e-3 for the sample tyre),
      // and on the Intel VM's Xeon such an operation takes a microcode assist: four lanes'
      // approximant took 59 ns there against 13 ns where δ was 0.1. With pow_remainder at least
      // 1e-20 (see the curve) the product is at least 2.8e-37, a normal float.
      const T d = max_of(abs(delta), T(0.03125));
      const T d2 = d * d;
      const T d4 = d2 * d2;
      near = near && delta > c.pow_floor && delta < T(1.5) &&
             c.pow_remainder * (d4 * d4 * d2 * d) <= T(6e-8) * (h4 * h4 * h2 * h);
      // N and D with δ² nested (Estrin's pairs, no δ⁴ formed): the smallest product is of order
      // δ²·n4, normal for the smallest δ a rounding leaves (about 2⁻⁴⁸).
      const T num = (T(1) + c.pow_n1 * delta) + delta2 * ((c.pow_n2 + c.pow_n3 * delta) +
                                                          delta2 * (c.pow_n4 + c.pow_n5 * delta));
      const T den = (T(1) + c.pow_d1 * delta) + delta2 * ((c.pow_d2 + c.pow_d3 * delta) +
                                                          delta2 * (c.pow_d4 + c.pow_d5 * delta));
      approx = memo.value * num;
      approx_den = den;
    } else {
      const T d = abs(delta);
      const T d3 = d * d * d;
      const T reach = T(kPowPade<T> ? 0.3 : 0.25);
      near = near && d < reach && c.pow_remainder * (d3 * d3 * d) < T(coarse ? 6e-8 : 1.1e-16);
      if constexpr (!kPowPade<T>) {
        // Estrin's scheme: three independent pairs, then δ² and δ⁴ (a shorter chain than
        // Horner's).
        const T s12 = c.pow_n1 + delta * c.pow_n2;
        const T s34 = c.pow_n3 + delta * c.pow_d1;
        const T s56 = c.pow_d2 + delta * c.pow_d3;
        approx = memo.value * (T(1) + delta * (s12 + delta2 * (s34 + delta2 * s56)));
      } else {
        // N and D side by side, each as two independent pairs; the value multiplies N while D is
        // computed (the caller takes N/D without forming it: see fz62).
        const T num = (T(1) + c.pow_n1 * delta) + delta2 * (c.pow_n2 + c.pow_n3 * delta);
        const T den = (T(1) + c.pow_d1 * delta) + delta2 * (c.pow_d2 + c.pow_d3 * delta);
        approx = memo.value * num;
        approx_den = den;
      }
    }
  }
  const auto far = used && !near;
  if (!any_lane(far)) return {approx, approx_den};
  const T exact = T(pow(x, T(c.pow_q)));
  memo.base = if_else(far, x, memo.base);
  memo.inv_base = if_else(far, T(1) / x, memo.inv_base);
  memo.value = if_else(far, exact, memo.value);
  return {if_else(far, exact, approx), if_else(far, T(1), approx_den)};
}

/// x^q as fz62_pow_ratio takes it, the quotient formed, every lane's result used.
template <typename T, typename P>
[[gnu::always_inline]] inline T fz62_pow(const Fz62Curve<T, P>& c, const T& x,
                                         Fz62PowMemo<T>& memo) {
  const Fz62Power<T> r = fz62_pow_ratio(c, x, memo, T(0) <= T(0));
  return r.num / r.den;
}

/// Fz62 − Fz at a loaded radius with its first two derivatives, and the deflection ρz there with
/// its.
template <typename T>
struct Fz62Value {
  // Fz62(Rl) − Fz, dFz62/dRl, d²Fz62/dRl², each times `scale` (> 0; see fz62).
  T excess, slope, curvature;
  T scale;
  T rho_z, drho_z, d2rho_z;
};

/// Fz62(Rl) − Fz and its derivatives, the second (curvature) only where kSecond (else 0: it is
/// not dead code for every type, and in fixed point it overflows at light loads).
/// Fz62 = (base − Fcy²)·S with S = (1 + PFZ1·dpi)·Fz0·(Q_FZ1 + Q_FZ2·x)·x, x = ρz/R0, and
/// Fcy² = p·L² with the power p = x^(2·Q_FCY2), L = Q_FCY·(Fy − Sfyg)/Fz0. Each of Fz62 − Fz and
/// its derivatives is written as a − p·b, with a and b computed while the power is (p' = p·g with
/// g = q·x'/x, p'' = p·g2): what waits for the power is one product and one subtraction, then the
/// step's division. Where fz62_pow_ratio gives the power as N/D (its Padé approximant), each is
/// returned times D (`scale`; 1 where pow was taken, in unloaded lanes and in fixed point), as
/// a·D − N·b (a·D waits for D as N·b for N): the approximant's division is off the solve's chain.
/// Every use of them is a sign (Fz62 − Fz at a point, the slope's), a quantity of degree 0 in D
/// (−F/F', Halley's −F·F'/(F'² − ½·F·F''), the Halley factor's tests against F'²) or a test with
/// D on both sides (the hump's Fz62 < 0); only the underflow guards (F'² > 0, a zero Halley
/// denominator) move, by a factor D² of order 1 where the approximant is taken. Four lanes on the
/// Intel VM: MF 6.2 / MF 6.1 1.334 → 1.320 paired, float 1.281 → 1.262; the 16-lane batch, bound
/// by throughput rather than latency, 1.240 → 1.247 (it keeps the scaling: its bits are four
/// lanes'), double unchanged (1.305).
template <bool kSecond, typename T, typename P>
[[gnu::always_inline]] inline Fz62Value<T> fz62(const Fz62Curve<T, P>& c, const T& rl,
                                                const T& fz_target, Fz62PowMemo<T>& memo) {
  T drho_z = T(0);
  T d2rho_z = T(0);
  const T rho_z = fz62_deflection(c, rl, drho_z, d2rho_z);
  const T x = rho_z * c.inv_r0;
  const T dx = drho_z * c.inv_r0;
  // Lateral force correction: Fy less the camber's share Sfyg (a polynomial in Rl/Romega).
  const T ratio = rl * c.inv_romega;
  const T sfyg = c.fys1_g + (c.fys2_g + c.fys3_g * ratio) * ratio;
  const T dsfyg = (c.fys2_g + T(2) * c.fys3_g * ratio) * c.inv_romega;
  T d2x = T(0);
  T d2sfyg = T(0);
  if constexpr (kSecond) {
    d2x = d2rho_z * c.inv_r0;
    d2sfyg = T(2) * c.fys3_g * c.inv_romega * c.inv_romega;
  }
  const auto loaded = x > T(0);
  // x^(2·Q_FCY2); unloaded 0 (MFeval: 0^q·0), or 1 where Q_FCY2 = 0, where it is not computed
  // (MF 5.2, PAC2002 and many MF 6.x files) unless Q_FCY2 is a fit's Jet (d(x^q)/dq = ln x at 0).
  const bool zero_exponent = is_zero(c.q_fcy2);
  T power = zero_exponent ? T(1) : T(0);
  T scale = T(1);
  constexpr bool kScalarParameters = std::is_arithmetic_v<P> || is_fixed_point<P>;
  if (!(kScalarParameters && zero_exponent) && any_lane(loaded)) {
    const Fz62Power<T> r = fz62_pow_ratio(c, if_else(loaded, x, T(1)), memo, loaded);
    power = if_else(loaded, r.num, power);
    if constexpr (!is_fixed_point<T>) scale = if_else(loaded, r.den, T(1));
  }
  // The terms without the power, times the power's denominator (fixed point's is 1: no product).
  const auto scaled = [&](const T& v) -> T {
    if constexpr (is_fixed_point<T>) {
      return v;
    } else {
      return v * scale;
    }
  };
  const T lateral = c.fcy_per_force * (c.fy - sfyg);
  const T dlateral = c.fcy_per_force * dsfyg;  // −dL/dRl
  const T lateral2 = lateral * lateral;
  const T dlateral2 = T(-2) * lateral * dlateral;
  const T stiffness = (c.q_fz1 + c.q_fz2 * x) * x * c.stiffness_scale;
  const T rate = (c.q_fz1 + T(2) * c.q_fz2 * x) * c.stiffness_scale;  // dS/dx
  const T dstiffness = rate * dx;
  const T excess = scaled(c.base * stiffness - fz_target) - power * (lateral2 * stiffness);
  T slope = T(0);
  T curvature = T(0);
  if constexpr (kSecond) {
    // g = p'/p = q·x'/x, g2 = p''/p = q·((q − 1)·(x'/x)² + x''/x) (unloaded x is taken as 1: x'
    // is 0 there, or at Romega itself finite, with p = 0 or g = 0);
    // (Fcy²)' = p·(g·L² + (L²)'), (Fcy²)'' = p·(g2·L² + 2·g·(L²)' + (L²)'').
    const T inv_x = T(1) / if_else(loaded, x, T(1));
    const T ux = dx * inv_x;
    const T growth = T(c.pow_q) * ux;
    const T growth2 = T(c.pow_q) * (T(c.pow_q - P(1)) * ux * ux + d2x * inv_x);
    const T dfcy2_per_power = growth * lateral2 + dlateral2;
    slope =
        scaled(c.base * dstiffness) - power * (lateral2 * dstiffness + dfcy2_per_power * stiffness);
    const T d2stiffness = T(2) * c.q_fz2 * c.stiffness_scale * dx * dx + rate * d2x;
    const T d2lateral2 = T(2) * (dlateral * dlateral - lateral * c.fcy_per_force * d2sfyg);
    const T d2fcy2_per_power = growth2 * lateral2 + T(2) * growth * dlateral2 + d2lateral2;
    curvature = scaled(c.base * d2stiffness) -
                power * (lateral2 * d2stiffness + T(2) * dfcy2_per_power * dstiffness +
                         d2fcy2_per_power * stiffness);
  } else {
    // Without the second derivative (float's and fixed point's Newton steps; every type's check at
    // Romega and bisection): (Fcy²)'·S = p·(g·S·L² + (L²)'·S) with g·S = q·x'·(S/x), no division by
    // x (x'/x overflows Q31.32 at the lightest loads).
    const T growth_s = T(c.pow_q) * dx * ((c.q_fz1 + c.q_fz2 * x) * c.stiffness_scale);
    slope = scaled(c.base * dstiffness) -
            power * (lateral2 * dstiffness + growth_s * lateral2 + dlateral2 * stiffness);
  }
  return {excess, slope, curvature, scale, rho_z, drho_z, d2rho_z};
}

/// x = ρ/R0 with q_fz2·x² + q_fz1·x = Fz / E, E = (base − Fcy²)·(1 + PFZ1·dpi)·Fz0, the start of
/// loaded_radius62:
/// - double (and double lanes, Jets): the positive root written without cancellation,
///   2·Fz / (E·q_fz1 + √(E·(E·q_fz1² + 4·q_fz2·Fz))), one division where Fz / E first would take
///   two (the start heads the solve's dependent chain: measured −3 ns per solve). 0 where Fz or E
///   is not positive.
/// - float and float lanes: the root's continued fraction cut after its third convergent. With
///   u = q_fz2·Fz/(E·q_fz1²) the root is (Fz/(E·q_fz1))·f(u), f = 2/(1 + √(1 + 4u)), and f solves
///   f = 1/(1 + u·f); its third convergent (1 + 2u)/(1 + 3u + u²) is below f by at most u⁴·f
///   (4e-5 at u = 0.08, the sample MF 6.2 tyre at FNOMIN; 0.2 % at 0.3; 3 % at 1) and equal to it
///   where Q_FZ2 = 0 (MF 5.2, PAC2002). Written as Fz·q_fz1·(A + 2w)/(A·(A + 3w) + w²) with
///   A = E·q_fz1², w = q_fz2·Fz: one division and no square root, where the root took two
///   divisions and a square root one after the other. The start heads the solve's dependent
///   chain: four lanes' MF 6.2 evaluation measured 8–14 ns per group of four faster (MF 6.2 /
///   MF 6.1 1.31 → 1.29–1.30), float 3–5 ns (1.30 → 1.29), the 16-lane batch 1.29 → 1.27
///   (alternating mf_bench runs), with the same evaluations on the benchmark's points (lanes 2.053
///   per group of four, float 2.278 per wheel). Below the root, never above it: where Q_FCY2 > 0
///   and the lateral term is strong, Fz62 can rise over Fz on a hump below Romega and fall below
///   it again deeper in, and a start beyond the hump's far side ends on Rl = 0 (the second
///   convergent, above the root, did that where the root did not; Mf62LoadedRadius.
///   StartStaysOnTheRomegaSideOfALateralHump). What it costs: where the quadratic is Fz62 itself
///   (γ = 0 and Fy = 0 exactly) the exact root converged in one evaluation, this start does so
///   for 89 % of float wheels and 64 % of groups of four at 0.3–1.6·FNOMIN (else two, as every
///   point with camber or a lateral force takes); over the envelope test's points float takes
///   0.6–2.5 % more evaluations and lanes 0.2–0.4 % (loads of several FNOMIN, where the
///   convergent is coarse). 0 where the denominator is 0; loaded_radius62 clamps a negative or
///   non-finite start onto its bracket.
/// - fixed point: Fz / E first, then the root: (E·Q_FZ1)² (~1e10) overflows Q31.32.
template <typename T, typename P>
[[gnu::always_inline]] inline T quadratic_deflection(const Fz62Curve<T, P>& c, const T& fz,
                                                     const T& fcy) {
  if constexpr (is_float_lanes<T> || std::is_same_v<T, float>) {
    // E = net·(1 + PFZ1·dpi)·Fz0.
    const T net = c.base - fcy * fcy;
    const T w = c.q_fz2 * fz;
    const T big_a = net * (c.stiffness_scale * c.q_fz1 * c.q_fz1);
    const T num = (fz * c.q_fz1) * (big_a + T(2) * w);
    const T den = big_a * (big_a + T(3) * w) + w * w;
    return div_or(num, den, T(0));
  }
  const T external = (c.base - fcy * fcy) * c.stiffness_scale;
  if constexpr (is_fixed_point<T>) {
    const T q = max_of(div_or(fz, external, T(0)), T(0));
    return div_or(T(2) * q, c.q_fz1 + sqrt(c.q_fz1 * c.q_fz1 + T(4) * c.q_fz2 * q), T(0));
  } else {
    const T linear = external * c.q_fz1;
    const T disc = max_of(linear * linear + T(4) * c.q_fz2 * fz * external, T(0));
    const auto loaded = external > T(0) && fz > T(0);
    return if_else(loaded, div_or(T(2) * fz, linear + sqrt(disc), T(0)), T(0));
  }
}

/// A power x^y another part of the evaluation needs, computed beside the solve's seeded power
/// (mf_pow_two) where that one is computed: MF 6.2's contact patch width on four lanes, where the
/// two cost about one. `done` where it was; else the caller computes it.
template <typename T>
struct PowBeside {
  T x, y;
  T value;
  bool done = false;
};

template <typename T>
struct LoadedRadius62 {
  T rl_m;
  T rho_m;
  int newton_steps;  // steps of the safeguarded Newton iteration (the most of any lane)
  bool fallback;     // a lane needed the bisection fallback (in the tested envelope only where a
                     // lateral hump stays below Fz: the bracket closes on its peak)
};

/// Rl with Fz62(Rl) = Fz: a safeguarded Newton (in double and on lanes: Halley) iteration on the
/// branch where the root lies.
/// - The branch: below Romega the tyre is compressed and Fz62 falls steeply with Rl; only where the
///   camber deflection alone carries more than Fz (a light, cambered wheel) does the root lie above
///   Romega. Above Romega Fz62 is a hump (Q_FYS's Sfyg grows with Rl/Romega), and just below it,
///   with Fy ≠ 0, it may dip (ρ^Q_FCY2): the bracket, [0, Romega] or [Romega, Romega + w], keeps
///   the search on the one branch. Romega's end is known (Fz62 evaluated there); the far end is
///   evaluated when a step would leave the bracket towards it: if Fz62 is on the same side of Fz
///   there, the branch has no root (loads beyond a fully squashed tyre, |γ| near 90° with the
///   limits off) and that end is the answer, as bisection gives.
/// - Start: the MF 6.1-style deflection (the quadratic in ρ/R0 with the Rl-independent
///   corrections; in float and on lanes its third convergent, quadratic_deflection) less the
///   camber's deflection at Romega. It leaves out Fcy's factor
///   (ρz/R0)^Q_FCY2 and is a few mm off (1 cm where that factor matters most). Where the start lies
///   below Romega on that branch and Q_FCY2 ≠ 0, the power at the start's deflection is computed
///   alongside its Rl (it seeds the memo of fz62_pow_ratio), so that the first evaluation, at
///   nearly that deflection, need not wait for pow; not in fixed point (no FPU to overlap it with).
/// - The step: in double (and a fit's Jets) and on lanes Halley's, −F·F'/(F'² − ½·F·F''), cubic,
///   where its factor on Newton's step, 1/(1 − F·F''/(2·F'²)), is within [2/3, 2] (else, far from
///   the root, Newton's). On the benchmark's points this takes double from 3.4 evaluations per
///   wheel on average to 2.5, and on lanes, where the slowest lane sets the count, the groups of
///   four needing a third from three quarters to 6 % without a start corrected for Fcy's factor
///   (13 % with it, which is therefore gone). Float takes Newton's step: in the portable scalar
///   build (no FMA) the second derivative costs more than the evaluations it saves (measured: +6 ns
///   per solve alone, +8 ns per MF 6.2 evaluation); fixed point too (F'² of ~1e6 N/m overflows
///   Q31.32), and neither computes the second derivative.
/// - Past a lateral hump (Q_FCY2 > 0: Fcy² grows with the deflection), a point below Fz may lie
///   deeper than the root: one whose Fz62 rises with Rl while ρz falls, or is negative, bounds the
///   search from below; where the bracket closes on the hump's peak without Fz62 reaching Fz, the
///   answer is the branch's end, 0, as the scan from Romega gives (see `hump` below).
/// - A step is taken where it lands inside the bracket and the slope is negative, else the
///   bracket's midpoint (or its far end, not yet evaluated). Converged when a step is at most
///   R0·ε^(3/4), ε of the output type (the error after it is of order the step² times
///   Fz62''/Fz62' ≲ 1e3 /m at the lightest loads, below ε·R0), or when the error left after a step
///   of the same kind as the one before, estimated from the two, is at most ε·R0 (this saves the
///   confirming evaluation): Newton's C·step² with C ≈ step / previous², Halley's K·step³ with
///   K ≈ step / previous³, asked to be 20× below ε·R0 and only where both steps' factor is within
///   10 % of 1 (the cubic regime): from a long previous step whose factor was merely within
///   [2/3, 2] it was 25× and 475× low (float lanes 1.6e-6 and 8e-7 m off, at light loads).
/// - ρz at Rl: its Taylor polynomial (to the second order) about the last point evaluated, at most
///   a step away, so that it is ready with Rl; evaluated afresh where that does not hold.
/// tests/mf/mf62_loaded_radius_test.cpp shows over the envelope (every MF 6.2, MF 5.2 and PAC2002
/// test tyre, loads 0 … 10·FZMAX, |γ| to 1.5707, slips, speeds, pressures, limits on and off) that
/// it converges in at most 11 steps (2–3 at most points; MF 5.2 and PAC2002, without the camber
/// and lateral terms, in 1: the start is their root, in float and on lanes where Q_FZ2 = 0) to the
/// least-deflection root, the one a tyre reaches when loaded from Romega. Should a lane still be
/// unconverged after kNewtonSteps, bisection of its remaining bracket finishes it (lanes: a
/// converged lane keeps its value).
/// Outside the envelope, where 1 + PFZ1·dpi < 0 (a tyre of negative stiffness: PFZ1 > 1 at a low
/// pressure with the limits off), Fz62 below Romega is positive only on a hump near Romega
/// (where Fcy² > 1 + speed − Fx²); where the hump reaches Fz, a step that leaves the bracket
/// evaluates Rl = 0, finds Fz62 below Fz there and answers 0, not the hump's root
/// (Mf62LoadedRadius.PressureFactorAtOrBelowZero counts these points).
template <typename T, typename P>
LoadedRadius62<T> loaded_radius62(const Fz62Curve<T, P>& c, const T& fz_target,
                                  PowBeside<T>* beside = nullptr) {
  constexpr int kNewtonSteps = 16;
  // Halley's step in double and on lanes, Newton's in float and fixed point (see above).
  constexpr bool kHalley = !std::is_same_v<T, float> && !is_fixed_point<T>;
  // Four lanes, where the solve's chain of dependent steps sets the time rather than the
  // instructions (the 8- and 16-lane batch), divide by both of Halley's denominators and select
  // the quotient (see the step; double measured no faster with it).
  constexpr bool kBothQuotients = is_float_lanes<T> && sizeof(T) == 4 * sizeof(float);
  constexpr bool coarse = std::is_same_v<T, float> || is_float_lanes<T> || is_fixed_point<T>;
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
  const T rho_romega_r0 = rho_romega * c.inv_r0;
  const T bound = c.base * c.stiffness_scale *
                  (c.q_fz1 * rho_romega_r0 + c.q_fz2 * rho_romega_r0 * rho_romega_r0);
  const auto evaluated = bound > fz_target || !(c.pressure > T(0));
  auto beyond = T(0) > T(0);  // no lane
  if (any_lane(evaluated)) {
    beyond = evaluated && fz62<false>(c, c.romega, fz_target, memo).excess > T(0);
    // Only those lanes keep the pow's memo (a lane's result must not depend on its neighbours).
    memo.base = if_else(evaluated, memo.base, T(0));
    memo.value = if_else(evaluated, memo.value, T(0));
    memo.inv_base = if_else(evaluated, memo.inv_base, T(0));
  }
  const T lo_end = if_else(beyond, c.romega, T(0));
  const T hi_end = if_else(beyond, c.romega + c.width, c.romega);
  T lo = lo_end;
  T hi = hi_end;
  auto lo_known = beyond;   // the root, if any, lies above lo (Fz62(lo) > Fz, or past the hump)
  auto hi_known = !beyond;  // Fz62(hi) ≤ Fz is known
  // Past a lateral hump: where Fcy² grows with the deflection (Q_FCY2 > 0) and the pressure factor
  // is positive, Fz62 below Romega rises from Romega over a hump and falls again deeper in, below
  // Fz (Fcy² outgrows 1 + speed − Fx²), below 0 where Fcy² exceeds it (and may rise again towards
  // Rl = 0 there, the camber's share of ρz vanishing). A point below Fz whose Fz62 rises with Rl
  // while its deflection falls with Rl, or whose Fz62 is negative, is past the hump's peak: the
  // least-deflection root, if the hump reaches Fz, lies on the Romega side of it, and the point
  // bounds the search from below as a point above Fz does. Where every such bound was a point past
  // the peak (lo_crossed false) and the bracket has closed on the peak, the hump does not reach Fz:
  // the branch has no root and its end, 0, is the answer, as for a load beyond a fully squashed
  // tyre.
  const bool hump_possible = c.pow_q > P(0);  // not on the benchmark's tyre (Q_FCY2 < 0)
  const auto hump = (hump_possible ? T(1) : T(0)) > T(0) && !beyond && c.pressure > T(0);
  auto lo_crossed = beyond;      // Fz62 > Fz seen at lo (kept only where a hump is possible)
  auto collapsed = T(0) > T(0);  // no lane yet: lanes whose hump stays below Fz
  // The side of the root an evaluated point bounds: the deep side (lo) where Fz62 > Fz, or past a
  // hump's peak; else the Romega side (hi).
  const auto deep_side = [&](const auto& above, const T& excess, const T& scale, const T& slope,
                             const T& drho_z) {
    if (!hump_possible) return above;
    return above || (hump && (excess < -fz_target * scale || (slope > T(0) && drho_z < T(0))));
  };
  // Start: q_fz2·x² + q_fz1·x = Fz / ((1 + speed − Fx² − Fcy²)(1 + PFZ1·dpi)·Fz0), x = ρ/R0.
  const T x0 = quadratic_deflection(c, fz_target, c.fcy_per_force * c.fy);
  // The camber's deflection at Romega is carried already; the free-rolling part makes up the rest
  // (negative where the camber's alone is more: the start is then Romega, below).
  const T rho_zfr0 = (x0 * c.r0 - rho_romega) * c.inv_free_share;
  // The power at the start's deflection, computed while its Rl and ρz are: the first evaluation
  // (at ρz ≈ x0·R0 where the free-rolling part is positive) then takes it from the memo
  // (fz62_pow_ratio) instead of waiting for pow. Not in fixed point (no FPU to overlap it with:
  // it would only add a division and the series), nor where Q_FCY2 = 0 (no power is computed),
  // nor where the root lies above Romega (the start is Romega, where the memo is exact already).
  if constexpr (!is_fixed_point<T>) {
    const auto seeded = rho_zfr0 > T(0) && !beyond;
    if (!is_zero(c.q_fcy2) && any_lane(seeded)) {
      // x0 > 0 wherever seeded; pow's argument does not wait for the mask.
      const T xs = if_else(x0 > T(0), x0, T(1));
      T value;
      if (beside != nullptr) {
        const TwoOf<T> both = mf_pow_two(xs, T(c.pow_q), beside->x, beside->y);
        value = both.first;
        beside->value = both.second;
        beside->done = true;
      } else {
        value = T(pow(xs, T(c.pow_q)));
      }
      memo.base = if_else(seeded, xs, memo.base);
      memo.inv_base = if_else(seeded, T(1) / xs, memo.inv_base);
      memo.value = if_else(seeded, value, memo.value);
    }
  }
  // On the bracket: [0, Romega] below Romega, Romega itself above it (lo = Romega). Two selects on
  // the chain where a clamp of ρ at 0 and of Rl at both ends took three, with the same value; a
  // NaN start (max_of and min_of keep their first argument then) becomes lo.
  T rl = min_of(c.romega, max_of(lo, c.romega - rho_zfr0));
  auto active = !(T(0) > T(0));     // every lane
  auto previous_settles = !active;  // the previous step may start a settled estimate (below)
  T previous_step = T(0);
  // ρz and its derivatives at the last point each lane evaluated while active.
  T rl_at = rl;
  T rho_at = T(0);
  T drho_at = T(0);
  T d2rho_at = T(0);
  T last_move = T(0);  // from the last point evaluated to the root, where converged
  T point = rl;        // where the next evaluation is (rl holds a converged lane's answer)
  LoadedRadius62<T> result{T(0), T(0), 0, false};
  // One step of the iteration; false when no lane is left active.
  const auto iterate = [&](int i) __attribute__((always_inline))->bool {
    const Fz62Value<T> at = fz62<kHalley>(c, point, fz_target, memo);
    rl_at = if_else(active, point, rl_at);
    rho_at = if_else(active, at.rho_z, rho_at);
    drho_at = if_else(active, at.drho_z, drho_at);
    d2rho_at = if_else(active, at.d2rho_z, d2rho_at);
    const T resid = at.excess;
    const T slope = at.slope;
    const auto above = resid > T(0);
    const auto deep = deep_side(above, resid, at.scale, slope, at.drho_z);
    lo = if_else(active && deep, point, lo);
    hi = if_else(active && !deep, point, hi);
    lo_known = lo_known || (active && deep);
    hi_known = hi_known || (active && !deep);
    T step = T(0);
    auto falling = slope < T(0);
    auto settles = !(T(0) > T(0));  // this step is of the kind the settled estimate assumes
    if constexpr (kHalley) {
      // −F·F'/(F'² − ½·F·F''): Newton's step times 1/(1 − F·F''/(2·F'²)) where that factor is
      // within [2/3, 2], else Newton's step (far from the root, where the curvature term is not
      // a small correction). A slope whose square underflows takes the bracket's step.
      const T slope2 = slope * slope;
      const T halley_den = slope2 - T(0.5) * resid * at.curvature;
      const auto cubic = halley_den > T(0.5) * slope2 && halley_den < T(1.5) * slope2;
      if constexpr (kBothQuotients) {
        // Both quotients, then the select: the comparison is off the chain (slope² is known
        // before the Halley denominator, so Newton's division starts first).
        // The same values as the select of the divisor. Four lanes, Intel VM: MF 6.2 / MF 6.1
        // 1.306 → 1.297 paired (three alternating runs).
        const T num = resid * slope;
        const T quotient = if_else(cubic, num / halley_den, num / slope2);
        step = -if_else(is_zero(if_else(cubic, halley_den, slope2)), T(0), quotient);
      } else {
        step = -div_or(resid * slope, if_else(cubic, halley_den, slope2), T(0));
      }
      falling = falling && slope2 > T(0);
      // Near the root the factor is near 1; within 10 % of it is the cubic regime the estimate
      // assumes (a long step whose factor is merely within [2/3, 2] left it 475× low).
      settles = halley_den > T(0.9) * slope2 && halley_den < T(1.1) * slope2;
    } else {
      step = -div_or(resid, slope, T(0));
    }
    const T newton = point + step;
    // Converged: a step at most the tolerance (it may round onto the bracket's end it came
    // from; a NaN step is not), or a step inside the bracket after one of the same kind whose
    // remaining error is at most ε·R0 (this saves the confirming step): Newton's C·step² with
    // C ≈ step / previous² (quadratic convergence), |step|³ ≤ ε·R0·previous²; Halley's K·step³
    // with K ≈ step / previous³ (cubic), step⁴ ≤ ε·R0·previous³/20 (see above).
    // At an end with Fz62 on the far side of Fz, the branch has no root: that end. Nor where the
    // bracket has closed on a hump's peak below Fz (lo past the peak, never above Fz): its end.
    const auto no_root = (above && !(point < hi_end)) || (!deep && !(point > lo_end));
    const T step_abs = abs(step);
    // The estimate's powers of the steps taken as at least the tolerance, so that they do not
    // underflow into denormals (a microcode assist on the Intel VM's Xeon: a step of 1e-11 m, as
    // after a cubic step, has a fourth power of 1e-44). The outcome is the same: a falling step
    // at or below the tolerance has converged anyway, and `settled` needs a falling step below
    // the previous one, so below the tolerance wherever the previous one is.
    const T step_c = max_of(step_abs, tolerance);
    const T previous_c = max_of(previous_step, tolerance);
    const T previous2 = previous_c * previous_c;
    const T remaining = kHalley ? step_c * step_c * step_c * step_c : step_c * step_c * step_c;
    const T allowed = kHalley ? T(0.05) * settle * previous2 * previous_c : settle * previous2;
    const auto inside = falling && newton > lo && newton < hi;
    const auto settled =
        previous_settles && settles && inside && step_abs < previous_step && remaining <= allowed;
    auto converged = is_zero(resid) || no_root || (falling && (step_abs <= tolerance || settled));
    const T landed = min_of(max_of(newton, lo), hi);
    T landed_or_end = landed;  // where a converged lane's Rl goes, unless it has no root
    if (hump_possible) {
      lo_crossed = lo_crossed || (active && above);
      const auto peak_below =
          lo_known && !lo_crossed && !beyond && !is_zero(resid) && !(hi - lo > tolerance);
      converged = converged || peak_below;
      landed_or_end = if_else(peak_below, lo_end, landed);
      collapsed = collapsed || (active && peak_below && !no_root);
    }
    // Where Newton's (Halley's) step leaves the bracket: its midpoint, or its far end where not
    // yet evaluated. Chosen before the step is known, so that one select follows it.
    T outside = T(0.5) * (lo + hi);
    outside = if_else(deep && !hi_known, hi_end, outside);
    outside = if_else(!deep && !lo_known, lo_end, outside);
    const T next = if_else(inside, newton, outside);
    // The converged step as computed, not as Rl's rounding leaves it: ρz below takes it (a light
    // load's ρz, ~1e-7 m, is only a few of float's Rl steps, 6e-8 m at 0.5 m; a step below half
    // of one rounds back onto Rl, the bracket's end).
    const auto within = !(newton < lo) && !(newton > hi);
    last_move = if_else(active && converged,
                        if_else(no_root, T(0), if_else(within, step, landed - point)), last_move);
    // The answer where converged; the next point, which an unconverged lane evaluates next, does
    // not wait for the convergence test (in a converged lane the next evaluation is not used):
    // four lanes' MF 6.2 / MF 6.1 1.321 → 1.306 paired on the Intel VM (three alternating runs;
    // the 16-lane batch 1.247 → 1.243, double and float within their noise).
    rl = if_else(active, if_else(converged, if_else(no_root, point, landed_or_end), next), rl);
    point = next;
    previous_settles = inside && settles;
    previous_step = step_abs;
    active = active && !converged;
    result.newton_steps = i + 1;
    return any_lane(active);
  };
  // On 8 lanes (the AVX2 and SSE2 batch) the first step is compiled on its own: every lane is
  // active and no step came before it, so its selects on `active` and the settled estimate fold
  // away (−46 instructions per block of eight, the batch's MF 6.2 / MF 6.1 1.320 → 1.300 paired,
  // four code placements). Four lanes are bound by the latency of the solve's chain rather than by
  // instructions: there the same measured slower (+0.3 to +3 %), and it is not done, nor in the
  // scalar paths. Nor on 16 lanes (AVX-512): on an Intel AVX-512 CPU it kept the bits
  // (SixteenLanesEqualEightBitForBit) but the batch's paired MF 6.2 / MF 6.1 went 1.38 → 1.41
  // (three alternating runs, 2026-11-30).
  constexpr bool kPeelFirst = is_float_lanes<T> && sizeof(T) == 8 * sizeof(float);
  if constexpr (kPeelFirst) {
    if (iterate(0)) {
      for (int i = 1; i < kNewtonSteps; ++i) {
        if (!iterate(i)) break;
      }
    }
  } else {
    for (int i = 0; i < kNewtonSteps; ++i) {
      if (!iterate(i)) break;
    }
  }
  if (any_lane(active)) {
    result.fallback = true;
    for (int i = 0; i < 80; ++i) {
      const T mid = T(0.5) * (lo + hi);
      const Fz62Value<T> at = fz62<false>(c, mid, fz_target, memo);
      const auto above = at.excess > T(0);
      const auto deep = deep_side(above, at.excess, at.scale, at.slope, at.drho_z);
      lo = if_else(active && deep, mid, lo);
      hi = if_else(active && !deep, mid, hi);
      if (hump_possible) lo_crossed = lo_crossed || (active && above);
    }
    rl = if_else(active, T(0.5) * (lo + hi), rl);
    if (hump_possible) {
      // Closed on a hump's peak below Fz: the branch's end (see above).
      const auto none = active && lo_known && !lo_crossed && !beyond;
      collapsed = collapsed || none;
      rl = if_else(none, lo_end, rl);
    }
  }
  // No root above Romega either (Fz62 > Fz at Romega and still at Romega + w: the camber alone
  // carries more than Fz there, as on a light, cambered wheel): Romega, the free radius, not the
  // bracket's end a tyre width above it (where Fz62 rises with Rl, the usual case, this is also
  // where Fz62 comes nearest Fz, MFeval's least-squares answer). ρz afresh there: the camber's.
  const auto no_root_above = beyond && !(rl < hi_end);
  rl = if_else(no_root_above, c.romega, rl);
  // ρz at the root from its Taylor polynomial about the last point evaluated (a step away at most,
  // where ρz is smooth: the camber part a quartic in Rl, the free-rolling part linear below
  // Romega), so that it is ready with Rl instead of after it, and is not limited to the deflections
  // Rl's rounding can express (Cz = Fz/ρz at the lightest loads: float's Rl − Romega alone was 9 %
  // off at 0.1 N); evaluated afresh where the step crossed Romega, where ρz was 0 (clamped; except
  // from Romega itself into the tyre, below) or where the fallback set Rl.
  const T moved = if_else(active, rl - rl_at, last_move);
  T rho = max_of(rho_at + moved * (drho_at + T(0.5) * d2rho_at * moved), T(0));
  // The side of Romega the root lies on, from the step as computed (Romega − Rl_at is exact near
  // Romega): a root within half an Rl step below Romega rounds onto it.
  const auto below = moved < c.romega - rl_at;
  const auto below_at = rl_at < c.romega;
  // From Romega itself with ρz = 0 there (no camber deflection: cam is 1 at Romega, so the camber
  // scale is 0; not a negative one, ASPECT_RATIO > 2.15, clamped) into the tyre, ρz is the free
  // part, linear, and the polynomial (slope −free_share there) is exact: the lightest loads' start.
  const auto at_romega = !(rl_at < c.romega) && !(rl_at > c.romega);
  const auto from_romega = at_romega && below && !(rho_at > T(0)) && !(c.camber_scale < T(0));
  const auto afresh =
      active || collapsed || no_root_above ||
      (((below && !below_at) || (below_at && !below) || !(rho_at > T(0))) && !from_romega);
  if (any_lane(afresh)) {
    T unused = T(0);
    rho = if_else(afresh, fz62_deflection(c, rl, unused), rho);
  }
  result.rl_m = rl;
  result.rho_m = rho;
  return result;
}

/// MF 6.2, MF 5.2 and PAC2002: Rl with Fz62(Rl) = Fz (decreasing in Rl) by loaded_radius62, at the
/// forces Fx and Fy after the lifted wheel's zeroing. It needs nothing else of the evaluation: on
/// lanes and in double evaluate starts it as soon as the forces are known, so that the moments'
/// work overlaps its chain of dependent steps (float, fixed point and Jets call it last). MF 6.2
/// solves for the load as given (MFeval 4.x's calculateRhoRl62 takes uFz, not the Fz limited to
/// FZMAX that the forces see); MF 5.2 / PAC2002 for the limited load.
template <typename T, typename P>
[[gnu::always_inline]] inline T fz62_target(const MfParameters<P>& p, const Prepared<T>& in) {
  return p.fit_type == FitType::mf62 ? in.ufz : in.fz;
}
template <typename T, typename P>
[[gnu::always_inline]] inline LoadedRadius62<T> solve_loaded_radius62(
    const MfParameters<P>& p, const Prepared<T>& in, const Basic<T>& b, const T& fx, const T& fy,
    PowBeside<T>* beside = nullptr) {
  return loaded_radius62(fz62_curve(p, in.gamma, in.omega, in.romega, b.dpi, fx, fy),
                         fz62_target(p, in), beside);
}

/// doExtras: Re, ω, and the loaded radius Rl, deflection ρ and vertical stiffness Cz, from the
/// forces in `out` (after the lifted wheel's zeroing); for every model but MF 6.1 from `solved`,
/// solve_loaded_radius62 at those forces.
template <typename T, typename P>
[[gnu::always_inline]] inline void loaded_radius(const MfParameters<P>& p, const Prepared<T>& in,
                                                 const Basic<T>& b, const LoadedRadius62<T>& solved,
                                                 MfOutput<T>& out) {
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
    out.rl_m = solved.rl_m;
    T rho_z = solved.rho_m;
    rho_z = if_else(is_zero(in.fz) || !(rho_z > T(0)), T(1e-6), rho_z);
    out.rho_m = rho_z;
    out.cz_npm = in.fz / rho_z;
  }
}

}  // namespace tread::mf::detail
