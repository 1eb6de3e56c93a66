#pragma once
// A free wheelset on straight track in kinematic (Klingel) motion, driven by the rolling-radius
// difference the node answers for each lateral displacement:
//     dy/dt   = V psi
//     dpsi/dt = -V delta_r(y) / (2 e0 r0)
// y: lateral displacement of the wheelset (to the left), psi: yaw angle, V: forward speed, e0: half
// the lateral distance between the contact points, r0: nominal rolling radius. Integrated with the
// semi-implicit (symplectic) Euler step at the rig period, delta r held over the step, so the
// undamped oscillation neither grows nor decays numerically. And the analysis of the resulting
// motion: amplitude and wavelength from the zero crossings.

#include <span>

namespace tread::host {

struct WheelsetHuntingParams {
  double speed_mps{30.0};
  double e0_mm{750.0};
  double r0_mm{460.0};
};

class WheelsetHunting {
 public:
  WheelsetHunting() = default;
  WheelsetHunting(const WheelsetHuntingParams& params, double y0_mm, double yaw0_rad = 0.0)
      : params_(params), y_mm_(y0_mm), yaw_rad_(yaw0_rad) {}

  [[nodiscard]] double y_mm() const { return y_mm_; }
  [[nodiscard]] double yaw_rad() const { return yaw_rad_; }
  [[nodiscard]] double distance_m() const { return distance_m_; }
  [[nodiscard]] const WheelsetHuntingParams& params() const { return params_; }

  /// One step of dt_s with delta r (mm) at the current y held over the step.
  void step(double delta_r_mm, double dt_s);

 private:
  WheelsetHuntingParams params_{};
  double y_mm_{0.0};
  double yaw_rad_{0.0};
  double distance_m_{0.0};
};

struct HuntingAnalysis {
  bool valid{false};         ///< at least two full periods seen
  double centre_mm{0.0};     ///< (max + min) / 2
  double amplitude_mm{0.0};  ///< (max − min) / 2
  double period_s{0.0};      ///< mean time between upward crossings of the centre
  double wavelength_m{0.0};  ///< period × speed
  int periods{0};
};

/// Amplitude and wavelength of a sampled hunting motion y(t) at constant speed.
HuntingAnalysis analyse_hunting(std::span<const double> t_s, std::span<const double> y_mm,
                                double speed_mps);

}  // namespace tread::host
