// Stage 1 of `tread fit` (the seed's method automated), the acceptance in small: synthetic
// measurements from MagicFormula61_Parameters.tir (tread::mf::evaluate<double>) on a test-rig grid
// (Fz 2, 4, 6 kN; kappa sweep at alpha = 0; alpha sweep at kappa = 0), Gaussian noise of 1 % of the
// peak force (fixed seed), fit; stiffness and peak within 2 %, curves within 1 % RMS of the true
// curves (relative to the true peak).
#include "fit/simple_fit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <sstream>
#include <vector>

#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread::fit {
namespace {

constexpr double kVx = 16.6;  // LONGVL of the file, well above VXLOW
constexpr double kSlipMax = 0.3;
constexpr double kStep = 0.005;

struct Truth {
  mf::MfParameters<double> params;
  mf::MfOptions options;
  double value(Channel c, double fz, double slip) const {
    mf::MfInput<double> in;
    in.fz_n = fz;
    in.vx_mps = kVx;
    if (c == Channel::fx_kappa) {
      in.kappa = slip;
    } else {
      in.alpha_rad = slip;
    }
    const mf::MfOutput<double> out = mf::evaluate(params, in, options);
    return c == Channel::fx_kappa ? out.fx_n : (c == Channel::fy_alpha ? out.fy_n : out.mz_nm);
  }
  double peak(Channel c, double fz) const {
    double p = 0.0;
    for (int i = -1500; i <= 1500; ++i) p = std::max(p, std::fabs(value(c, fz, i * 2e-4)));
    return p;
  }
  double slope(Channel c, double fz) const {
    const double h = 1e-6;
    return (value(c, fz, h) - value(c, fz, -h)) / (2.0 * h);
  }
};

Truth load_truth() {
  const auto path = tread::testing::tyre_file("MagicFormula61_Parameters.tir");
  if (!std::filesystem::exists(path)) throw std::runtime_error("missing " + path.string());
  Truth t;
  t.params = tyre::load_mf_parameters(path).params;
  t.options.combined = true;
  return t;
}

MeasurementSet synthetic(const Truth& truth, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  MeasurementSet set;
  set.source = "synthetic";
  const int n = static_cast<int>(std::lround(kSlipMax / kStep));
  for (double fz : {2000.0, 4000.0, 6000.0}) {
    const double sx = 0.01 * truth.peak(Channel::fx_kappa, fz);
    const double sy = 0.01 * truth.peak(Channel::fy_alpha, fz);
    const double sm = 0.01 * truth.peak(Channel::mz_alpha, fz);
    for (int i = -n; i <= n; ++i) {  // kappa sweep at alpha = 0: Fx only
      MeasurementPoint p;
      p.fz_n = fz;
      p.vx_mps = kVx;
      p.kappa = i * kStep;
      p.fx_n = truth.value(Channel::fx_kappa, fz, p.kappa) + sx * normal(rng);
      set.points.push_back(p);
    }
    for (int i = -n; i <= n; ++i) {  // alpha sweep at kappa = 0: Fy and Mz
      MeasurementPoint p;
      p.fz_n = fz;
      p.vx_mps = kVx;
      p.alpha_rad = i * kStep;
      p.fy_n = truth.value(Channel::fy_alpha, fz, p.alpha_rad) + sy * normal(rng);
      p.mz_nm = truth.value(Channel::mz_alpha, fz, p.alpha_rad) + sm * normal(rng);
      set.points.push_back(p);
    }
  }
  return set;
}

const ChannelFit& find(const SimpleFit& fit, Channel c, double fz) {
  for (const auto& f : fit.fits) {
    if (f.channel == c && std::fabs(f.fz_n - fz) < 1.0) return f;
  }
  throw std::runtime_error("no fit");
}

// `asymmetric_e`: with the seed's six constants, MF 6.1's Fx(kappa) (PEX4 = 0.59: a curvature
// that differs on either side of the origin) stays about 1.04 % RMS from the truth; the 7th
// constant EA removes that model error. `fx_rms_limit` is the curve limit for Fx(kappa).
void check_recovery(bool asymmetric_e, double fx_rms_limit) {
  const Truth truth = load_truth();
  const MeasurementSet data = synthetic(truth, 42);
  SimpleFitSettings settings;
  settings.asymmetric_e = asymmetric_e;
  const SimpleFit fit = fit_simple(data, settings, {});
  ASSERT_EQ(fit.loads_n.size(), 3u);
  EXPECT_NEAR(fit.loads_n[0], 2000.0, 1e-9);
  EXPECT_NEAR(fit.loads_n[2], 6000.0, 1e-9);
  ASSERT_EQ(fit.fits.size(), 9u);
  for (double fz : {2000.0, 4000.0, 6000.0}) {
    for (Channel c : kChannels) {
      const ChannelFit& f = find(fit, c, fz);
      SCOPED_TRACE(std::string(channel_name(c)) + " at " + std::to_string(fz));
      EXPECT_EQ(f.points, 121u);
      EXPECT_GT(f.constants.c, 1.0);
      EXPECT_LT(f.constants.c, 3.0);
      EXPECT_LT(f.constants.e, 1.0);
      const double true_peak = truth.peak(c, fz);
      double ss = 0.0;
      int count = 0;
      for (int i = -1500; i <= 1500; ++i) {
        const double x = i * 2e-4;
        const double d = simple_curve(f.constants, x) - truth.value(c, fz, x);
        ss += d * d;
        ++count;
      }
      const double rms_rel = std::sqrt(ss / count) / true_peak;
      const double slope_rel = slope_at_origin(f.constants) / truth.slope(c, fz) - 1.0;
      const double peak_rel = peak_abs(f.constants, -kSlipMax, kSlipMax) / true_peak - 1.0;
      std::printf("%-10s Fz %5.0f N: slope %+.3f %%, peak %+.3f %%, curve RMS %.3f %% of peak\n",
                  channel_name(c), fz, 100 * slope_rel, 100 * peak_rel, 100 * rms_rel);
      if (c == Channel::mz_alpha) {
        // Mz of MF 6.1 (−t·Fy + Mzr) is not a basic Magic Formula curve: only a sound fit.
        EXPECT_GT(f.r2, 0.95);
        continue;
      }
      EXPECT_LT(std::fabs(slope_rel), 0.02);
      EXPECT_LT(std::fabs(peak_rel), 0.02);
      EXPECT_LT(rms_rel, c == Channel::fx_kappa ? fx_rms_limit : 0.01);
      EXPECT_GT(f.r2, 0.99);
      for (std::size_t i = 0; i < (asymmetric_e ? 7u : 6u); ++i) {
        EXPECT_TRUE(std::isfinite(f.stddev[i])) << kConstantNames[i];
      }
    }
  }
}

TEST(SimpleFit, RecoversMf61WithAsymmetricCurvature) {
  check_recovery(true, 0.01);
}

TEST(SimpleFit, RecoversMf61WithTheSeedsSixConstants) {
  check_recovery(false, 0.011);
}

TEST(SimpleFit, DeterministicAndMapInterpolates) {
  const Truth truth = load_truth();
  const SimpleFit a = fit_simple(synthetic(truth, 7), SimpleFitSettings{}, {});
  const SimpleFit b = fit_simple(synthetic(truth, 7), SimpleFitSettings{}, {});
  std::ostringstream sa, sb;
  write_simple_fit_csv(a, sa);
  write_simple_fit_csv(b, sb);
  EXPECT_EQ(sa.str(), sb.str());

  const ChannelFit& lo = find(a, Channel::fy_alpha, 2000.0);
  const ChannelFit& mid = find(a, Channel::fy_alpha, 4000.0);
  const SimpleConstants at_mid = interpolate_constants(a, Channel::fy_alpha, 4000.0);
  EXPECT_DOUBLE_EQ(at_mid.d, mid.constants.d);
  const SimpleConstants below = interpolate_constants(a, Channel::fy_alpha, 1000.0);
  EXPECT_DOUBLE_EQ(below.b, lo.constants.b);
  const SimpleConstants q = interpolate_constants(a, Channel::fy_alpha, 3000.0);
  EXPECT_NEAR(q.d, 0.5 * (lo.constants.d + mid.constants.d), 1e-9 * std::fabs(q.d));
  // The interpolated curve at 3 kN lies near the true one (D grows nearly linearly with Fz).
  const double true_peak = truth.peak(Channel::fy_alpha, 3000.0);
  EXPECT_NEAR(peak_abs(q, -kSlipMax, kSlipMax), true_peak, 0.05 * true_peak);
}

TEST(SimpleFit, ReportAndCsvNameEveryFit) {
  const Truth truth = load_truth();
  const SimpleFit fit = fit_simple(synthetic(truth, 3), SimpleFitSettings{}, {});
  std::ostringstream csv, report;
  write_simple_fit_csv(fit, csv);
  write_simple_fit_report(fit, "synthetic", report);
  std::istringstream lines(csv.str());
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line.rfind("channel,fz_N,points,B,C,D,E,SH,SV,EA,sd_B", 0), 0u);
  int rows = 0;
  while (std::getline(lines, line)) ++rows;
  EXPECT_EQ(rows, 9);
  EXPECT_NE(report.str().find("## Fx(kappa)"), std::string::npos);
  EXPECT_NE(report.str().find("## Mz(alpha)"), std::string::npos);
}

}  // namespace
}  // namespace tread::fit
