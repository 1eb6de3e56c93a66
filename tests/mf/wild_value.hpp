#pragma once
// Test helper: random finite values for the fuzz tests of the Magic Formula (scalar and four-lane).

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace tread::testing {

/// A random finite T: mostly physical (|v| ≲ typical), sometimes 0, 100 × typical, huge or tiny
/// anywhere in T's range (10^k from T's smallest subnormal to its largest value), T's largest
/// values, or subnormal.
template <typename T>
T wild(std::mt19937_64& rng, double typical) {
  constexpr double kMax = static_cast<double>(std::numeric_limits<T>::max());
  constexpr double kTiny = static_cast<double>(std::numeric_limits<T>::denorm_min());
  std::uniform_int_distribution<int> pick(0, 9);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> exponent(std::log10(kTiny), std::log10(kMax));
  const double sign = unit(rng) < 0 ? -1.0 : 1.0;
  double v = 0.0;
  switch (pick(rng)) {
    case 0:
      v = 0.0;
      break;
    case 1:
      v = sign * std::pow(10.0, exponent(rng));
      break;
    case 2:
      v = sign * kMax * std::fabs(unit(rng));
      break;
    case 3:
      v = sign * kTiny * 3.0;
      break;
    case 4:
      v = sign * typical * 100.0 * std::fabs(unit(rng));
      break;
    default:
      v = typical * unit(rng);
      break;
  }
  return static_cast<T>(std::clamp(v, -kMax, kMax));
}

}  // namespace tread::testing
