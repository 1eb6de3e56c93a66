// Generation time of the standard wheel profiles (construction, sampling) and evaluation cost.
#include <benchmark/benchmark.h>

#include <vector>

#include "profile/rail_profile.hpp"
#include "profile/wheel_profile.hpp"

namespace tread::profile {
namespace {

/// All 81 standard profiles (3 families × 3 h × 9 e), 1:15, width 140: construction only.
void BM_ConstructAllStandardProfiles(benchmark::State& state) {
  const std::vector<WheelParameters> all = standard_wheel_parameters();
  for (auto _ : state) {
    for (const WheelParameters& p : all) {
      WheelProfile w(p);
      benchmark::DoNotOptimize(w);
    }
  }
  state.counters["profiles"] = static_cast<double>(all.size());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(all.size()));
}
BENCHMARK(BM_ConstructAllStandardProfiles)->Unit(benchmark::kMicrosecond);

/// All 81 × 4 outer slopes × 2 widths = 648 variants, constructed and sampled at 0.1 mm.
void BM_GenerateAndSampleAllVariants(benchmark::State& state) {
  std::vector<WheelParameters> all;
  for (const OuterSlope s :
       {OuterSlope::k1in15, OuterSlope::k6_7, OuterSlope::k10, OuterSlope::k15}) {
    for (const double width : {135.0, 140.0}) {
      const auto some = standard_wheel_parameters(s, width);
      all.insert(all.end(), some.begin(), some.end());
    }
  }
  for (auto _ : state) {
    for (const WheelParameters& p : all) {
      const SampledProfile sampled = WheelProfile(p).sample(0.1);
      benchmark::DoNotOptimize(sampled.z_mm.data());
    }
  }
  state.counters["profiles"] = static_cast<double>(all.size());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(all.size()));
}
BENCHMARK(BM_GenerateAndSampleAllVariants)->Unit(benchmark::kMillisecond);

/// One evaluation z, tan at a varying y of each family.
void BM_EvaluateAt(benchmark::State& state) {
  const WheelProfile w({static_cast<WheelFamily>(state.range(0)), 28.0, 30.0});
  double y = -70.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(w.at(y));
    y += 0.0137;
    if (y > 70.0) {
      y = -70.0;
    }
  }
}
BENCHMARK(BM_EvaluateAt)->Arg(0)->Arg(1)->Arg(2);

void BM_RailHeadsPlaced(benchmark::State& state) {
  for (auto _ : state) {
    for (const RailSection s : {RailSection::k60E1, RailSection::k54E1}) {
      for (const RailInclination i :
           {RailInclination::kNone, RailInclination::k1in20, RailInclination::k1in40}) {
        RailProfile r(s, i, TrackPlacement{});
        benchmark::DoNotOptimize(r);
      }
    }
  }
}
BENCHMARK(BM_RailHeadsPlaced)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace tread::profile

BENCHMARK_MAIN();
