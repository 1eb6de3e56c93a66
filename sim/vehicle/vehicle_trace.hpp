#pragma once
// One run of the vehicle model, sample by sample: what the manoeuvres evaluate their results on.

#include <array>
#include <vector>

#include "vehicle/vehicle_model.hpp"

namespace tread::vehicle {

/// One step: the state at t_s, the controls and the wheel inputs computed from it, and the forces
/// the tyre returned for those inputs (which the step from t_s to t_s + dt used).
struct TraceSample {
  double t_s{0.0};
  VehicleState state;
  Controls controls;
  std::array<WheelKinematics, kWheelCount> inputs{};
  std::array<WheelForces, kWheelCount> forces{};
};

using Trace = std::vector<TraceSample>;

}  // namespace tread::vehicle
