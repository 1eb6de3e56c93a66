#pragma once
// Stage 2 of `tread fit` (--model mf61 | pac2002): the full pure- and combined-slip coefficient
// set, staged as practitioners do, each stage its own Ceres problem through the templated core
// (mf_stage_fit.hpp):
//   1. Fx0 at γ = 0, then its camber term (mf_longitudinal_fit.hpp)
//   2. Fy0 at γ = 0, then its camber terms (mf_lateral_fit.hpp)
//   3. Mz0 at γ = 0, then its camber terms, with Fy held (mf_aligning_fit.hpp)
//   4. combined Fx, Fy, then the Fx arm of Mz (mf_combined_fit.hpp)
// The coefficients not fitted (FNOMIN, R0, scaling factors, limits, pressure and turn-slip terms,
// Mx, My, ...) stay as in the starting set. Host side: allocates, throws.

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "fit/measurement.hpp"
#include "fit/mf_stage_fit.hpp"
#include "mf/mf_parameters.hpp"
#include "tir/tir_file.hpp"

namespace tread::fit {

/// Every coefficient the staged fit of `model` frees, in stage order.
std::vector<std::string> fitted_keys(MfFitModel model);

/// `p` with every coefficient of fitted_keys(model) at its book value (MFeval's default): a
/// neutral start that keeps the tyre's FNOMIN, R0, scalings and limits.
mf::MfParameters<double> neutral_start(const mf::MfParameters<double>& p, MfFitModel model);

/// Throws std::runtime_error if `p`'s FITTYP does not belong to `model` (mf61: MF 6.1/6.2;
/// pac2002: PAC2002 or MF 5.2).
void check_model(const mf::MfParameters<double>& p, MfFitModel model, const std::string& origin);

struct StagedFit {
  MfFitModel model = MfFitModel::mf61;
  mf::MfParameters<double> params;
  std::vector<double> levels;  ///< load levels found (N)
  std::vector<StageResult> stages;
  double seconds = 0.0;  ///< the whole staged fit
};

/// `progress` (may be empty) receives one line per solver iteration and per stage.
StagedFit fit_mf_staged(const MeasurementSet& data, const mf::MfParameters<double>& start,
                        MfFitModel model, const std::function<void(const std::string&)>& progress);

/// Writes every fitted coefficient into its section of `file` (the starting .tir).
void set_fitted_coefficients(tir::TirFile& file, const StagedFit& fit);

/// RMS / R² of the fitted set per channel and load level, on every point of `data`.
std::vector<ChannelLoadStats> final_stats(const StagedFit& fit, const MeasurementSet& data);

/// The fitted set's slope at the origin (γ = 0, at `fz_n` and `vx_mps`): dFx/dκ at α = 0 for
/// FitChannel::fx, dFy/dα and dMz/dα at κ = 0 for fy and mz.
double fitted_slope(const StagedFit& fit, FitChannel channel, double fz_n, double vx_mps);

/// slope_sign_doubt for each load level and each channel the data measure (fitted_slope at the
/// first point's Vx): the warnings of a fit that mirrors the tyre.
std::vector<std::string> sign_doubts(const StagedFit& fit, const MeasurementSet& data);

/// Markdown report: per stage the coefficients ± standard deviations, iterations, time, and RMS /
/// R² per channel and load; the fitted set's slip stiffnesses and peak friction per load; then
/// RMS / R² of the final set on every point.
void write_staged_report(const StagedFit& fit, const MeasurementSet& data, std::ostream& out);

/// PNG plots in `dir` (created), one per load and channel: measured Fx(κ) at α = 0, Fy(α) and
/// Mz(α) at κ = 0 (every camber, in colour per camber) with the fitted curves.
void plot_staged_fit(const StagedFit& fit, const MeasurementSet& data, const std::string& dir);

}  // namespace tread::fit
