#pragma once
// Stage 2 of `tread fit`, combined slip of MF 6.1 / PAC2002 through the staged engine
// (mf_stage_fit.hpp), after the pure-slip stages (their coefficients held): the weighting
// functions Gxα of Fx (RBX1, RBX2, RCX1, REX1, REX2, RHX1; MF 6.1 also RBX3) and Gyκ with the
// κ-induced side force SVyκ of Fy (RBY1…3, RCY1, REY1, REY2, RHY1, RHY2, RVY1…6; MF 6.1 also
// RBY4) on the points with both slips non-zero, then the Fx moment arm of Mz (SSZ1…4) on every
// Mz point (s·Fx acts at κ = 0 too). Starting values: the current (book) ones and, for Gxα and Gyκ,
// two more (steeper weighting functions; the lowest cost wins). Host side.

#include <functional>
#include <string>
#include <vector>

#include "fit/measurement.hpp"
#include "fit/mf_stage_fit.hpp"
#include "mf/mf_parameters.hpp"

namespace tread::fit {

std::vector<std::string> combined_fx_keys(MfFitModel model);
std::vector<std::string> combined_fy_keys(MfFitModel model);
std::vector<std::string> combined_mz_keys();

/// Skipped (no result) without combined points.
std::vector<StageResult> fit_combined_stages(
    const MeasurementSet& data, const std::vector<double>& levels, MfFitModel model,
    mf::MfParameters<double>& params, const std::function<void(const std::string&)>& progress);

/// The SSZ stage alone (on every Mz point, needs combined points), named `name`.
std::vector<StageResult> fit_combined_mz(const MeasurementSet& data,
                                         const std::vector<double>& levels,
                                         mf::MfParameters<double>& params,
                                         const std::function<void(const std::string&)>& progress,
                                         const std::string& name);

}  // namespace tread::fit
