#pragma once
// doExtras' contact patch (calculateContactPatch): its length and width from the load, bounded by
// the load at which the tyre bottoms on the rim. MF 5.2 / PAC2002: length from Q_A1/Q_A2 (MFeval's
// fit of them from R0·Cz/Fz0 where both are 0), width the tyre's; MF 6.x: from Q_RA1/Q_RA2 and
// Q_RB1/Q_RB2 in the relative deflection Fz/(Cz·R0).

#include "mf/mf_detail_common.hpp"
#include "mf/mf_math.hpp"
#include "mf/mf_parameters.hpp"
#include "mf/mf_prepared.hpp"
#include "mf/mf_types.hpp"

#include <cmath>

namespace tread::mf::detail {

/// The load, limited where the tyre bottoms on the rim, and (MF 6.x) the relative deflection
/// Fz/(Cz·R0) of the contact patch.
template <typename T>
struct ContactLoad {
  T fz, relative;
};
template <typename T, typename P>
[[gnu::always_inline]] inline ContactLoad<T> contact_load(const MfParameters<P>& p,
                                                          const Prepared<T>& in,
                                                          const Basic<T>& b) {
  const T r0 = p.unloaded_radius_m;
  const T ncz = p.vertical_stiffness_npm * (T(1) + p.pfz1 * b.dpi);
  T fz = in.ufz;
  const T rl_approx = r0 - fz / ncz;
  fz = if_else(rl_approx - (p.rim_radius_m + p.bottom_offst_m) < T(0),
               (r0 - p.rim_radius_m - p.bottom_offst_m) * ncz, fz);
  fz = max_of(fz, T(0));
  return {fz, fz / (ncz * r0)};
}

/// The power of the relative deflection the MF 6.x width takes: its cube root.
template <typename T>
T contact_width_power() {
  return T(1) / T(3);
}

/// calculateContactPatch: out.contact_length_m and out.contact_width_m. MF 6.x: `cube_root` is
/// the relative deflection's cube root where the caller has it (PowBeside), else null; `load`
/// contact_load's result where the caller has it, else null.
template <typename T, typename P>
[[gnu::always_inline]] inline void contact_patch(const MfParameters<P>& p, const Prepared<T>& in,
                                                 const Basic<T>& b, MfOutput<T>& out,
                                                 const T* cube_root_given = nullptr,
                                                 const ContactLoad<T>* load_given = nullptr) {
  const T r0 = p.unloaded_radius_m;
  const T fz0 = p.fnomin_n;
  const ContactLoad<T> load = load_given != nullptr ? *load_given : contact_load(p, in, b);
  const T fz = load.fz;
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
    const T f = load.relative;
    out.contact_length_m = T(2) * r0 * (p.q_ra2 * f + p.q_ra1 * sqrt(f));
    const T cube_root = if_else(
        f > T(0),
        cube_root_given != nullptr ? *cube_root_given : mf_pow(f, contact_width_power<T>()), T(0));
    out.contact_width_m = T(2) * p.width_m * (p.q_rb2 * f + p.q_rb1 * cube_root);
  }
}

}  // namespace tread::mf::detail
