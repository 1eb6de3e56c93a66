#pragma once
// A scripted tyre test rig: prescribed slip, load and displacement sweeps per channel, as a tyre
// test machine or a HIL bench drives them. (The vehicle-model rig that derives slip from wheel
// speeds and body motion is a separate model.)
//   wheel 0: κ triangle sweep ±0.3 at Fz 4 kN        wheel 1: α triangle sweep ±0.2 rad at 4 kN
//   wheel 2: combined κ and α sweeps at 4 kN          wheel 3: Fz sweep 1…7 kN at α = 0.05 rad
//   wheelset j: lateral displacement 8 mm · sin(2π t / 2 s + j·π/2)

#include "proto/data_model.hpp"

namespace tread::host {

struct ScriptedRigSettings {
  double sweep_period_s{4.0};
  double vx_mps{16.7};
  double fz_n{4000.0};
};

class ScriptedRig {
 public:
  explicit ScriptedRig(const ScriptedRigSettings& settings = {}) : settings_(settings) {}
  /// The rig's inputs at time `t_s` (all four wheels and both wheelsets).
  [[nodiscard]] proto::RigData inputs_at(double t_s, std::uint32_t cycle) const;

 private:
  ScriptedRigSettings settings_;
};

}  // namespace tread::host
