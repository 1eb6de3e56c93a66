// The acceptance test of `tread fit` Stage 2 (issue 7, "Done when"): for every .tir of
// data/tyres the core supports, synthetic measurements on a test-rig-like grid
// (synthetic_measurements.hpp: Fz 0.5/1/1.5 × FNOMIN, pure κ and α sweeps at five cambers, combined
// sweeps; Gaussian noise 1 % of the peak, fixed seed) are fitted by the staged fit from a neutral
// start (every fitted coefficient at its book value; FNOMIN, R0, scalings and limits from the
// file), and the result is compared with the TRUE, noise-free model at each load:
//   - longitudinal slip stiffness dFx/dκ and cornering stiffness dFy/dα at the origin (γ = 0),
//   - peak friction μx = max|Fx|/Fz over κ ∈ [−0.3, 0.3], μy = max|Fy|/Fz over α ∈ [−0.3, 0.3],
//     within 2 %;
//   - the force curves within 1 % RMS of the true curves, relative to the true peak force at that
//     load: Fx(κ) and Fy(α) at every camber of the grid, and combined Fx and Fy along every
//     combined sweep of the grid.
//   - the aligning moment Mz(α) the same way (1 % of the true peak |Mz| at that load), pure and
//     combined. Excluded files: chrono_feda_335_65R22_5_G275MSA_60psi.tir (FITTYP 5, an MF 5.0
//     truck
// tyre: the core does not evaluate it) and chrono_HMMWV_Pac89Tire.json (PAC89: another model, not
// an MF 5.2/6.1/PAC2002 coefficient set).
#include "fit/mf_staged_fit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "fit/synthetic_measurements.hpp"
#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread::fit {
namespace {

struct Case {
  const char* file;
  MfFitModel model;
};

double value(const mf::MfParameters<double>& p, FitChannel c, double fz, double kappa, double alpha,
             double gamma) {
  StageSample s;
  s.fz_n = fz;
  s.kappa = kappa;
  s.alpha_rad = alpha;
  s.gamma_rad = gamma;
  s.vx_mps = 16.7;
  s.channel = c;
  return model_value(p, s);
}

/// Values along a sweep of 601 points of κ (fx) or α over [−0.3, 0.3] at fixed other slip.
std::vector<double> curve(const mf::MfParameters<double>& p, FitChannel c, bool kappa_sweep,
                          double fz, double other, double gamma) {
  std::vector<double> v;
  for (int i = -300; i <= 300; ++i) {
    const double x = i * 1e-3;
    v.push_back(kappa_sweep ? value(p, c, fz, x, other, gamma) : value(p, c, fz, other, x, gamma));
  }
  return v;
}

double peak_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

double rms_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double ss = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) ss += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(ss / static_cast<double>(a.size()));
}

// The synthetic grid keeps to the tyre's slip range: the FEDA tyre (KPUMAX = 0, ALPMAX 0.198 rad)
// got κ up to 0.3 and α up to 0.3 rad, the model's clamped outputs written as if measured there.
TEST(SyntheticGrid, KeepsToTheTyresSlipRange) {
  const auto truth =
      tyre::load_mf_parameters(testing::tyre_file("chrono_feda_335_65R22_5_G275MSA_60psi.tir"))
          .params;
  const std::vector<MeasurementPoint> points = synthetic_inputs(truth, SyntheticGrid{});
  ASSERT_FALSE(points.empty());
  double kappa_min = 0.0, kappa_max = 0.0, alpha_max = 0.0;
  for (const MeasurementPoint& m : points) {
    kappa_min = std::min(kappa_min, m.kappa);
    kappa_max = std::max(kappa_max, m.kappa);
    alpha_max = std::max(alpha_max, m.alpha_rad);
  }
  EXPECT_LE(kappa_max, truth.kpumax);
  EXPECT_LE(alpha_max, truth.alpmax_rad);
  EXPECT_LT(kappa_min, -0.25);  // the braking side is kept
}

class MfStagedFit : public ::testing::TestWithParam<Case> {};

TEST_P(MfStagedFit, RecoversStiffnessFrictionAndCurvesFromNeutralStart) {
  const Case c = GetParam();
  const auto path = tread::testing::tyre_file(c.file);
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const mf::MfParameters<double> truth = tyre::load_mf_parameters(path).params;
  check_model(truth, c.model, c.file);
  const SyntheticGrid grid;
  const MeasurementSet data = synthesize_measurements(truth, grid, 20261121);
  const mf::MfParameters<double> start = neutral_start(truth, c.model);
  const StagedFit fit = fit_mf_staged(data, start, c.model, {});
  std::printf("%s: %zu points, staged fit %.2f s\n", c.file, data.points.size(), fit.seconds);
  for (const auto& s : fit.stages) {
    std::printf("  %-16s %5zu points %3d iterations%s %.2f s\n", s.name.c_str(), s.points,
                s.iterations, s.converged ? "" : " (limit)", s.seconds);
  }
  ASSERT_GE(fit.stages.size(), 11u);

  std::vector<double> loads;
  for (double f : grid.load_factors) loads.push_back(std::min(f * truth.fnomin_n, truth.fzmax_n));
  const double h = 1e-5;
  for (double fz : loads) {
    const double kx_true =
        (value(truth, FitChannel::fx, fz, h, 0, 0) - value(truth, FitChannel::fx, fz, -h, 0, 0)) /
        (2 * h);
    const double kx_fit = (value(fit.params, FitChannel::fx, fz, h, 0, 0) -
                           value(fit.params, FitChannel::fx, fz, -h, 0, 0)) /
                          (2 * h);
    const double ky_true =
        (value(truth, FitChannel::fy, fz, 0, h, 0) - value(truth, FitChannel::fy, fz, 0, -h, 0)) /
        (2 * h);
    const double ky_fit = (value(fit.params, FitChannel::fy, fz, 0, h, 0) -
                           value(fit.params, FitChannel::fy, fz, 0, -h, 0)) /
                          (2 * h);
    const auto fx_true = curve(truth, FitChannel::fx, true, fz, 0, 0);
    const auto fy_true = curve(truth, FitChannel::fy, false, fz, 0, 0);
    const auto mz_true = curve(truth, FitChannel::mz, false, fz, 0, 0);
    const double fx_peak = peak_abs(fx_true), fy_peak = peak_abs(fy_true);
    const double mz_peak = peak_abs(mz_true);
    const double mux_true = fx_peak / fz;
    const double mux_fit = peak_abs(curve(fit.params, FitChannel::fx, true, fz, 0, 0)) / fz;
    const double muy_true = fy_peak / fz;
    const double muy_fit = peak_abs(curve(fit.params, FitChannel::fy, false, fz, 0, 0)) / fz;
    std::printf("  Fz %6.0f N: Kx %+.3f %%, Ky %+.3f %%, mux %+.3f %%, muy %+.3f %%\n", fz,
                100 * (kx_fit / kx_true - 1), 100 * (ky_fit / ky_true - 1),
                100 * (mux_fit / mux_true - 1), 100 * (muy_fit / muy_true - 1));
    EXPECT_NEAR(kx_fit / kx_true, 1.0, 0.02) << c.file << " Fz " << fz;
    EXPECT_NEAR(ky_fit / ky_true, 1.0, 0.02) << c.file << " Fz " << fz;
    EXPECT_NEAR(mux_fit / mux_true, 1.0, 0.02) << c.file << " Fz " << fz;
    EXPECT_NEAR(muy_fit / muy_true, 1.0, 0.02) << c.file << " Fz " << fz;

    double worst_fx = 0, worst_fy = 0, worst_mz = 0, worst_cfx = 0, worst_cfy = 0, worst_cmz = 0;
    for (double g0 : grid.cambers_rad) {
      const double g = std::min(std::max(g0, truth.cammin_rad), truth.cammax_rad);
      const double rx = rms_diff(curve(fit.params, FitChannel::fx, true, fz, 0, g),
                                 curve(truth, FitChannel::fx, true, fz, 0, g)) /
                        fx_peak;
      const double ry = rms_diff(curve(fit.params, FitChannel::fy, false, fz, 0, g),
                                 curve(truth, FitChannel::fy, false, fz, 0, g)) /
                        fy_peak;
      const double rz = rms_diff(curve(fit.params, FitChannel::mz, false, fz, 0, g),
                                 curve(truth, FitChannel::mz, false, fz, 0, g)) /
                        mz_peak;
      EXPECT_LT(rx, 0.01) << c.file << " Fx(kappa) Fz " << fz << " gamma " << g;
      EXPECT_LT(ry, 0.01) << c.file << " Fy(alpha) Fz " << fz << " gamma " << g;
      EXPECT_LT(rz, 0.01) << c.file << " Mz(alpha) Fz " << fz << " gamma " << g;
      worst_fx = std::max(worst_fx, rx);
      worst_fy = std::max(worst_fy, ry);
      worst_mz = std::max(worst_mz, rz);
    }
    for (double g0 : grid.combined_cambers_rad) {
      const double g = std::min(std::max(g0, truth.cammin_rad), truth.cammax_rad);
      for (double a : grid.combined_alphas_rad) {
        const double rx = rms_diff(curve(fit.params, FitChannel::fx, true, fz, a, g),
                                   curve(truth, FitChannel::fx, true, fz, a, g)) /
                          fx_peak;
        const double ry = rms_diff(curve(fit.params, FitChannel::fy, true, fz, a, g),
                                   curve(truth, FitChannel::fy, true, fz, a, g)) /
                          fy_peak;
        const double rz = rms_diff(curve(fit.params, FitChannel::mz, true, fz, a, g),
                                   curve(truth, FitChannel::mz, true, fz, a, g)) /
                          mz_peak;
        EXPECT_LT(rx, 0.01) << c.file << " combined Fx(kappa) alpha " << a << " Fz " << fz;
        EXPECT_LT(ry, 0.01) << c.file << " combined Fy(kappa) alpha " << a << " Fz " << fz;
        EXPECT_LT(rz, 0.01) << c.file << " combined Mz(kappa) alpha " << a << " Fz " << fz;
        worst_cfx = std::max(worst_cfx, rx);
        worst_cfy = std::max(worst_cfy, ry);
        worst_cmz = std::max(worst_cmz, rz);
      }
      for (double k : grid.combined_kappas) {
        const double rx = rms_diff(curve(fit.params, FitChannel::fx, false, fz, k, g),
                                   curve(truth, FitChannel::fx, false, fz, k, g)) /
                          fx_peak;
        const double ry = rms_diff(curve(fit.params, FitChannel::fy, false, fz, k, g),
                                   curve(truth, FitChannel::fy, false, fz, k, g)) /
                          fy_peak;
        const double rz = rms_diff(curve(fit.params, FitChannel::mz, false, fz, k, g),
                                   curve(truth, FitChannel::mz, false, fz, k, g)) /
                          mz_peak;
        EXPECT_LT(rx, 0.01) << c.file << " combined Fx(alpha) kappa " << k << " Fz " << fz;
        EXPECT_LT(ry, 0.01) << c.file << " combined Fy(alpha) kappa " << k << " Fz " << fz;
        EXPECT_LT(rz, 0.01) << c.file << " combined Mz(alpha) kappa " << k << " Fz " << fz;
        worst_cfx = std::max(worst_cfx, rx);
        worst_cfy = std::max(worst_cfy, ry);
        worst_cmz = std::max(worst_cmz, rz);
      }
    }
    std::printf(
        "  Fz %6.0f N: worst RMS/peak pure Fx %.3f %%, Fy %.3f %%, Mz %.3f %%; combined Fx %.3f "
        "%%, Fy %.3f %%, Mz %.3f %%\n",
        fz, 100 * worst_fx, 100 * worst_fy, 100 * worst_mz, 100 * worst_cfx, 100 * worst_cfy,
        100 * worst_cmz);
  }
}

INSTANTIATE_TEST_SUITE_P(
    RefdataTir, MfStagedFit,
    ::testing::Values(Case{"MagicFormula61_Parameters.tir", MfFitModel::mf61},
                      Case{"MagicFormula62_Parameters.tir", MfFitModel::mf61},
                      Case{"PacejkaBook_Defaults.tir", MfFitModel::mf61},
                      Case{"reference_tire_tvd3.tir", MfFitModel::mf61},
                      Case{"MagicFormula52_Parameters.tir", MfFitModel::pac2002},
                      Case{"chrono_Sedan_Pac02Tire.tir", MfFitModel::pac2002},
                      Case{"chrono_VW_mf_185_80R14_PAC2002.tir", MfFitModel::pac2002},
                      Case{"derived_chrono_VW_mf_185_80R14_PAC2002_FITTYP6.tir",
                           MfFitModel::pac2002}),
    [](const ::testing::TestParamInfo<Case>& param_info) {
      std::string name = param_info.param.file;
      name = name.substr(0, name.find('.'));
      for (char& ch : name) {
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      }
      return name;
    });

}  // namespace
}  // namespace tread::fit
