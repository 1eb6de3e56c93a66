#pragma once
// Rigid wheel–rail contact without wheelset roll and without penetration: for a lateral wheelset
// displacement y, the contact point of each wheel is the global minimum of the vertical gap between
// wheel and rail over their common lateral range. Both profiles are piecewise linear between their
// samples, so the gap's global minimum lies at a sample of one of them; every sample is examined
// (no local descent), which finds two-point contact and the jumps between contact zones. The
// minimum is then refined by a local least-squares parabola of the gap (robust against measured
// noise).
//
// Frames: wheel profile y from the taping line, + toward the field side, z = radius increase; rail
// profile in the track frame (see rail_placement.hpp), z up; one rail profile serves both rails
// (mirrored). Wheelset y > 0 moves it toward the left rail; delta_r = r_left - r_right.
// Contact angle gamma = atan(-dz/dy) of the wheel profile at the contact point: positive where the
// radius grows toward the flange (tread and flange of a normal wheel), the same sign on both
// wheels.

#include <cstddef>
#include <vector>

#include "contact/profile_function.hpp"
#include "contact/rail_placement.hpp"
#include "profile/sampled_profile.hpp"

namespace tread::contact {

struct WheelsetSetup {
  double back_to_back_mm = 1360.0;
  double r0_left_mm = 460.0;   ///< rolling radius at the taping line, left wheel
  double r0_right_mm = 460.0;  ///< right wheel
};

struct SearchSettings {
  double refine_half_window_mm = 0.1;  ///< parabola fit of the gap around the minimum; 0 = off
  double slope_half_window_mm = 0.05;  ///< least-squares window for the contact angle
  double second_contact_min_distance_mm = 1.0;  ///< separation of a second (two-point) contact
  double curvature_half_window_mm = 0.5;        ///< least-squares window for profile curvatures
};

/// Where a contact point lies on the wheel and what the wheel and rail look like there.
struct ContactPoint {
  double y_wheel_mm = 0.0;                         ///< position on the wheel profile (wheel frame)
  double r_mm = 0.0;                               ///< rolling radius r0 + z_wheel
  double gamma_rad = 0.0;                          ///< contact angle
  double lateral_relative_curvature_per_mm = 0.0;  ///< as WheelContact's
};

struct WheelContact {
  double y_wheel_mm = 0.0;  ///< contact position on the wheel profile (wheel frame)
  double y_rail_mm = 0.0;   ///< contact position on the rail profile (track frame of its side)
  double r_mm = 0.0;        ///< rolling radius r0 + z_wheel
  double gamma_rad = 0.0;   ///< contact angle, see above
  /// Lateral relative curvature of the two surfaces at the contact, in the contact plane (normal
  /// to the contact normal): the gap between wheel and rail opens as (kappa / 2) s^2 along the
  /// contact tangent. > 0 for a Hertzian contact; <= 0 conformal. From the profiles' second
  /// derivatives: kappa = -(z_wheel'' + z_rail'') cos^3(gamma).
  double lateral_relative_curvature_per_mm = 0.0;
  /// Vertical gap (mm) at the best other local minimum at least second_contact_min_distance_mm
  /// away; near 0 means two-point contact; +inf when there is none.
  double second_gap_mm = 0.0;
  double y_rail_second_mm = 0.0;  ///< where that second candidate is (track frame)
  ContactPoint second;            ///< that candidate's geometry (when second_gap_mm is finite)
  /// The contact lies at the end of the wheel's or the rail's sampled range: the profiles do not
  /// cover this displacement (e.g. flange contact below the end of a rail head table).
  bool at_profile_end = false;
};

struct ContactState {
  double y_mm = 0.0;
  WheelContact left;
  WheelContact right;
  double delta_r_mm() const { return left.r_mm - right.r_mm; }
};

/// The contact table over a uniform y grid as plain vectors (input of the lut/ generator).
struct ContactTable {
  double y_first_mm = 0.0;
  double y_step_mm = 0.0;
  std::vector<double> y_mm;
  std::vector<double> r_left_mm;
  std::vector<double> r_right_mm;
  std::vector<double> delta_r_mm;
  std::vector<double> gamma_left_rad;
  std::vector<double> gamma_right_rad;
  std::vector<double> yc_left_mm;  ///< contact position on the left wheel (wheel frame)
  std::vector<double> yc_right_mm;
  std::vector<double> yr_left_mm;  ///< contact position on the left rail (track frame)
  std::vector<double> yr_right_mm;
  std::vector<double> second_gap_left_mm;
  std::vector<double> second_gap_right_mm;
  std::vector<bool> at_profile_end;  ///< either wheel's contact at the end of a profile
};

class RigidContact {
 public:
  /// rail_track: rail head in the track frame (place_rail() for an upright head). Throws
  /// std::invalid_argument for bad profiles.
  RigidContact(const profile::SampledProfile& wheel_left,
               const profile::SampledProfile& wheel_right,
               const profile::SampledProfile& rail_track, const WheelsetSetup& setup,
               const SearchSettings& settings = {});

  /// Contact of both wheels at wheelset displacement y_mm. Throws std::domain_error when the
  /// wheel and rail no longer overlap laterally.
  ContactState at(double y_mm) const;

  /// at() on y = y_min, y_min + step, ... up to y_max (inclusive, within step/1000).
  ContactTable table(double y_min_mm, double y_max_mm, double step_mm) const;

  const WheelsetSetup& setup() const { return setup_; }

 private:
  WheelContact solve(const ProfileFunction& wheel, double shift_mm, double r0_mm) const;
  ContactPoint describe(const ProfileFunction& wheel, double y_rail_mm, double shift_mm,
                        double r0_mm) const;

  ProfileFunction wheel_left_;
  ProfileFunction wheel_right_;
  ProfileFunction rail_;
  WheelsetSetup setup_;
  SearchSettings settings_;
};

/// The contact table of one wheel/rail pair over y_min, y_min + step, ... y_max: the entry point
/// for the lut/ generator (RigidContact(...).table(...) with default search settings).
ContactTable contact_table(const profile::SampledProfile& wheel_left,
                           const profile::SampledProfile& wheel_right,
                           const profile::SampledProfile& rail_track, const WheelsetSetup& setup,
                           double y_min_mm, double y_max_mm, double step_mm);

}  // namespace tread::contact
