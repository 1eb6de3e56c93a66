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

#include "mf/mf_contact_patch.hpp"
#include "mf/mf_detail_common.hpp"
#include "mf/mf_forces.hpp"
#include "mf/mf_inputs.hpp"
#include "mf/mf_math.hpp"
#include "mf/mf_moments.hpp"
#include "mf/mf_options.hpp"
#include "mf/mf_output.hpp"
#include "mf/mf_parameters.hpp"
#include "mf/mf_prepared.hpp"
#include "mf/mf_radius.hpp"
#include "mf/mf_relaxation.hpp"
#include "mf/mf_turn_slip.hpp"
#include "mf/mf_types.hpp"

namespace tread::mf {

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
  const MzTrail<T> tr = mz_trail(p, in, b, options, y0);
  const T r0 = p.unloaded_radius_m;
  const T fz_mz = tr.fz_mz;
  const T dfz = b.dfz;
  const T g = b.gamma_z;
  const T kya_prime = tr.kya_prime;
  const T alphar = tr.alphar;
  const T alphat = tr.alphat;
  const T dt = tr.dt;
  const T bt = tr.bt;
  const T ct = tr.ct;
  const T et = tr.et;

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

  const MzTurnSlip<T> zeta = mz_turn_slip(p, in, b, options, tr, y0, gyk);
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
  if (options.moments_xy) {
    out.mx_nm = mx(p, in, b, fy);
    out.my_nm = my(p, in, fx);
  }
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
    loaded_radius(p, in, b, out);
    if (!options.extras_loaded_radius_only) {
      contact_patch(p, in, b, out);
      relaxation(p, in, b, kxk, y0.kya, out);
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
