// Inputs, option sets, the evaluate_four reference and the bit-for-bit comparison of the batch
// tests (mf_evaluate_batch_test.cpp with every shipped tyre on the host, mf_batch_core_test.cpp
// with the core alone on every target).
#pragma once

#include <array>
#include <cstddef>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "mf/mf_evaluate_four.hpp"
#include "mf/mf_options.hpp"
#include "mf/mf_types.hpp"
#include "wild_value.hpp"

namespace tread::testing {

/// n wheels' inputs: physical ones across the envelope, every fifth wild (zero, huge, tiny,
/// subnormal), wheel 1's κ NaN.
inline std::vector<mf::MfInput<float>> batch_inputs(std::mt19937_64& rng, std::size_t n) {
  std::uniform_real_distribution<double> fz(-500.0, 12000.0), kappa(-1.0, 1.0), alpha(-0.6, 0.6),
      gamma(-0.2, 0.2), vx(-5.0, 60.0), phit(-2.0, 2.0), p(0.0, 4e5);
  std::vector<mf::MfInput<float>> in(n);
  for (std::size_t i = 0; i < n; ++i) {
    mf::MfInput<float>& x = in[i];
    if (i % 5 == 4) {
      x.fz_n = wild<float>(rng, 5000.0);
      x.kappa = wild<float>(rng, 0.2);
      x.alpha_rad = wild<float>(rng, 0.2);
      x.gamma_rad = wild<float>(rng, 0.05);
      x.vx_mps = wild<float>(rng, 20.0);
      x.phit_1pm = wild<float>(rng, 0.5);
      x.p_pa = wild<float>(rng, 2e5);
    } else {
      x.fz_n = static_cast<float>(fz(rng));
      x.kappa = static_cast<float>(kappa(rng));
      x.alpha_rad = static_cast<float>(alpha(rng));
      x.gamma_rad = static_cast<float>(gamma(rng));
      x.vx_mps = static_cast<float>(i % 7 == 3 ? 0.0 : vx(rng));
      x.phit_1pm = static_cast<float>(i % 3 == 0 ? phit(rng) : 0.0);
      x.p_pa = static_cast<float>(p(rng));
    }
  }
  if (n > 1) in[1].kappa = std::numeric_limits<float>::quiet_NaN();
  return in;
}

/// One set of options the batch is checked with, and how to name it in a failure.
struct BatchOptionSet {
  mf::MfOptions options;
  std::string name;
};

/// The eight useModes (limits on or off × α* or not × turn slip or not).
inline constexpr std::array<int, 8> kUseModes = {111, 112, 121, 122, 211, 212, 221, 222};

/// Every useMode × extras off / on / loaded radius only × the three mounted sides.
inline std::vector<BatchOptionSet> batch_option_sets() {
  std::vector<BatchOptionSet> sets;
  for (const int mode : kUseModes) {
    for (int extras = 0; extras < 3; ++extras) {
      for (const mf::MountedSide side :
           {mf::MountedSide::as_measured, mf::MountedSide::left, mf::MountedSide::right}) {
        mf::MfOptions o = mf::options_from_use_mode(mode).value;
        o.extras = extras > 0;
        o.extras_loaded_radius_only = extras == 2;
        o.side = side;
        sets.push_back({o, "mode " + std::to_string(mode) + " extras " + std::to_string(extras) +
                               " side " + std::to_string(static_cast<int>(side))});
      }
    }
  }
  return sets;
}

/// evaluate_four on groups of four (the last padded with its first input), every wheel on the
/// options' side: what the batch must give bit for bit.
inline std::vector<mf::MfOutput<float>> in_fours(const mf::MfParameters<float>& p,
                                                 const std::vector<mf::MfInput<float>>& in,
                                                 const mf::MfOptions& options) {
  std::vector<mf::MfOutput<float>> out(in.size());
  const std::array<mf::MountedSide, 4> sides = {options.side, options.side, options.side,
                                                options.side};
  for (std::size_t g = 0; g < in.size(); g += 4) {
    std::array<mf::MfInput<float>, 4> four;
    for (std::size_t k = 0; k < 4; ++k) four[k] = in[g + k < in.size() ? g + k : g];
    std::array<mf::MfOutput<float>, 4> result;
    mf::evaluate_four(p, four, options, sides, result);
    for (std::size_t k = 0; k < 4 && g + k < in.size(); ++k) out[g + k] = result[k];
  }
  return out;
}

/// The outputs' bits (every float field) and status.
inline bool same_bits(const mf::MfOutput<float>& a, const mf::MfOutput<float>& b) {
  constexpr std::size_t kFloats = offsetof(mf::MfOutput<float>, status);
  return std::memcmp(&a, &b, kFloats) == 0 && a.status == b.status;
}

}  // namespace tread::testing
