#pragma once
// Transparent channels for node and loop tests: outputs are simple functions of the inputs.
#include "node/channels.hpp"

namespace tread::testing {

struct LinearTyre {
  int resets = 0;
  float last_dt_s = -1.0F;
  bool defective = false;  ///< report a non-finite model result (as a tyre with defective data)
  node::TyreResult evaluate(const proto::WheelInput& in, float dt_s) {
    last_dt_s = dt_s;
    node::TyreResult r;
    float kappa = in.kappa;
    if (kappa > 1.0F || kappa < -1.0F) {
      kappa = kappa > 0.0F ? 1.0F : -1.0F;
      r.clamped = true;
    }
    r.fx_n = 1000.0F * kappa * in.fz_n / 4000.0F;
    r.fy_n = -20000.0F * in.alpha_rad;
    r.mz_nm = 10.0F * in.gamma_rad;
    r.mx_nm = 0.001F * in.fz_n;
    r.my_nm = -0.01F * in.vx_mps;
    r.rl_m = 0.3F;
    r.non_finite = defective;
    return r;
  }
  void reset() { ++resets; }
};

struct LinearContact {
  node::ContactResult evaluate(const proto::WheelsetInput& in) const {
    node::ContactResult r;
    float y = in.lateral_mm;
    if (y > 12.0F || y < -12.0F) {
      y = y > 0.0F ? 12.0F : -12.0F;
      r.clamped = true;
    }
    r.r_left_mm = 460.0F + 0.1F * y;
    r.r_right_mm = 460.0F - 0.1F * y;
    r.delta_r_mm = 0.2F * y;
    r.gamma_left_rad = 0.05F;
    r.gamma_right_rad = 0.05F;
    return r;
  }
};

}  // namespace tread::testing
