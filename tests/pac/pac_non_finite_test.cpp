// PAC89 / PAC94 with defective coefficient sets (fuzz): every coefficient and design parameter in
// turn set to 0, its negative, huge and tiny, with random wild inputs, in double and float: no
// output is ever NaN or inf, and a non-finite result is reported as Status::non_finite (that
// output 0), never as ok.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "pac/pac89.hpp"
#include "pac/pac94.hpp"
#include "pac_test_sets.hpp"

namespace {

using tread::Status;
using tread::pac::PacInput;
using tread::pac::PacOutput;
using tread::pac::PacParams;
using tread::pac::Slip;
namespace t = tread::pac::testing;

template <typename T>
bool all_finite(const PacOutput<T>& o) {
  return std::isfinite(o.fx_n) && std::isfinite(o.fy_n) && std::isfinite(o.mz_nm) &&
         std::isfinite(o.mx_nm) && std::isfinite(o.my_nm);
}

/// Every coefficient slot of a parameter set (a, b, c, the design parameters and the limits).
template <typename T>
std::vector<T*> slots(PacParams<T>& p) {
  std::vector<T*> s;
  for (T& v : p.a) s.push_back(&v);
  for (T& v : p.b) s.push_back(&v);
  for (T& v : p.c) s.push_back(&v);
  for (T* v : {&p.unloaded_radius_m, &p.rolling_resistance, &p.lateral_stiffness_npm, &p.fz_max_n,
               &p.kappa_max, &p.alpha_max_rad, &p.gamma_max_rad}) {
    s.push_back(v);
  }
  return s;
}

template <typename T>
T wild(std::mt19937_64& rng, double typical) {
  std::uniform_int_distribution<int> pick(0, 5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  switch (pick(rng)) {
    case 0:
      return T(0);
    case 1:
      return static_cast<T>(unit(rng) * 1e30);
    case 2:
      return static_cast<T>(unit(rng) * 1e-30);
    default:
      return static_cast<T>(unit(rng) * typical);
  }
}

template <typename T, typename Eval>
void fuzz_defective(Eval eval, int& non_finite_status) {
  PacParams<T> base = t::symmetric_set<T>();
  base.lateral_stiffness_npm = T(2e5);
  base.rolling_resistance = T(0.015);
  base.unloaded_radius_m = T(0.4);
  std::mt19937_64 rng(0x9ac);
  const std::size_t n = slots(base).size();
  for (std::size_t k = 0; k < n; ++k) {
    const T v = *slots(base)[k];
    const T huge = std::numeric_limits<T>::max();
    for (const T value : {T(0), -v, T(-1), huge, -huge, T(1e30), T(-1e30), T(1e-30)}) {
      PacParams<T> p = base;
      *slots(p)[k] = value;
      for (int i = 0; i < 40; ++i) {
        const PacInput<T> in{wild<T>(rng, 8000.0), wild<T>(rng, 0.5), wild<T>(rng, 0.5),
                             wild<T>(rng, 0.1)};
        for (const Slip slip : {Slip::kPure, Slip::kCombined}) {
          const PacOutput<T> o = eval(p, in, slip);
          ASSERT_TRUE(all_finite(o)) << "slot " << k << " = " << value << " Fz " << in.fz_n
                                     << " kappa " << in.kappa << " alpha " << in.alpha_rad;
          if (o.status == Status::non_finite) ++non_finite_status;
        }
      }
    }
  }
}

TEST(PacNonFinite, DefectiveCoefficientsNeverGiveNanOrInf) {
  int non_finite = 0;
  const auto pac89 = [](const auto& p, const auto& in, Slip s) {
    return tread::pac::pac89_eval(p, in, s);
  };
  const auto pac94 = [](const auto& p, const auto& in, Slip s) {
    return tread::pac::pac94_eval(p, in, s);
  };
  fuzz_defective<double>(pac89, non_finite);
  fuzz_defective<float>(pac89, non_finite);
  fuzz_defective<double>(pac94, non_finite);
  fuzz_defective<float>(pac94, non_finite);
  EXPECT_GT(non_finite, 0);  // the defective sets do overflow somewhere, and say so
}

TEST(PacNonFinite, OverflowingFxIsZeroAndFlaggedTheRestKept) {
  // b2 = the largest double: D = (b1 Fz + b2)·Fz overflows at Fz = 4 kN.
  PacParams<double> p = t::symmetric_set<double>();
  p.b[2] = std::numeric_limits<double>::max();
  const PacInput<double> in{4000.0, 0.05, 0.05, 0.0};
  const PacOutput<double> good =
      tread::pac::pac89_eval(t::symmetric_set<double>(), in, Slip::kPure);
  const PacOutput<double> o = tread::pac::pac89_eval(p, in, Slip::kPure);
  EXPECT_EQ(good.status, Status::ok);
  EXPECT_EQ(o.status, Status::non_finite);
  EXPECT_EQ(o.fx_n, 0.0);
  EXPECT_DOUBLE_EQ(o.fy_n, good.fy_n);
  EXPECT_DOUBLE_EQ(o.mz_nm, good.mz_nm);
  const PacOutput<float> f = tread::pac::pac94_eval(
      [] {
        PacParams<float> q = t::symmetric_set<float>();
        q.b[2] = std::numeric_limits<float>::max();
        return q;
      }(),
      PacInput<float>{4000.0F, 0.05F, 0.05F, 0.0F}, Slip::kCombined);
  EXPECT_EQ(f.status, Status::non_finite);
  EXPECT_TRUE(all_finite(f));
}

}  // namespace
