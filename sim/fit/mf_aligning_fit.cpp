#include "fit/mf_aligning_fit.hpp"

#include <cmath>
#include <tuple>

namespace tread::fit {
namespace {

/// QDZ1, QDZ2 from the trail at the origin per load: t0 ≈ −(dMz/dα)/(dFy/dα), Dt = t0 at SHt = 0,
/// Dt = (QDZ1 + QDZ2·dfz)·Fz·R0/Fz0' (LTR = 1).
void aligning_start(const std::vector<StageSample>& mz, const std::vector<double>& levels,
                    mf::MfParameters<double>& p) {
  const double fz0 = p.fnomin_n * p.lfzo;
  std::vector<double> dfz, qdz;
  for (std::size_t level = 0; level < levels.size(); ++level) {
    std::vector<double> a, m;
    double vx = 0.0, fz = 0.0;
    for (const auto& s : mz) {
      if (s.load_level != level || std::fabs(s.alpha_rad) > 0.02) continue;
      a.push_back(s.alpha_rad);
      m.push_back(s.value);
      vx = s.vx_mps;
      fz += s.fz_n;
    }
    if (a.size() < 3) continue;
    fz /= static_cast<double>(a.size());
    const double mz_slope = fit_line(a, m).second;
    StageSample plus{fz, 0.0, 1e-4, 0.0, vx, FitChannel::fy, 0.0, 1.0, level};
    StageSample minus = plus;
    minus.alpha_rad = -1e-4;
    const double kya = (model_value(p, plus) - model_value(p, minus)) / 2e-4;
    if (!(std::fabs(kya) > 0.0)) continue;
    dfz.push_back((fz - fz0) / fz0);
    qdz.push_back(-mz_slope / kya * fz0 / (fz * p.unloaded_radius_m * p.ltr));
  }
  if (dfz.empty()) return;
  std::tie(p.qdz1, p.qdz2) = fit_line(dfz, qdz, p.qdz2);
}

}  // namespace

std::vector<std::string> aligning_keys() {
  return {"QBZ1", "QBZ2", "QBZ3", "QBZ9", "QBZ10", "QCZ1", "QDZ1", "QDZ2",
          "QDZ6", "QDZ7", "QEZ1", "QEZ2", "QEZ3",  "QEZ4", "QHZ1", "QHZ2"};
}

std::vector<std::string> aligning_camber_keys(MfFitModel model) {
  if (model == MfFitModel::mf61) {
    return {"QBZ4",  "QBZ5",  "QDZ3", "QDZ4", "QDZ8", "QDZ9",
            "QDZ10", "QDZ11", "QEZ5", "QHZ3", "QHZ4"};
  }
  return {"QBZ4", "QBZ5", "QDZ3", "QDZ4", "QDZ8", "QDZ9", "QEZ5", "QHZ3", "QHZ4"};
}

std::vector<StageResult> fit_aligning_stages(
    const MeasurementSet& data, const std::vector<double>& levels, MfFitModel model,
    mf::MfParameters<double>& params, const std::function<void(const std::string&)>& progress) {
  std::vector<StageResult> results;
  const std::vector<StageSample> flat =
      select_samples(data, levels, FitChannel::mz, [](const MeasurementPoint& m) {
        return std::fabs(m.kappa) <= kPureTolerance && std::fabs(m.gamma_rad) <= kPureTolerance;
      });
  if (flat.size() <= aligning_keys().size()) return results;  // no Mz(α) sweep: skipped
  aligning_start(flat, levels, params);
  results.push_back(
      fit_stage({"Mz0 (gamma = 0)", aligning_keys(), 100}, flat, levels, params, progress));
  const std::vector<StageSample> cambered = select_samples(
      data, levels, FitChannel::mz,
      [](const MeasurementPoint& m) { return std::fabs(m.kappa) <= kPureTolerance; });
  bool any_camber = false;
  for (const auto& s : cambered) any_camber = any_camber || std::fabs(s.gamma_rad) > kPureTolerance;
  if (any_camber) {
    std::vector<std::string> all_keys = aligning_keys();
    for (auto& k : aligning_camber_keys(model)) all_keys.push_back(k);
    results.push_back(
        fit_stage({"Mz0 (all cambers)", all_keys, 100}, cambered, levels, params, progress));
  }
  return results;
}

std::vector<StageResult> refit_aligning_pure(
    const MeasurementSet& data, const std::vector<double>& levels, MfFitModel model,
    mf::MfParameters<double>& params, const std::function<void(const std::string&)>& progress) {
  std::vector<StageResult> results;
  const std::vector<StageSample> pure = select_samples(
      data, levels, FitChannel::mz,
      [](const MeasurementPoint& m) { return std::fabs(m.kappa) <= kPureTolerance; });
  std::vector<std::string> keys = aligning_keys();
  bool any_camber = false;
  for (const auto& s : pure) any_camber = any_camber || std::fabs(s.gamma_rad) > kPureTolerance;
  if (any_camber) {
    for (auto& k : aligning_camber_keys(model)) keys.push_back(k);
  }
  if (pure.size() <= keys.size()) return results;
  results.push_back(
      fit_stage({"Mz0 (pass 2, with s Fx)", keys, 100}, pure, levels, params, progress));
  return results;
}

}  // namespace tread::fit
