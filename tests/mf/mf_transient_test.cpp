// src/mf/mf_transient.hpp: the first-order relaxation stage. A step in κ (or α) reaches
// 1 − 1/e of its final value after σ/Vx seconds, the output force is the steady-state force at
// the transient slip, it converges to the steady state, and it never allocates state beyond the
// object (checked by its size).
#include "mf/mf_transient.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "golden_path.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread::mf {
namespace {

MfInput<double> input(double kappa, double alpha, double vx) {
  MfInput<double> in;
  in.fz_n = 5000.0;
  in.kappa = kappa;
  in.alpha_rad = alpha;
  in.vx_mps = vx;
  return in;
}

class MfTransientTest : public ::testing::TestWithParam<const char*> {};

TEST_P(MfTransientTest, StepResponseTimeConstantIsSigmaOverVx) {
  const MfParameters<double> p = tyre::load_mf_parameters(testing::tyre_file(GetParam())).params;
  const MfOptions o = options_from_use_mode(111).value;
  const double vx = 20.0;
  const double dt = 1e-3;
  // Relaxation lengths at this load (they do not depend on the slips).
  const MfOutput<double> ss = evaluate(p, input(0.05, 0.04, vx), o);
  ASSERT_GT(ss.sigmax_m, 0.01);
  ASSERT_GT(ss.sigmay_m, 0.01);
  const double tau_x = ss.sigmax_m / vx;
  const double tau_y = ss.sigmay_m / vx;

  MfTransient<double> tr;
  tr.reset(0.0, 0.0);
  const int n_x = static_cast<int>(std::lround(tau_x / dt));
  const int n_y = static_cast<int>(std::lround(tau_y / dt));
  const int n_end = 20 * std::max(n_x, n_y);
  for (int i = 1; i <= n_end; ++i) {
    const MfOutput<double> out = tr.step(p, input(0.05, 0.04, vx), o, dt);
    if (i == n_x) {
      const double expected = 0.05 * (1.0 - std::exp(-i * dt / tau_x));
      EXPECT_NEAR(tr.kappa(), expected, 1e-9);
      // 1 − 1/e at t = τ (up to the rounding of τ to whole steps).
      EXPECT_NEAR(tr.kappa() / 0.05, 1.0 - std::exp(-1.0), dt / tau_x);
      // The force is the steady-state force at the transient slips.
      const MfOutput<double> at = evaluate(p, input(tr.kappa(), tr.alpha_rad(), vx), o);
      EXPECT_DOUBLE_EQ(out.fx_n, at.fx_n);
    }
    if (i == n_y) {
      EXPECT_NEAR(tr.alpha_rad(), 0.04 * (1.0 - std::exp(-i * dt / tau_y)), 1e-9);
    }
    if (i == n_end) {
      EXPECT_NEAR(out.fx_n, ss.fx_n, 1e-6 * std::fabs(ss.fx_n));
      EXPECT_NEAR(out.fy_n, ss.fy_n, 1e-6 * std::fabs(ss.fy_n));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Files, MfTransientTest,
                         ::testing::Values("MagicFormula61_Parameters.tir",
                                           "MagicFormula52_Parameters.tir"));

TEST(MfTransient, StandstillHoldsAndLargeStepsAreStable) {
  const MfParameters<double> p;  // book tyre
  const MfOptions o = options_from_use_mode(111).value;
  MfTransient<double> tr;
  tr.reset(0.01, 0.0);
  tr.step(p, input(0.2, 0.1, 0.0), o, 1e-3);
  EXPECT_DOUBLE_EQ(tr.kappa(), 0.01);
  // A huge step lands on the input (exact integration, no overshoot).
  tr.step(p, input(0.2, 0.1, 30.0), o, 10.0);
  EXPECT_NEAR(tr.kappa(), 0.2, 1e-12);
  EXPECT_NEAR(tr.alpha_rad(), 0.1, 1e-12);
}

TEST(MfTransient, FloatAndNoHeapState) {
  const MfParameters<float> p = convert_parameters<float>(MfParameters<double>{});
  const MfOptions o = options_from_use_mode(111).value;
  MfTransient<float> tr;
  tr.reset(0.0f, 0.0f);
  MfInput<float> in;
  in.fz_n = 4000.0f;
  in.kappa = 0.05f;
  in.vx_mps = 20.0f;
  for (int i = 0; i < 2000; ++i) tr.step(p, in, o, 1e-3f);
  EXPECT_NEAR(static_cast<double>(tr.kappa()), 0.05, 1e-6);
  static_assert(sizeof(MfTransient<float>) <= 32, "plain value state");
}

}  // namespace
}  // namespace tread::mf
