#pragma once
// Stage 2 of `tread fit`, pure lateral force Fy0(α, Fz, γ) of MF 6.1 / PAC2002, through the
// staged engine (mf_stage_fit.hpp: tread::mf::evaluate<ceres::Jet>, combined slip, limits on) —
// no second copy of the equations. First the γ-free coefficients of the lateral section (PCY1,
// PDY1, PDY2, PEY1, PEY2, PEY3, PKY1, PKY2, PKY4, PHY1, PHY2, PVY1, PVY2) on the points with
// |κ|, |γ| ≤ 1e-3, then those with the camber terms on every camber; every other coefficient
// (FNOMIN, scaling factors, ...) comes from the starting set. Bounds: 1 < PCY1 < 3, PEY1 < 1,
// 0.1 < PKY4 < 3. Staged as practitioners do: Stage 1 basic-formula fits per load give the
// starting coefficients (C, μ(dfz), E(dfz), SH, SV/Fz lines, a small fit of Kya(Fz)).
// fit_mf_pure_lateral is the γ = 0 stage alone (the benchmark). Host side: allocates,
// throws.

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "fit/measurement.hpp"
#include "fit/mf_stage_fit.hpp"
#include "mf/mf_parameters.hpp"

namespace tread::fit {

inline constexpr int kLateralCoefficientCount = 13;
inline constexpr std::array<const char*, kLateralCoefficientCount> kLateralCoefficientNames = {
    "PCY1", "PDY1", "PDY2", "PEY1", "PEY2", "PEY3", "PKY1",
    "PKY2", "PKY4", "PHY1", "PHY2", "PVY1", "PVY2"};

struct LateralFit {
  mf::MfParameters<double> params;  ///< the starting set with the fitted coefficients
  std::array<double, kLateralCoefficientCount> stddev{};  ///< NaN where not available
  std::size_t points = 0;
  double rms_n = 0.0;
  double r2 = 0.0;
  int iterations = 0;
  /// Ceres reported convergence. False after 100 iterations: with γ = 0 data a nearly flat
  /// direction can keep the solver creeping while the curves no longer change.
  bool converged = false;
};

/// Starting values of the 13 γ-free coefficients from Stage 1 (basic-formula fits per load of the
/// pure lateral points at γ = 0): C, μ(dfz), E(dfz), SH(dfz), SV/Fz(dfz) lines, Kya(Fz) fitted.
void lateral_staged_start(const MeasurementSet& data, mf::MfParameters<double>& p);

/// The camber coefficients of the pure lateral force: MF 6.1 PDY3, PEY4, PEY5, PKY3, PKY5, PKY6,
/// PKY7, PVY3, PVY4; PAC2002 / MF 5.2 PDY3, PEY4, PKY3, PHY3, PVY3, PVY4.
std::vector<std::string> lateral_camber_keys(MfFitModel model);

/// The pure lateral stages on `params`: the 13 γ-free coefficients on the points at κ = 0, γ = 0
/// (after lateral_staged_start), then the camber coefficients on the points at κ = 0 and every
/// camber (skipped without cambered points).
std::vector<StageResult> fit_lateral_stages(
    const MeasurementSet& data, const std::vector<double>& levels, MfFitModel model,
    mf::MfParameters<double>& params, const std::function<void(const std::string&)>& progress);

/// `progress` (may be empty) receives one line per solver iteration.
LateralFit fit_mf_pure_lateral(const MeasurementSet& data, const mf::MfParameters<double>& start,
                               const std::function<void(const std::string&)>& progress);

/// The fitted values of `fit` (kLateralCoefficientNames).
std::array<double, kLateralCoefficientCount> lateral_values(const LateralFit& fit);

}  // namespace tread::fit
