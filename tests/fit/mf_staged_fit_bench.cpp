// The whole staged fit (--model mf61: Fx0, Fy0, Mz0 with camber, combined Fx, Fy, Mz) on the
// synthetic test-rig grid of MagicFormula61_Parameters.tir (6 006 points, each with Fx, Fy, Mz;
// 1 % noise, fixed seed), from the neutral start. A figure for the README, not a target.
#include <benchmark/benchmark.h>

#include "fit/mf_staged_fit.hpp"
#include "fit/synthetic_measurements.hpp"
#include "golden_path.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace {

using namespace tread;

void BM_Mf61StagedFit(benchmark::State& state) {
  const auto path = tread::testing::tyre_file("MagicFormula61_Parameters.tir");
  const mf::MfParameters<double> truth = tyre::load_mf_parameters(path).params;
  const fit::MeasurementSet data =
      fit::synthesize_measurements(truth, fit::SyntheticGrid{}, 20261121);
  const mf::MfParameters<double> start = fit::neutral_start(truth, fit::MfFitModel::mf61);
  fit::StagedFit result;
  for (auto _ : state) {
    result = fit::fit_mf_staged(data, start, fit::MfFitModel::mf61, {});
    benchmark::DoNotOptimize(result.seconds);
  }
  state.counters["points"] = static_cast<double>(data.points.size());
  state.counters["stages"] = static_cast<double>(result.stages.size());
}
BENCHMARK(BM_Mf61StagedFit)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
