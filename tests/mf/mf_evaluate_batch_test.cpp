// mf::evaluate_batch (src/mf/mf_evaluate_batch.hpp): the Magic Formula on the widest float lanes
// the CPU has (16 with AVX-512, 8 with AVX2; 4 elsewhere).
//   - Every wheel's outputs are evaluate_four's for it on the same CPU, bit for bit, with the same
//     status: every .tir the MF core loads, all eight useModes, extras on/off/loaded radius only,
//     the three mounted sides, physical and wild inputs (zero, huge, tiny, subnormal; NaN inputs).
//     (GCC contracts the same a·b + c into FMAs at every width since the lane operators take their
//     operands by reference, mf_lanes.hpp; a difference names the first field that differs.)
//   - A wheel's outputs do not depend on its neighbours, its place in its block or the batch's
//     length: bit for bit, batches of every length from 0 to 3 blocks, at every width the CPU runs.
//   - 8 and 16 lanes give the same bits; batch_lanes() (16 with AVX-512, else 8 on x86-64) and
//     sixteen_lanes_available() say what the CPU runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "batch_inputs.hpp"
#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "mf/mf_evaluate_batch.hpp"
#include "mf/mf_evaluate_four.hpp"
#include "shipped_mf_tyres.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread::mf {
namespace {

std::vector<MfParameters<float>> all_mf_tyres() {
  std::vector<MfParameters<float>> tyres;
  for (const MfParameters<double>& p : testing::shipped_mf_tyres()) {
    tyres.push_back(convert_parameters<float>(p));
  }
  return tyres;
}

constexpr std::size_t kFields = offsetof(MfOutput<float>, status) / sizeof(float);
std::array<float, kFields> fields_of(const MfOutput<float>& o) {
  std::array<float, kFields> f;
  std::memcpy(f.data(), &o, sizeof(f));
  return f;
}

/// The widths this CPU runs: 8 on any x86-64 (and 16 with AVX-512), else 4.
std::vector<int> widths() {
  if (batch_lanes() == 4) return {4};
  std::vector<int> w = {8};
  if (sixteen_lanes_available()) w.push_back(16);
  return w;
}

TEST(MfEvaluateBatch, EqualsEvaluateFour) {
  for (const int lanes : widths()) {
    const std::vector<MfParameters<float>> tyres = all_mf_tyres();
    ASSERT_GE(tyres.size(), 8U);
    std::mt19937_64 rng(17);
    // Several hundred wheels per tyre and option set: a change in how GCC contracted one of the
    // batch's products into an FMA showed in 3 % of the evaluations, which 29 wheels per set
    // missed.
    const std::size_t n = static_cast<std::size_t>(64 * batch_lanes() + 5);
    const std::vector<testing::BatchOptionSet> sets = testing::batch_option_sets();
    std::size_t compared = 0;
    for (const MfParameters<float>& p : tyres) {
      for (const testing::BatchOptionSet& set : sets) {
        const std::vector<MfInput<float>> in = testing::batch_inputs(rng, n);
        const std::vector<MfOutput<float>> expected = testing::in_fours(p, in, set.options);
        std::vector<MfOutput<float>> got(n);
        evaluate_batch_on(lanes, p, in, set.options, got);
        for (std::size_t i = 0; i < n; ++i) {
          const std::string where = "fit " + std::to_string(static_cast<int>(p.fit_type)) + " " +
                                    set.name + " wheel " + std::to_string(i);
          ASSERT_EQ(got[i].status, expected[i].status) << where;
          const auto a = fields_of(got[i]);
          const auto b = fields_of(expected[i]);
          for (std::size_t k = 0; k < kFields; ++k) {
            ASSERT_EQ(std::memcmp(&a[k], &b[k], sizeof(float)), 0)
                << where << " field " << k << ": " << a[k] << " vs " << b[k];
          }
          ++compared;
        }
      }
    }
    std::printf("[ compared ] %zu wheels on %d lanes, all bit for bit\n", compared, lanes);
  }
}

// evaluate_four's x86-64-v4 code (mf_evaluate_four_v4.cpp: its selects one vpternlogd) gives the
// x86-64-v3 clone's bits, so that four lanes are reproducible on every x86-64 CPU with AVX2 and FMA.
// A select is exact, but its form changes which products GCC fuses into FMAs (sgn_nz_times): this
// is what keeps the two equal. Runs where the CPU is x86-64-v4 (both run there).
TEST(MfEvaluateFour, X8664V4EqualsV3BitForBit) {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
  __builtin_cpu_init();
  if (!__builtin_cpu_supports("x86-64-v4")) GTEST_SKIP() << "needs an x86-64-v4 CPU";
  const std::vector<MfParameters<float>> tyres = all_mf_tyres();
  std::mt19937_64 rng(29);
  std::size_t compared = 0;
  for (const MfParameters<float>& p : tyres) {
    for (const testing::BatchOptionSet& set : testing::batch_option_sets()) {
      const std::vector<MfInput<float>> in = testing::batch_inputs(rng, 4 * 64);
      const std::array<MountedSide, 4> sides = {MountedSide::left, MountedSide::right,
                                                set.options.side, MountedSide::as_measured};
      for (std::size_t g = 0; g < in.size(); g += 4) {
        const std::array<MfInput<float>, 4> four = {in[g], in[g + 1], in[g + 2], in[g + 3]};
        MfOutput<lanes::F4> v4;
        MfOutput<lanes::F4> v3;
        evaluate_four(p, four, set.options, sides, v4);
        detail::evaluate_four_without_v4(p, four, set.options, sides, v3);
        // The outputs' float fields in order (MfOutput<F4>: kFields lanes, then the status).
        std::array<lanes::F4, kFields> a;
        std::array<lanes::F4, kFields> b;
        std::memcpy(a.data(), &v4, sizeof(a));
        std::memcpy(b.data(), &v3, sizeof(b));
        for (int k = 0; k < 4; ++k) {
          const std::string where = "fit " + std::to_string(static_cast<int>(p.fit_type)) + " " +
                                    set.name + " wheel " +
                                    std::to_string(g + static_cast<std::size_t>(k));
          ASSERT_EQ(v4.status[k], v3.status[k]) << where;
          for (std::size_t f = 0; f < kFields; ++f) {
            const float x = a[f][k];
            const float y = b[f][k];
            ASSERT_EQ(std::memcmp(&x, &y, sizeof(float)), 0)
                << where << " field " << f << ": " << x << " vs " << y;
          }
          ++compared;
        }
      }
    }
  }
  std::printf("[ compared ] %zu wheels, x86-64-v4 against x86-64-v3, all bit for bit\n", compared);
#else
  GTEST_SKIP() << "the x86-64-v4 code exists only in GCC builds for x86-64";
#endif
}

TEST(MfEvaluateBatch, EveryLengthAndPlaceInABlock) {
  for (const int lanes : widths()) {
    for (const char* tyre : {"MagicFormula61_Parameters.tir", "MagicFormula62_Parameters.tir",
                             "chrono_Sedan_Pac02Tire.tir"}) {
      const MfParameters<float> p =
          convert_parameters<float>(tyre::load_mf_parameters(testing::tyre_file(tyre)).params);
      const MfOptions o = options_from_use_mode(111).value;
      std::mt19937_64 rng(5);
      const auto most = static_cast<std::size_t>(3 * lanes);
      const std::vector<MfInput<float>> all = testing::batch_inputs(rng, most);
      // Each wheel alone (its block padded with copies of it).
      std::vector<MfOutput<float>> alone(most);
      for (std::size_t i = 0; i < most; ++i) {
        evaluate_batch_on(lanes, p, std::span<const MfInput<float>>(all).subspan(i, 1), o,
                          std::span<MfOutput<float>>(alone).subspan(i, 1));
      }
      for (std::size_t length = 0; length <= most; ++length) {
        for (std::size_t start = 0; start + length <= most; start += 1 + most / 7) {
          std::vector<MfOutput<float>> got(length);
          evaluate_batch_on(lanes, p, std::span<const MfInput<float>>(all).subspan(start, length),
                            o, got);
          for (std::size_t i = 0; i < length; ++i) {
            ASSERT_TRUE(testing::same_bits(got[i], alone[start + i]))
                << tyre << " lanes " << lanes << " length " << length << " start " << start
                << " wheel " << i;
          }
        }
      }
    }
  }
  // evaluate_batch is evaluate_batch_on(batch_lanes(), …).
  const MfParameters<float> p = convert_parameters<float>(
      tyre::load_mf_parameters(testing::tyre_file("MagicFormula61_Parameters.tir")).params);
  std::mt19937_64 rng(9);
  const std::vector<MfInput<float>> in = testing::batch_inputs(rng, 37);
  const MfOptions o = options_from_use_mode(111).value;
  std::vector<MfOutput<float>> a(in.size());
  std::vector<MfOutput<float>> b(in.size());
  evaluate_batch(p, in, o, a);
  evaluate_batch_on(batch_lanes(), p, in, o, b);
  for (std::size_t i = 0; i < in.size(); ++i) ASSERT_TRUE(testing::same_bits(a[i], b[i])) << i;
}

TEST(MfEvaluateBatch, SixteenLanesEqualEightBitForBit) {
  if (!sixteen_lanes_available()) GTEST_SKIP() << "no AVX-512 on this CPU";
  std::mt19937_64 rng(23);
  std::size_t compared = 0;
  for (const MfParameters<float>& p : all_mf_tyres()) {
    for (const int mode : testing::kUseModes) {
      const MfOptions o = options_from_use_mode(mode).value;
      const std::vector<MfInput<float>> in = testing::batch_inputs(rng, 53);
      std::vector<MfOutput<float>> eight(in.size());
      std::vector<MfOutput<float>> sixteen(in.size());
      evaluate_batch_on(8, p, in, o, eight);
      evaluate_batch_on(16, p, in, o, sixteen);
      for (std::size_t i = 0; i < in.size(); ++i) {
        ASSERT_TRUE(testing::same_bits(eight[i], sixteen[i])) << "mode " << mode << " wheel " << i;
        ++compared;
      }
    }
  }
  std::printf("[ compared ] %zu wheels\n", compared);
}

TEST(MfEvaluateBatch, LanesForThisCpu) {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
  __builtin_cpu_init();
  const bool v4 = __builtin_cpu_supports("x86-64-v4");
  EXPECT_EQ(sixteen_lanes_available(), v4);
  EXPECT_EQ(batch_lanes(), v4 ? 16 : 8);
#else
  EXPECT_EQ(batch_lanes(), 4);
  EXPECT_FALSE(sixteen_lanes_available());
#endif
}

}  // namespace
}  // namespace tread::mf
