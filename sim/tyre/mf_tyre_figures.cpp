#include "tyre/mf_tyre_figures.hpp"

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

  constexpr int kSteps = 1000;
  for (int i = -kSteps; i <= kSteps; ++i) {
    const double kappa = static_cast<double>(i) / kSteps;
    const double mu = eval({kappa, 0.0}).fx_n / f.fz_n;
    if (kappa > 0.0 && mu > f.mux_drive) {
      f.mux_drive = mu;
      f.kappa_drive = kappa;
    }
    if (kappa < 0.0 && -mu > f.mux_brake) {
      f.mux_brake = -mu;
      f.kappa_brake = kappa;
    }
    const double alpha = 0.5 * static_cast<double>(i) / kSteps;
    const double muy = std::fabs(eval({0.0, alpha}).fy_n) / f.fz_n;
    if (muy > f.muy) {
      f.muy = muy;
      f.alpha_muy_rad = alpha;
    }
  }

  // The model's own stiffnesses (MFeval's Kxk and Kya outputs) at the free-rolling point.
  f.kxk_n = free.kxk_n;
  f.kya_nprad = -free.kya_nprad;
  const double small_alpha = 0.5 * 3.14159265358979323846 / 180.0;
  f.trail_m = eval({0.0, small_alpha}).t_m;
  return f;
}

}  // namespace tread::tyre
