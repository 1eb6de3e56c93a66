#include "vehicle/tyre_function.hpp"

#include <cmath>

#include "mf/mf_evaluate.hpp"

namespace tread::vehicle {

TyreFunction mf_tyre_function(const mf::MfParameters<double>& params, mf::MfOptions options) {
  options.extras = false;
  return [params, options](std::size_t /*wheel*/, const WheelKinematics& k) {
    mf::MfInput<double> in;
    in.fz_n = k.fz_n;
    in.kappa = k.kappa;
    in.alpha_rad = k.alpha_rad;
    in.gamma_rad = k.gamma_rad;
    in.vx_mps = k.vx_mps;
    const mf::MfOutput<double> out = mf::evaluate(params, in, options);
    return WheelForces{out.fx_n, out.fy_n, out.mz_nm};
  };
}

double peak_braking_slip(const TyreFunction& tyre, std::size_t wheel, double fz_n, double vx_mps) {
  WheelKinematics k;
  k.fz_n = fz_n;
  k.vx_mps = vx_mps;
  k.omega_radps = 0.0;  // not used by the tyre's forces
  const auto braking_force = [&](double kappa) {
    k.kappa = kappa;
    return -tyre(wheel, k).fx_n;
  };
  // Scan κ ∈ [−1, 0] at 0.001 for the largest braking force, then refine by golden section in
  // the neighbouring cells.
  double best_kappa = 0.0;
  double best = braking_force(0.0);
  for (int i = 1; i <= 1000; ++i) {
    const double kappa = -0.001 * i;
    const double f = braking_force(kappa);
    if (f > best) {
      best = f;
      best_kappa = kappa;
    }
  }
  double lo = std::fmax(best_kappa - 0.001, -1.0);
  double hi = std::fmin(best_kappa + 0.001, 0.0);
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 40; ++i) {
    const double a = hi - ratio * (hi - lo);
    const double b = lo + ratio * (hi - lo);
    if (braking_force(a) > braking_force(b)) {
      hi = b;
    } else {
      lo = a;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace tread::vehicle
