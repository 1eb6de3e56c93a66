// The rig side's cost per cycle: the vehicle model's wheel_inputs() + step() (what runs besides
// the node's answers), and a whole manoeuvre in process with the Magic Formula in double.
#include <benchmark/benchmark.h>

#include <cmath>

#include "golden_path.hpp"
#include "tyre/mf_parameters_from_tir.hpp"
#include "vehicle/manoeuvre.hpp"
#include "vehicle/manoeuvre_runner.hpp"
#include "vehicle/vehicle_model.hpp"

namespace {

using namespace tread::vehicle;

void BM_VehicleModelCycle(benchmark::State& state) {
  VehicleParams p;
  VehicleModel model(p, straight_running_state(p, 20.0));
  std::array<WheelForces, kWheelCount> forces{};
  for (WheelForces& f : forces) f = {10.0, -200.0, 5.0};
  Controls c;
  c.steer_wheel_rad = 0.1;
  for (auto _ : state) {
    const auto in = model.wheel_inputs();
    benchmark::DoNotOptimize(in);
    model.step(forces, c, 1e-3);
  }
}
BENCHMARK(BM_VehicleModelCycle);

void BM_StepSteerInProcess(benchmark::State& state) {
  const auto tir =
      tread::tyre::load_mf_parameters(tread::testing::tyre_file("MagicFormula61_Parameters.tir"));
  VehicleParams p;
  p.wheel_radius_m = tir.params.unloaded_radius_m;
  const TyreFunction tyre = mf_tyre_function(tir.params);
  StepSteerOptions o;
  o.steer_wheel_rad = 0.33;
  StepSteerManoeuvre m(p, tyre, o);
  for (auto _ : state) {
    const ManoeuvreRun run = run_manoeuvre(m, p, tyre, 1e-3);
    benchmark::DoNotOptimize(run.final_state.x_m);
  }
  state.SetLabel("4 s at 1 kHz, Magic Formula in double on 4 wheels");
}
BENCHMARK(BM_StepSteerInProcess)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
