#include "fit/mf_stage_fit.hpp"

#include <ceres/ceres.h>
#include <ceres/dynamic_autodiff_cost_function.h>
#include <ceres/manifold.h>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "fit/mf_coefficients.hpp"
#include "mf/mf_evaluate.hpp"

namespace tread::fit {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Derivatives per Jet pass: stages of up to 8 coefficients take one pass of Jet<8>, larger ones
// passes of Jet<16> (one pass up to 16 coefficients).
constexpr int kSmallStride = 8;
constexpr int kStride = 16;

template <typename T>
T channel_value(const mf::MfOutput<T>& out, FitChannel c) {
  switch (c) {
    case FitChannel::fx:
      return out.fx_n;
    case FitChannel::fy:
      return out.fy_n;
    case FitChannel::mz:
      return out.mz_nm;
  }
  return out.fy_n;
}

/// All samples of a stage in one cost function: one Jet pass through the core per sample.
/// Not on mf::evaluate_batch's float lanes: the Jacobian needs ceres::Jet (the lanes are float
/// only), and the cost-only evaluations (T = double, one per trial step) take little of a fit
/// (the staged MF 6.1 fit of `tread fit --synthesize` data, 2026-11-26: 171 of them 0.17 s, the
/// 431 Jacobian evaluations 5.0 s), while their value decides whether Ceres takes a step and when
/// it stops (function_tolerance 1e-7, relative): float residuals, ~1e-7 relative at best and up
/// to 1e-5 of a channel's scale, would put noise above those tolerances near the optimum.
struct StageResidual {
  const mf::MfParameters<double>* base;
  const std::vector<StageSample>* samples;
  const std::vector<int>* indices;
  mf::MfOptions options;
  template <typename T>
  bool operator()(T const* const* k, T* residual) const {
    mf::MfParameters<T> p = mf::convert_parameters<T>(*base);
    for (std::size_t i = 0; i < indices->size(); ++i) coefficient(p, (*indices)[i]) = k[0][i];
    for (std::size_t i = 0; i < samples->size(); ++i) {
      const StageSample& s = (*samples)[i];
      mf::MfInput<T> in;
      in.fz_n = T(s.fz_n);
      in.kappa = T(s.kappa);
      in.alpha_rad = T(s.alpha_rad);
      // The combined Mz takes αt,eq = atan(sqrt(tan²αt + (Kxκ/Kyα·κ)²))·sgn αt: sqrt has no
      // derivative at 0, so a point at α = κ = 0 with SHt = 0 (the book start) gives a NaN
      // Jacobian. Such points are evaluated 1e-9 rad off the origin (a change of ~1e-9 relative).
      if (s.channel == FitChannel::mz && !(std::fabs(s.alpha_rad) > 0.0)) in.alpha_rad = T(1e-9);
      in.gamma_rad = T(s.gamma_rad);
      in.vx_mps = T(s.vx_mps);
      residual[i] =
          (channel_value(mf::evaluate(p, in, options), s.channel) - T(s.value)) * T(s.weight);
    }
    return true;
  }
};

class Progress : public ceres::IterationCallback {
 public:
  Progress(std::string stage, const std::function<void(const std::string&)>& f)
      : stage_(std::move(stage)), f_(f) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (f_) {
      std::ostringstream line;
      line << stage_ << ": iteration " << s.iteration << ": cost " << s.cost << ", |step| "
           << s.step_norm;
      f_(line.str());
    }
    return ceres::SOLVER_CONTINUE;
  }

 private:
  std::string stage_;
  const std::function<void(const std::string&)>& f_;
};

/// The columns of `problem`'s Jacobian (its one parameter block, at its current values) that
/// are, after scaling each to unit norm, within 1e-6 of the span of the columns before them, or
/// zero: Gram–Schmidt in the block's order (see fit_stage).
std::vector<int> dependent_columns(ceres::Problem& problem, std::size_t n) {
  ceres::CRSMatrix crs;
  double cost = 0.0;
  if (!problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr, &crs))
    return {};
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
  for (int r = 0; r < crs.num_rows; ++r) {
    for (int at = crs.rows[static_cast<std::size_t>(r)];
         at < crs.rows[static_cast<std::size_t>(r) + 1]; ++at) {
      j(r, crs.cols[static_cast<std::size_t>(at)]) = crs.values[static_cast<std::size_t>(at)];
    }
  }
  if (!j.allFinite()) return {};
  double largest = 0.0;
  for (Eigen::Index c = 0; c < j.cols(); ++c) largest = std::max(largest, j.col(c).norm());
  std::vector<int> dependent;
  std::vector<Eigen::VectorXd> basis;
  for (std::size_t c = 0; c < n && static_cast<Eigen::Index>(c) < j.cols(); ++c) {
    Eigen::VectorXd v = j.col(static_cast<Eigen::Index>(c));
    const double norm = v.norm();
    if (!(norm > 1e-12 * largest)) {
      dependent.push_back(static_cast<int>(c));
      continue;
    }
    v /= norm;
    for (int pass = 0; pass < 2; ++pass) {  // twice: classical Gram–Schmidt's lost orthogonality
      for (const Eigen::VectorXd& b : basis) v -= b.dot(v) * b;
    }
    const double rest = v.norm();
    if (!(rest > 1e-6)) {
      dependent.push_back(static_cast<int>(c));
      continue;
    }
    basis.push_back(v / rest);
  }
  return dependent;
}

}  // namespace

std::pair<double, double> fit_line(const std::vector<double>& u, const std::vector<double>& v,
                                   double single_slope) {
  const double n = static_cast<double>(u.size());
  double su = 0, sv = 0, suu = 0, suv = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    su += u[i];
    sv += v[i];
    suu += u[i] * u[i];
    suv += u[i] * v[i];
  }
  const double den = n * suu - su * su;
  const double b = u.size() > 1 && std::fabs(den) > 0.0 ? (n * suv - su * sv) / den : single_slope;
  return {(sv - b * su) / n, b};
}

const char* fit_channel_name(FitChannel c) {
  switch (c) {
    case FitChannel::fx:
      return "Fx";
    case FitChannel::fy:
      return "Fy";
    case FitChannel::mz:
      return "Mz";
  }
  return "?";
}

const char* fit_channel_unit(FitChannel c) {
  return c == FitChannel::mz ? "Nm" : "N";
}

mf::MfOptions fit_options() {
  mf::MfOptions o;
  o.use_limits = true;
  o.combined = true;
  o.extras = false;
  return o;
}

double model_value(const mf::MfParameters<double>& p, const StageSample& s) {
  mf::MfInput<double> in;
  in.fz_n = s.fz_n;
  in.kappa = s.kappa;
  in.alpha_rad = s.alpha_rad;
  in.gamma_rad = s.gamma_rad;
  in.vx_mps = s.vx_mps;
  return channel_value(mf::evaluate(p, in, fit_options()), s.channel);
}

std::vector<double> load_levels(const MeasurementSet& data) {
  std::vector<double> fz;
  for (const auto& p : data.points) fz.push_back(p.fz_n);
  std::sort(fz.begin(), fz.end());
  std::vector<double> levels;
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < fz.size(); ++i) {
    if (count > 0 && fz[i] - fz[i - 1] > 0.1 * std::max(std::fabs(fz[i]), 1.0)) {
      levels.push_back(sum / static_cast<double>(count));
      sum = 0.0;
      count = 0;
    }
    sum += fz[i];
    ++count;
  }
  if (count > 0) levels.push_back(sum / static_cast<double>(count));
  return levels;
}

std::size_t nearest_level(const std::vector<double>& levels, double fz_n) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < levels.size(); ++i) {
    if (std::fabs(levels[i] - fz_n) < std::fabs(levels[best] - fz_n)) best = i;
  }
  return best;
}

std::vector<StageSample> select_samples(const MeasurementSet& data,
                                        const std::vector<double>& levels, FitChannel channel,
                                        const std::function<bool(const MeasurementPoint&)>& keep) {
  std::vector<StageSample> out;
  std::vector<double> peak(levels.size(), 0.0);
  for (const auto& m : data.points) {
    const double v =
        channel == FitChannel::fx ? m.fx_n : (channel == FitChannel::fy ? m.fy_n : m.mz_nm);
    if (!std::isfinite(v) || !keep(m)) continue;
    StageSample s;
    s.fz_n = m.fz_n;
    s.kappa = m.kappa;
    s.alpha_rad = m.alpha_rad;
    s.gamma_rad = m.gamma_rad;
    s.vx_mps = m.vx_mps;
    s.channel = channel;
    s.value = v;
    s.load_level = levels.empty() ? 0 : nearest_level(levels, m.fz_n);
    if (s.load_level < peak.size()) peak[s.load_level] = std::max(peak[s.load_level], std::fabs(v));
    out.push_back(s);
  }
  for (auto& s : out) {
    const double p = s.load_level < peak.size() ? peak[s.load_level] : 0.0;
    s.weight = p > 0.0 ? 1.0 / p : 1.0;
  }
  return out;
}

std::vector<ChannelLoadStats> channel_load_stats(const mf::MfParameters<double>& params,
                                                 const std::vector<StageSample>& samples,
                                                 const std::vector<double>& levels) {
  std::vector<ChannelLoadStats> stats;
  for (FitChannel c : {FitChannel::fx, FitChannel::fy, FitChannel::mz}) {
    for (std::size_t level = 0; level < std::max<std::size_t>(levels.size(), 1); ++level) {
      double ss_res = 0.0, sum = 0.0, sum2 = 0.0;
      std::size_t n = 0;
      for (const auto& s : samples) {
        if (s.channel != c || s.load_level != level) continue;
        const double r = model_value(params, s) - s.value;
        ss_res += r * r;
        sum += s.value;
        sum2 += s.value * s.value;
        ++n;
      }
      if (n == 0) continue;
      const double nn = static_cast<double>(n);
      const double ss_tot = sum2 - sum * sum / nn;
      ChannelLoadStats st;
      st.channel = c;
      st.fz_n = levels.empty() ? 0.0 : levels[level];
      st.points = n;
      st.rms = std::sqrt(ss_res / nn);
      st.r2 = ss_tot > 0.0 ? 1.0 - ss_res / ss_tot : kNaN;
      stats.push_back(st);
    }
  }
  return stats;
}

StageResult fit_stage(const StageSpec& spec, const std::vector<StageSample>& samples,
                      const std::vector<double>& levels, mf::MfParameters<double>& params,
                      const std::function<void(const std::string&)>& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t n = spec.keys.size();
  if (samples.size() <= n) {
    throw std::runtime_error(spec.name + ": " + std::to_string(samples.size()) + " points for " +
                             std::to_string(n) + " coefficients");
  }
  std::vector<int> indices;
  for (const auto& key : spec.keys) indices.push_back(required_coefficient_index(key));
  StageResult result;
  result.name = spec.name;
  result.keys = spec.keys;
  result.points = samples.size();
  std::vector<double> k(n);
  for (std::size_t i = 0; i < n; ++i) {
    k[i] = coefficient(params, indices[i]);
    // Start inside the bounds.
    const CoefficientBounds b = coefficient_bounds(spec.keys[i]);
    k[i] = std::min(std::max(k[i], b.lower), b.upper);
  }
  result.start = k;
  const mf::MfParameters<double> base = params;
  const StageResidual residual{&base, &samples, &indices, fit_options()};
  std::vector<int> held;  // indices into spec.keys, held at their start values
  auto make_problem = [&](ceres::Problem& problem, std::vector<double>& x) {
    ceres::CostFunction* cost = nullptr;
    if (n <= static_cast<std::size_t>(kSmallStride)) {
      auto* c = new ceres::DynamicAutoDiffCostFunction<StageResidual, kSmallStride>(
          new StageResidual(residual));
      c->AddParameterBlock(static_cast<int>(n));
      c->SetNumResiduals(static_cast<int>(samples.size()));
      cost = c;
    } else {
      auto* c = new ceres::DynamicAutoDiffCostFunction<StageResidual, kStride>(
          new StageResidual(residual));
      c->AddParameterBlock(static_cast<int>(n));
      c->SetNumResiduals(static_cast<int>(samples.size()));
      cost = c;
    }
    problem.AddResidualBlock(cost, nullptr, x.data());
    for (std::size_t i = 0; i < n; ++i) {
      const CoefficientBounds b = coefficient_bounds(spec.keys[i]);
      if (std::isfinite(b.lower)) {
        problem.SetParameterLowerBound(x.data(), static_cast<int>(i), b.lower);
      }
      if (std::isfinite(b.upper)) {
        problem.SetParameterUpperBound(x.data(), static_cast<int>(i), b.upper);
      }
    }
    if (!held.empty())
      problem.SetManifold(x.data(), new ceres::SubsetManifold(static_cast<int>(n), held));
  };
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = spec.max_iterations;
  so.function_tolerance = 1e-7;  // relative cost change: far below the noise
  so.gradient_tolerance = 1e-14;
  so.parameter_tolerance = 1e-10;
  so.num_threads = 1;
  so.logging_type = ceres::SILENT;
  Progress callback(spec.name, progress);
  so.callbacks.push_back(&callback);

  std::vector<std::vector<double>> starts = {k};
  for (const auto& other : spec.other_starts) {
    std::vector<double> x = k;
    for (const auto& [key, v] : other) {
      for (std::size_t i = 0; i < n; ++i) {
        if (spec.keys[i] == key) x[i] = v;
      }
    }
    starts.push_back(x);
  }
  // Several starts: each is screened with a few iterations, the best one is solved to the end.
  if (starts.size() > 1) {
    ceres::Solver::Options screen = so;
    screen.max_num_iterations = 10;
    screen.callbacks.clear();
    double screen_cost = std::numeric_limits<double>::infinity();
    std::vector<double> chosen = k;
    for (auto& x : starts) {
      ceres::Problem problem;
      make_problem(problem, x);
      ceres::Solver::Summary summary;
      ceres::Solve(screen, &problem, &summary);
      if (summary.IsSolutionUsable() && summary.final_cost < screen_cost) {
        screen_cost = summary.final_cost;
        chosen = x;
      }
    }
    k = chosen;
  }
  const std::vector<double> chosen_start = k;
  ceres::Solver::Summary best;
  auto problem = std::make_unique<ceres::Problem>();
  make_problem(*problem, k);
  ceres::Solve(so, problem.get(), &best);
  held = dependent_columns(*problem, n);
  if (!held.empty() && held.size() < n) {
    // Solved again from the chosen start, the undetermined keys held at the stage's start values.
    k = chosen_start;
    for (const int i : held)
      k[static_cast<std::size_t>(i)] = result.start[static_cast<std::size_t>(i)];
    problem = std::make_unique<ceres::Problem>();
    make_problem(*problem, k);
    ceres::Solve(so, problem.get(), &best);
  } else {
    held.clear();
  }
  for (const int i : held) result.held.push_back(spec.keys[static_cast<std::size_t>(i)]);
  const double final_cost = best.final_cost;
  result.iterations = static_cast<int>(best.iterations.size());
  result.converged = best.termination_type == ceres::CONVERGENCE;
  result.values = k;
  for (std::size_t i = 0; i < n; ++i) coefficient(params, indices[i]) = k[i];

  result.stddev.assign(n, kNaN);
  ceres::Covariance::Options co;
  co.algorithm_type = ceres::DENSE_SVD;
  co.null_space_rank = -1;  // flat directions (a coefficient without effect on these points)
  co.num_threads = 1;
  ceres::Covariance covariance(co);
  const std::vector<std::pair<const double*, const double*>> blocks = {{k.data(), k.data()}};
  std::vector<double> c(n * n);
  // Only for a usable, finite solution: Ceres's covariance does not check the Jacobian (a NaN in
  // it crashed the SVD).
  const bool finite = std::isfinite(final_cost) &&
                      std::all_of(k.begin(), k.end(), [](double v) { return std::isfinite(v); });
  if (best.IsSolutionUsable() && finite && covariance.Compute(blocks, problem.get()) &&
      covariance.GetCovarianceBlock(k.data(), k.data(), c.data())) {
    // The residuals are weighted: the variance of a weighted residual scales the covariance.
    const double s2 = 2.0 * final_cost / static_cast<double>(samples.size() - n);
    for (std::size_t i = 0; i < n; ++i)
      result.stddev[i] = std::sqrt(std::max(0.0, c[i * n + i] * s2));
    for (const int i : held) result.stddev[static_cast<std::size_t>(i)] = kNaN;
  }
  result.stats = channel_load_stats(params, samples, levels);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace tread::fit
