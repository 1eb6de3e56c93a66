#pragma once
// The forces Fx and Fy: pure slip (calculateFx0, calculateFy0) and combined slip (calculateFx's
// Gxa, calculateFy's Gyk and SVyk), each split at its Magic Formula core so that all cores of an
// evaluation are evaluated together (mf_cores): the *_args functions compute a core's arguments
// and the rest of the equation, the *_finish functions complete it from the core's value.

#include "mf/mf_detail_common.hpp"
#include "mf/mf_math.hpp"
#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"
#include "mf/mf_prepared.hpp"

namespace tread::mf::detail {

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
  const T bx = div_or(kxk, cx * dx + sgn_nz_times(dx, T(1e-6)), T(0));
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

/// The argument of Kyα's load curve sin(pky4·atan(x)) at γ*. Always inlined: GCC's flatten left
/// this small function out of line in the lane batches' AVX2/AVX-512 clones, called with the
/// baseline ABI for its eight- and sixteen-lane vectors (a crash).
template <typename T, typename P>
[[gnu::always_inline]] inline T kya_load_arg(const MfParameters<P>& p, const Prepared<T>& in,
                                             const Basic<T>& b, const T& gamma_star) {
  const T gs2 = gamma_star * gamma_star;
  return (in.fz / b.fz0_prime) / ((p.pky2 + p.pky5 * gs2) * (T(1) + p.ppy2 * b.dpi));
}

/// calculateFy0 up to its core (everything but fy0), with the given γ (and γ*), turn slip switch
/// and Kyα's load curve at that γ* (`kya_load`: sin(pky4·atan(kya_load_arg))). Mz evaluates it
/// again at γ = 0; the evaluation computes both load curves side by side (mf_sin_two).
template <typename T, typename P>
Fy0Result<T> fy0_args(const MfParameters<P>& p, const Prepared<T>& in, const Basic<T>& b,
                      const MfOptions& options, const T& gamma_star, bool turn_slip,
                      const T& kya_load) {
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
          kya_load * zeta3 * p.lky;
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
    const T kya_prime = r.kya + sgn_nz_times(r.kya, eps);
    const T kyao_prime = kya0 + sgn_nz_times(kya0, eps);
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
            ((r.kyg0 * gamma_star - svyg) / (r.kya + sgn_nz_times(r.kya, eps))) * zeta0 + zeta4 -
            T(1);
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
  r.by = div_or(r.kya, r.cy * dy + sgn_nz_times(dy, eps), T(0));
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
  Fy0Result<T> r = fy0_args(p, in, b, options, gamma_star, turn_slip,
                            mf_sin(p.pky4 * mf_atan(kya_load_arg(p, in, b, gamma_star))));
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

}  // namespace tread::mf::detail
