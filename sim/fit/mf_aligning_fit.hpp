#pragma once
// Stage 2 of `tread fit`, pure aligning moment Mz0(α, Fz, γ) of MF 6.1 / PAC2002, through the
// staged engine (mf_stage_fit.hpp). Mz = −t·Fy + Mzr needs the lateral force: it runs after the
// lateral stages, with their coefficients held. First the γ-free trail and residual-moment
// coefficients (QBZ1…3, QBZ9, QBZ10, QCZ1, QDZ1, QDZ2, QDZ6, QDZ7, QEZ1…4, QHZ1, QHZ2) on the
// points at κ = 0, γ = 0, then the camber terms (MF 6.1: QBZ4, QBZ5, QDZ3, QDZ4, QDZ8…11, QEZ5,
// QHZ3, QHZ4; PAC2002: the same without QDZ10/QDZ11) on the points at κ = 0 and every camber.
// Starting values: the book's, with the peak trail QDZ1/QDZ2 from the slopes at the origin
// (t ≈ −(dMz/dα)/(dFy/dα) per load). Host side.

#include <functional>
#include <string>
#include <vector>

#include "fit/measurement.hpp"
#include "fit/mf_stage_fit.hpp"
#include "mf/mf_parameters.hpp"

namespace tread::fit {

std::vector<std::string> aligning_keys();
std::vector<std::string> aligning_camber_keys(MfFitModel model);

std::vector<StageResult> fit_aligning_stages(
    const MeasurementSet& data, const std::vector<double>& levels, MfFitModel model,
    mf::MfParameters<double>& params, const std::function<void(const std::string&)>& progress);

/// The second pass after the combined stages: the pure-slip Mz points also carry s·Fx (Fx0 at
/// κ = 0 is SVx plus the SHx slope), which the first pass had to absorb into the trail and residual
/// terms while SSZ was still 0. With SSZ fitted, all the aligning coefficients of the first pass
/// are fitted again on the points at κ = 0 (every camber).
std::vector<StageResult> refit_aligning_pure(
    const MeasurementSet& data, const std::vector<double>& levels, MfFitModel model,
    mf::MfParameters<double>& params, const std::function<void(const std::string&)>& progress);

}  // namespace tread::fit
