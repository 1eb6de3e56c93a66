// ns per lookup of the generated tables (target ≤ 5 ns), float and fixed point, and the time to
// generate the default tables from the double definitions.
#include <benchmark/benchmark.h>

#include <vector>

#include "lut/lut_generator.hpp"
#include "lut/tread_lut.hpp"

namespace {

using namespace tread;

std::vector<float> displacements(float lo, float hi) {
  std::vector<float> y(1024);
  for (std::size_t i = 0; i < y.size(); ++i) {
    y[i] = lo + (hi - lo) * static_cast<float>((i * 7919U) % 1024U) / 1024.0F;
  }
  return y;
}

void BM_RadiusLookupF32(benchmark::State& state) {
  const lut::ProfileTable& t = lut::profiles()[0];
  const auto y = displacements(-40.0F, 40.0F);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(rail::lookup(t.f32, y[i++ & 1023U]));
  }
}
BENCHMARK(BM_RadiusLookupF32);

void BM_RadiusLookupQ(benchmark::State& state) {
  const lut::ProfileTable& t = lut::profiles()[0];
  std::vector<std::int32_t> y;
  for (const float v : displacements(-40.0F, 40.0F))
    y.push_back(static_cast<std::int32_t>(v * 1000.0F));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(rail::lookup(t.q, y[i++ & 1023U]));
  }
}
BENCHMARK(BM_RadiusLookupQ);

void BM_ContactLookupF32(benchmark::State& state) {
  const lut::ContactPairTable& t = lut::contact_pairs()[0];
  const auto y = displacements(-11.0F, 11.0F);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(rail::lookup(t.f32, y[i++ & 1023U]));
  }
}
BENCHMARK(BM_ContactLookupF32);

void BM_ContactLookupQ(benchmark::State& state) {
  const lut::ContactPairTable& t = lut::contact_pairs()[0];
  std::vector<std::int32_t> y;
  for (const float v : displacements(-11.0F, 11.0F))
    y.push_back(static_cast<std::int32_t>(v * 1000.0F));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(rail::lookup(t.q, y[i++ & 1023U]));
  }
}
BENCHMARK(BM_ContactLookupQ);

void BM_GenerateDefaultTables(benchmark::State& state) {
  for (auto _ : state) {
    std::vector<host::RadiusTableData> r;
    for (const char* p : {"S1002:h=28,e=32.5,slope=1:15", "S1002:h=28,e=32.5,slope=6.7",
                          "EPS:h=28,e=32.5", "1/40:h=28,e=32.5"}) {
      r.push_back(host::make_radius_table(p));
    }
    std::vector<host::ContactTableData> c;
    for (const char* p : {"wheel=S1002,rail=60E1,cant=1:40", "wheel=S1002,rail=60E1,cant=1:20"}) {
      c.push_back(host::make_contact_table(p));
    }
    benchmark::DoNotOptimize(host::write_lut_source(r, c));
  }
}
BENCHMARK(BM_GenerateDefaultTables)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
