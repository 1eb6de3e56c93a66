#include "fit/mf_lateral_fit.hpp"

#include <ceres/ceres.h>

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include "fit/mf_stage_fit.hpp"
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

}  // namespace

void lateral_staged_start(const MeasurementSet& data, mf::MfParameters<double>& p) {
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
  std::tie(p.pdy1, p.pdy2) = fit_line(dfz, mu, p.pdy2);
  std::tie(p.pey1, p.pey2) = fit_line(dfz, e, p.pey2);
  p.pey3 = 0.0;
  std::tie(p.phy1, p.phy2) = fit_line(dfz, sh, p.phy2);
  std::tie(p.pvy1, p.pvy2) = fit_line(dfz, svfz, p.pvy2);
  // Kya/Fz0 = PKY1 sin(PKY4 atan(Fz/(PKY2 Fz0))): a few starts for PKY2, best kept. One load
  // does not tell PKY2 and PKY4 apart from PKY1: the start file's are kept, PKY1 matches Kya.
  if (fzr.size() < 2) {
    const double shape = std::sin(p.pky4 * std::atan(fzr.front() / p.pky2));
    if (std::fabs(shape) > 1e-6) p.pky1 = kyar.front() / shape;
    return;
  }
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

LateralFit fit_mf_pure_lateral(const MeasurementSet& data, const mf::MfParameters<double>& start,
                               const std::function<void(const std::string&)>& progress) {
  const std::vector<double> levels = load_levels(data);
  const std::vector<StageSample> samples =
      select_samples(data, levels, FitChannel::fy, [](const MeasurementPoint& m) {
        return std::fabs(m.kappa) <= kPureTolerance && std::fabs(m.gamma_rad) <= kPureTolerance;
      });
  if (samples.size() <= static_cast<std::size_t>(kN)) {
    throw std::runtime_error(data.source +
                             ": too few pure lateral points (|kappa|, |gamma| <= "
                             "1e-3 with Fy_N) for the MF lateral fit");
  }
  LateralFit fit;
  fit.params = start;
  lateral_staged_start(data, fit.params);
  StageSpec spec;
  spec.name = "Fy0 (gamma = 0)";
  spec.keys.assign(kLateralCoefficientNames.begin(), kLateralCoefficientNames.end());
  const StageResult r = fit_stage(spec, samples, levels, fit.params, progress);
  for (std::size_t i = 0; i < fit.stddev.size(); ++i) fit.stddev[i] = r.stddev[i];
  fit.iterations = r.iterations;
  fit.converged = r.converged;
  fit.points = samples.size();
  double ss_res = 0.0, sum = 0.0, sum2 = 0.0;
  for (const auto& s : samples) {
    const double d = model_value(fit.params, s) - s.value;
    ss_res += d * d;
    sum += s.value;
    sum2 += s.value * s.value;
  }
  const double n = static_cast<double>(samples.size());
  fit.rms_n = std::sqrt(ss_res / n);
  const double ss_tot = sum2 - sum * sum / n;
  fit.r2 = ss_tot > 0.0 ? 1.0 - ss_res / ss_tot : std::numeric_limits<double>::quiet_NaN();
  return fit;
}

std::vector<std::string> lateral_camber_keys(MfFitModel model) {
  if (model == MfFitModel::mf61) {
    return {"PDY3", "PEY4", "PEY5", "PKY3", "PKY5", "PKY6", "PKY7", "PVY3", "PVY4"};
  }
  return {"PDY3", "PEY4", "PKY3", "PHY3", "PVY3", "PVY4"};
}

std::vector<StageResult> fit_lateral_stages(
    const MeasurementSet& data, const std::vector<double>& levels, MfFitModel model,
    mf::MfParameters<double>& params, const std::function<void(const std::string&)>& progress) {
  std::vector<StageResult> results;
  const std::vector<StageSample> flat_samples =
      select_samples(data, levels, FitChannel::fy, [](const MeasurementPoint& m) {
        return std::fabs(m.kappa) <= kPureTolerance && std::fabs(m.gamma_rad) <= kPureTolerance;
      });
  if (flat_samples.size() <= kLateralCoefficientNames.size()) return results;  // skipped
  lateral_staged_start(data, params);
  StageSpec flat{"Fy0 (gamma = 0)", {}, 100};
  flat.keys.assign(kLateralCoefficientNames.begin(), kLateralCoefficientNames.end());
  results.push_back(fit_stage(flat, flat_samples, levels, params, progress));
  const std::vector<StageSample> cambered = select_samples(
      data, levels, FitChannel::fy,
      [](const MeasurementPoint& m) { return std::fabs(m.kappa) <= kPureTolerance; });
  bool any_camber = false;
  for (const auto& s : cambered) any_camber = any_camber || std::fabs(s.gamma_rad) > kPureTolerance;
  if (any_camber) {
    // Then the camber terms together with the γ-free ones on every camber: the γ-free
    // coefficients shape every cambered curve too, so all the points refine them.
    std::vector<std::string> all_keys = flat.keys;
    for (auto& k : lateral_camber_keys(model)) all_keys.push_back(k);
    results.push_back(
        fit_stage({"Fy0 (all cambers)", all_keys, 100}, cambered, levels, params, progress));
  }
  return results;
}

std::array<double, kLateralCoefficientCount> lateral_values(const LateralFit& fit) {
  mf::MfParameters<double> p = fit.params;
  const std::array<double*, kN> m = lateral_members(p);
  std::array<double, kN> v{};
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = *m[i];
  return v;
}

}  // namespace tread::fit
