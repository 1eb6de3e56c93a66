// Inputs and the bit-for-bit comparison of the batch tests (mf_evaluate_batch_test.cpp with every
// shipped tyre on the host, mf_batch_core_test.cpp with the core alone on every target).
#pragma once

#include <cstddef>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

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

/// The outputs' bits (every float field) and status.
inline bool same_bits(const mf::MfOutput<float>& a, const mf::MfOutput<float>& b) {
  constexpr std::size_t kFloats = offsetof(mf::MfOutput<float>, status);
  return std::memcmp(&a, &b, kFloats) == 0 && a.status == b.status;
}

}  // namespace tread::testing
