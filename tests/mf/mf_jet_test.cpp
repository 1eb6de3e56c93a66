// src/mf with ceres::Jet (what the fitter differentiates): it compiles, the value part equals the
// double evaluation, and the derivatives agree with central differences.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <cmath>

#include "mf/mf_evaluate.hpp"

namespace tread::mf {
namespace {

using Jet = ceres::Jet<double, 3>;

TEST(MfJet, ValueAndDerivatives) {
  const MfParameters<double> pd;
  MfParameters<Jet> pj = convert_parameters<Jet>(pd);
  pj.pky1.v[0] = 1.0;  // d/dPKY1
  pj.pdx1.v[1] = 1.0;  // d/dPDX1
  MfInput<Jet> in;
  in.fz_n = Jet(4500.0);
  in.kappa = Jet(0.04);
  in.alpha_rad = Jet(0.06, 2);  // d/dα
  in.gamma_rad = Jet(0.02);
  in.vx_mps = Jet(15.0);
  for (int mode : {111, 121, 211}) {
    const MfOptions o = options_from_use_mode(mode).value;
    const MfOutput<Jet> oj = evaluate(pj, in, o);

    MfInput<double> ind{4500.0, 0.04, 0.06, 0.02, 15.0, 0.0, 0.0};
    const MfOutput<double> od = evaluate(pd, ind, o);
    EXPECT_DOUBLE_EQ(oj.fx_n.a, od.fx_n);
    EXPECT_DOUBLE_EQ(oj.fy_n.a, od.fy_n);
    EXPECT_DOUBLE_EQ(oj.mz_nm.a, od.mz_nm);
    EXPECT_DOUBLE_EQ(oj.mx_nm.a, od.mx_nm);
    EXPECT_DOUBLE_EQ(oj.my_nm.a, od.my_nm);

    const double h = 1e-6;
    MfParameters<double> pp = pd, pm = pd;
    pp.pky1 += h;
    pm.pky1 -= h;
    const double dfy_dpky1 = (evaluate(pp, ind, o).fy_n - evaluate(pm, ind, o).fy_n) / (2 * h);
    EXPECT_NEAR(oj.fy_n.v[0], dfy_dpky1, 1e-4 * std::fabs(dfy_dpky1) + 1e-6);
    pp = pd;
    pm = pd;
    pp.pdx1 += h;
    pm.pdx1 -= h;
    const double dfx_dpdx1 = (evaluate(pp, ind, o).fx_n - evaluate(pm, ind, o).fx_n) / (2 * h);
    EXPECT_NEAR(oj.fx_n.v[1], dfx_dpdx1, 1e-4 * std::fabs(dfx_dpdx1) + 1e-6);
    MfInput<double> ip = ind, im = ind;
    ip.alpha_rad += h;
    im.alpha_rad -= h;
    const double dmz_dalpha = (evaluate(pd, ip, o).mz_nm - evaluate(pd, im, o).mz_nm) / (2 * h);
    EXPECT_NEAR(oj.mz_nm.v[2], dmz_dalpha, 1e-4 * std::fabs(dmz_dalpha) + 1e-6);
    EXPECT_TRUE(ceres::isfinite(oj.rl_m));
  }
}

}  // namespace
}  // namespace tread::mf
