#include "rig/scripted_rig.hpp"

#include <cmath>
#include <numbers>

namespace tread::host {
namespace {

/// Triangle wave in [-1, 1] with the given period, starting at -1.
double triangle(double t, double period) {
  const double phase = std::fmod(t / period, 1.0);
  return phase < 0.5 ? -1.0 + 4.0 * phase : 3.0 - 4.0 * phase;
}

}  // namespace

proto::RigData ScriptedRig::inputs_at(double t_s, std::uint32_t cycle) const {
  const double p = settings_.sweep_period_s;
  const auto f = [](double v) { return static_cast<float>(v); };
  proto::RigData d;
  const float vx = f(settings_.vx_mps);
  const float fz = f(settings_.fz_n);
  d.wheels[0] = {f(0.3 * triangle(t_s, p)), 0.0F, 0.0F, fz, vx, 0.0F, false};
  d.wheels[1] = {0.0F, f(0.2 * triangle(t_s, p)), 0.0F, fz, vx, 0.0F, false};
  d.wheels[2] = {
      f(0.15 * triangle(t_s, p)), f(0.1 * triangle(t_s, p / 3.0)), 0.0F, fz, vx, 0.0F, false};
  d.wheels[3] = {0.0F, 0.05F, 0.0F, f(4000.0 + 3000.0 * triangle(t_s, p)), vx, 0.0F, false};
  for (std::size_t j = 0; j < proto::kMaxWheelsets; ++j) {
    const double phase =
        2.0 * std::numbers::pi * t_s / 2.0 + static_cast<double>(j) * std::numbers::pi / 2.0;
    d.wheelsets[j] = {f(8.0 * std::sin(phase)), 0.0F, false};
  }
  d.rig_cycle = cycle;
  return d;
}

}  // namespace tread::host
