#include "vehicle/manoeuvre_runner.hpp"

#include <cmath>

namespace tread::vehicle {

ManoeuvreRun run_manoeuvre(Manoeuvre& manoeuvre, const VehicleParams& params,
                           const TyreFunction& tyre, double dt_s) {
  ManoeuvreRun run;
  manoeuvre.reset();
  VehicleModel model(params, manoeuvre.initial_state());
  run.trace.reserve(static_cast<std::size_t>(std::ceil(manoeuvre.duration_s() / dt_s)) + 2);
  for (;;) {
    const double t_s = model.state().t_s;
    if (manoeuvre.finished(t_s, model.state())) break;
    TraceSample sample;
    sample.t_s = t_s;
    sample.state = model.state();
    sample.inputs = model.wheel_inputs();
    for (std::size_t i = 0; i < kWheelCount; ++i) sample.forces[i] = tyre(i, sample.inputs[i]);
    sample.controls = manoeuvre.controls(t_s, dt_s, model.state());
    model.step(sample.forces, sample.controls, dt_s);
    run.trace.push_back(sample);
  }
  // The final state as the last sample (no step is taken from it: its controls are zero).
  TraceSample last;
  last.t_s = model.state().t_s;
  last.state = model.state();
  last.inputs = model.wheel_inputs();
  for (std::size_t i = 0; i < kWheelCount; ++i) last.forces[i] = tyre(i, last.inputs[i]);
  run.trace.push_back(last);
  run.final_state = model.state();
  run.results = manoeuvre.results(run.trace);
  return run;
}

}  // namespace tread::vehicle
