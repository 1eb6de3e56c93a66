#include "vehicle/tyre_function.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread::vehicle {
namespace {

TEST(TyreFunction, PeakBrakingSlipIsTheArgmaxOfTheBrakingForce) {
  // An analytic tyre: Fx = −D·sin(C·atan(B·|κ|))·sign(κ) for κ < 0 with its peak at
  // B·|κ| = tan(π/(2C)).
  const double b = 12.0;
  const double c = 1.6;
  const TyreFunction tyre = [&](std::size_t, const WheelKinematics& k) {
    return WheelForces{k.fz_n * std::sin(c * std::atan(b * k.kappa)), 0.0, 0.0};
  };
  const double expected = -std::tan(std::acos(-1.0) / (2.0 * c)) / b;
  EXPECT_NEAR(peak_braking_slip(tyre, 0, 4000.0, 20.0), expected, 1e-6);
}

TEST(TyreFunction, MagicFormulaWrapperIsEvaluate) {
  const auto path = testing::tyre_file("MagicFormula61_Parameters.tir");
  ASSERT_TRUE(std::filesystem::exists(path)) << "missing reference data: " << path;
  const mf::MfParameters<double> params = tyre::load_mf_parameters(path).params;
  const TyreFunction tyre = mf_tyre_function(params);
  WheelKinematics k;
  k.kappa = -0.07;
  k.alpha_rad = 0.03;
  k.fz_n = 4500.0;
  k.vx_mps = 20.0;
  mf::MfInput<double> in;
  in.kappa = k.kappa;
  in.alpha_rad = k.alpha_rad;
  in.fz_n = k.fz_n;
  in.vx_mps = k.vx_mps;
  const mf::MfOutput<double> out = mf::evaluate(params, in, mf::MfOptions{});
  const WheelForces f = tyre(3, k);
  EXPECT_DOUBLE_EQ(f.fx_n, out.fx_n);
  EXPECT_DOUBLE_EQ(f.fy_n, out.fy_n);
  EXPECT_DOUBLE_EQ(f.mz_nm, out.mz_nm);
  // The braking peak of this tyre at 4.5 kN lies near κ = −0.12 (MFeval-validated core).
  const double peak = peak_braking_slip(tyre, 0, 4500.0, 20.0);
  EXPECT_GT(peak, -0.2);
  EXPECT_LT(peak, -0.08);
}

}  // namespace
}  // namespace tread::vehicle
