// PAC94: the same model properties as PAC89, its reduction to PAC89 when the PAC94-only
// coefficients are 0 (with PAC89's shift terms mapped to PAC94's), and each PAC94 extension checked
// against an equivalent PAC89 curve.
#include "pac/pac94.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "pac/pac89.hpp"
#include "pac_test_sets.hpp"

namespace {

using tread::pac::Pac89;
using tread::pac::Pac94;
using tread::pac::pac94_eval;
using tread::pac::PacInput;
using tread::pac::PacParams;
using tread::pac::Slip;
namespace t = tread::pac::testing;

constexpr double kPi = std::numbers::pi;

TEST(Pac94, ReducesToPac89WithoutShiftsAndExtensions) {
  // The two models group their terms differently; aarch64 contracts a*b+c into FMA, so equality
  // holds to rounding (a few 1e-15 relative), not to the last bit.
  const auto near = [](double a, double b) {
    return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b));
  };
  const auto p = t::symmetric_set<double>();
  for (double fz = 0.5; fz < 9.0; fz += 0.7) {
    for (double s = -40.0; s <= 40.0; s += 0.83) {
      for (const double g : {-3.0, 0.0, 2.0}) {
        EXPECT_PRED2(near, Pac94::fx0(p, fz, s), Pac89::fx0(p, fz, s));
        EXPECT_PRED2(near, Pac94::fy0(p, fz, s, g), Pac89::fy0(p, fz, s, g));
        EXPECT_PRED2(near, Pac94::mz0(p, fz, s, g), Pac89::mz0(p, fz, s, g));
      }
    }
  }
}

TEST(Pac94, ShiftTermsUseThePac94Layout) {
  // PAC94: Sh_y = a8 Fz + a9 + a10 γ, Sv_y = a11 Fz + a12 + (a13 Fz² + a14 Fz) γ;
  // PAC89: Sh_y = a8 γ + a9 Fz + a10, Sv_y = a11 Fz γ + a12 Fz + a13. Map one onto the other.
  auto p94 = t::symmetric_set<double>();
  p94.a[8] = 0.05;   // Sh per kN
  p94.a[9] = 0.3;    // Sh constant
  p94.a[10] = 0.02;  // Sh per degree of camber
  p94.a[11] = 4.0;   // Sv per kN
  p94.a[12] = 20.0;  // Sv constant
  p94.a[14] = 1.5;   // Sv per kN per degree (a13 Fz² term left 0: PAC89 has no Fz² γ term)
  auto p89 = t::symmetric_set<double>();
  p89.a[8] = 0.02;
  p89.a[9] = 0.05;
  p89.a[10] = 0.3;
  p89.a[11] = 1.5;
  p89.a[12] = 4.0;
  p89.a[13] = 20.0;
  for (double s = -20.0; s <= 20.0; s += 0.9) {
    for (const double g : {-2.0, 0.0, 3.0}) {
      EXPECT_NEAR(Pac94::fy0(p94, 4.0, s, g), Pac89::fy0(p89, 4.0, s, g), 1e-9 * t::fy_D(4.0));
    }
  }
  // Mz: PAC94 Sh_z = c11 Fz + c12 + c13 γ, Sv_z = c14 Fz + c15 + (c16 Fz² + c17 Fz) γ;
  //     PAC89 Sh_z = c11 γ + c12 Fz + c13, Sv_z = (c14 Fz² + c15 Fz) γ + c16 Fz + c17.
  auto q94 = t::symmetric_set<double>();
  q94.c[11] = 0.1, q94.c[12] = -0.2, q94.c[13] = 0.05;
  q94.c[14] = 2.0, q94.c[15] = 3.0, q94.c[16] = 0.1, q94.c[17] = 0.4;
  auto q89 = t::symmetric_set<double>();
  q89.c[11] = 0.05, q89.c[12] = 0.1, q89.c[13] = -0.2;
  q89.c[14] = 0.1, q89.c[15] = 0.4, q89.c[16] = 2.0, q89.c[17] = 3.0;
  for (double s = -20.0; s <= 20.0; s += 0.9) {
    for (const double g : {-2.0, 0.0, 3.0}) {
      EXPECT_NEAR(Pac94::mz0(q94, 4.0, s, g), Pac89::mz0(q89, 4.0, s, g), 1e-9 * t::mz_D(4.0));
    }
  }
}

TEST(Pac94, AsymmetricCurvatureB13MatchesScaledPac89) {
  // E = E89 (1 − b13 sgn(κ + Sh)): for κ > 0 the curve is PAC89 with E·(1 − b13), for κ < 0 with
  // E·(1 + b13).
  auto p = t::symmetric_set<double>();
  p.b[13] = 0.4;
  auto up = t::symmetric_set<double>();
  up.b[8] = 0.3 * (1 - 0.4);
  auto down = t::symmetric_set<double>();
  down.b[8] = 0.3 * (1 + 0.4);
  for (double k = 0.25; k <= 60.0; k += 0.5) {
    EXPECT_DOUBLE_EQ(Pac94::fx0(p, 4.0, k), Pac89::fx0(up, 4.0, k));
    EXPECT_DOUBLE_EQ(Pac94::fx0(p, 4.0, -k), Pac89::fx0(down, 4.0, -k));
  }
  // Sv_x = b11 Fz + b12 shifts the whole curve.
  auto v = t::symmetric_set<double>();
  v.b[11] = 10.0;
  v.b[12] = 5.0;
  EXPECT_DOUBLE_EQ(Pac94::fx0(v, 4.0, 7.0),
                   Pac89::fx0(t::symmetric_set<double>(), 4.0, 7.0) + 45.0);
}

TEST(Pac94, CamberReducesPeakThroughA15AndC18) {
  auto p = t::symmetric_set<double>();
  p.a[15] = 0.01;  // D_y = (a1 Fz + a2)(1 − a15 γ²) Fz
  p.c[18] = 0.02;  // D_z = (c1 Fz² + c2 Fz)(1 − c18 γ²)
  const double g = 3.0;
  double peak = 0.0;
  for (double a = 0.0; a <= 40.0; a += 1e-4) peak = std::max(peak, Pac94::fy0(p, 4.0, a, g));
  EXPECT_NEAR(peak, t::fy_D(4.0) * (1 - 0.01 * g * g), 1e-6 * t::fy_D(4.0));
  // Asymptote with B < 0 (Mz): D sin(πC/2) on the side where B·X → +∞.
  EXPECT_NEAR(Pac94::mz0(p, 4.0, -1e7, g),
              t::mz_D(4.0) * (1 - 0.02 * g * g) * std::sin(kPi * t::kCz / 2), 1e-3 * t::mz_D(4.0));
}

TEST(Pac94, SlopeAndSymmetryAndCombined) {
  const auto p = t::symmetric_set<double>();
  const double h = 1e-5;
  EXPECT_NEAR((Pac94::fy0(p, 3.0, h, 0.0) - Pac94::fy0(p, 3.0, -h, 0.0)) / (2 * h), t::fy_BCD(3.0),
              1e-6 * t::fy_BCD(3.0));
  for (double s = -0.5; s <= 0.5; s += 0.05) {
    const auto a = pac94_eval(p, PacInput<double>{5000.0, s, s / 2, 0.0}, Slip::kCombined);
    const auto b = pac94_eval(p, PacInput<double>{5000.0, -s, -s / 2, 0.0}, Slip::kCombined);
    EXPECT_DOUBLE_EQ(a.fx_n, -b.fx_n);
    EXPECT_DOUBLE_EQ(a.fy_n, -b.fy_n);
    const auto pk = pac94_eval(p, PacInput<double>{5000.0, s, 0.0, 0.0}, Slip::kPure);
    const auto ck = pac94_eval(p, PacInput<double>{5000.0, s, 0.0, 0.0}, Slip::kCombined);
    EXPECT_NEAR(ck.fx_n, pk.fx_n, 1e-9 * t::fx_D(5.0));
  }
}

TEST(Pac94, FuzzNoNanOrInf) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> exp10(-40.0, 38.0);
  std::bernoulli_distribution neg(0.5);
  auto value = [&] {
    const double m = std::pow(10.0, exp10(rng));
    return neg(rng) ? -m : m;
  };
  auto p = t::symmetric_set<double>();
  p.b[13] = 0.3, p.a[15] = 0.01, p.a[16] = 0.02, p.a[17] = 0.1, p.c[18] = 0.01, p.c[19] = 0.02;
  p.c[20] = 0.1, p.c[10] = 0.05;  // (1 − c10|γ|) crosses 0 at |γ| = 20° < the 28.6° limit
  PacParams<float> pf;
  for (std::size_t i = 0; i < p.a.size(); ++i) pf.a[i] = static_cast<float>(p.a[i]);
  for (std::size_t i = 0; i < p.b.size(); ++i) pf.b[i] = static_cast<float>(p.b[i]);
  for (std::size_t i = 0; i < p.c.size(); ++i) pf.c[i] = static_cast<float>(p.c[i]);
  for (int i = 0; i < 50000; ++i) {
    const PacInput<double> in{value(), value(), value(), value()};
    const PacInput<float> inf{static_cast<float>(in.fz_n), static_cast<float>(in.kappa),
                              static_cast<float>(in.alpha_rad), static_cast<float>(in.gamma_rad)};
    for (const auto slip : {Slip::kPure, Slip::kCombined}) {
      const auto o = pac94_eval(p, in, slip);
      const auto f = pac94_eval(pf, inf, slip);
      ASSERT_TRUE(std::isfinite(o.fx_n) && std::isfinite(o.fy_n) && std::isfinite(o.mz_nm));
      ASSERT_TRUE(std::isfinite(f.fx_n) && std::isfinite(f.fy_n) && std::isfinite(f.mz_nm));
    }
  }
  // Exactly at the E denominator's zero: 1 − c10·|γ| = 0 at γ = 20°.
  const auto o = pac94_eval(p, PacInput<double>{4000.0, 0.1, 0.1, 20.0 * kPi / 180.0}, Slip::kPure);
  EXPECT_TRUE(std::isfinite(o.mz_nm));
}

}  // namespace
