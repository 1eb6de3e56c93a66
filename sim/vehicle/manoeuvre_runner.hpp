#pragma once
// Runs a manoeuvre end to end against a tyre function, in process: each step
//   inputs = model.wheel_inputs(); forces = tyre(i, inputs[i]); controls = manoeuvre.controls(...);
//   model.step(forces, controls, dt)
// which is what the rig does over CAN with the node's answers in place of the tyre function.

#include "vehicle/manoeuvre.hpp"
#include "vehicle/tyre_function.hpp"
#include "vehicle/vehicle_trace.hpp"

namespace tread::vehicle {

struct ManoeuvreRun {
  /// One sample per step, then the final state as a last sample (its inputs and forces are
  /// evaluated, its controls are zero: no step is taken from it).
  Trace trace;
  std::vector<ManoeuvreResult> results;
  VehicleState final_state;
};

/// Resets the manoeuvre and runs it from its initial state until finished() at the step dt_s.
ManoeuvreRun run_manoeuvre(Manoeuvre& manoeuvre, const VehicleParams& params,
                           const TyreFunction& tyre, double dt_s = 1e-3);

}  // namespace tread::vehicle
