// ns per PAC89/PAC94 evaluation (Fx, Fy, Mz, Mx, My), float and double, pure and combined slip.
// Inputs cycle through 1024 precomputed points (loads 1…9 kN, κ ±0.3, α ±0.2 rad, γ ±0.05 rad) so
// nothing is constant-folded.
#include <benchmark/benchmark.h>

#include <array>
#include <random>

#include "pac/pac89.hpp"
#include "pac/pac94.hpp"
#include "pac_test_sets.hpp"

namespace {

using tread::pac::PacInput;
using tread::pac::PacParams;
using tread::pac::Slip;

template <typename T>
std::array<PacInput<T>, 1024> inputs() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> fz(1000.0, 9000.0), k(-0.3, 0.3), a(-0.2, 0.2),
      g(-0.05, 0.05);
  std::array<PacInput<T>, 1024> in{};
  for (auto& x : in) {
    x = {static_cast<T>(fz(rng)), static_cast<T>(k(rng)), static_cast<T>(a(rng)),
         static_cast<T>(g(rng))};
  }
  return in;
}

template <typename T>
PacParams<T> params() {
  auto p = tread::pac::testing::symmetric_set<T>();
  p.a[10] = T(0.1);  // non-zero shifts so no branch is trivially skipped
  p.a[13] = T(20);
  p.lateral_stiffness_npm = T(2e5);
  p.rolling_resistance = T(0.015);
  p.unloaded_radius_m = T(0.4);
  return p;
}

template <typename T, int Model, Slip S>
void BM_pac(benchmark::State& state) {
  const auto p = params<T>();
  const auto in = inputs<T>();
  std::size_t i = 0;
  for (auto _ : state) {
    const auto o =
        Model == 89 ? tread::pac::pac89_eval(p, in[i], S) : tread::pac::pac94_eval(p, in[i], S);
    benchmark::DoNotOptimize(o);
    i = (i + 1) & 1023U;
  }
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_pac<float, 89, Slip::kPure>)->Name("pac89/float/pure");
BENCHMARK(BM_pac<float, 89, Slip::kCombined>)->Name("pac89/float/combined");
BENCHMARK(BM_pac<double, 89, Slip::kPure>)->Name("pac89/double/pure");
BENCHMARK(BM_pac<double, 89, Slip::kCombined>)->Name("pac89/double/combined");
BENCHMARK(BM_pac<float, 94, Slip::kPure>)->Name("pac94/float/pure");
BENCHMARK(BM_pac<float, 94, Slip::kCombined>)->Name("pac94/float/combined");
BENCHMARK(BM_pac<double, 94, Slip::kPure>)->Name("pac94/double/pure");
BENCHMARK(BM_pac<double, 94, Slip::kCombined>)->Name("pac94/double/combined");

}  // namespace

BENCHMARK_MAIN();
