#pragma once
// The figures a vehicle-dynamics engineer reads off a tyre first, computed from its Magic Formula
// parameters (host side): at one load (FNOMIN by default), the file's own speed (LONGVL) and
// pressure, γ = 0, pure slip, in ISO-W axes.
//
//   peak μx    max |Fx| / Fz over κ ∈ [−1, 1] (drive and brake peaks reported separately)
//   peak μy    max |Fy| / Fz over α ∈ [−0.5, 0.5] rad
//              both within KPUMIN…KPUMAX and ALPMIN…ALPMAX where the limits are on
//   Kxκ        longitudinal slip stiffness at the free-rolling point (the model's BCDx, MFeval's
//              Kxk output; N per unit slip)
//   Kyα        cornering stiffness, the model's Kya with its sign turned so that a normal tyre
//              has Kyα > 0 (ISO-W gives Fy < 0 for α > 0, and MFeval reports Kya < 0), N/rad
//   t          pneumatic trail (the model's t, as MFeval reports it) at α = 0.5°, m
//   Re, Rl     effective rolling and loaded radius in free rolling (m)
// Peaks are taken on grids of 2001 points.

#include "mf/mf_options.hpp"
#include "mf/mf_parameters.hpp"

namespace tread::tyre {

struct MfTyreFigures {
  double fz_n = 0.0;
  double vx_mps = 0.0;
  double p_pa = 0.0;           ///< the pressure evaluated (the file's INFLPRES)
  double mux_drive = 0.0;      ///< max Fx / Fz for κ > 0
  double kappa_drive = 0.0;    ///< where it is reached
  double mux_brake = 0.0;      ///< max −Fx / Fz for κ < 0
  double kappa_brake = 0.0;    ///< where it is reached
  double muy = 0.0;            ///< max |Fy| / Fz
  double alpha_muy_rad = 0.0;  ///< where it is reached
  double kxk_n = 0.0;          ///< dFx/dκ at κ = 0
  double kya_nprad = 0.0;      ///< −dFy/dα at α = 0
  double trail_m = 0.0;        ///< pneumatic trail at α = 0.5°
  double re_m = 0.0;           ///< effective rolling radius, free rolling
  double rl_m = 0.0;           ///< loaded radius, free rolling
  bool finite = true;          ///< false if any evaluation gave a non-finite value
  /// With the limits on: whether the range KPUMIN…KPUMAX holds drive (κ > 0) and brake (κ < 0)
  /// slip at all, and whether a peak lies at an end of the tyre's range (the curve may rise
  /// beyond it, where the file says nothing).
  bool drive_in_range = true;
  bool brake_in_range = true;
  bool kappa_drive_at_limit = false;
  bool kappa_brake_at_limit = false;
  bool alpha_muy_at_limit = false;
};

/// The figures at `fz_n` (≤ 0: the file's FNOMIN) and `vx_mps` (≤ 0: LONGVL), `options` as
/// given (limits, side ...).
MfTyreFigures tyre_figures(const mf::MfParameters<double>& params, const mf::MfOptions& options,
                           double fz_n = 0.0, double vx_mps = 0.0);

}  // namespace tread::tyre
