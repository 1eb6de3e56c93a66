// Property/fuzz test of src/mf: random finite inputs, including huge, tiny, negative, zero and
// subnormal values, in every useMode and both mounted sides, float and double, for each Magic
// Formula .tir in the reference data: no output may be NaN or Inf.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "mf_output_columns.hpp"
#include "tyre/mf_parameters_from_tir.hpp"
#include "wild_value.hpp"

namespace tread::mf {
namespace {

using testing::wild;

template <typename T>
void fuzz(const std::string& tir_name, int cases) {
  const auto path = testing::tyre_file(tir_name);
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const MfParameters<T> p = convert_parameters<T>(tyre::load_mf_parameters(path).params);
  std::mt19937_64 rng(0x7ead + static_cast<std::uint64_t>(cases));
  const auto columns = testing::output_columns<T>();
  int bad = 0;
  for (int i = 0; i < cases; ++i) {
    MfInput<T> in;
    in.fz_n = wild<T>(rng, 8000.0);
    in.kappa = wild<T>(rng, 1.0);
    in.alpha_rad = wild<T>(rng, 1.0);
    in.gamma_rad = wild<T>(rng, 0.2);
    in.vx_mps = wild<T>(rng, 30.0);
    in.phit_1pm = wild<T>(rng, 0.5);
    in.p_pa = wild<T>(rng, 3e5);
    for (int mode : {111, 112, 121, 122, 211, 212, 221, 222}) {
      MfOptions o = options_from_use_mode(mode).value;
      o.side = (i % 2 == 0) ? MountedSide::left : MountedSide::right;
      o.combined = (i % 3 != 0);
      const MfOutput<T> out = evaluate(p, in, o);
      // evaluate() writes a non-finite output as 0: its status says whether one came out.
      if (out.status == Status::non_finite && ++bad <= 10) {
        ADD_FAILURE() << tir_name << " mode " << mode << ": non-finite output for Fz " << in.fz_n
                      << " kappa " << in.kappa << " alpha " << in.alpha_rad << " gamma "
                      << in.gamma_rad << " Vx " << in.vx_mps << " phit " << in.phit_1pm << " P "
                      << in.p_pa;
      }
      for (const auto& c : columns) {
        const T v = out.*(c.member);
        if (!std::isfinite(v)) {
          if (++bad <= 10) {
            ADD_FAILURE() << tir_name << " mode " << mode << " " << c.name << " = " << v
                          << " for Fz " << in.fz_n << " kappa " << in.kappa << " alpha "
                          << in.alpha_rad << " gamma " << in.gamma_rad << " Vx " << in.vx_mps
                          << " phit " << in.phit_1pm << " P " << in.p_pa;
          }
        }
      }
    }
  }
  EXPECT_EQ(bad, 0);
}

class MfFuzz : public ::testing::TestWithParam<std::string> {};

TEST_P(MfFuzz, DoubleNeverNanOrInf) {
  fuzz<double>(GetParam(), 20000);
}
TEST_P(MfFuzz, FloatNeverNanOrInf) {
  fuzz<float>(GetParam(), 20000);
}

INSTANTIATE_TEST_SUITE_P(
    Files, MfFuzz,
    ::testing::Values("MagicFormula61_Parameters.tir", "MagicFormula62_Parameters.tir",
                      "MagicFormula52_Parameters.tir", "PacejkaBook_Defaults.tir",
                      "derived_chrono_VW_mf_185_80R14_PAC2002_FITTYP6.tir",
                      "chrono_VW_mf_185_80R14_PAC2002.tir", "reference_tire_tvd3.tir"));

}  // namespace
}  // namespace tread::mf
