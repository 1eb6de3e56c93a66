#pragma once
// The Magic Formula MF 6.1 / MF 6.2 / MF-Tyre 5.2 steady state, following MFeval 4.3.1
// (Marco Furlan) equation by equation so the results match it, including MFeval's documented
// departures from the book to match TNO:
//   - A_mu = 1 in the digressive friction factor (so LMUX' = LMUX*), LMUV = 0;
//   - Dt from (A60) (QDZ3·γ, not |γ*|), Bt from (A58), Mx from Besselink's draft (49) with
//     QSX12…14, My from (A48) (MF 5.2: the equation manual's form), αr,eq/αt,eq from (A54)/(A55),
//     s from (A56);
//   - t multiplied by LFZO; Fy' of Mz = Gyk·Fy0(γ = 0) with the original γ* in Gyk;
//   - the low-speed model below VXLOW (linear κ, α and φt reduction, cosine reduction of SVx, SHx,
//     SVy, SHy, SVyk, t, Mzr; the empirical My reduction), φt·cos α with limits on;
//   - Fz is clamped only above FZMAX; FZMIN is used only in Mz0 (Fz low limit), Mx (Fz·(Fz/FZMIN)²)
//     and My (Fz·Fz/FZMIN); MF 6.2's loaded radius is solved for the load as given (unclamped),
//     its deflection's Cz = Fz/rho with the clamped load, as MFeval 4.x;
//   - MF 5.2 (FITTYP 6): Kyg0, SHy with PHY3, Mz = −t·(Fy − SVyk) + Mzr + s·Fx (SVyk of the
//     combined Fy itself, as MFeval 4.3.1's output shows, not the γ = 0 one), My without the
//     camber/pressure terms, contact length from Q_A1/Q_A2 (with MFeval's fallback), relaxation
//     lengths from PTX/PTY.
// Where MFeval divides by zero or takes acos of more than 1 (turn slip at φt = 0, Fz = 0 with the
// limits off, Q_FZ2 = 0) it returns NaN/Inf; here those spots take the limiting finite value, so a
// finite input always gives a finite output for a sound parameter set. Where MFeval is finite the
// arithmetic is the same. Parameters no tyre has (VERTICAL_STIFFNESS, FNOMIN, UNLOADED_RADIUS,
// LONGVL or NOMPRES 0, huge coefficients, ...) and NaN inputs can still make an output NaN or inf:
// such an output is returned as 0 with MfOutput::status non_finite, never as NaN/inf.
// Deliberate differences:
//   - rho/Rl for FITTYP ≠ 61 (MF 5.2, MF 6.2): MFeval minimises (Fz62(Rl) − Fz)² with fminsearch
//     (TolX 1e-6, start 0.3 m); here the root of Fz62(Rl) = Fz is found by a safeguarded Newton
//     iteration to the output type's resolution (detail::loaded_radius62). The two agree to about
//     1e-8 m.
//   - rho/Rl for FITTYP 61 solve the same quadratic in the cancellation-free form.
//   - TYRESIDE mirroring (MountedSide), which MFeval ignores.
//   - A finite-arithmetic envelope, applied in every mode: Fz ≤ 10·max(FZMAX, FNOMIN), |κ| ≤ 100,
//     |α|, |γ| ≤ 1.5707 rad, |Vx| ≤ 1000 m/s, |φt| ≤ 100 1/m, 1e-6·NOMPRES ≤ p ≤ 100·NOMPRES.
//     Inputs outside it are clamped and MfOutput::status is out_of_range. It lies far outside any
//     tyre's measured range.
//
// Options: MfOptions (useMode, mounted side, combined/uncombined, extras on/off).
// PAC2002 (FitType::pac2002) takes the MF 5.2 path with the camber scale factors LGAX/LGAY/LGAZ.
// Scalar: float, double or ceres::Jet (elementary functions through mf_math.hpp: libm/ADL for
// double and Jet, tread's polynomial approximations for float). No heap, no exceptions, no
// virtual calls, no I/O.

#include "mf/mf_math.hpp"
#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"
#include "mf/mf_types.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <type_traits>
#include <utility>

namespace tread::mf {

namespace detail {

using std::abs;
using std::acos;
using std::exp;
using std::pow;
using std::sqrt;

/// Per-lane truth values: bool for the scalars (double, float, ceres::Jet), lanes::Mask4 for
/// lanes::F4. Every branch on an input-dependent value is written as if_else (a select), so the
/// same code runs four wheels at a time; any_lane skips work no lane needs. For the scalars these
/// are the plain `c ? a : b` and `if`, so their results do not change by a bit.
template <typename T>
using MaskOf = decltype(std::declval<const T&>() < std::declval<const T&>());

template <typename T>
constexpr bool is_lanes = !std::is_same_v<MaskOf<T>, bool>;

/// Fixed-point scalars (fixed::Fixed64) mark themselves with a kIsFixedPoint member.
template <typename T>
constexpr bool is_fixed_point = requires {
  T::kIsFixedPoint;
};

/// √(a² + b²). Floating point: as written (so its results do not change by a bit). Fixed point:
/// scaled by the larger magnitude, so squares of large values (a side-slip speed tan α·Vx near
/// α = 90°) do not leave the format.
template <typename T>
T hypot_of(const T& a, const T& b) {
  if constexpr (is_fixed_point<T>) {
    const T x = abs(a);
    const T y = abs(b);
    const T big = x < y ? y : x;
    const T small = x < y ? x : y;
    if (!(big > T(0))) return big;  // 0 (or invalid)
    const T ratio = small / big;
    return big * sqrt(T(1) + ratio * ratio);
  } else {
    return sqrt(a * a + b * b);
  }
}

inline bool any_lane(bool b) {
  return b;
}
template <typename T>
T if_else(bool c, const T& a, const T& b) {
  return c ? a : b;
}

template <typename T>
auto is_zero(const T& x) {
  return !(x < T(0)) && !(x > T(0));
}
/// MATLAB sign(): −1, 0, +1.
template <typename T>
T sgn(const T& x) {
  return if_else(x > T(0), T(1), if_else(x < T(0), T(-1), T(0)));
}
/// sign() with sign(0) = 1, as MFeval writes `s = sign(x); s(s == 0) = 1`.
template <typename T>
T sgn_nz(const T& x) {
  return if_else(x < T(0), T(-1), T(1));
}
template <typename T>
T max_of(const T& a, const T& b) {
  return if_else(a < b, b, a);
}
template <typename T>
T min_of(const T& a, const T& b) {
  return if_else(b < a, b, a);
}
/// num/den, or `fallback` where den is exactly 0 (MFeval: Inf or NaN there).
template <typename T>
T div_or(const T& num, const T& den, const T& fallback) {
  if constexpr (is_lanes<T>) {
    return if_else(is_zero(den), fallback, num / den);
  } else {
    return is_zero(den) ? fallback : num / den;
  }
}
/// MfOutput<T>::status from the out-of-range and non-finite truth values.
template <typename T, typename M>
typename StatusFor<T>::type to_status(const M& out_of_range, const M& non_finite) {
  if constexpr (is_lanes<T>) {
    return {out_of_range, non_finite};
  } else {
    if (non_finite) return Status::non_finite;
    return out_of_range ? Status::out_of_range : Status::ok;
  }
}

/// Pointers to every value of an MfOutput.
template <typename T>
std::array<T*, 29> output_values(MfOutput<T>& o) {
  return {&o.fx_n,        &o.fy_n,      &o.fz_n,
          &o.mx_nm,       &o.my_nm,     &o.mz_nm,
          &o.kappa,       &o.alpha_rad, &o.gamma_rad,
          &o.phit_1pm,    &o.vx_mps,    &o.p_pa,
          &o.re_m,        &o.rho_m,     &o.contact_length_m,
          &o.t_m,         &o.mux,       &o.muy,
          &o.omega_radps, &o.rl_m,      &o.contact_width_m,
          &o.mzr_nm,      &o.cx_npm,    &o.cy_npm,
          &o.cz_npm,      &o.kya_nprad, &o.sigmax_m,
          &o.sigmay_m,    &o.kxk_n};
}

/// Whether x is finite, per lane: x − x is 0 for a finite x and NaN for NaN and ±inf. For
/// ceres::Jet (which compares by value only) isfinite() also checks the derivatives.
template <typename T>
auto finite(const T& x) {
  if constexpr (is_lanes<T> || std::is_floating_point_v<T>) {
    return (x - x) <= T(0);
  } else {
    using std::isfinite;
    return static_cast<bool>(isfinite(x));
  }
}

/// Σ (v − v) over v[B, E) as a balanced tree (no long dependency chain): 0 when every value is
/// finite, NaN otherwise (a sum of zeros cannot overflow).
template <std::size_t B, std::size_t E, typename T, std::size_t N>
T zero_or_nan(const std::array<T*, N>& v) {
  if constexpr (E - B == 1) {
    return *v[B] - *v[B];
  } else {
    constexpr std::size_t kMid = B + (E - B) / 2;
    return zero_or_nan<B, kMid>(v) + zero_or_nan<kMid, E>(v);
  }
}

/// Replaces every non-finite output by 0 and returns the non-finite truth value (per lane): one
/// subtraction per output, a tree of additions and one compare; the replacement runs only when a
/// lane needs it.
template <typename T>
MaskOf<T> replace_non_finite(MfOutput<T>& out) {
  const std::array<T*, 29> v = output_values(out);
  MaskOf<T> non_finite{};
  if constexpr (is_lanes<T> || std::is_floating_point_v<T>) {
    static_assert(offsetof(MfOutput<T>, status) == 29 * sizeof(T), "output_values: all of them");
    non_finite = !finite(zero_or_nan<0, 29>(v));
  } else {
    for (T* x : v) non_finite = non_finite || !finite(*x);
  }
  if (any_lane(non_finite)) {
    for (T* x : v) *x = if_else(finite(*x), *x, T(0));
  }
  return non_finite;
}

template <typename T>
T pi() {
  return T(3.14159265358979323846);
}

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

template <typename T>
struct Fy0Result {
  T fy0, muy, kya, kyg0, shy, svy, by, cy, zeta2;
  T dy, ba, ey;  // Fy0 = Dy·sin(Cy·atan(Ba − Ey·(Ba − atan Ba))) + SVy (fy0_finish)
};

/// Fx0 before its core: Fx0 = Dx·sin(Cx·atan(Bk − Ex·(Bk − atan Bk))) + SVx (fx0_finish).
template <typename T>
struct Fx0Args {
  T dx, cx, bk, ex, svx;
};

/// A combining factor (Gxa, Gyk) before its two cores: G = cos-core(s1) / cos-core(s0), the
/// denominator 1 where s0 = 0.
template <typename T>
struct CombinedArgs {
  T c, e, s0, s1;
};

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

  if (options.use_turn_slip) {
    const T fz0_prime = p.lfzo * p.fnomin_n;
    const T dfz = (fz - fz0_prime) / fz0_prime;
    const T vsy = -mf_tan(alpha) * abs(vx);
    T vc_prime = hypot_of(vx, vsy);
    in.epsilong = p.pecp1 * (T(1) + p.pecp2 * dfz);
    vc_prime = if_else(abs(vx) < p.vxlow_mps, p.vxlow_mps * sgn_nz(vx), vc_prime);
    const T psi_dot = -phit * vc_prime;
    in.phi = div_or(psi_dot - (T(1) - in.epsilong) * in.omega * mf_sin(gamma), vc_prime, T(0));
  }
  return in;
}

/// calculateBasic.
template <typename T, typename P>
Basic<T> basic(const MfParameters<P>& p, const Prepared<T>& in, const MfOptions& options) {
  Basic<T> b;
  const T vcx = in.vx;
  const T tan_alpha = mf_tan(in.alpha);
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
  const T vc_prime = vc + T(1e-6) * sgn_nz(vc);
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

/// calculateFx0 up to its core; writes mux and Kxk.
template <typename T, typename P>
Fx0Args<T> fx0_args(const MfParameters<P>& p, const Prepared<T>& in, const Basic<T>& b,
                    const MfOptions& options, T& mux, T& kxk) {
  const T dfz = b.dfz;
  const T dpi = b.dpi;
  const T fz = in.fz;
  T zeta1 = T(1);
  if (options.use_turn_slip) {
    const T bxp = p.pdxp1 * (T(1) + p.pdxp2 * dfz) * cos_atan(p.pdxp3 * in.kappa);
    zeta1 = cos_atan(bxp * p.unloaded_radius_m * in.phi);
  }
  const T cx = p.pcx1 * p.lcx;
  mux = (p.pdx1 + p.pdx2 * dfz) * (T(1) + p.ppx3 * dpi + p.ppx4 * dpi * dpi) *
        (T(1) - p.pdx3 * b.gamma_x * b.gamma_x) * b.lmux_star;
  mux = if_else(is_zero(fz), T(0), mux);
  const T dx = mux * fz * zeta1;
  kxk = fz * (p.pkx1 + p.pkx2 * dfz) * mf_exp(p.pkx3 * dfz) *
        (T(1) + p.ppx1 * dpi + p.ppx2 * dpi * dpi) * p.lkx;
  const T bx = div_or(kxk, cx * dx + T(1e-6) * sgn_nz(dx), T(0));
  T shx = (p.phx1 + p.phx2 * dfz) * p.lhx;
  T svx = fz * (p.pvx1 + p.pvx2 * dfz) * p.lvx * b.lmux_prime * zeta1;
  svx = if_else(in.is_low_speed, svx * in.reduction_smooth, svx);
  shx = if_else(in.is_low_speed, shx * in.reduction_smooth, shx);
  const T kappax = in.kappa + shx;
  T ex = (p.pex1 + p.pex2 * dfz + p.pex3 * dfz * dfz) * (T(1) - p.pex4 * sgn(kappax)) * p.lex;
  if (options.use_limits) ex = min_of(ex, T(1));
  const T bk = bx * kappax;
  return {dx, cx, bk, ex, svx};
}

/// Fx0 from its core sin(Cx·atan(Bk − Ex·(Bk − atan Bk))).
template <typename T>
T fx0_finish(const Prepared<T>& in, const Fx0Args<T>& a, const T& core) {
  const T f = a.dx * core + a.svx;
  return if_else(in.vx < T(0), -f, f);
}

/// calculateFy0 up to its core (everything but fy0), with the given γ (and γ*) and turn slip switch
/// (Mz evaluates it again at γ = 0).
template <typename T, typename P>
Fy0Result<T> fy0_args(const MfParameters<P>& p, const Prepared<T>& in, const Basic<T>& b,
                      const MfOptions& options, const T& gamma_star, bool turn_slip) {
  Fy0Result<T> r;
  const T dfz = b.dfz;
  const T dpi = b.dpi;
  const T fz = in.fz;
  const T fz0_prime = b.fz0_prime;
  const T r0 = p.unloaded_radius_m;
  const T vcx = in.vx;
  const T eps = T(1e-6);
  const bool mf5x = is_mf5x(p);

  T zeta2 = T(1);
  T zeta3 = T(1);
  if (turn_slip) {
    zeta3 = cos_atan(p.pkyp1 * r0 * r0 * in.phi * in.phi);
    const T byp = p.pdyp1 * (T(1) + p.pdyp2 * dfz) * cos_atan(p.pdyp3 * mf_tan(in.alpha));
    const T r0phi = r0 * abs(in.phi);
    zeta2 = cos_atan(byp * (r0phi + p.pdyp4 * sqrt(r0phi)));
  }
  r.zeta2 = zeta2;

  const T gs2 = gamma_star * gamma_star;
  r.kya = p.pky1 * fz0_prime * (T(1) + p.ppy1 * dpi) * (T(1) - p.pky3 * abs(gamma_star)) *
          mf_sin(p.pky4 *
                 mf_atan((fz / fz0_prime) / ((p.pky2 + p.pky5 * gs2) * (T(1) + p.ppy2 * dpi)))) *
          zeta3 * p.lky;
  const T svyg = fz * (p.pvy3 + p.pvy4 * dfz) * gamma_star * p.lkyc * b.lmuy_prime * zeta2;
  if (mf5x) {
    const T kya0 =
        p.pky1 * fz0_prime * mf_sin(p.pky4 * mf_atan(fz / (p.pky2 * fz0_prime))) * p.lkyc;
    r.kyg0 = (p.phy3 * kya0 + fz * (p.pvy3 + p.pvy4 * dfz)) * p.lkyc;
  } else {
    r.kyg0 = fz * (p.pky6 + p.pky7 * dfz) * (T(1) + p.ppy5 * dpi) * p.lkyc;
  }

  T zeta0 = T(1);
  T zeta4 = T(1);
  if (turn_slip) {
    const T kya0 = p.pky1 * fz0_prime * (T(1) + p.ppy1 * dpi) *
                   mf_sin(p.pky4 * mf_atan((fz / fz0_prime) / (p.pky2 * (T(1) + p.ppy2 * dpi)))) *
                   zeta3 * p.lky;
    const T kya_prime = r.kya + eps * sgn_nz(r.kya);
    const T kyao_prime = kya0 + eps * sgn_nz(kya0);
    const T chyp = p.phyp1;
    const T dhyp = (p.phyp2 + p.phyp3 * dfz) * sgn(vcx);
    T ehyp = p.phyp4;
    if (options.use_limits) ehyp = min_of(ehyp, T(1));
    const T kyrp0 = div_or(r.kyg0, T(1) - in.epsilong, T(0));
    const T bhyp = div_or(kyrp0, chyp * dhyp * kyao_prime, T(0));
    const T x = bhyp * r0 * in.phi;
    const T shyp = dhyp * mf_sin(chyp * mf_atan(x - ehyp * (x - mf_atan(x)))) * sgn(vcx);
    zeta0 = T(0);
    zeta4 = T(1) + shyp - svyg / kya_prime;
  }

  if (mf5x) {
    r.shy = (p.phy1 + p.phy2 * dfz) * p.lhy + p.phy3 * gamma_star * p.lkyc;
  } else {
    r.shy = (p.phy1 + p.phy2 * dfz) * p.lhy +
            ((r.kyg0 * gamma_star - svyg) / (r.kya + eps * sgn_nz(r.kya))) * zeta0 + zeta4 - T(1);
  }
  r.svy = fz * (p.pvy1 + p.pvy2 * dfz) * p.lvy * b.lmuy_prime * zeta2 + svyg;
  r.svy = if_else(in.is_low_speed, r.svy * in.reduction_smooth, r.svy);
  r.shy = if_else(in.is_low_speed, r.shy * in.reduction_smooth, r.shy);
  const T alphay = b.alpha_star + r.shy;
  r.cy = p.pcy1 * p.lcy;
  r.muy = (p.pdy1 + p.pdy2 * dfz) * (T(1) + p.ppy3 * dpi + p.ppy4 * dpi * dpi) *
          (T(1) - p.pdy3 * gs2) * b.lmuy_star;
  const T dy = r.muy * fz * zeta2;
  T ey = (p.pey1 + p.pey2 * dfz) *
         (T(1) + p.pey5 * gs2 - (p.pey3 + p.pey4 * gamma_star) * sgn_nz(alphay)) * p.ley;
  if (options.use_limits) ey = min_of(ey, T(1));
  r.by = div_or(r.kya, r.cy * dy + eps * sgn_nz(dy), T(0));
  r.dy = dy;
  r.ba = r.by * alphay;
  r.ey = ey;
  r.muy = if_else(is_zero(fz), T(0), r.muy);
  return r;
}

/// Fy0 from its core sin(Cy·atan(Ba − Ey·(Ba − atan Ba))).
template <typename T>
void fy0_finish(const Prepared<T>& in, const MfOptions& options, const T& core, Fy0Result<T>& r) {
  r.fy0 = r.dy * core + r.svy;
  if (options.use_alpha_star) r.fy0 = if_else(in.vx < T(0), -r.fy0, r.fy0);
}

/// calculateFy0 in one go (the paths that do not batch their cores).
template <typename T, typename P>
Fy0Result<T> fy0(const MfParameters<P>& p, const Prepared<T>& in, const Basic<T>& b,
                 const MfOptions& options, const T& gamma_star, bool turn_slip) {
  Fy0Result<T> r = fy0_args(p, in, b, options, gamma_star, turn_slip);
  fy0_finish(in, options, mf_sin(r.cy * mf_atan(r.ba - r.ey * (r.ba - mf_atan(r.ba)))), r);
  return r;
}

/// calculateFy (combined) up to Gyk's cores; writes SVyk (after the low-speed reduction).
template <typename T, typename P>
CombinedArgs<T> gyk_args(const MfParameters<P>& p, const Prepared<T>& in, const Basic<T>& b,
                         const MfOptions& options, const T& muy, const T& zeta2, T& svyk) {
  const T dfz = b.dfz;
  const T dvyk = muy * in.fz * (p.rvy1 + p.rvy2 * dfz + p.rvy3 * b.gamma_star) *
                 cos_atan(p.rvy4 * b.alpha_star) * zeta2;
  svyk = dvyk * mf_sin(p.rvy5 * mf_atan(p.rvy6 * in.kappa)) * p.lvyka;
  const T shyk = p.rhy1 + p.rhy2 * dfz;
  T eyk = p.rey1 + p.rey2 * dfz;
  if (options.use_limits) eyk = min_of(eyk, T(1));
  const T cyk = p.rcy1;
  const T byk = (p.rby1 + p.rby4 * b.gamma_star * b.gamma_star) *
                cos_atan(p.rby2 * (b.alpha_star - p.rby3)) * p.lyka;
  const T kappas = in.kappa + shyk;
  svyk = if_else(in.is_low_speed, svyk * in.reduction_smooth, svyk);
  return {cyk, eyk, byk * shyk, byk * kappas};
}

/// Gxa or Gyk from its two cores cos(C·atan(s − E·(s − atan s))) at s0 and s1.
template <typename T>
T combined_finish(const CombinedArgs<T>& a, const T& core0, const T& core1) {
  const T g0 = if_else(is_zero(a.s0), T(1), core0);
  return div_or(core1, g0, T(1));
}

/// calculateFx (combined): Gxa up to its cores.
template <typename T, typename P>
CombinedArgs<T> gxa_args(const MfParameters<P>& p, const Prepared<T>& in, const Basic<T>& b,
                         const MfOptions& options) {
  const T cxa = p.rcx1;
  T exa = p.rex1 + p.rex2 * b.dfz;
  if (options.use_limits) exa = min_of(exa, T(1));
  const T shxa = p.rhx1;
  const T bxa =
      (p.rbx1 + p.rbx3 * b.gamma_star_x * b.gamma_star_x) * cos_atan(p.rbx2 * in.kappa) * p.lxal;
  const T alphas = b.alpha_star + shxa;
  return {cxa, exa, bxa * shxa, bxa * alphas};
}

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
  T fys1_g, fys2_g, fys3_g;  // Q_FYS1…3·γ
  T base;                    // 1 + Q_V2·(R0/V0)·|ω| − (Q_FCX·Fx/Fz0)²
  T pressure;                // 1 + PFZ1·dpi
  T fcy_per_force;           // Q_FCY / Fz0
  T fy;
  T pow_c1, pow_c2, pow_c3, pow_c4;  // binomial coefficients C(Q_FCY2, k), k = 1…4
};

template <typename T, typename P>
Fz62Curve<T, P> fz62_curve(const MfParameters<P>& p, const T& gamma, const T& omega,
                           const T& romega, const T& dpi, const T& fx, const T& fy) {
  Fz62Curve<T, P> c;
  c.q_fcy2 = p.q_fcy2;
  c.r0 = p.unloaded_radius_m;
  c.fz0 = p.fnomin_n;
  c.romega = romega;
  c.width = p.width_m;
  c.inv_r0 = T(1) / c.r0;
  c.inv_romega = T(1) / romega;
  const T a = p.vertical_stiffness_npm * c.r0 / c.fz0;
  c.q_fz1 = sqrt(max_of(T(0), a * a - T(4) * p.q_fz2));
  c.q_fz2 = p.q_fz2;
  c.q_cam1 = p.q_cam1;
  c.q_cam2 = p.q_cam2;
  const T rtw = (T(1.075) - T(0.5) * p.aspect_ratio) * p.width_m;
  const T den = (p.q_cam1 * romega + p.q_cam2 * romega * romega) * gamma;
  const auto cambered = !is_zero(den);
  c.camber_scale = T(0);
  if (any_lane(cambered)) {
    c.camber_scale =
        if_else(cambered, (gamma * gamma) * (rtw / T(8)) * abs(mf_tan(gamma)) / (den * den), T(0));
  }
  c.free_share = T(1) - p.q_cam3 * abs(gamma);
  c.fys1_g = p.q_fys1 * gamma;
  c.fys2_g = p.q_fys2 * gamma;
  c.fys3_g = p.q_fys3 * gamma;
  const T fcx = p.q_fcx * fx / c.fz0;
  c.base = T(1) + p.q_v2 * (c.r0 / p.longvl_mps) * abs(omega) - fcx * fcx;
  c.pressure = T(1) + p.pfz1 * dpi;
  c.fcy_per_force = T(p.q_fcy) / c.fz0;
  c.fy = fy;
  const T q = T(p.q_fcy2);
  c.pow_c1 = q;
  c.pow_c2 = c.pow_c1 * (q - T(1)) / T(2);
  c.pow_c3 = c.pow_c2 * (q - T(2)) / T(3);
  c.pow_c4 = c.pow_c3 * (q - T(3)) / T(4);
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
  T value = T(0);
};

/// x^q from the memo's base b: (b·(1 + δ))^q = b^q·(1 + C(q,1)δ + … + C(q,4)δ⁴) for |δ| ≤ δmax
/// (the remainder C(q,5)·δ⁵: |δ| ≤ 2e-4 in double, 1e-2 in float keeps it below ε for
/// |Q_FCY2| ≤ 3), else pow, which becomes the new base.
template <typename T, typename P>
[[gnu::always_inline]] inline T fz62_pow(const Fz62Curve<T, P>& c, const T& x,
                                         Fz62PowMemo<T>& memo) {
  constexpr bool coarse = std::is_same_v<T, float> || is_lanes<T> || is_fixed_point<T>;
  const T delta = div_or(x - memo.base, memo.base, T(1));
  const auto near = memo.base > T(0) && abs(delta) < T(coarse ? 1e-2 : 2e-4);
  const T series =
      memo.value *
      (T(1) + delta * (c.pow_c1 + delta * (c.pow_c2 + delta * (c.pow_c3 + delta * c.pow_c4))));
  const auto far = !near;
  if (!any_lane(far)) return series;
  const T exact = T(pow(x, T(c.q_fcy2)));
  memo.base = if_else(far, x, memo.base);
  memo.value = if_else(far, exact, memo.value);
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
    rho_pow = if_else(loaded, fz62_pow(c, if_else(loaded, rho_r0, T(1)), memo), rho_pow);
    drho_pow = if_else(loaded, c.pow_c1 * div_or(rho_pow, rho_r0, T(0)) * drho_r0, T(0));
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
///   corrections) less the camber's deflection at Romega.
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
  }
  const T lo_end = if_else(beyond, c.romega, T(0));
  const T hi_end = if_else(beyond, c.romega + c.width, c.romega);
  T lo = lo_end;
  T hi = hi_end;
  auto lo_known = beyond;   // Fz62(lo) > Fz is known
  auto hi_known = !beyond;  // Fz62(hi) ≤ Fz is known
  // Start: q_fz2·x² + q_fz1·x = Fz / ((1 + speed − Fx² − Fy²)(1 + PFZ1·dpi)·Fz0), x = ρ/R0.
  const T fcy0 = c.fcy_per_force * c.fy;
  const T external = (c.base - fcy0 * fcy0) * c.pressure * c.fz0;
  const T q = max_of(div_or(fz_target, external, T(0)), T(0));
  const T x0 = div_or(T(2) * q, c.q_fz1 + sqrt(c.q_fz1 * c.q_fz1 + T(4) * c.q_fz2 * q), T(0));
  // The camber's deflection at Romega is carried already; the free-rolling part makes up the rest.
  const T free_share = max_of(c.free_share, T(0.1));
  const T rho_zfr0 = max_of(x0 * c.r0 - rho_romega, T(0)) / free_share;
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

/// TYRESIDE mirroring, y → −y, where `mirror` is set (per lane for lanes): the lateral inputs
/// (α, γ, φt) on the way in, the lateral outputs on the way out.
template <typename T, typename M>
MfInput<T> mirror_input(MfInput<T> in, const M& mirror) {
  in.alpha_rad = if_else(mirror, -in.alpha_rad, in.alpha_rad);
  in.gamma_rad = if_else(mirror, -in.gamma_rad, in.gamma_rad);
  in.phit_1pm = if_else(mirror, -in.phit_1pm, in.phit_1pm);
  return in;
}
template <typename T, typename M>
void mirror_output(MfOutput<T>& out, const M& mirror) {
  for (T* y : {&out.fy_n, &out.mx_nm, &out.mz_nm, &out.mzr_nm, &out.alpha_rad, &out.gamma_rad,
               &out.phit_1pm}) {
    *y = if_else(mirror, -*y, *y);
  }
}

}  // namespace detail

/// Whether a tyre measured as `tyre_side` and mounted on `side` is mirrored (y → −y).
constexpr bool mirrored(MountedSide side, TyreSide tyre_side) {
  if (side == MountedSide::left) return tyre_side == TyreSide::right;
  if (side == MountedSide::right) return tyre_side == TyreSide::left;
  return false;
}

/// One steady-state evaluation. Never allocates, never throws; never returns NaN or inf: finite
/// inputs and a sound parameter set give finite outputs, anything else (a NaN input, zero
/// VERTICAL_STIFFNESS, ...) gives 0 for each non-finite output and Status::non_finite.
template <typename T, typename P>
MfOutput<T> evaluate(const MfParameters<P>& params, const MfInput<T>& input,
                     const MfOptions& options) {
  using namespace detail;  // NOLINT(google-build-using-namespace): the maths helpers and ADL
  const MfParameters<P>& p = params;

  // TYRESIDE mirroring: y → −y.
  const bool mirror = mirrored(options.side, p.tyre_side);
  const MfInput<T> in_raw = mirror ? mirror_input(input, true) : input;

  const Prepared<T> in = prepare(p, in_raw, options);
  const Basic<T> b = basic(p, in, options);

  MfOutput<T> out;

  T mux = T(0);
  T kxk = T(0);
  const Fx0Args<T> x0 = fx0_args(p, in, b, options, mux, kxk);
  Fy0Result<T> y0 = fy0_args(p, in, b, options, b.gamma_star, options.use_turn_slip);

  // Combined slip (or, with options.combined off, the pure-slip forces). The Magic Formula cores
  // of an evaluation are gathered first and evaluated together (mf_cores: float in passes of four
  // lanes, double and Jet one by one): Fx0, Fy0, Gyk's two, and in combined slip the trail's,
  // Gxa's two and (MF 6.x) Fy0(γ = 0)'s.
  T svyk = T(0);
  T gyk = T(1);
  Cores<T> cores;
  const int lane_fx0 = cores.add(x0.cx, x0.bk, x0.ex, false);
  const int lane_fy0 = cores.add(y0.cy, y0.ba, y0.ey, false);
  const bool with_gyk = options.combined || options.use_turn_slip;
  CombinedArgs<T> gyk_a{};
  int lane_gyk = 0;
  if (with_gyk) {
    gyk_a = gyk_args(p, in, b, options, y0.muy, y0.zeta2, svyk);
    lane_gyk = cores.add(gyk_a.c, gyk_a.s0, gyk_a.e, true);
    static_cast<void>(cores.add(gyk_a.c, gyk_a.s1, gyk_a.e, true));
  }

  // Aligning moment: calculateMz0's trail and residual-moment coefficients.
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

  // calculateMz (combined): the equivalent slip angles and the cores of the trail, Gxa (two) and
  // (MF 6.x) Fy0 at γ = 0 for Fy' (turn slip as in the main evaluation; MFeval evaluates Gyk again
  // at γ = 0 but with the original γ* (its starVar), which is the same Gyk).
  const bool mf5x = is_mf5x(p);
  T alphar_eq = T(0);
  CombinedArgs<T> gxa_a{};
  Fy0Result<T> y00{};
  int lane_trail = 0;
  int lane_gxa = 0;
  int lane_fy00 = 0;
  if (options.combined) {
    const T kk = div_or(kxk, kya_prime, T(0)) * in.kappa;
    const T tan_r = mf_tan(alphar);
    const T tan_t = mf_tan(alphat);
    alphar_eq = mf_atan(hypot_of(tan_r, kk)) * sgn(alphar);
    const T alphat_eq = mf_atan(hypot_of(tan_t, kk)) * sgn(alphat);
    const T bta = bt * alphat_eq;
    gxa_a = gxa_args(p, in, b, options);
    lane_trail = cores.add(ct, bta, et, true);
    lane_gxa = cores.add(gxa_a.c, gxa_a.s0, gxa_a.e, true);
    static_cast<void>(cores.add(gxa_a.c, gxa_a.s1, gxa_a.e, true));
    if (!mf5x) {
      y00 = fy0_args(p, in, b, options, T(0), options.use_turn_slip);
      lane_fy00 = cores.add(y00.cy, y00.ba, y00.ey, false);
    }
  }

  T core_out[kMaxCores];
  mf_cores(cores, core_out);
  const T fx_pure = fx0_finish(in, x0, core_out[lane_fx0]);
  fy0_finish(in, options, core_out[lane_fy0], y0);
  if (with_gyk) gyk = combined_finish(gyk_a, core_out[lane_gyk], core_out[lane_gyk + 1]);
  const T fx = options.combined
                   ? combined_finish(gxa_a, core_out[lane_gxa], core_out[lane_gxa + 1]) * fx_pure
                   : fx_pure;
  const T fy = options.combined ? gyk * y0.fy0 + svyk : y0.fy0;

  T zeta0 = T(1), zeta2 = T(1), zeta6 = T(1), zeta7 = T(1), zeta8 = T(1);
  if (options.use_turn_slip) {
    zeta0 = T(0);
    zeta2 = y0.zeta2;
    zeta6 = cos_atan(p.qbrp1 * r0 * in.phi);
    T mzp_inf = p.qcrp1 * abs(y0.muy) * r0 * fz_mz * sqrt(fz_mz / b.fz0_prime) * p.lmp;
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
    zeta7 = if_else(is_zero(drp) && is_zero(mzp90), T(1), (T(2) / pi<T>()) * acos(ratio));
    zeta8 = T(1) + drp;
  }
  const T dr =
      fz_mz * r0 *
          ((p.qdz6 + p.qdz7 * dfz) * p.lres * zeta2 +
           ((p.qdz8 + p.qdz9 * dfz) * (T(1) + p.ppz2 * dpi) + (p.qdz10 + p.qdz11 * dfz) * abs(gs)) *
               gs * p.lkzc * zeta0) *
          b.lmuy_star * sgn(in.vx) * mf_cos(b.alpha_star) +
      zeta8 - T(1);
  const T br = (p.qbz9 * p.lky / b.lmuy_star + p.qbz10 * y0.by * y0.cy) * zeta6;
  const T cr = zeta7;

  T mz;
  T t;
  T mzr;
  if (!options.combined) {
    // Pure slip: calculateMz0's Mz0 = −t0·Fy0(γ = 0, no turn slip) + Mzr0.
    const T bta = bt * alphat;
    t = dt * mf_cos(ct * mf_atan(bta - et * (bta - mf_atan(bta)))) * b.cos_alpha_prime;
    mzr = dr * mf_cos(cr * mf_atan(br * alphar)) * b.cos_alpha_prime;
    const Fy0Result<T> y00_pure = fy0(p, in, b, options, T(0), false);
    mz = -t * y00_pure.fy0 + mzr;
  } else {
    const T s = r0 * (p.ssz1 + p.ssz2 * (fy / p.fnomin_n) + (p.ssz3 + p.ssz4 * dfz) * g) * p.ls;
    mzr = dr * mf_cos(cr * mf_atan(br * alphar_eq));
    t = dt * core_out[lane_trail] * b.cos_alpha_prime;
    t = t * p.lfzo;
    t = if_else(in.is_low_speed, t * in.reduction_smooth, t);
    mzr = if_else(in.is_low_speed, mzr * in.reduction_smooth, mzr);
    if (mf5x) {
      mz = -t * (fy - svyk) + mzr + s * fx;
    } else {
      fy0_finish(in, options, core_out[lane_fy00], y00);  // Fy' = Gyk·Fy0(γ = 0)
      mz = -t * (gyk * y00.fy0) + mzr + s * fx;
    }
  }

  out.fx_n = fx;
  out.fy_n = fy;
  out.fz_n = in.ufz;
  out.mx_nm = mx(p, in, b, fy);
  out.my_nm = my(p, in, fx);
  out.mz_nm = mz;
  out.kappa = in.ukappa_low;
  out.alpha_rad = in.ualpha;
  out.gamma_rad = in.ugamma;
  out.phit_1pm = in.phit;
  out.vx_mps = in.vx;
  out.p_pa = in.p;
  out.t_m = t;
  out.mux = mux;
  out.muy = options.use_limits ? abs(y0.muy) : y0.muy;
  out.mzr_nm = mzr;
  out.kya_nprad = y0.kya;
  out.kxk_n = kxk;

  const auto lifted = !(in.ufz > T(0));  // Fz ≤ 0: no contact, no forces (MFeval: 0 as well)
  if (any_lane(lifted)) {
    out.fx_n = if_else(lifted, T(0), out.fx_n);
    out.fy_n = if_else(lifted, T(0), out.fy_n);
    out.mx_nm = if_else(lifted, T(0), out.mx_nm);
    out.my_nm = if_else(lifted, T(0), out.my_nm);
    out.mz_nm = if_else(lifted, T(0), out.mz_nm);
    out.t_m = if_else(lifted, T(0), out.t_m);
    out.mzr_nm = if_else(lifted, T(0), out.mzr_nm);
  }

  if (options.extras) {
    // doExtras: Re, rho, Rl, Cz.
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
      const T external =
          (T(1) + speed_effect - fx_effect - fy_effect) * (T(1) + p.pfz1 * dpi) * fz0;
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

    // calculateContactPatch.
    if (!options.extras_loaded_radius_only) {
      const T ncz = p.vertical_stiffness_npm * (T(1) + p.pfz1 * dpi);
      T fz = in.ufz;
      const T rl_approx = r0 - fz / ncz;
      fz = if_else(rl_approx - (p.rim_radius_m + p.bottom_offst_m) < T(0),
                   (r0 - p.rim_radius_m - p.bottom_offst_m) * ncz, fz);
      fz = max_of(fz, T(0));
      if (is_mf5x(p)) {
        P q_a1 = p.q_a1;  // a property of the tyre: the same for every lane
        P q_a2 = p.q_a2;
        if (is_zero(q_a1) && is_zero(q_a2)) {
          using std::log10;
          const P y = log10(p.unloaded_radius_m * (p.vertical_stiffness_npm / p.fnomin_n));
          q_a1 = P(-0.0388) * y * y * y + P(0.2509) * y * y + P(-0.6283) * y + P(0.6279);
          q_a2 = P(1.693) * q_a1 * q_a1;
        }
        out.contact_length_m = T(2) * r0 * (q_a2 * (fz / fz0) + q_a1 * sqrt(fz / fz0));
        out.contact_width_m = p.width_m;
      } else {
        const T f = fz / (ncz * r0);
        out.contact_length_m = T(2) * r0 * (p.q_ra2 * f + p.q_ra1 * sqrt(f));
        const T cube_root = if_else(f > T(0), mf_pow(f, T(1) / T(3)), T(0));
        out.contact_width_m = T(2) * p.width_m * (p.q_rb2 * f + p.q_rb1 * cube_root);
      }
    }

    // calculateRelax.
    if (!options.extras_loaded_radius_only) {
      const T dfz_r = (in.fz - b.fz0_prime) / b.fz0_prime;
      out.cx_npm = p.longitudinal_stiffness_npm *
                   (T(1) + p.pcfx1 * dfz_r + p.pcfx2 * dfz_r * dfz_r) * (T(1) + p.pcfx3 * dpi);
      out.cy_npm = p.lateral_stiffness_npm * (T(1) + p.pcfy1 * dfz_r + p.pcfy2 * dfz_r * dfz_r) *
                   (T(1) + p.pcfy3 * dpi);
      if (is_mf5x(p)) {
        out.sigmax_m =
            (p.ptx1 + p.ptx2 * dfz_r) * exp(-p.ptx3 * dfz_r) * p.lsgkp * r0 * in.fz / fz0;
        const T sigmayg = T(1) - p.pky3 * abs(in.gamma);
        const T ptyfzn = p.pty2 * b.fz0_prime;
        out.sigmay_m = p.pty1 * mf_sin(T(2) * mf_atan(div_or(in.fz, ptyfzn, T(0)))) * sigmayg * r0 *
                       p.lfzo * p.lsgal;
      } else {
        out.sigmax_m = abs(div_or(kxk, out.cx_npm, T(0)));
        out.sigmay_m = abs(div_or(y0.kya, out.cy_npm, T(0)));
      }
    }
  }

  if (mirror) mirror_output(out, true);
  // No NaN or inf leaves: a non-finite output (defective parameters, a NaN input) becomes 0 and
  // the status says so.
  const auto non_finite = replace_non_finite(out);
  out.status = to_status<T>(in.out_of_range, non_finite);
  return out;
}

// float and double are compiled once, in the core (mf_evaluate.cpp), with the core's flags and
// optimisation: a program using this header calls those instead of compiling (and inlining) its own
// copy with its own. Otherwise the numbers would depend on the caller's build: on a Cortex-M4F,
// a·b + c becomes one vfma.f32 at -O2 and a vmul and a vadd at -O0.
extern template MfOutput<float> evaluate<float>(const MfParameters<float>&, const MfInput<float>&,
                                                const MfOptions&);
extern template MfOutput<double> evaluate<double>(const MfParameters<double>&,
                                                  const MfInput<double>&, const MfOptions&);

}  // namespace tread::mf
