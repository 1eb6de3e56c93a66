#include "fit/mf_longitudinal_fit.hpp"

#include <cmath>
#include <limits>
#include <tuple>

#include "fit/simple_fit.hpp"

namespace tread::fit {

std::vector<std::string> longitudinal_keys() {
  return {"PCX1", "PDX1", "PDX2", "PEX1", "PEX2", "PEX3", "PEX4",
          "PKX1", "PKX2", "PKX3", "PHX1", "PHX2", "PVX1", "PVX2"};
}

void longitudinal_staged_start(const MeasurementSet& data, mf::MfParameters<double>& p) {
  MeasurementSet longitudinal;
  longitudinal.source = data.source;
  for (const auto& m : data.points) {
    if (std::isfinite(m.fx_n)) {
      MeasurementPoint q = m;
      q.fy_n = q.mz_nm = std::numeric_limits<double>::quiet_NaN();
      longitudinal.points.push_back(q);
    }
  }
  const SimpleFit simple = fit_simple(longitudinal, SimpleFitSettings{}, {});
  std::vector<double> dfz, c, mu, e, kxfz, sh, svfz;
  const double fz0 = p.fnomin_n * p.lfzo;
  for (const auto& f : simple.fits) {
    if (f.channel != Channel::fx_kappa) continue;
    dfz.push_back((f.fz_n - fz0) / fz0);
    c.push_back(f.constants.c);
    mu.push_back(std::fabs(f.constants.d) / f.fz_n);
    e.push_back(f.constants.e);
    kxfz.push_back(f.constants.b * f.constants.c * f.constants.d / f.fz_n);
    sh.push_back(f.constants.sh);
    svfz.push_back(f.constants.sv / f.fz_n);
  }
  if (dfz.empty()) return;
  double csum = 0.0;
  for (double v : c) csum += v;
  p.pcx1 = csum / static_cast<double>(c.size());
  std::tie(p.pdx1, p.pdx2) = fit_line(dfz, mu, p.pdx2);
  std::tie(p.pex1, p.pex2) = fit_line(dfz, e, p.pex2);
  p.pex3 = 0.0;
  p.pex4 = 0.0;
  std::tie(p.pkx1, p.pkx2) = fit_line(dfz, kxfz, p.pkx2);
  p.pkx3 = 0.0;
  std::tie(p.phx1, p.phx2) = fit_line(dfz, sh, p.phx2);
  std::tie(p.pvx1, p.pvx2) = fit_line(dfz, svfz, p.pvx2);
}

std::vector<StageResult> fit_longitudinal_stages(
    const MeasurementSet& data, const std::vector<double>& levels, MfFitModel /*model*/,
    mf::MfParameters<double>& params, const std::function<void(const std::string&)>& progress) {
  std::vector<StageResult> results;
  const std::vector<StageSample> flat =
      select_samples(data, levels, FitChannel::fx, [](const MeasurementPoint& m) {
        return std::fabs(m.alpha_rad) <= kPureTolerance && std::fabs(m.gamma_rad) <= kPureTolerance;
      });
  if (flat.size() <= longitudinal_keys().size()) return results;  // no Fx(κ) sweep: skipped
  longitudinal_staged_start(data, params);
  results.push_back(
      fit_stage({"Fx0 (gamma = 0)", longitudinal_keys(), 100}, flat, levels, params, progress));
  const std::vector<StageSample> cambered = select_samples(
      data, levels, FitChannel::fx,
      [](const MeasurementPoint& m) { return std::fabs(m.alpha_rad) <= kPureTolerance; });
  bool any_camber = false;
  for (const auto& s : cambered) any_camber = any_camber || std::fabs(s.gamma_rad) > kPureTolerance;
  // PDX3 (μx with γ²) is the only camber term of Fx0, in both coefficient sets (PAC2002 scales
  // γ by LGAX); it is fitted together with the γ-free terms on every camber.
  if (any_camber) {
    std::vector<std::string> all_keys = longitudinal_keys();
    all_keys.emplace_back("PDX3");
    results.push_back(
        fit_stage({"Fx0 (all cambers)", all_keys, 100}, cambered, levels, params, progress));
  }
  return results;
}

}  // namespace tread::fit
