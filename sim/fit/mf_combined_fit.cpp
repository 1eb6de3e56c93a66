#include "fit/mf_combined_fit.hpp"

#include <cmath>
#include <utility>

namespace tread::fit {
namespace {

bool combined_point(const MeasurementPoint& m) {
  return std::fabs(m.kappa) > kPureTolerance && std::fabs(m.alpha_rad) > kPureTolerance;
}

}  // namespace

std::vector<std::string> combined_fx_keys(MfFitModel model) {
  std::vector<std::string> keys = {"RBX1", "RBX2", "RCX1", "REX1", "REX2", "RHX1"};
  if (model == MfFitModel::mf61) keys.emplace_back("RBX3");
  return keys;
}

std::vector<std::string> combined_fy_keys(MfFitModel model) {
  std::vector<std::string> keys = {"RBY1", "RBY2", "RBY3", "RCY1", "REY1", "REY2", "RHY1",
                                   "RHY2", "RVY1", "RVY2", "RVY3", "RVY4", "RVY5", "RVY6"};
  if (model == MfFitModel::mf61) keys.emplace_back("RBY4");
  return keys;
}

std::vector<std::string> combined_mz_keys() {
  return {"SSZ1", "SSZ2", "SSZ3", "SSZ4"};
}

std::vector<StageResult> fit_combined_stages(
    const MeasurementSet& data, const std::vector<double>& levels, MfFitModel model,
    mf::MfParameters<double>& params, const std::function<void(const std::string&)>& progress) {
  std::vector<StageResult> results;
  const std::vector<StageSample> fx = select_samples(data, levels, FitChannel::fx, combined_point);
  const std::vector<StageSample> fy = select_samples(data, levels, FitChannel::fy, combined_point);
  if (fx.size() > combined_fx_keys(model).size()) {
    results.push_back(fit_stage(
        {"Fx (combined)",
         combined_fx_keys(model),
         100,
         {{{"RBX1", 15.0}, {"RBX2", 15.0}}, {{"RBX1", 25.0}, {"RBX2", 25.0}, {"REX1", -1.0}}}},
        fx, levels, params, progress));
  }
  if (fy.size() > combined_fy_keys(model).size()) {
    results.push_back(fit_stage(
        {"Fy (combined)",
         combined_fy_keys(model),
         100,
         {{{"RBY1", 10.0}, {"RBY2", 10.0}}, {{"RBY1", 25.0}, {"RBY2", 15.0}, {"REY1", 0.5}}}},
        fy, levels, params, progress));
  }
  if (!fx.empty()) {
    for (auto& r : fit_combined_mz(data, levels, params, progress, "Mz (combined)")) {
      results.push_back(std::move(r));
    }
  }
  return results;
}

std::vector<StageResult> fit_combined_mz(const MeasurementSet& data,
                                         const std::vector<double>& levels,
                                         mf::MfParameters<double>& params,
                                         const std::function<void(const std::string&)>& progress,
                                         const std::string& name) {
  std::vector<StageResult> results;
  // The Fx arm s·Fx of Mz also acts at κ = 0 (Fx0(0) = SVx and the SHx slope): the SSZ stage
  // sees every Mz point.
  const std::vector<StageSample> mz =
      select_samples(data, levels, FitChannel::mz, [](const MeasurementPoint&) { return true; });
  bool any_combined = false;
  for (const auto& s : mz) {
    any_combined = any_combined ||
                   (std::fabs(s.kappa) > kPureTolerance && std::fabs(s.alpha_rad) > kPureTolerance);
  }
  if (any_combined && mz.size() > combined_mz_keys().size()) {
    results.push_back(fit_stage({name, combined_mz_keys(), 100}, mz, levels, params, progress));
  }
  return results;
}

}  // namespace tread::fit
