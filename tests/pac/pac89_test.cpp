// PAC89 from the model's own properties (symmetric synthetic set, see pac_test_sets.hpp):
// slope at the origin = BCD, peak = D + Sv, asymptote D sin(πC/2) + Sv, odd symmetry, combined →
// pure, zero load, and no NaN/Inf for any finite input (fuzz).
#include "pac/pac89.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "pac_test_sets.hpp"

namespace {

using tread::pac::Pac89;
using tread::pac::pac89_eval;
using tread::pac::PacInput;
using tread::pac::PacParams;
using tread::pac::Slip;
namespace t = tread::pac::testing;

constexpr double kPi = std::numbers::pi;

double max_over(double lo, double hi, int n, const auto& f) {
  double m = -std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i) m = std::max(m, f(lo + (hi - lo) * i / n));
  return m;
}

TEST(Pac89, SlopeAtOriginIsBCD) {
  const auto p = t::symmetric_set<double>();
  for (const double fz : {1.0, 4.0, 8.0}) {
    const double h = 1e-5;
    const double dfx = (Pac89::fx0(p, fz, h) - Pac89::fx0(p, fz, -h)) / (2 * h);
    const double dfy = (Pac89::fy0(p, fz, h, 0.0) - Pac89::fy0(p, fz, -h, 0.0)) / (2 * h);
    const double dmz = (Pac89::mz0(p, fz, h, 0.0) - Pac89::mz0(p, fz, -h, 0.0)) / (2 * h);
    EXPECT_NEAR(dfx, t::fx_BCD(fz), 1e-6 * t::fx_BCD(fz)) << fz;
    EXPECT_NEAR(dfy, t::fy_BCD(fz), 1e-6 * t::fy_BCD(fz)) << fz;
    EXPECT_NEAR(dmz, t::mz_BCD(fz), 1e-6 * std::abs(t::mz_BCD(fz))) << fz;
  }
  // The SI interface: dFx/dκ = 100·BCD (κ in %), dFy/dα = (180/π)·BCD (α in degrees).
  const double h = 1e-7;
  auto fx = [&](double k) {
    return pac89_eval(p, PacInput<double>{4000.0, k, 0.0, 0.0}, Slip::kPure).fx_n;
  };
  auto fy = [&](double a) {
    return pac89_eval(p, PacInput<double>{4000.0, 0.0, a, 0.0}, Slip::kPure).fy_n;
  };
  EXPECT_NEAR((fx(h) - fx(-h)) / (2 * h), 100.0 * t::fx_BCD(4.0), 1e-5 * 100.0 * t::fx_BCD(4.0));
  EXPECT_NEAR((fy(h) - fy(-h)) / (2 * h), 180.0 / kPi * t::fy_BCD(4.0),
              1e-5 * 180.0 / kPi * t::fy_BCD(4.0));
}

TEST(Pac89, PeakIsDPlusSvAndAsymptoteIsDSinHalfPiCPlusSv) {
  auto p = t::symmetric_set<double>();
  // Shift the lateral curve: Sh = a10 = 0.7 deg, Sv = a13 = 55 N (+ a12·Fz = 3·Fz).
  p.a[10] = 0.7;
  p.a[12] = 3.0;
  p.a[13] = 55.0;
  for (const double fz : {2.0, 4.0, 6.0}) {
    const double sv = 3.0 * fz + 55.0;
    const double peak_x =
        max_over(0.0, 100.0, 200000, [&](double k) { return Pac89::fx0(p, fz, k); });
    const double peak_y =
        max_over(-0.7, 40.0, 200000, [&](double a) { return Pac89::fy0(p, fz, a, 0.0); });
    EXPECT_NEAR(peak_x, t::fx_D(fz), 1e-6 * t::fx_D(fz));
    EXPECT_NEAR(peak_y, t::fy_D(fz) + sv, 1e-6 * t::fy_D(fz));
    // Large slip: atan(B X − E(B X − atan B X)) → π/2 for E < 1.
    EXPECT_NEAR(Pac89::fx0(p, fz, 1e7), t::fx_D(fz) * std::sin(kPi * t::kCx / 2),
                1e-3 * t::fx_D(fz));
    EXPECT_NEAR(Pac89::fy0(p, fz, 1e7, 0.0), t::fy_D(fz) * std::sin(kPi * t::kCy / 2) + sv,
                1e-3 * t::fy_D(fz));
    // Mz has B < 0 (BCD < 0 < D): its "far" side where B·X → +∞ is X → −∞.
    EXPECT_NEAR(Pac89::mz0(p, fz, -1e7, 0.0), t::mz_D(fz) * std::sin(kPi * t::kCz / 2),
                1e-3 * std::abs(t::mz_D(fz)));
    // The curve passes through Sv at X = 0, i.e. at α = −Sh.
    EXPECT_NEAR(Pac89::fy0(p, fz, -0.7, 0.0), sv, 1e-9 * t::fy_D(fz));
  }
}

TEST(Pac89, SymmetricCoefficientsGiveOddCurves) {
  const auto p = t::symmetric_set<double>();
  for (double s = -30.0; s <= 30.0; s += 0.37) {
    EXPECT_DOUBLE_EQ(Pac89::fx0(p, 4.0, s), -Pac89::fx0(p, 4.0, -s));
    EXPECT_DOUBLE_EQ(Pac89::fy0(p, 4.0, s, 2.0), -Pac89::fy0(p, 4.0, -s, 2.0));
    EXPECT_DOUBLE_EQ(Pac89::fy0(p, 4.0, s, 2.0), Pac89::fy0(p, 4.0, s, -2.0));  // |γ| only
    EXPECT_DOUBLE_EQ(Pac89::mz0(p, 4.0, s, 0.0), -Pac89::mz0(p, 4.0, -s, 0.0));
  }
  const auto o = pac89_eval(p, PacInput<double>{3000.0, 0.1, -0.1, 0.0}, Slip::kCombined);
  const auto m = pac89_eval(p, PacInput<double>{3000.0, -0.1, 0.1, 0.0}, Slip::kCombined);
  EXPECT_DOUBLE_EQ(o.fx_n, -m.fx_n);
  EXPECT_DOUBLE_EQ(o.fy_n, -m.fy_n);
  EXPECT_DOUBLE_EQ(o.mz_nm, -m.mz_nm);
}

TEST(Pac89, CombinedEqualsPureWhenTheOtherSlipIsZero) {
  auto p = t::symmetric_set<double>();
  p.a[10] = 0.4;  // shifts must not matter for this property
  p.a[13] = 30.0;
  p.c[13] = -0.2;
  p.c[17] = 4.0;
  for (double fz = 500.0; fz <= 9000.0; fz += 850.0) {
    for (double s = -0.9; s <= 0.9; s += 0.0731) {
      const auto pk = pac89_eval(p, PacInput<double>{fz, s, 0.0, 0.01}, Slip::kPure);
      const auto ck = pac89_eval(p, PacInput<double>{fz, s, 0.0, 0.01}, Slip::kCombined);
      EXPECT_NEAR(ck.fx_n, pk.fx_n, 1e-9 * std::abs(pk.fx_n) + 1e-9);
      const auto pa = pac89_eval(p, PacInput<double>{fz, 0.0, s, 0.01}, Slip::kPure);
      const auto ca = pac89_eval(p, PacInput<double>{fz, 0.0, s, 0.01}, Slip::kCombined);
      EXPECT_NEAR(ca.fy_n, pa.fy_n, 1e-9 * std::abs(pa.fy_n) + 1e-9);
      EXPECT_NEAR(ca.mz_nm, pa.mz_nm, 1e-9 * std::abs(pa.mz_nm) + 1e-9);
      EXPECT_EQ(ca.fx_n, 0.0);  // κ = 0: no longitudinal force in combined mode
    }
  }
}

TEST(Pac89, CombinedSlipReducesEachForce) {
  // The resultant follows the pure curve of the combined slip magnitude: with equal κ and tan α,
  // both components are 1/√2 of the pure force at slip magnitude √2·κ.
  const auto p = t::symmetric_set<double>();
  const double k = 0.05;
  const auto c = pac89_eval(p, PacInput<double>{4000.0, k, std::atan(k), 0.0}, Slip::kCombined);
  const double s = std::sqrt(2.0) * k;
  EXPECT_NEAR(c.fx_n, Pac89::fx0(p, 4.0, 100.0 * s) / std::sqrt(2.0), 1e-9 * t::fx_D(4.0));
  EXPECT_NEAR(c.fy_n, Pac89::fy0(p, 4.0, t::deg(std::atan(s)), 0.0) / std::sqrt(2.0),
              1e-9 * t::fy_D(4.0));
  const auto pure = pac89_eval(p, PacInput<double>{4000.0, k, std::atan(k), 0.0}, Slip::kPure);
  EXPECT_LT(std::hypot(c.fx_n, c.fy_n), std::hypot(pure.fx_n, pure.fy_n));
}

TEST(Pac89, ZeroOrNegativeLoadGivesZero) {
  const auto p = t::symmetric_set<double>();
  for (const double fz : {0.0, -1.0, -1e9}) {
    for (const auto slip : {Slip::kPure, Slip::kCombined}) {
      const auto o = pac89_eval(p, PacInput<double>{fz, 0.1, 0.1, 0.05}, slip);
      EXPECT_EQ(o.fx_n, 0.0);
      EXPECT_EQ(o.fy_n, 0.0);
      EXPECT_EQ(o.mz_nm, 0.0);
      EXPECT_EQ(o.mx_nm, 0.0);
      EXPECT_EQ(o.my_nm, 0.0);
    }
  }
}

TEST(Pac89, StatusReportsClampingAndNonFiniteInputs) {
  const auto p = t::symmetric_set<double>();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  using tread::Status;
  EXPECT_EQ(pac89_eval(p, PacInput<double>{4000.0, 0.1, 0.1, 0.0}, Slip::kPure).status, Status::ok);
  EXPECT_EQ(pac89_eval(p, PacInput<double>{0.0, 0.1, 0.1, 0.0}, Slip::kPure).status, Status::ok);
  EXPECT_EQ(pac89_eval(p, PacInput<double>{-1.0, 0.1, 0.1, 0.0}, Slip::kPure).status,
            Status::out_of_range);
  EXPECT_EQ(pac89_eval(p, PacInput<double>{4000.0, 1.5, 0.1, 0.0}, Slip::kPure).status,
            Status::out_of_range);
  EXPECT_EQ(pac89_eval(p, PacInput<double>{4000.0, 0.1, 1.58, 0.0}, Slip::kPure).status,
            Status::out_of_range);
  EXPECT_EQ(pac89_eval(p, PacInput<double>{4000.0, 0.1, 0.1, -0.6}, Slip::kPure).status,
            Status::out_of_range);
  EXPECT_EQ(pac89_eval(p, PacInput<double>{2e5, 0.1, 0.1, 0.0}, Slip::kPure).status,
            Status::out_of_range);
  // Clamped inputs give the value at the limit.
  EXPECT_EQ(pac89_eval(p, PacInput<double>{4000.0, 3.0, 0.0, 0.0}, Slip::kPure).fx_n,
            pac89_eval(p, PacInput<double>{4000.0, 1.0, 0.0, 0.0}, Slip::kPure).fx_n);
  for (const PacInput<double> in :
       {PacInput<double>{nan, 0.1, 0.1, 0.0}, PacInput<double>{4000.0, nan, 0.1, 0.0},
        PacInput<double>{4000.0, 0.1, inf, 0.0}, PacInput<double>{4000.0, 0.1, 0.1, -inf}}) {
    for (const auto slip : {Slip::kPure, Slip::kCombined}) {
      const auto o = pac89_eval(p, in, slip);
      EXPECT_EQ(o.status, Status::invalid_argument);
      EXPECT_EQ(o.fx_n, 0.0);
      EXPECT_EQ(o.fy_n, 0.0);
      EXPECT_EQ(o.mz_nm, 0.0);
    }
  }
}

TEST(Pac89, FloatAgreesWithDouble) {
  const auto pd = t::symmetric_set<double>();
  const auto pf = t::symmetric_set<float>();
  for (double k = -0.5; k <= 0.5; k += 0.01) {
    const auto d = pac89_eval(pd, PacInput<double>{4000.0, k, k, 0.02}, Slip::kCombined);
    const auto f = pac89_eval(
        pf, PacInput<float>{4000.0f, static_cast<float>(k), static_cast<float>(k), 0.02f},
        Slip::kCombined);
    EXPECT_NEAR(f.fx_n, d.fx_n, 2e-4 * t::fx_D(4.0));
    EXPECT_NEAR(f.fy_n, d.fy_n, 2e-4 * t::fy_D(4.0));
    EXPECT_NEAR(f.mz_nm, d.mz_nm, 2e-4 * t::mz_D(4.0));
  }
}

// Inputs: zeros, denormals, tiny, huge, ±max, and log-uniform random magnitudes of both signs.
template <typename T>
std::vector<T> fuzz_values(std::mt19937_64& rng, int n) {
  using L = std::numeric_limits<T>;
  std::vector<T> v = {T(0),      -T(0),    L::denorm_min(), -L::denorm_min(), L::min(),
                      -L::min(), L::max(), L::lowest(),     L::epsilon(),     T(1),
                      T(-1),     T(1e-30), T(-1e-30),       T(1e30),          T(-1e30)};
  std::uniform_real_distribution<double> exp10(-40.0, 38.0);
  std::bernoulli_distribution neg(0.5);
  while (static_cast<int>(v.size()) < n) {
    const double mag = std::pow(10.0, exp10(rng));
    v.push_back(static_cast<T>(neg(rng) ? -mag : mag));
  }
  return v;
}

template <typename T, typename Eval>
void fuzz(const PacParams<T>& p, Eval eval) {
  std::mt19937_64 rng(1234);
  const auto v = fuzz_values<T>(rng, 60);
  std::uniform_int_distribution<std::size_t> pick(0, v.size() - 1);
  for (int i = 0; i < 50000; ++i) {
    const PacInput<T> in{v[pick(rng)], v[pick(rng)], v[pick(rng)], v[pick(rng)]};
    for (const auto slip : {Slip::kPure, Slip::kCombined}) {
      const auto o = eval(p, in, slip);
      ASSERT_TRUE(std::isfinite(o.fx_n) && std::isfinite(o.fy_n) && std::isfinite(o.mz_nm) &&
                  std::isfinite(o.mx_nm) && std::isfinite(o.my_nm))
          << in.fz_n << " " << in.kappa << " " << in.alpha_rad << " " << in.gamma_rad;
    }
  }
}

TEST(Pac89, FuzzNoNanOrInf) {
  auto pd = t::symmetric_set<double>();
  pd.lateral_stiffness_npm = 2e5;
  pd.rolling_resistance = 0.015;
  pd.unloaded_radius_m = 0.4;
  fuzz(pd, [](const auto& p, const auto& in, Slip s) { return pac89_eval(p, in, s); });
  auto pf = t::symmetric_set<float>();
  pf.lateral_stiffness_npm = 2e5f;
  fuzz(pf, [](const auto& p, const auto& in, Slip s) { return pac89_eval(p, in, s); });
  // Degenerate coefficient sets (all zero: C·D = 0, a4 = 0) stay finite too.
  fuzz(PacParams<double>{},
       [](const auto& p, const auto& in, Slip s) { return pac89_eval(p, in, s); });
  fuzz(PacParams<float>{},
       [](const auto& p, const auto& in, Slip s) { return pac89_eval(p, in, s); });
}

}  // namespace
