// Google Benchmark of src/mf: ns per evaluation (one wheel, one instant), float and double, pure
// and combined slip, forces and moments only (extras off) and with the extras (Re, Rl, patch...).
// Parameters: data/tyres/MagicFormula61_Parameters.tir (MF 6.1) and MagicFormula62_Parameters.tir
// (MF 6.2, the same tyre), useMode 111.
// Inputs cycle through 1024 precomputed physical operating points, so branches are not trivially
// predicted. Target (issue 3): MF 6.1 combined Fx, Fy, Mz, Mx, My in float ≤ 100 ns per wheel.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "mf/mf_evaluate_batch.hpp"
#include "mf/mf_evaluate_four.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace tread::mf {
namespace {

constexpr std::size_t kInputs = 1024;

template <typename T>
std::array<MfInput<T>, kInputs> make_inputs() {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> fz(500.0, 9000.0), kappa(-0.3, 0.3), alpha(-0.25, 0.25),
      gamma(-0.08, 0.08), vx(5.0, 40.0);
  std::array<MfInput<T>, kInputs> inputs{};
  for (auto& in : inputs) {
    in.fz_n = static_cast<T>(fz(rng));
    in.kappa = static_cast<T>(kappa(rng));
    in.alpha_rad = static_cast<T>(alpha(rng));
    in.gamma_rad = static_cast<T>(gamma(rng));
    in.vx_mps = static_cast<T>(vx(rng));
  }
  return inputs;
}

template <typename T>
MfParameters<T> tyre_parameters(const char* tir) {
  return convert_parameters<T>(tyre::load_mf_parameters(testing::tyre_file(tir)).params);
}

template <typename T>
void bench(benchmark::State& state, const char* tir, bool combined, bool extras) {
  const MfParameters<T> p = tyre_parameters<T>(tir);
  MfOptions o = options_from_use_mode(111).value;
  o.combined = combined;
  o.extras = extras;
  const auto inputs = make_inputs<T>();
  std::size_t i = 0;
  for (auto _ : state) {
    MfOutput<T> out = evaluate(p, inputs[i], o);
    benchmark::DoNotOptimize(out);
    i = (i + 1) % kInputs;
  }
  state.SetItemsProcessed(state.iterations());
}

/// Four wheels per call (evaluate_four: four float lanes, results left in the lanes); items are
/// wheels, so the reported time per item is per wheel.
void bench_four(benchmark::State& state, const char* tir, bool combined, bool extras) {
  const MfParameters<float> p = tyre_parameters<float>(tir);
  MfOptions o = options_from_use_mode(111).value;
  o.combined = combined;
  o.extras = extras;
  const auto inputs = make_inputs<float>();
  const std::array<MountedSide, 4> sides{MountedSide::left, MountedSide::right, MountedSide::left,
                                         MountedSide::right};
  MfOutput<lanes::F4> out{};
  std::size_t i = 0;
  for (auto _ : state) {
    const std::array<MfInput<float>, 4> four{inputs[i], inputs[i + 1], inputs[i + 2],
                                             inputs[i + 3]};
    evaluate_four(p, four, o, sides, out);
    benchmark::DoNotOptimize(out);
    i = (i + 4) % kInputs;
  }
  state.SetItemsProcessed(4 * state.iterations());
}

/// The 1024 inputs in one evaluate_batch_on call on `lanes` lanes (8: AVX2 where the CPU has it,
/// 16: AVX-512 where it has it); items are wheels, so the reported time per item is per wheel.
void bench_batch(benchmark::State& state, int lanes, const char* tir, bool extras) {
  const MfParameters<float> p = tyre_parameters<float>(tir);
  MfOptions o = options_from_use_mode(111).value;
  o.extras = extras;
  const auto inputs = make_inputs<float>();
  std::array<MfOutput<float>, kInputs> out{};
  for (auto _ : state) {
    evaluate_batch_on(lanes, p, inputs, o, out);
    benchmark::DoNotOptimize(out);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(kInputs) * state.iterations());
  const int ran = batch_lanes() == 4 ? 4 : (lanes == 16 && !sixteen_lanes_available() ? 8 : lanes);
  state.SetLabel(std::to_string(ran) + " lanes");
}

constexpr const char* kMf61 = "MagicFormula61_Parameters.tir";
constexpr const char* kMf52 = "MagicFormula52_Parameters.tir";
constexpr const char* kMf62 = "MagicFormula62_Parameters.tir";  // the same tyre as kMf61

void BM_Mf61_Float_Combined(benchmark::State& s) {
  bench<float>(s, kMf61, true, false);
}
void BM_Mf61_Float_Pure(benchmark::State& s) {
  bench<float>(s, kMf61, false, false);
}
void BM_Mf61_Double_Combined(benchmark::State& s) {
  bench<double>(s, kMf61, true, false);
}
void BM_Mf61_Double_Pure(benchmark::State& s) {
  bench<double>(s, kMf61, false, false);
}
void BM_Mf61_Float_Combined_Extras(benchmark::State& s) {
  bench<float>(s, kMf61, true, true);
}
void BM_Mf61_Double_Combined_Extras(benchmark::State& s) {
  bench<double>(s, kMf61, true, true);
}
void BM_Mf52_Float_Combined(benchmark::State& s) {
  bench<float>(s, kMf52, true, false);
}
void BM_Mf52_Double_Combined(benchmark::State& s) {
  bench<double>(s, kMf52, true, false);
}
// MF 6.2 with the extras: the loaded radius solved from Fz62(Rl) (issue 17: ≤ 1.3× MF 6.1 with
// the extras, in every path).
void BM_Mf62_Double_Combined_Extras(benchmark::State& s) {
  bench<double>(s, kMf62, true, true);
}
void BM_Mf62_Float_Combined_Extras(benchmark::State& s) {
  bench<float>(s, kMf62, true, true);
}
void BM_Mf62_FloatFour_Combined_Extras(benchmark::State& s) {
  bench_four(s, kMf62, true, true);
}
void BM_Mf62_FloatFour_Combined(benchmark::State& s) {
  bench_four(s, kMf62, true, false);
}
void BM_Mf61_FloatFour_Combined(benchmark::State& s) {
  bench_four(s, kMf61, true, false);
}
void BM_Mf61_FloatFour_Combined_Extras(benchmark::State& s) {
  bench_four(s, kMf61, true, true);
}

void BM_Mf61_FloatBatch_Combined_Extras(benchmark::State& s) {
  bench_batch(s, batch_lanes(), "MagicFormula61_Parameters.tir", true);
}
void BM_Mf61_FloatBatch8_Combined_Extras(benchmark::State& s) {
  bench_batch(s, 8, "MagicFormula61_Parameters.tir", true);
}
void BM_Mf61_FloatBatch16_Combined_Extras(benchmark::State& s) {
  bench_batch(s, 16, "MagicFormula61_Parameters.tir", true);
}
void BM_Mf62_FloatBatch_Combined_Extras(benchmark::State& s) {
  bench_batch(s, batch_lanes(), "MagicFormula62_Parameters.tir", true);
}
/// MF 6.2 / MF 6.1 with all outputs in one path, measured in pairs (issue 17's ratio): each
/// iteration times a block of MF 6.1 evaluations and the same block in MF 6.2 right after it (which
/// of the two goes first alternates), so that the load of a shared machine, which changes over
/// seconds (one benchmark's repetitions ranged 895–1426 ns here), falls on both alike. The counter
/// `mf62_over_mf61` is the median of the pairs' ratios; the reported time is that of a pair.
template <typename Block>
void paired_ratio(benchmark::State& state, Block&& block) {
  using Clock = std::chrono::steady_clock;
  std::vector<double> ratios;
  ratios.reserve(1U << 20U);
  bool mf62_first = false;
  for (auto _ : state) {
    double seconds[2] = {0.0, 0.0};  // MF 6.1, MF 6.2
    for (int k = 0; k < 2; ++k) {
      const bool mf62 = (k == 0) == mf62_first;
      const auto start = Clock::now();
      block(mf62);
      seconds[mf62 ? 1 : 0] = std::chrono::duration<double>(Clock::now() - start).count();
    }
    mf62_first = !mf62_first;
    if (seconds[0] > 0.0) ratios.push_back(seconds[1] / seconds[0]);
  }
  if (!ratios.empty()) {
    auto middle = ratios.begin() + static_cast<std::ptrdiff_t>(ratios.size() / 2);
    std::nth_element(ratios.begin(), middle, ratios.end());
    state.counters["mf62_over_mf61"] = *middle;
  }
}

template <typename T>
void ratio_scalar(benchmark::State& state) {
  const MfParameters<T> p61 = tyre_parameters<T>(kMf61);
  const MfParameters<T> p62 = tyre_parameters<T>(kMf62);
  const MfOptions o = options_from_use_mode(111).value;
  const auto inputs = make_inputs<T>();
  std::size_t at = 0;  // both models evaluate the same 64 points of a pair
  std::size_t blocks = 0;
  paired_ratio(state, [&](bool mf62) {
    const MfParameters<T>& p = mf62 ? p62 : p61;
    for (std::size_t i = 0; i < 64; ++i) {
      MfOutput<T> out = evaluate(p, inputs[at + i], o);
      benchmark::DoNotOptimize(out);
    }
    if (++blocks % 2 == 0) at = (at + 64) % kInputs;  // the pair's second block: the next points
  });
}

void BM_Ratio_Double(benchmark::State& s) {
  ratio_scalar<double>(s);
}
void BM_Ratio_Float(benchmark::State& s) {
  ratio_scalar<float>(s);
}
void BM_Ratio_FloatFour(benchmark::State& s) {
  const MfParameters<float> p61 = tyre_parameters<float>(kMf61);
  const MfParameters<float> p62 = tyre_parameters<float>(kMf62);
  const MfOptions o = options_from_use_mode(111).value;
  const auto inputs = make_inputs<float>();
  const std::array<MountedSide, 4> sides{MountedSide::left, MountedSide::right, MountedSide::left,
                                         MountedSide::right};
  MfOutput<lanes::F4> out{};
  std::size_t at = 0;  // both models evaluate the same 64 points of a pair
  std::size_t blocks = 0;
  paired_ratio(s, [&](bool mf62) {
    const MfParameters<float>& p = mf62 ? p62 : p61;
    for (std::size_t i = 0; i < 64; i += 4) {
      const std::array<MfInput<float>, 4> four{inputs[at + i], inputs[at + i + 1],
                                               inputs[at + i + 2], inputs[at + i + 3]};
      evaluate_four(p, four, o, sides, out);
      benchmark::DoNotOptimize(out);
    }
    if (++blocks % 2 == 0) at = (at + 64) % kInputs;
  });
}
void BM_Ratio_FloatBatch(benchmark::State& s) {
  const MfParameters<float> p61 = tyre_parameters<float>(kMf61);
  const MfParameters<float> p62 = tyre_parameters<float>(kMf62);
  const MfOptions o = options_from_use_mode(111).value;
  const auto inputs = make_inputs<float>();
  std::array<MfOutput<float>, kInputs> out{};
  paired_ratio(s, [&](bool mf62) {
    evaluate_batch_on(batch_lanes(), mf62 ? p62 : p61, inputs, o, out);
    benchmark::DoNotOptimize(out);
  });
}
BENCHMARK(BM_Ratio_Double);
BENCHMARK(BM_Ratio_Float);
BENCHMARK(BM_Ratio_FloatFour);
BENCHMARK(BM_Ratio_FloatBatch);

BENCHMARK(BM_Mf61_FloatBatch_Combined_Extras);
BENCHMARK(BM_Mf61_FloatBatch8_Combined_Extras);
BENCHMARK(BM_Mf61_FloatBatch16_Combined_Extras);
BENCHMARK(BM_Mf62_FloatBatch_Combined_Extras);
BENCHMARK(BM_Mf61_Float_Combined);
BENCHMARK(BM_Mf61_FloatFour_Combined);
BENCHMARK(BM_Mf61_FloatFour_Combined_Extras);
BENCHMARK(BM_Mf61_Float_Pure);
BENCHMARK(BM_Mf61_Double_Combined);
BENCHMARK(BM_Mf61_Double_Pure);
BENCHMARK(BM_Mf61_Float_Combined_Extras);
BENCHMARK(BM_Mf61_Double_Combined_Extras);
BENCHMARK(BM_Mf52_Float_Combined);
BENCHMARK(BM_Mf52_Double_Combined);
BENCHMARK(BM_Mf62_Double_Combined_Extras);
BENCHMARK(BM_Mf62_Float_Combined_Extras);
BENCHMARK(BM_Mf62_FloatFour_Combined_Extras);
BENCHMARK(BM_Mf62_FloatFour_Combined);

}  // namespace
}  // namespace tread::mf

BENCHMARK_MAIN();
