// mf::evaluate_batch with the core alone (no .tir reader): the test that runs on every target,
// cross builds included (aarch64 and armhf under qemu-user, where the batch is 4 lanes wide: its
// blocks evaluate_four's, and its padding and tail its own). tests/mf/mf_evaluate_batch_test.cpp
// checks every shipped tyre file on the host.
//   - Every wheel's outputs are evaluate_four's for it on the same CPU, bit for bit, with the same
//     status: the default (MF 6.1) tyre evaluated as MF 6.1, MF 6.2 and MF 5.2, all eight useModes,
//     extras on/off/loaded radius only, the three mounted sides, physical and wild inputs.
//   - Batches of every length from 0 to 3 blocks and every start give each wheel the outputs it
//     has alone.
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <cstring>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include "batch_inputs.hpp"
#include "mf/mf_evaluate_batch.hpp"
#include "mf/mf_evaluate_four.hpp"
#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"

namespace tread::mf {
namespace {

std::vector<MfParameters<float>> tyres() {
  std::vector<MfParameters<float>> t;
  for (const FitType fit : {FitType::mf61, FitType::mf62, FitType::mf52}) {
    MfParameters<float> p;
    p.fit_type = fit;
    t.push_back(p);
  }
  return t;
}

TEST(MfBatchCore, EqualsEvaluateFourBitForBit) {
  const int lanes = batch_lanes();
  std::mt19937_64 rng(31);
  const auto n = static_cast<std::size_t>(3 * lanes + 5);
  std::size_t compared = 0;
  const std::vector<testing::BatchOptionSet> sets = testing::batch_option_sets();
  for (const MfParameters<float>& p : tyres()) {
    for (const testing::BatchOptionSet& set : sets) {
      const std::vector<MfInput<float>> in = testing::batch_inputs(rng, n);
      std::vector<MfOutput<float>> got(n);
      evaluate_batch(p, in, set.options, got);
      const std::vector<MfOutput<float>> expected = testing::in_fours(p, in, set.options);
      for (std::size_t i = 0; i < n; ++i) {
        ASSERT_TRUE(testing::same_bits(got[i], expected[i]))
            << "fit " << static_cast<int>(p.fit_type) << " " << set.name << " wheel " << i;
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, tyres().size() * sets.size() * n);
}

TEST(MfBatchCore, EveryLengthAndStartGivesTheWheelsOwnOutputs) {
  const int lanes = batch_lanes();
  const MfParameters<float> p;
  const MfOptions o = options_from_use_mode(111).value;
  std::mt19937_64 rng(5);
  const auto most = static_cast<std::size_t>(3 * lanes);
  const std::vector<MfInput<float>> all = testing::batch_inputs(rng, most);
  std::vector<MfOutput<float>> alone(most);
  for (std::size_t i = 0; i < most; ++i) {
    evaluate_batch(p, std::span<const MfInput<float>>(all).subspan(i, 1), o,
                   std::span<MfOutput<float>>(alone).subspan(i, 1));
  }
  for (std::size_t length = 0; length <= most; ++length) {
    for (std::size_t start = 0; start + length <= most; ++start) {
      std::vector<MfOutput<float>> got(length);
      evaluate_batch(p, std::span<const MfInput<float>>(all).subspan(start, length), o, got);
      for (std::size_t i = 0; i < length; ++i) {
        ASSERT_TRUE(testing::same_bits(got[i], alone[start + i]))
            << "lanes " << lanes << " length " << length << " start " << start << " wheel " << i;
      }
    }
  }
}

}  // namespace
}  // namespace tread::mf
