#pragma once
// What the `tread contact` and `tread conicity` commands share: the wheel/rail/wheelset settings as
// plain values and their turning into a RigidContact (profiles read, smoothed, rail placed).

#include <optional>
#include <string>
#include <vector>

#include "contact/rail_placement.hpp"
#include "contact/rigid_contact.hpp"
#include "profile/profile_file.hpp"
#include "profile/wheel_profile.hpp"

namespace tread::contact {

/// Reading options whose hints name the command line's options with `prefix` ("--wheel-").
inline profile::ProfileReadOptions read_options(const char* prefix) {
  profile::ProfileReadOptions o;
  o.option_prefix = prefix;
  return o;
}

struct ContactSetup {
  std::string wheel_spec;        ///< built-in wheel, e.g. "S1002:h=28,e=32.5,slope=1:15"
  std::string wheel_file;        ///< left wheel (and right unless wheel_right_file) file
  std::string wheel_right_file;  ///< optional right wheel file
  std::string rail_spec;         ///< built-in rail head, e.g. "60E1"
  std::string rail_file;         ///< rail file (CSV, .prr, .ban)
  /// How the wheel files (both) and the rail file are read (format, z down, mirror y; see
  /// profile_file.hpp).
  profile::ProfileReadOptions wheel_read = read_options("--wheel-");
  profile::ProfileReadOptions rail_read = read_options("--rail-");
  std::string rail_frame =
      "upright";              ///< "upright" (own frame, placed by cant and gauge) | "track"
  std::string cant = "1:40";  ///< rail inclination: "1:N", "none" or "0"
  double gauge_mm = 1435.0;
  double back_to_back_mm = 1360.0;
  double r0_mm = 460.0;
  std::optional<double> r0_right_mm;
  double smooth_half_window_mm = 0.0;  ///< local quadratic smoothing of the profiles (0 = off)
};

/// EN 15302's e0: half the lateral distance between the two wheels' taping lines, b2b / 2 + 70 mm
/// (750 mm for the standard back-to-back of 1360 mm). The Annex B wavelength and the creepages'
/// yaw lever use it.
double half_contact_base_mm(const ContactSetup& setup);

/// The wheelset's nominal rolling radius r0: the mean of the two wheels' (--r0 and --r0-right).
double nominal_r0_mm(const ContactSetup& setup);

/// Parses a wheel/rail pair given as one "key=value,..." spec (the node's and the demo's
/// --wheelset-profile, the LUT generator's pairs) into a ContactSetup. The keys are those of the
/// `tread contact` options: wheel, wheel-file, wheel-right-file, rail, rail-file, rail-frame, cant,
/// gauge, b2b, r0, r0-right. Throws std::invalid_argument naming the item.
ContactSetup parse_wheelset_profile(const std::string& spec);

/// A built-in wheel: "S1002", "EPS" or "1/40", optionally ":h=28,e=32.5,slope=1:15,width=140,
/// chamfer=1". Throws std::invalid_argument naming the bad part.
profile::WheelParameters parse_wheel_spec(const std::string& spec);

/// "1:40" -> atan(1/40); "none" or "0" -> 0. Throws std::invalid_argument otherwise, and for 1:N
/// with N below 5 (steeper than any rail is canted).
double parse_cant_rad(const std::string& text);

/// Throws std::invalid_argument naming the option if a dimension cannot be a wheelset's: --r0 or
/// --r0-right outside 100 … 1500 mm, --gauge or --b2b ≤ 0, and (rails placed by --gauge) --b2b
/// not below --gauge or, for a built-in wheel, b2b + 2·e not below it (no lateral play).
/// build_contact calls it first.
void check_wheelset_dimensions(const ContactSetup& setup);

/// Reads the profiles (profile::read_profile_file) and builds the contact. Throws
/// std::runtime_error / std::invalid_argument with a message naming the offending option or file.
/// `warnings` receives what the file reader changed or assumed, and a warning when a rail file
/// whose head is inclined already is inclined again by `cant`.
RigidContact build_contact(const ContactSetup& setup, std::vector<std::string>& warnings);
/// The same, the warnings dropped.
RigidContact build_contact(const ContactSetup& setup);

/// Smallest |y| of the table whose contact lies at the end of a profile (see
/// WheelContact::at_profile_end), if any: the results from there on are not meaningful.
std::optional<double> first_profile_end_abs_y(const ContactTable& table);

}  // namespace tread::contact
