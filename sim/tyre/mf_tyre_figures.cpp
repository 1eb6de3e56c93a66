#include "tyre/mf_tyre_figures.hpp"

#include <algorithm>
#include <cmath>

#include "mf/mf_evaluate.hpp"

namespace tread::tyre {

namespace {

struct Point {
  double kappa = 0.0;
  double alpha_rad = 0.0;
};

}  // namespace

MfTyreFigures tyre_figures(const mf::MfParameters<double>& params, const mf::MfOptions& options,
                           double fz_n, double vx_mps) {
  MfTyreFigures f;
  f.fz_n = fz_n > 0.0 ? fz_n : params.fnomin_n;
  f.vx_mps = vx_mps > 0.0 ? vx_mps : params.longvl_mps > 0.0 ? params.longvl_mps : 16.7;
  mf::MfOptions o = options;
  o.combined = true;
  o.extras = true;
  const auto eval = [&](Point pt) {
    mf::MfInput<double> in;
    in.fz_n = f.fz_n;
    in.kappa = pt.kappa;
    in.alpha_rad = pt.alpha_rad;
    in.vx_mps = f.vx_mps;
    const mf::MfOutput<double> out = evaluate(params, in, o);
    // evaluate() writes a non-finite output as 0 and says so in the status.
    if (out.status == Status::non_finite) f.finite = false;
    return out;
  };

  const mf::MfOutput<double> free = eval({});
  f.p_pa = free.p_pa;
  f.re_m = free.re_m;
  f.rl_m = free.rl_m;

  // With the limits on (useMode 1xx) the model clamps κ and α to KPUMIN…KPUMAX and ALPMIN…ALPMAX:
  // the peaks are searched only there, on the grid and at the range's ends, so that a clamped
  // point never stands for the peak; a peak at an end of the range is flagged.
  const bool limits = o.use_limits;
  const double kappa_lo = limits ? std::max(-1.0, params.kpumin) : -1.0;
  const double kappa_hi = limits ? std::min(1.0, params.kpumax) : 1.0;
  const double alpha_lo = limits ? std::max(-0.5, params.alpmin_rad) : -0.5;
  const double alpha_hi = limits ? std::min(0.5, params.alpmax_rad) : 0.5;
  // Whether the value at an end of the search is the tyre's limit (not the grid's window).
  const bool kappa_lo_limit = limits && params.kpumin > -1.0;
  const bool kappa_hi_limit = limits && params.kpumax < 1.0;
  const bool alpha_lo_limit = limits && params.alpmin_rad > -0.5;
  const bool alpha_hi_limit = limits && params.alpmax_rad < 0.5;
  const auto take_kappa = [&](double kappa, bool at_limit) {
    if (!(kappa >= kappa_lo && kappa <= kappa_hi)) return;
    const double mu = eval({kappa, 0.0}).fx_n / f.fz_n;
    if (kappa > 0.0 && mu > f.mux_drive) {
      f.mux_drive = mu;
      f.kappa_drive = kappa;
      f.kappa_drive_at_limit = at_limit;
    }
    if (kappa < 0.0 && -mu > f.mux_brake) {
      f.mux_brake = -mu;
      f.kappa_brake = kappa;
      f.kappa_brake_at_limit = at_limit;
    }
  };
  const auto take_alpha = [&](double alpha, bool at_limit) {
    if (!(alpha >= alpha_lo && alpha <= alpha_hi)) return;
    const double muy = std::fabs(eval({0.0, alpha}).fy_n) / f.fz_n;
    if (muy > f.muy) {
      f.muy = muy;
      f.alpha_muy_rad = alpha;
      f.alpha_muy_at_limit = at_limit;
    }
  };
  // The ends first: a grid point of the same value further in does not displace them (>).
  take_kappa(kappa_lo, kappa_lo_limit);
  take_kappa(kappa_hi, kappa_hi_limit);
  take_alpha(alpha_lo, alpha_lo_limit);
  take_alpha(alpha_hi, alpha_hi_limit);
  constexpr int kSteps = 1000;
  for (int i = -kSteps; i <= kSteps; ++i) {
    take_kappa(static_cast<double>(i) / kSteps, false);
    take_alpha(0.5 * static_cast<double>(i) / kSteps, false);
  }
  f.drive_in_range = kappa_hi > 0.0;
  f.brake_in_range = kappa_lo < 0.0;

  // The model's own stiffnesses (MFeval's Kxk and Kya outputs) at the free-rolling point.
  f.kxk_n = free.kxk_n;
  f.kya_nprad = -free.kya_nprad;
  const double small_alpha = 0.5 * 3.14159265358979323846 / 180.0;
  f.trail_m = eval({0.0, small_alpha}).t_m;
  return f;
}

}  // namespace tread::tyre
