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
//     iteration (Halley's steps in double and on lanes) to the output type's resolution
//     (detail::loaded_radius62). The two agree to about 1e-8 m.
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

#include <type_traits>

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
  // MF 6.2's (and MF 5.2's, PAC2002's) loaded radius (below). Where two tangents cost about one
  // (four lanes on x86-64, kTwoForOne), its curve takes tan γ computed beside basic's tan α and is
  // built before the forces are known (kCurveFirst, after the cores).
  const bool solve62 = options.extras && p.fit_type != FitType::mf61;
  constexpr bool kCurveFirst = is_lanes<T> && kTwoForOne<T>;
  const bool tan_gamma_beside = kTwoForOne<T> && solve62;
  T tan_gamma = T(0);
  const Basic<T> b = basic(p, in, options, tan_gamma_beside ? &tan_gamma : nullptr);

  MfOutput<T> out;

  T mux = T(0);
  T kxk = T(0);
  const Fx0Args<T> x0 = fx0_args(p, in, b, options, mux, kxk);
  // Kyα's load curve at γ* and, where Mz needs Fy0 at γ = 0 (combined, MF 6.x), at γ = 0: side
  // by side.
  const bool mf5x = is_mf5x(p);
  const bool with_y00 = options.combined && !mf5x;
  TwoOf<T> kya_load{T(0), T(0)};
  if (with_y00) {
    const TwoOf<T> at =
        mf_atan_two(kya_load_arg(p, in, b, b.gamma_star), kya_load_arg(p, in, b, T(0)));
    kya_load = mf_sin_two(p.pky4 * at.first, p.pky4 * at.second);
  } else {
    kya_load.first = mf_sin(p.pky4 * mf_atan(kya_load_arg(p, in, b, b.gamma_star)));
  }
  Fy0Result<T> y0 =
      fy0_args(p, in, b, options, b.gamma_star, options.use_turn_slip, kya_load.first);

  // Combined slip (or, with options.combined off, the pure-slip forces). The Magic Formula cores
  // of an evaluation are gathered first and evaluated together (mf_cores: float in passes of four
  // lanes, double stage by stage, Jet one by one): Fx0, Fy0, Gyk's two, and in combined slip the trail's,
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

  // calculateMz (combined): the equivalent slip angles and the cores of the trail, Gxa (two) and
  // (MF 6.x) Fy0 at γ = 0 for Fy' (turn slip as in the main evaluation; MFeval evaluates Gyk again
  // at γ = 0 but with the original γ* (its starVar), which is the same Gyk).
  MzEquivalentSlip<T> eq{T(0), T(0)};
  CombinedArgs<T> gxa_a{};
  Fy0Result<T> y00{};
  int lane_trail = 0;
  int lane_gxa = 0;
  int lane_fy00 = 0;
  if (options.combined) {
    eq = mz_equivalent_slip(in, tr, kxk);
    gxa_a = gxa_args(p, in, b, options);
    lane_trail = cores.add(tr.ct, tr.bt * eq.alphat_eq, tr.et, true);
    lane_gxa = cores.add(gxa_a.c, gxa_a.s0, gxa_a.e, true);
    static_cast<void>(cores.add(gxa_a.c, gxa_a.s1, gxa_a.e, true));
    if (with_y00) {
      y00 = fy0_args(p, in, b, options, T(0), options.use_turn_slip, kya_load.second);
      lane_fy00 = cores.add(y00.cy, y00.ba, y00.ey, false);
    }
  }

  T core_out[kMaxCores];
  mf_cores(cores, core_out);
  // Four lanes: the solve's curve but for what the forces set, here rather than after the forces,
  // off the solve's chain (it has three divisions and, for the power's approximant, about a
  // hundred scalar operations). AVX2 VM, four code placements of evaluate_four each, three
  // alternating runs: MF 6.2 / MF 6.1 1.305 → 1.254 (means) together with tan γ beside tan α and
  // contact_load once, the bits unchanged; built before the cores instead 1.266, after basic()
  // 1.287. The 8-lane batch measured slower with it (1.3105 → 1.3215, the same method) and
  // builds the curve after the forces.
  struct NoCurve {};
  std::conditional_t<kCurveFirst, Fz62Curve<T, P>, NoCurve> curve62;
  if constexpr (kCurveFirst) {
    if (solve62) {
      curve62 = fz62_curve_without_forces(p, in.gamma, in.omega, in.romega, b.dpi,
                                          tan_gamma_beside ? &tan_gamma : nullptr);
    }
  }
  const T fx_pure = fx0_finish(in, x0, core_out[lane_fx0]);
  fy0_finish(in, options, core_out[lane_fy0], y0);
  if (with_gyk) gyk = combined_finish(gyk_a, core_out[lane_gyk], core_out[lane_gyk + 1]);
  const T fx = options.combined
                   ? combined_finish(gxa_a, core_out[lane_gxa], core_out[lane_gxa + 1]) * fx_pure
                   : fx_pure;
  const T fy = options.combined ? gyk * y0.fy0 + svyk : y0.fy0;
  // MF 6.2's (and MF 5.2's, PAC2002's) loaded radius, a root search whose steps depend on each
  // other, needs only the forces (zeroed on a lifted wheel, as zero_lifted does below). On lanes
  // and in double it is started here, so that Mz's and the moments' work overlaps its chain (AVX2
  // VM, two sets of 8 alternating runs: the 8-lane batch's MF 6.2 / MF 6.1 1.31–1.35 → 1.27–1.28,
  // medians; four lanes unchanged. Double on the Intel VM, two sets of 10 alternating runs:
  // 1.301 → 1.291 and 1.304 → 1.296, MF 6.1 unchanged); in float, fixed point and Jets after
  // everything else, as before (float measured about 1 % slower here, 13 ns on the AVX-512 VM).
  constexpr bool kSolveBeforeMoments = is_lanes<T> || std::is_same_v<T, double>;
  LoadedRadius62<T> solved{T(0), T(0), 0, false};
  // MF 6.2's contact patch width takes a cube root (a power): where two powers cost about one
  // (kTwoForOne), beside the solve's seeded power; the contact load it is taken of is passed on
  // to contact_patch.
  PowBeside<T> width_power;
  ContactLoad<T> width_load{};
  const bool width_beside =
      kTwoForOne<T> && p.fit_type == FitType::mf62 && !options.extras_loaded_radius_only;
  if constexpr (kSolveBeforeMoments) {
    if (solve62) {
      const auto lifted = !(in.ufz > T(0));
      const T fx_solve = if_else(lifted, T(0), fx);
      const T fy_solve = if_else(lifted, T(0), fy);
      if (width_beside) {
        width_load = contact_load(p, in, b);
        width_power.x = width_load.relative;
        width_power.y = contact_width_power<T>();
      }
      PowBeside<T>* const beside = width_beside ? &width_power : nullptr;
      if constexpr (kCurveFirst) {
        fz62_set_forces(curve62, p, fx_solve, fy_solve);
        solved = loaded_radius62(curve62, fz62_target(p, in), beside);
      } else {
        solved = solve_loaded_radius62(p, in, b, fx_solve, fy_solve, beside);
      }
    }
  }

  const MzResidual<T> res =
      mz_residual(p, in, b, tr, y0, mz_turn_slip(p, in, b, options, tr, y0, gyk));
  MzResult<T> m;
  if (!options.combined) {
    m = mz_pure(p, in, b, options, tr, res);
  } else {
    T fy_prime;
    if (mf5x) {
      fy_prime = fy - svyk;
    } else {
      fy0_finish(in, options, core_out[lane_fy00], y00);  // Fy' = Gyk·Fy0(γ = 0)
      fy_prime = gyk * y00.fy0;
    }
    m = mz_combined(p, in, b, tr, res, eq.alphar_eq, core_out[lane_trail], fx, fy, fy_prime);
  }

  out.fx_n = fx;
  out.fy_n = fy;
  out.fz_n = in.ufz;
  if (options.moments_xy) {
    out.mx_nm = mx(p, in, b, fy);
    out.my_nm = my(p, in, fx);
  }
  out.mz_nm = m.mz;
  out.kappa = in.ukappa_low;
  out.alpha_rad = in.ualpha;
  out.gamma_rad = in.ugamma;
  out.phit_1pm = in.phit;
  out.vx_mps = in.vx;
  out.p_pa = in.p;
  out.t_m = m.t;
  out.mux = mux;
  out.muy = options.use_limits ? abs(y0.muy) : y0.muy;
  out.mzr_nm = m.mzr;
  out.kya_nprad = y0.kya;
  out.kxk_n = kxk;

  zero_lifted(out, !(in.ufz > T(0)));  // Fz ≤ 0: no contact

  if (options.extras) {
    if constexpr (!kSolveBeforeMoments) {
      if (solve62) solved = solve_loaded_radius62(p, in, b, out.fx_n, out.fy_n);
    }
    loaded_radius(p, in, b, solved, out);
    if (!options.extras_loaded_radius_only) {
      contact_patch(p, in, b, out, width_power.done ? &width_power.value : nullptr,
                    width_beside ? &width_load : nullptr);
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
