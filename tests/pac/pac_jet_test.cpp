// PAC89/PAC94 instantiate with ceres::Jet (the fitter differentiates through them): the derivative
// of Fx with respect to κ at the origin is 100·BCD and dFy/dα is (180/π)·BCD, and the derivative
// with respect to a coefficient matches a central difference.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <numbers>

#include "pac/pac89.hpp"
#include "pac/pac94.hpp"
#include "pac_test_sets.hpp"

namespace {

using J = ceres::Jet<double, 2>;
using tread::pac::PacInput;
using tread::pac::PacParams;
using tread::pac::Slip;
namespace t = tread::pac::testing;

PacParams<J> to_jet(const PacParams<double>& p) {
  PacParams<J> q;
  for (std::size_t i = 0; i < p.a.size(); ++i) q.a[i] = J(p.a[i]);
  for (std::size_t i = 0; i < p.b.size(); ++i) q.b[i] = J(p.b[i]);
  for (std::size_t i = 0; i < p.c.size(); ++i) q.c[i] = J(p.c[i]);
  return q;
}

TEST(PacJet, DerivativesAtTheOrigin) {
  const auto pj = to_jet(t::symmetric_set<double>());
  const PacInput<J> kin{J(4000.0), J(0.0, 0), J(0.0), J(0.0)};  // d/dκ in v[0]
  const PacInput<J> ain{J(4000.0), J(0.0), J(0.0, 1), J(0.0)};  // d/dα in v[1]
  EXPECT_NEAR(tread::pac::pac89_eval(pj, kin, Slip::kPure).fx_n.v[0], 100.0 * t::fx_BCD(4.0),
              1e-9 * 100.0 * t::fx_BCD(4.0));
  EXPECT_NEAR(tread::pac::pac94_eval(pj, ain, Slip::kPure).fy_n.v[1],
              180.0 / std::numbers::pi * t::fy_BCD(4.0), 1e-6 * t::fy_BCD(4.0));
}

TEST(PacJet, CoefficientDerivativeMatchesFiniteDifference) {
  auto p = t::symmetric_set<double>();
  auto pj = to_jet(p);
  pj.b[2] = J(p.b[2], 0);  // d/d b2 (friction level)
  pj.b[4] = J(p.b[4], 1);  // d/d b4 (slip stiffness)
  for (const auto slip : {Slip::kPure, Slip::kCombined}) {
    const PacInput<J> in{J(3000.0), J(0.08), J(0.04), J(0.01)};
    const auto o = tread::pac::pac89_eval(pj, in, slip);
    const PacInput<double> ind{3000.0, 0.08, 0.04, 0.01};
    for (int k = 0; k < 2; ++k) {
      const std::size_t idx = k == 0 ? 2 : 4;
      const double h = 1e-4 * p.b[idx];
      auto pp = p;
      auto pm = p;
      pp.b[idx] += h;
      pm.b[idx] -= h;
      const double fd = (tread::pac::pac89_eval(pp, ind, slip).fx_n -
                         tread::pac::pac89_eval(pm, ind, slip).fx_n) /
                        (2 * h);
      EXPECT_NEAR(o.fx_n.v[k], fd, 1e-6 * std::abs(fd) + 1e-9);
    }
  }
}

}  // namespace
