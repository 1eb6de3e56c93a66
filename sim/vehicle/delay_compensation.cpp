#include "vehicle/delay_compensation.hpp"

namespace tread::vehicle {

std::array<WheelForces, kWheelCount> DelayCompensator::correct(
    const std::array<WheelForces, kWheelCount>& answered,
    const std::array<WheelKinematics, kWheelCount>& sent,
    const std::array<WheelKinematics, kWheelCount>& now) const {
  std::array<WheelForces, kWheelCount> out = answered;
  for (std::size_t i = 0; i < kWheelCount; ++i) {
    const WheelForces at_now = reference_(i, now[i]);
    const WheelForces at_sent = reference_(i, sent[i]);
    out[i].fx_n += at_now.fx_n - at_sent.fx_n;
    out[i].fy_n += at_now.fy_n - at_sent.fy_n;
    out[i].mz_nm += at_now.mz_nm - at_sent.mz_nm;
  }
  return out;
}

}  // namespace tread::vehicle
