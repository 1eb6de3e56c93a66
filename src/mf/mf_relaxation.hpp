#pragma once
// doExtras' relaxation lengths (calculateRelax): the carcass stiffnesses Cx, Cy from the load and
// pressure, and σx, σy: MF 6.x as Kxκ/Cx and Kyα/Cy, MF 5.2 / PAC2002 from PTX1…3 and PTY1, PTY2.

#include "mf/mf_detail_common.hpp"
#include "mf/mf_math.hpp"
#include "mf/mf_parameters.hpp"
#include "mf/mf_prepared.hpp"
#include "mf/mf_types.hpp"

#include <cmath>

namespace tread::mf::detail {

/// calculateRelax: out.cx_npm, out.cy_npm, out.sigmax_m and out.sigmay_m, given the slip
/// stiffnesses Kxκ and Kyα.
template <typename T, typename P>
[[gnu::always_inline]] inline void relaxation(const MfParameters<P>& p, const Prepared<T>& in,
                                              const Basic<T>& b, const T& kxk, const T& kya,
                                              MfOutput<T>& out) {
  const T r0 = p.unloaded_radius_m;
  const T fz0 = p.fnomin_n;
  const T dpi = b.dpi;
  const T dfz_r = (in.fz - b.fz0_prime) / b.fz0_prime;
  out.cx_npm = p.longitudinal_stiffness_npm * (T(1) + p.pcfx1 * dfz_r + p.pcfx2 * dfz_r * dfz_r) *
               (T(1) + p.pcfx3 * dpi);
  out.cy_npm = p.lateral_stiffness_npm * (T(1) + p.pcfy1 * dfz_r + p.pcfy2 * dfz_r * dfz_r) *
               (T(1) + p.pcfy3 * dpi);
  if (is_mf5x(p)) {
    out.sigmax_m = (p.ptx1 + p.ptx2 * dfz_r) * exp(-p.ptx3 * dfz_r) * p.lsgkp * r0 * in.fz / fz0;
    const T sigmayg = T(1) - p.pky3 * abs(in.gamma);
    const T ptyfzn = p.pty2 * b.fz0_prime;
    out.sigmay_m = p.pty1 * mf_sin(T(2) * mf_atan(div_or(in.fz, ptyfzn, T(0)))) * sigmayg * r0 *
                   p.lfzo * p.lsgal;
  } else {
    out.sigmax_m = abs(div_or(kxk, out.cx_npm, T(0)));
    out.sigmay_m = abs(div_or(kya, out.cy_npm, T(0)));
  }
}

}  // namespace tread::mf::detail
