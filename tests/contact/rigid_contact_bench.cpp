// Contact-table generation time: EN 15302 wheel A on rail A (0.01 mm profile samples: 13 500 wheel
// and 7 200 rail points), y in [-12, 12] mm at 0.1 mm (241 displacements, two wheels each), and
// one displacement alone.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>

#include "contact/profile_csv.hpp"
#include "contact/rigid_contact.hpp"
#include "golden_path.hpp"

namespace {

tread::contact::RigidContact make_contact() {
  const auto dir = tread::testing::test_data("rail/en15302");
  const auto wheel = tread::contact::read_profile_csv(dir / "WheelA.csv");
  const auto rail = tread::contact::read_profile_csv(dir / "RailA.csv");
  return tread::contact::RigidContact(wheel, wheel, rail, {1360.0, 460.0, 460.0});
}

void BM_ContactTable_pm12_step0_1(benchmark::State& state) {
  const auto contact = make_contact();
  for (auto _ : state) {
    auto table = contact.table(-12.0, 12.0, 0.1);
    benchmark::DoNotOptimize(table.delta_r_mm.data());
  }
  state.counters["rows"] = 241;
}
BENCHMARK(BM_ContactTable_pm12_step0_1)->Unit(benchmark::kMillisecond);

void BM_ContactAtOneDisplacement(benchmark::State& state) {
  const auto contact = make_contact();
  double y = 0.0;
  for (auto _ : state) {
    auto c = contact.at(y);
    benchmark::DoNotOptimize(c);
    y = y > 6.0 ? -6.0 : y + 0.37;
  }
}
BENCHMARK(BM_ContactAtOneDisplacement)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
