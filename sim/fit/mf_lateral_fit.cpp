#include "fit/mf_lateral_fit.hpp"

#include <ceres/ceres.h>

#include <cmath>
#include <limits>
#include <memory>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include "fit/simple_fit.hpp"
#include "mf/mf_evaluate.hpp"

namespace tread::fit {
namespace {

constexpr int kN = kLateralCoefficientCount;

template <typename T>
std::array<T*, kN> lateral_members(mf::MfParameters<T>& p) {
  return {&p.pcy1, &p.pdy1, &p.pdy2, &p.pey1, &p.pey2, &p.pey3, &p.pky1,
          &p.pky2, &p.pky4, &p.phy1, &p.phy2, &p.pvy1, &p.pvy2};
}

struct Sample {
  double fz_n, alpha_rad, vx_mps, fy_n;
};

struct LateralResidual {
  const mf::MfParameters<double>* base;
  const std::vector<Sample>* samples;
  double inv_scale;
  mf::MfOptions options;
  template <typename T>
  bool operator()(const T* const k, T* residual) const {
    mf::MfParameters<T> p = mf::convert_parameters<T>(*base);
    const std::array<T*, kN> members = lateral_members(p);
    for (int i = 0; i < kN; ++i) *members[static_cast<std::size_t>(i)] = k[i];
    for (std::size_t i = 0; i < samples->size(); ++i) {
      const Sample& s = (*samples)[i];
      mf::MfInput<T> in;
      in.fz_n = T(s.fz_n);
      in.alpha_rad = T(s.alpha_rad);
      in.vx_mps = T(s.vx_mps);
      residual[i] = (mf::evaluate(p, in, options).fy_n - T(s.fy_n)) * T(inv_scale);
    }
    return true;
  }
};

class Progress : public ceres::IterationCallback {
 public:
  explicit Progress(const std::function<void(const std::string&)>& f) : f_(f) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (f_) {
      std::ostringstream line;
      line << "iteration " << s.iteration << ": cost " << s.cost;
      f_(line.str());
    }
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const std::function<void(const std::string&)>& f_;
};

struct KyaResidual {
  double fz_over_fz0, kya_over_fz0;
  template <typename T>
  bool operator()(const T* const k, T* r) const {
    using std::atan;
    using std::sin;
    r[0] = k[0] * sin(k[2] * atan(T(fz_over_fz0) / k[1])) - T(kya_over_fz0);
    return true;
  }
};

/// Least-squares line v = a + b·u; b = 0 with a single point.
std::pair<double, double> line_fit(const std::vector<double>& u, const std::vector<double>& v) {
  const double n = static_cast<double>(u.size());
  double su = 0, sv = 0, suu = 0, suv = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    su += u[i];
    sv += v[i];
    suu += u[i] * u[i];
    suv += u[i] * v[i];
  }
  const double den = n * suu - su * su;
  const double b = u.size() > 1 && std::fabs(den) > 0.0 ? (n * suv - su * sv) / den : 0.0;
  return {(sv - b * su) / n, b};
}

/// The practitioners' first stage: basic-formula fits per load (Stage 1) give C, μ = |D|/Fz,
/// Kya = BCD, E, SH, SV/Fz per load; lines over dfz and a small fit of Kya(Fz) turn them into
/// starting coefficients.
void staged_start(const MeasurementSet& data, mf::MfParameters<double>& p) {
  MeasurementSet lateral;
  lateral.source = data.source;
  for (const auto& m : data.points) {
    if (std::isfinite(m.fy_n)) {
      MeasurementPoint q = m;
      q.fx_n = q.mz_nm = std::numeric_limits<double>::quiet_NaN();
      lateral.points.push_back(q);
    }
  }
  const SimpleFit simple = fit_simple(lateral, SimpleFitSettings{}, {});
  std::vector<double> dfz, c, mu, e, sh, svfz, fzr, kyar;
  const double fz0 = p.fnomin_n * p.lfzo;
  for (const auto& f : simple.fits) {
    if (f.channel != Channel::fy_alpha) continue;
    const double d = (f.fz_n - fz0) / fz0;
    dfz.push_back(d);
    c.push_back(f.constants.c);
    mu.push_back(std::fabs(f.constants.d) / f.fz_n);
    e.push_back(f.constants.e);
    sh.push_back(f.constants.sh);
    svfz.push_back(f.constants.sv / f.fz_n);
    fzr.push_back(f.fz_n / fz0);
    kyar.push_back(f.constants.b * f.constants.c * f.constants.d / fz0);
  }
  if (dfz.empty()) return;
  double csum = 0.0;
  for (double v : c) csum += v;
  p.pcy1 = csum / static_cast<double>(c.size());
  std::tie(p.pdy1, p.pdy2) = line_fit(dfz, mu);
  std::tie(p.pey1, p.pey2) = line_fit(dfz, e);
  p.pey3 = 0.0;
  std::tie(p.phy1, p.phy2) = line_fit(dfz, sh);
  std::tie(p.pvy1, p.pvy2) = line_fit(dfz, svfz);
  // Kya/Fz0 = PKY1 sin(PKY4 atan(Fz/(PKY2 Fz0))): a few starts for PKY2, best kept.
  double best = std::numeric_limits<double>::infinity();
  for (double pky2 : {1.0, 2.0, 3.0, 5.0}) {
    std::array<double, 3> k = {kyar.back(), pky2, 2.0};
    ceres::Problem problem;
    for (std::size_t i = 0; i < fzr.size(); ++i) {
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<KyaResidual, 1, 3>(new KyaResidual{fzr[i], kyar[i]}),
          nullptr, k.data());
    }
    problem.SetParameterLowerBound(k.data(), 1, 0.05);
    problem.SetParameterLowerBound(k.data(), 2, 0.1);
    problem.SetParameterUpperBound(k.data(), 2, 3.0);
    ceres::Solver::Options so;
    so.linear_solver_type = ceres::DENSE_QR;
    so.num_threads = 1;
    so.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);
    if (summary.final_cost < best) {
      best = summary.final_cost;
      p.pky1 = k[0];
      p.pky2 = k[1];
      p.pky4 = k[2];
    }
  }
}

}  // namespace

LateralFit fit_mf_pure_lateral(const MeasurementSet& data, const mf::MfParameters<double>& start,
                               const std::function<void(const std::string&)>& progress) {
  std::vector<Sample> samples;
  double scale = 0.0;
  for (const auto& p : data.points) {
    if (std::fabs(p.kappa) > 1e-3 || std::fabs(p.gamma_rad) > 1e-3 || !std::isfinite(p.fy_n)) {
      continue;
    }
    samples.push_back({p.fz_n, p.alpha_rad, p.vx_mps, p.fy_n});
    scale = std::max(scale, std::fabs(p.fy_n));
  }
  if (samples.size() <= static_cast<std::size_t>(kN)) {
    throw std::runtime_error(data.source +
                             ": too few pure lateral points (|kappa|, |gamma| <= "
                             "1e-3 with Fy_N) for the MF lateral fit");
  }
  if (!(scale > 0.0)) scale = 1.0;
  LateralFit fit;
  fit.params = start;
  staged_start(data, fit.params);
  std::array<double, kN> k{};
  {
    const std::array<double*, kN> m = lateral_members(fit.params);
    for (std::size_t i = 0; i < k.size(); ++i) k[i] = *m[i];
  }
  mf::MfOptions options;
  options.combined = false;
  options.extras = false;

  auto build = [&](ceres::Problem& problem) {
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<LateralResidual, ceres::DYNAMIC, kN>(
                                 new LateralResidual{&fit.params, &samples, 1.0 / scale, options},
                                 static_cast<int>(samples.size())),
                             nullptr, k.data());
    problem.SetParameterLowerBound(k.data(), 0, 1.0 + 1e-6);  // PCY1
    problem.SetParameterUpperBound(k.data(), 0, 3.0);
    problem.SetParameterUpperBound(k.data(), 3, 1.0);  // PEY1
  };
  ceres::Problem problem;
  build(problem);
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = 100;
  so.function_tolerance = 1e-9;
  so.gradient_tolerance = 1e-14;
  so.parameter_tolerance = 1e-10;
  so.num_threads = 1;
  so.logging_type = ceres::SILENT;
  Progress callback(progress);
  so.callbacks.push_back(&callback);
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  fit.iterations = static_cast<int>(summary.iterations.size());
  fit.converged = summary.termination_type == ceres::CONVERGENCE;
  {
    const std::array<double*, kN> m = lateral_members(fit.params);
    for (std::size_t i = 0; i < k.size(); ++i) *m[i] = k[i];
  }
  fit.points = samples.size();
  const double n = static_cast<double>(samples.size());
  fit.rms_n = std::sqrt(2.0 * summary.final_cost / n) * scale;
  double mean = 0.0;
  for (const auto& s : samples) mean += s.fy_n;
  mean /= n;
  double ss_tot = 0.0;
  for (const auto& s : samples) ss_tot += (s.fy_n - mean) * (s.fy_n - mean);
  fit.r2 = ss_tot > 0.0 ? 1.0 - fit.rms_n * fit.rms_n * n / ss_tot
                        : std::numeric_limits<double>::quiet_NaN();

  fit.stddev.fill(std::numeric_limits<double>::quiet_NaN());
  ceres::Covariance::Options co;
  co.algorithm_type = ceres::DENSE_SVD;
  // Pure-lateral data at γ = 0 can leave a direction nearly flat (e.g. Ey at its clamp): the
  // pseudo-inverse drops it instead of failing, so the others still get a standard deviation.
  co.null_space_rank = -1;
  co.num_threads = 1;
  ceres::Covariance covariance(co);
  const std::vector<std::pair<const double*, const double*>> blocks = {{k.data(), k.data()}};
  std::array<double, kN * kN> c{};
  if (covariance.Compute(blocks, &problem) &&
      covariance.GetCovarianceBlock(k.data(), k.data(), c.data())) {
    const double s2 = 2.0 * summary.final_cost / (n - kN);
    for (std::size_t i = 0; i < k.size(); ++i) {
      fit.stddev[i] = std::sqrt(std::max(0.0, c[i * kN + i] * s2));
    }
  }
  return fit;
}

std::array<double, kLateralCoefficientCount> lateral_values(const LateralFit& fit) {
  mf::MfParameters<double> p = fit.params;
  const std::array<double*, kN> m = lateral_members(p);
  std::array<double, kN> v{};
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = *m[i];
  return v;
}

void set_lateral_coefficients(tir::TirFile& file, const LateralFit& fit) {
  const std::array<double, kN> v = lateral_values(fit);
  for (std::size_t i = 0; i < v.size(); ++i) {
    file.set("LATERAL_COEFFICIENTS", kLateralCoefficientNames[i], v[i]);
  }
}

void write_lateral_report(const LateralFit& fit, const std::string& source, std::ostream& out) {
  const std::array<double, kN> v = lateral_values(fit);
  out << "# tread fit --model mf61 (pure lateral, gamma = 0)\n\nInput: `" << source << "`, "
      << fit.points << " points, " << fit.iterations << " solver iterations ("
      << (fit.converged ? "converged" : "stopped at the iteration limit") << "). RMS " << fit.rms_n
      << " N, R² " << fit.r2
      << ". Standard deviations from the Ceres covariance scaled by the residual variance.\n\n"
      << "| coefficient | value | standard deviation |\n|---|---|---|\n";
  for (std::size_t i = 0; i < v.size(); ++i) {
    out << "| " << kLateralCoefficientNames[i] << " | " << v[i] << " | " << fit.stddev[i] << " |\n";
  }
}

}  // namespace tread::fit
