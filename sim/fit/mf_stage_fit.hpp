#pragma once
// One stage of the staged Magic Formula fit: a separate Ceres problem over a named subset of the
// coefficients, every other coefficient held at its current value, evaluated through the templated
// core (tread::mf::evaluate<ceres::Jet>, combined slip on, limits on, no extras: what a rig
// measures) — no second copy of the equations. The longitudinal, lateral, aligning and combined
// stages (mf_longitudinal_fit.cpp, ...) only choose the coefficients and the points; this file
// solves, bounds (coefficient_bounds), reports progress (one line per iteration), the standard
// deviations (Ceres covariance, pseudo-inverse for flat directions, scaled by the residual
// variance) and RMS / R² per channel and load. Host side: allocates, throws.

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "fit/measurement.hpp"
#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"

namespace tread::fit {

/// Which coefficient set is fitted: MF 6.1 (also for MF 6.2 files: the same force and moment
/// equations) or PAC2002 (also MF-Tyre 5.2: the equations the core shares for both).
enum class MfFitModel { mf61, pac2002 };

/// |slip| (and |γ| in rad) up to which a point counts as pure slip / zero camber.
inline constexpr double kPureTolerance = 1e-3;

/// Least-squares line v = a + b·u as {a, b}; where the points do not give a slope (a single
/// point, or every u the same) b = `single_slope` and a = mean(v − b·u).
std::pair<double, double> fit_line(const std::vector<double>& u, const std::vector<double>& v,
                                   double single_slope = 0.0);

enum class FitChannel { fx, fy, mz };
const char* fit_channel_name(FitChannel c);  ///< "Fx", "Fy", "Mz"
const char* fit_channel_unit(FitChannel c);  ///< "N", "N", "Nm"

/// One measured value of one channel at one operating point.
struct StageSample {
  double fz_n = 0.0, kappa = 0.0, alpha_rad = 0.0, gamma_rad = 0.0, vx_mps = 0.0;
  FitChannel channel = FitChannel::fy;
  double value = 0.0;
  double weight = 1.0;  ///< the residual is (model − value)·weight
  std::size_t load_level = 0;
};

/// The options every stage evaluates the core with (and the report and plots use).
mf::MfOptions fit_options();
/// The core's value of `channel` at the sample's inputs.
double model_value(const mf::MfParameters<double>& p, const StageSample& s);

/// Load levels: clusters of Fz (sorted values jumping by more than 10 %), their mean loads.
std::vector<double> load_levels(const MeasurementSet& data);
std::size_t nearest_level(const std::vector<double>& levels, double fz_n);

/// The points of `data` with a finite value in `channel` for which `keep` holds, weighted by
/// 1 / (largest |value| of that channel at that load among the kept points), so each load counts
/// in relative terms.
std::vector<StageSample> select_samples(const MeasurementSet& data,
                                        const std::vector<double>& levels, FitChannel channel,
                                        const std::function<bool(const MeasurementPoint&)>& keep);

struct ChannelLoadStats {
  FitChannel channel = FitChannel::fy;
  double fz_n = 0.0;
  std::size_t points = 0;
  double rms = 0.0;  ///< N or Nm
  double r2 = 0.0;
};

struct StageResult {
  std::string name;
  std::vector<std::string> keys;
  std::vector<double> start, values, stddev;  ///< stddev NaN where not available (and held)
  /// Coefficients the stage's points do not determine (a column of the Jacobian that is a
  /// combination of earlier keys' columns, e.g. PDX2 beside PDX1 at a single load level, or
  /// without effect, e.g. a camber term on uncambered points): held at their start values.
  std::vector<std::string> held;
  std::size_t points = 0;
  int iterations = 0;
  bool converged = false;  ///< Ceres reported convergence (false: iteration limit)
  double seconds = 0.0;
  std::vector<ChannelLoadStats> stats;
};

struct StageSpec {
  std::string name;
  std::vector<std::string> keys;  ///< .tir keys of the coefficients freed
  int max_iterations = 100;
  /// Further starts (each: coefficients set differently from the current values). Every start
  /// gets 10 iterations; the one with the lowest cost then is solved to convergence. Deterministic.
  std::vector<std::vector<std::pair<std::string, double>>> other_starts = {};
};

/// Fits spec.keys to `samples` starting from (and writing back into) `params`. A key whose
/// Jacobian column at the solution is, to 1e-6 of its norm, a combination of the columns of the
/// keys before it (spec.keys's order: the main coefficients first) is not determined by these
/// points: the stage is solved again with such keys held at their start values (StageResult::held,
/// standard deviation NaN). Throws std::runtime_error if there are not more samples than
/// coefficients.
StageResult fit_stage(const StageSpec& spec, const std::vector<StageSample>& samples,
                      const std::vector<double>& levels, mf::MfParameters<double>& params,
                      const std::function<void(const std::string&)>& progress);

/// RMS and R² per channel and load of `params` on `samples`.
std::vector<ChannelLoadStats> channel_load_stats(const mf::MfParameters<double>& params,
                                                 const std::vector<StageSample>& samples,
                                                 const std::vector<double>& levels);

}  // namespace tread::fit
