// The benchmark: Stage 2 pure-lateral MF 6.1 fit on 5 000 points (5 loads × 1 000 slip
// angles from MagicFormula61_Parameters.tir, 1 % Gaussian noise, fixed seed), from the neutral
// (book-default) lateral coefficients. Target ≤ 10 s on the CI's 2 cores.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "fit/lateral_start.hpp"
#include "fit/mf_lateral_fit.hpp"
#include "golden_path.hpp"
#include "mf/mf_evaluate.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

namespace {

using namespace tread;

double fy(const mf::MfParameters<double>& p, double fz, double alpha) {
  return tread::testing::pure_fy_n(p, fz, alpha);
}

void BM_Mf61PureLateralFit5000(benchmark::State& state) {
  const auto path = tread::testing::tyre_file("MagicFormula61_Parameters.tir");
  const mf::MfParameters<double> truth = tyre::load_mf_parameters(path).params;
  const mf::MfParameters<double> start = tread::testing::book_lateral_start(truth);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal(0.0, 1.0);
  fit::MeasurementSet data;
  for (double fz : {2000.0, 3000.0, 4000.0, 5000.0, 6000.0}) {
    double peak = 0.0;
    for (int i = 0; i < 1000; ++i) peak = std::max(peak, std::fabs(fy(truth, fz, -0.3 + i * 6e-4)));
    for (int i = 0; i < 1000; ++i) {
      fit::MeasurementPoint p;
      p.fz_n = fz;
      p.vx_mps = 16.6;
      p.alpha_rad = -0.3 + i * 6e-4;
      p.fy_n = fy(truth, fz, p.alpha_rad) + 0.01 * peak * normal(rng);
      data.points.push_back(p);
    }
  }
  fit::LateralFit result;
  for (auto _ : state) {
    result = fit::fit_mf_pure_lateral(data, start, {});
    benchmark::DoNotOptimize(result.rms_n);
  }
  state.counters["points"] = static_cast<double>(result.points);
  state.counters["iterations"] = result.iterations;
  state.counters["rms_N"] = result.rms_n;
}
BENCHMARK(BM_Mf61PureLateralFit5000)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
