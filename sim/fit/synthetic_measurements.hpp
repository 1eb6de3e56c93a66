#pragma once
// Synthetic tyre measurements from a coefficient set (host side): what `tread fit --synthesize`
// writes and the acceptance test fits. A test-rig-like grid: three loads around FNOMIN (0.5, 1,
// 1.5 × FNOMIN, at most FZMAX), pure κ sweeps at α = 0 and pure α sweeps at κ = 0 at five
// cambers, and combined sweeps (κ sweeps at three slip angles, α sweeps at three slip ratios) at
// γ = 0 and one camber; Vx = 16.7 m/s. Every point carries Fx, Fy and Mz from the core (combined
// slip, limits on: tread::fit::fit_options) plus Gaussian noise of `noise_rel` × the largest
// |value| of that channel at that load on its pure γ = 0 sweep. Deterministic for a seed
// (std::mt19937_64 and std::normal_distribution of the standard library in use).

#include <cstdint>
#include <iosfwd>
#include <vector>

#include "fit/measurement.hpp"
#include "mf/mf_parameters.hpp"

namespace tread::fit {

struct SyntheticGrid {
  std::vector<double> load_factors = {0.5, 1.0, 1.5};  ///< × FNOMIN (limited to FZMAX)
  double kappa_max = 0.3, kappa_step = 0.01;
  double alpha_max_rad = 0.3, alpha_step_rad = 0.01;
  /// Within |κ|, |α| < fine_range the sweeps step a quarter as far (the slip stiffnesses).
  double fine_range = 0.05;
  std::vector<double> cambers_rad = {-0.08, -0.04, 0.0, 0.04, 0.08};  ///< limited to CAMMIN/MAX
  std::vector<double> combined_alphas_rad = {-0.1, 0.04, 0.1};        ///< of the combined κ sweeps
  std::vector<double> combined_kappas = {-0.1, 0.04, 0.1};            ///< of the combined α sweeps
  std::vector<double> combined_cambers_rad = {0.0, 0.04};
  double vx_mps = 16.7;
  double noise_rel = 0.01;
};

/// The grid's points (inputs only, outputs NaN); slips outside the tyre's KPUMIN…KPUMAX and
/// ALPMIN…ALPMAX are left out.
std::vector<MeasurementPoint> synthetic_inputs(const mf::MfParameters<double>& truth,
                                               const SyntheticGrid& grid);

/// The grid evaluated on `truth` with noise (noise_rel = 0: the true values).
MeasurementSet synthesize_measurements(const mf::MfParameters<double>& truth,
                                       const SyntheticGrid& grid, std::uint64_t seed);

/// CSV that read_measurement_csv reads: Fz_N,kappa,alpha_rad,gamma_rad,Vx_mps,Fx_N,Fy_N,Mz_Nm.
void write_measurement_csv(const MeasurementSet& data, std::ostream& out);

}  // namespace tread::fit
