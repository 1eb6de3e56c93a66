#pragma once
// Stage 2 of `tread fit`, first step: MF 6.1 / PAC2002 pure lateral force Fy0(α, Fz) at γ = 0,
// fitted through the templated core (tread::mf::evaluate<ceres::Jet>, uncombined, no extras) —
// no second copy of the equations. The coefficients fitted are the γ-free ones of the lateral
// section: PCY1, PDY1, PDY2, PEY1, PEY2, PEY3, PKY1, PKY2, PKY4, PHY1, PHY2, PVY1, PVY2; every
// other coefficient (FNOMIN, scaling factors, ...) comes from the starting set. Bounds: 1 < PCY1 <
// 3, PEY1 < 1. Points used: |κ| and |γ| ≤ 1e-3 with a measured Fy. Staged as practitioners do:
// Stage 1 basic-formula fits per load give the starting coefficients (C, μ(dfz), E(dfz), SH, SV/Fz
// lines, a small fit of Kya(Fz)), then all 13 are fitted together. Host side: allocates, throws.

#include <array>
#include <functional>
#include <iosfwd>
#include <string>

#include "fit/measurement.hpp"
#include "mf/mf_parameters.hpp"
#include "tir/tir_file.hpp"

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

/// `progress` (may be empty) receives one line per solver iteration.
LateralFit fit_mf_pure_lateral(const MeasurementSet& data, const mf::MfParameters<double>& start,
                               const std::function<void(const std::string&)>& progress);

/// The fitted values of `fit` (kLateralCoefficientNames).
std::array<double, kLateralCoefficientCount> lateral_values(const LateralFit& fit);

/// Writes the fitted coefficients into [LATERAL_COEFFICIENTS] of `file` (the starting .tir).
void set_lateral_coefficients(tir::TirFile& file, const LateralFit& fit);

/// Markdown report: coefficients ± standard deviations, RMS, R².
void write_lateral_report(const LateralFit& fit, const std::string& source, std::ostream& out);

}  // namespace tread::fit
