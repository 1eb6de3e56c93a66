#pragma once
// Stage 2 of `tread fit`, pure longitudinal force Fx0(κ, Fz, γ) of MF 6.1 / PAC2002, through the
// staged engine (mf_stage_fit.hpp, the templated core on Jets). First the 14 γ-free coefficients
// PCX1, PDX1, PDX2, PEX1…PEX4, PKX1…PKX3, PHX1, PHX2, PVX1, PVX2 on the points at α = 0, γ = 0,
// started from Stage 1 (basic-formula fits per load: C, μx(dfz), E(dfz), Kx/Fz(dfz), SH(dfz),
// SV/Fz(dfz) lines); then PDX3 on the points at α = 0 and every camber. Host side.

#include <functional>
#include <string>
#include <vector>

#include "fit/measurement.hpp"
#include "fit/mf_stage_fit.hpp"
#include "mf/mf_parameters.hpp"

namespace tread::fit {

/// The γ-free pure longitudinal coefficients.
std::vector<std::string> longitudinal_keys();

/// Starting values of longitudinal_keys() from Stage 1 fits of the pure Fx(κ) points at γ = 0.
void longitudinal_staged_start(const MeasurementSet& data, mf::MfParameters<double>& p);

/// The pure longitudinal stages on `params` (the camber stage is skipped without cambered points).
std::vector<StageResult> fit_longitudinal_stages(
    const MeasurementSet& data, const std::vector<double>& levels, MfFitModel model,
    mf::MfParameters<double>& params, const std::function<void(const std::string&)>& progress);

}  // namespace tread::fit
