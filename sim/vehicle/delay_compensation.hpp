#pragma once
// Forces that arrive a cycle late. Over CAN in periodic mode the node's answer to the inputs sent
// in cycle n reaches the rig in cycle n + 1, so the rig would step with forces computed for the
// previous inputs. The wheel spin + transient slip loop (ωn ≈ 300…400 rad/s, lightly damped)
// does not tolerate that at a 1 ms step: with a one-cycle delay its linearisation is unstable
// below about 25 m/s for the loads of a car, and the wheel settles into a limit cycle of κ
// (±0.006 at 80 km/h on the outer front wheel in a 4 m/s² turn, ±900 N of Fx). Without delay it
// is stable at every speed (see the tests).
//
// The correction adds the reference tyre model's change between the inputs the answer was
// computed for and the current ones:
//     F = F_node(sent) + F_ref(now) − F_ref(sent)
// exact to first order in the change of the inputs, so the node's answer still sets the level
// and the reference only carries it over the delay. With no delay (sent == now) it returns the
// node's answer unchanged.

#include <array>
#include <utility>

#include "vehicle/tyre_function.hpp"
#include "vehicle/vehicle_model.hpp"

namespace tread::vehicle {

class DelayCompensator {
 public:
  explicit DelayCompensator(TyreFunction reference) : reference_(std::move(reference)) {}

  /// The forces to step with now: `answered` came back for `sent`; `now` is wheel_inputs() of
  /// the current state.
  [[nodiscard]] std::array<WheelForces, kWheelCount> correct(
      const std::array<WheelForces, kWheelCount>& answered,
      const std::array<WheelKinematics, kWheelCount>& sent,
      const std::array<WheelKinematics, kWheelCount>& now) const;

 private:
  TyreFunction reference_;
};

}  // namespace tread::vehicle
