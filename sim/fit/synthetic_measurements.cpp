#include "fit/synthetic_measurements.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <random>

#include "fit/mf_stage_fit.hpp"
#include "mf/mf_evaluate.hpp"

namespace tread::fit {
namespace {

/// −max…max in `step`, and in step/4 where |x| < fine (the stiffness region).
std::vector<double> sweep(double max, double step, double fine) {
  std::vector<double> v;
  const long n = std::lround(max / step);
  for (long i = -n; i <= n; ++i) {
    const double x = static_cast<double>(i) * step;
    v.push_back(x);
    if (i < n && std::fabs(x + 0.5 * step) < fine) {
      for (int j = 1; j < 4; ++j) v.push_back(x + 0.25 * step * j);
    }
  }
  return v;
}

mf::MfOutput<double> evaluate_point(const mf::MfParameters<double>& p, const MeasurementPoint& m) {
  mf::MfInput<double> in;
  in.fz_n = m.fz_n;
  in.kappa = m.kappa;
  in.alpha_rad = m.alpha_rad;
  in.gamma_rad = m.gamma_rad;
  in.vx_mps = m.vx_mps;
  return mf::evaluate(p, in, fit_options());
}

}  // namespace

std::vector<MeasurementPoint> synthetic_inputs(const mf::MfParameters<double>& truth,
                                               const SyntheticGrid& grid) {
  std::vector<MeasurementPoint> points;
  auto add = [&](double fz, double kappa, double alpha, double gamma) {
    // Slips beyond the tyre's range are left out: the model clamps them, and the clamped outputs
    // would be written as if measured there (KPUMAX = 0: a flat Fx of noise for every κ > 0).
    if (kappa < truth.kpumin || kappa > truth.kpumax || alpha < truth.alpmin_rad ||
        alpha > truth.alpmax_rad) {
      return;
    }
    MeasurementPoint m;
    m.fz_n = fz;
    m.kappa = kappa;
    m.alpha_rad = alpha;
    m.gamma_rad = std::min(std::max(gamma, truth.cammin_rad), truth.cammax_rad);
    m.vx_mps = grid.vx_mps;
    points.push_back(m);
  };
  const std::vector<double> kappas = sweep(grid.kappa_max, grid.kappa_step, grid.fine_range);
  const std::vector<double> alphas =
      sweep(grid.alpha_max_rad, grid.alpha_step_rad, grid.fine_range);
  for (double factor : grid.load_factors) {
    const double fz = std::min(factor * truth.fnomin_n, truth.fzmax_n);
    for (double gamma : grid.cambers_rad) {
      for (double k : kappas) add(fz, k, 0.0, gamma);
      for (double a : alphas) add(fz, 0.0, a, gamma);
    }
    for (double gamma : grid.combined_cambers_rad) {
      for (double a : grid.combined_alphas_rad) {
        for (double k : kappas) add(fz, k, a, gamma);
      }
      for (double k : grid.combined_kappas) {
        for (double a : alphas) add(fz, k, a, gamma);
      }
    }
  }
  return points;
}

MeasurementSet synthesize_measurements(const mf::MfParameters<double>& truth,
                                       const SyntheticGrid& grid, std::uint64_t seed) {
  MeasurementSet data;
  data.source = "synthetic";
  data.points = synthetic_inputs(truth, grid);
  // Noise level per load and channel: noise_rel × the peak of the pure γ = 0 sweep.
  std::vector<double> loads;
  for (const auto& m : data.points) {
    if (std::find(loads.begin(), loads.end(), m.fz_n) == loads.end()) loads.push_back(m.fz_n);
  }
  std::vector<std::array<double, 3>> peak(loads.size(), {0.0, 0.0, 0.0});
  for (auto& m : data.points) {
    const mf::MfOutput<double> out = evaluate_point(truth, m);
    m.fx_n = out.fx_n;
    m.fy_n = out.fy_n;
    m.mz_nm = out.mz_nm;
    if (std::fabs(m.gamma_rad) > 1e-12) continue;
    const std::size_t l =
        static_cast<std::size_t>(std::find(loads.begin(), loads.end(), m.fz_n) - loads.begin());
    if (std::fabs(m.alpha_rad) < 1e-12) peak[l][0] = std::max(peak[l][0], std::fabs(m.fx_n));
    if (std::fabs(m.kappa) < 1e-12) {
      peak[l][1] = std::max(peak[l][1], std::fabs(m.fy_n));
      peak[l][2] = std::max(peak[l][2], std::fabs(m.mz_nm));
    }
  }
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (auto& m : data.points) {
    const std::size_t l =
        static_cast<std::size_t>(std::find(loads.begin(), loads.end(), m.fz_n) - loads.begin());
    m.fx_n += grid.noise_rel * peak[l][0] * normal(rng);
    m.fy_n += grid.noise_rel * peak[l][1] * normal(rng);
    m.mz_nm += grid.noise_rel * peak[l][2] * normal(rng);
  }
  return data;
}

void write_measurement_csv(const MeasurementSet& data, std::ostream& out) {
  out << "Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps,Fx_N,Fy_N,Mz_Nm\n" << std::setprecision(17);
  for (const auto& m : data.points) {
    out << m.fz_n << ',' << m.kappa << ',' << m.alpha_rad << ',' << m.gamma_rad << ',' << m.vx_mps
        << ',' << m.fx_n << ',' << m.fy_n << ',' << m.mz_nm << '\n';
  }
}

}  // namespace tread::fit
