// Stage 2, pure lateral MF 6.1 through the templated core with Jets: synthetic Fy(α) at Fz 2, 4,
// 6 kN (α sweep ±0.3 rad in 0.005 rad steps) from MagicFormula61_Parameters.tir with 1 % Gaussian
// noise (fixed seed), fitted from the
// neutral (Pacejka-book default) lateral coefficients; cornering stiffness and peak within 2 %,
// curves within 1 % RMS of the true curves.
#include "fit/mf_lateral_fit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

#include "fit/lateral_start.hpp"
#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread::fit {
namespace {

double fy(const mf::MfParameters<double>& p, double fz, double alpha) {
  return tread::testing::pure_fy_n(p, fz, alpha);
}

double peak(const mf::MfParameters<double>& p, double fz) {
  double v = 0.0;
  for (int i = -1500; i <= 1500; ++i) v = std::max(v, std::fabs(fy(p, fz, i * 2e-4)));
  return v;
}

TEST(MfLateralFit, RecoversMf61PureLateralFromNeutralStart) {
  const auto path = tread::testing::tyre_file("MagicFormula61_Parameters.tir");
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const mf::MfParameters<double> truth = tyre::load_mf_parameters(path).params;
  // Neutral start: the file's non-lateral data (FNOMIN, scalings), book-default lateral terms.
  const mf::MfParameters<double> start = tread::testing::book_lateral_start(truth);

  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal(0.0, 1.0);
  MeasurementSet data;
  data.source = "synthetic";
  for (double fz : {2000.0, 4000.0, 6000.0}) {
    const double sigma = 0.01 * peak(truth, fz);
    for (int i = -60; i <= 60; ++i) {
      MeasurementPoint p;
      p.fz_n = fz;
      p.vx_mps = 16.6;
      p.alpha_rad = i * 0.005;
      p.fy_n = fy(truth, fz, p.alpha_rad) + sigma * normal(rng);
      data.points.push_back(p);
    }
  }
  const LateralFit fit = fit_mf_pure_lateral(data, start, {});
  EXPECT_EQ(fit.points, 363u);
  std::printf("iterations %d, RMS %.2f N\n", fit.iterations, fit.rms_n);
  EXPECT_GT(fit.r2, 0.999);
  for (double sd : fit.stddev) EXPECT_TRUE(std::isfinite(sd));
  for (double fz : {2000.0, 4000.0, 6000.0}) {
    const double h = 1e-6;
    const double k_true = (fy(truth, fz, h) - fy(truth, fz, -h)) / (2 * h);
    const double k_fit = (fy(fit.params, fz, h) - fy(fit.params, fz, -h)) / (2 * h);
    const double p_true = peak(truth, fz);
    const double p_fit = peak(fit.params, fz);
    double ss = 0.0;
    int n = 0;
    for (int i = -1500; i <= 1500; ++i, ++n) {
      const double d = fy(fit.params, fz, i * 2e-4) - fy(truth, fz, i * 2e-4);
      ss += d * d;
    }
    const double rms_rel = std::sqrt(ss / n) / p_true;
    std::printf("Fy MF 6.1 Fz %5.0f N: stiffness %+.3f %%, peak %+.3f %%, RMS %.3f %% of peak\n",
                fz, 100 * (k_fit / k_true - 1), 100 * (p_fit / p_true - 1), 100 * rms_rel);
    EXPECT_NEAR(k_fit / k_true, 1.0, 0.02);
    EXPECT_NEAR(p_fit / p_true, 1.0, 0.02);
    EXPECT_LT(rms_rel, 0.01);
  }
}

}  // namespace
}  // namespace tread::fit
