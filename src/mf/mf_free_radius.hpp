#pragma once
// The free (unloaded) radius of the rotating tyre, Romega = R0·(Q_RE0 + Q_V1·(ω·R0/V0)²): R0
// grown by the centrifugal term at the wheel speed ω (MF 6.x, MFeval's calculateRe). The core's
// rolling-radius iteration uses it, and so do host checks of the loaded radius against it, so the
// two cannot differ.

#include "mf/mf_parameters.hpp"

namespace tread::mf {

template <typename T, typename P>
[[gnu::always_inline]] inline T free_radius_m(const MfParameters<P>& p, const T& omega_radps) {
  const T r0 = p.unloaded_radius_m;
  const T speed = (omega_radps * r0) / p.longvl_mps;
  return r0 * (p.q_re0 + p.q_v1 * speed * speed);
}

}  // namespace tread::mf
