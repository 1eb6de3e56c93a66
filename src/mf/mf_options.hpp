#pragma once
// Options of a Magic Formula evaluation, after MFeval's three-digit useMode:
//   hundreds: 1 = input limits on (FZMAX, KPUMIN/KPUMAX, ALPMIN/ALPMAX, CAMMIN/CAMMAX,
//             PRESMIN/PRESMAX, low-speed model below VXLOW), 2 = off;
//   tens:     1 = alpha* = alpha (TNO), 2 = alpha* = tan(alpha)·sign(Vx), gamma* = sin(gamma)
//             (book);
//   units:    1 = combined slip without turn slip, 2 = with turn slip.

#include <cstdint>

#include "core/status.hpp"

namespace tread::mf {

/// The wheel the tyre is mounted on. `as_measured` evaluates the coefficients as the file gives
/// them (what MFeval does: it reads TYRESIDE and ignores it). `left`/`right` mirror the tyre
/// (y → −y: α, γ, φt change sign on the way in; Fy, Mx, Mz on the way out) when the mounted side
/// differs from the file's TYRESIDE.
enum class MountedSide : std::uint8_t { as_measured, left, right };

struct MfOptions {
  bool use_limits = true;       ///< useMode 1xx (true) / 2xx (false)
  bool use_alpha_star = false;  ///< useMode x2x
  bool use_turn_slip = false;   ///< useMode xx2
  MountedSide side = MountedSide::as_measured;
  /// Combined slip (MFeval, Adams USE_MODE 4). False: uncombined (Adams USE_MODE 3): Fx = Fx0,
  /// Fy = Fy0, Mz = Mz0 = −t0·Fy0(γ = 0) + Mzr0, as MFeval's calculateMz0.
  bool combined = true;
  /// Also compute the overturning and rolling resistance moments Mx and My. No other output
  /// depends on them; false leaves both 0, for a caller that does not use them (a table of Fx, Fy
  /// and Mz saves their atan, sin, cos and pow).
  bool moments_xy = true;
  /// Also compute Re, Rl, rho, contact patch, Cx/Cy/Cz and relaxation lengths. Forces and moments
  /// do not need them (except the turn-slip spin, which needs the rolling speed from Re).
  bool extras = true;
  /// With extras: only what the loaded radius needs (Re, ω, Rl, ρ, Cz); the contact patch, Cx/Cy
  /// and the relaxation lengths stay 0. For a real-time caller that sends Rl alone.
  bool extras_loaded_radius_only = false;
};

/// MFeval's useMode (111…222). Status::invalid_argument for any other number.
constexpr Result<MfOptions> options_from_use_mode(int use_mode) noexcept {
  Result<MfOptions> result;
  const int hundreds = use_mode / 100;
  const int tens = (use_mode / 10) % 10;
  const int units = use_mode % 10;
  if (use_mode < 100 || use_mode > 999 || hundreds < 1 || hundreds > 2 || tens < 1 || tens > 2 ||
      units < 1 || units > 2) {
    result.status = Status::invalid_argument;
    return result;
  }
  result.value.use_limits = hundreds == 1;
  result.value.use_alpha_star = tens == 2;
  result.value.use_turn_slip = units == 2;
  return result;
}

}  // namespace tread::mf
