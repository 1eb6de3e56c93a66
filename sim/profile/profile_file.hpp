#pragma once
// One entry point for every profile file a user brings: CSV (y_mm,z_mm, tolerant dialect), SIMPACK/
// CONTACT .prw/.prr and MiniProf .whl/.ban. The file is read for a role (wheel or rail), checked
// against what its header says, turned into this project's convention (see sampled_profile.hpp)
// and returned with a list of warnings that say what was changed or assumed. Errors name the file
// (and the line where there is one).
//
// Steps after the format's own reading (miniprof_profile.hpp, simpack_profile.hpp,
// profile_csv.hpp):
// 1. axes: z_down negates z, mirror_y negates y (the file's convention -> this project's).
// 2. the profile is a curve, not a function of y: measured points step back in y (noise, a few
//    0.001 mm), worn gauge faces and true rail drawings have vertical sides and undercuts. Only
//    the envelope the other body can touch matters: the max-z envelope for both roles (rail: the
//    upper envelope, z up; wheel: z = radius increase, so max z is the part nearest the rail).
//    The envelope is exact for the polyline (vertices, and crossings of segments between them);
//    a profile with y strictly monotonic is kept point for point. Points below the envelope are
//    dropped, with a warning per place: back-steps up to backstep_tolerance_mm are reported as
//    measurement noise, larger ones as a vertical side or undercut, with how much was hidden.
// 3. wheel: the flange must be on the -y side with z up toward its tip (else the error suggests
//    --wheel-mirror-y / --wheel-z-down), and y = 0 must be the taping line, 70 mm from the flange
//    back: the flange back (the first point of the envelope, where the flange's back flank has
//    become steep) is located and the profile shifted when it is more than origin_tolerance_mm
//    away from y = -70 (warning with the offset); a wheel whose flange back was not measured is
//    refused when its flange tip is far from an EN 13715 wheel's (y = -55 mm).
// 4. rail: the head's inclination in its file is measured from its symmetry (midpoints of
//    horizontal chords 1 to 10 mm below the top, iterated in the uncanted frame) and reported in
//    rail_inclination_rad (the contact tools warn when such a rail is canted again).
// 5. optional resampling on a uniform grid (resample_step_mm).

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "profile/sampled_profile.hpp"

namespace tread::profile {

enum class ProfileRole { kWheel, kRail };

enum class ProfileFormat { kAuto, kCsv, kSimpack, kMiniProf };

/// "wheel" / "rail".
const char* role_name(ProfileRole role);
/// "auto", "csv", "simpack", "miniprof".
const char* format_name(ProfileFormat format);
/// Parses the names above; throws std::invalid_argument naming the value otherwise.
ProfileFormat parse_profile_format(const std::string& text);

struct ProfileReadOptions {
  ProfileFormat format = ProfileFormat::kAuto;  ///< kAuto: by extension, then by content
  bool z_down = false;                          ///< the file's z points down (negated on reading)
  bool mirror_y = false;  ///< the file's y points the other way (negated on reading)
  /// Back-steps in y up to this are measurement noise (reported as such); larger ones are
  /// geometry (vertical sides, undercuts). Both are resolved by the max-z envelope.
  double backstep_tolerance_mm = 0.05;
  /// Wheels: locate the taping line by the flange back (70 mm from it) when y = 0 is more than
  /// origin_tolerance_mm away from it; false: only check and warn.
  bool locate_wheel_origin = true;
  double origin_tolerance_mm = 1.0;
  /// > 0: the cleaned profile is resampled (linear) on a uniform grid of this step.
  double resample_step_mm = 0.0;
  /// How the command line names z_down and mirror_y, for the hints of errors: "--" + "z-down" in
  /// `tread profile`, "--wheel-" and "--rail-" in the contact commands.
  std::string option_prefix = "--";
};

/// The distance of a wheel's taping line from its flange back (EN 13715).
inline constexpr double kTapingLineFromFlangeBack_mm = 70.0;

struct ProfileFile {
  SampledProfile profile;  ///< this project's convention, y strictly increasing, mm
  ProfileRole role = ProfileRole::kWheel;
  ProfileFormat format = ProfileFormat::kCsv;  ///< the format it was read as
  /// What was changed or assumed on reading, each naming the file; empty for a clean file.
  std::vector<std::string> warnings;
  /// Header fields the reader used, as (key, value), for `tread profile --input` to show.
  std::vector<std::pair<std::string, std::string>> header;
  std::size_t points_read = 0;    ///< points in the file (after a SIMPACK file's bounds)
  std::size_t points_hidden = 0;  ///< points dropped below the contact envelope
  double y_shift_mm = 0.0;        ///< added to y to put a wheel's taping line at y = 0
  /// A wheel's z at its taping line as the file has it (0 where it is 0): subtracted from z, so
  /// that z = 0 there, where the rolling radius r0 is.
  double taping_z_in_file_mm = 0.0;
  /// Rail: the head's inclination as given in the file (rad, + = top toward -y, the sense of a
  /// cant toward the track centre in the upright frame), when the head could be measured.
  std::optional<double> rail_inclination_rad;
};

/// Reads `path` as a `role` profile. Throws std::runtime_error ("file:line: message" where there
/// is a line) for unreadable or malformed files and for a file whose header says it is the other
/// role.
ProfileFile read_profile_file(const std::filesystem::path& path, ProfileRole role,
                              const ProfileReadOptions& options = {});

}  // namespace tread::profile
