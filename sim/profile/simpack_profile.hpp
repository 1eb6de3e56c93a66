#pragma once
// SIMPACK rail–wheel profile files: .prw (wheel, header type 1) and .prr (rail, header type 0).
// The point list is the original data; the spline block's processing settings are applied on
// reading: units (units.len.f = user length per metre), shift.y/z, rotate (about x, angle unit
// units.ang.f), bounds (when min < max), mirror.y/z. SIMPACK's z points down in both profile
// frames, so on reading: wheel z = SIMPACK z (radius increase, + toward the flange tip), rail
// z = -SIMPACK z (height, up). y is kept (+ toward the field side in both).

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "profile/sampled_profile.hpp"

namespace tread::profile {

enum class SimpackProfileType { kRail = 0, kWheel = 1 };

struct SimpackProfile {
  SimpackProfileType type = SimpackProfileType::kWheel;
  std::string comment;     ///< the spline block's comment, if any
  SampledProfile profile;  ///< in this project's convention (see above), y increasing, mm
};

/// The same before the monotonicity check: points in file order (after the processing settings and
/// the z convention above), for read_profile_file, which cleans measured profiles.
struct SimpackPoints {
  SimpackProfileType type = SimpackProfileType::kWheel;
  std::string comment;
  ProfilePoints points;
  /// Settings the file gives that change SIMPACK's profile but not tread's (approx.smooth,
  /// inversion), and point.dist.min's dropped points: "file:line: ..." each.
  std::vector<std::string> notes;
};
SimpackPoints read_simpack_points(std::istream& in, const std::string& source_name);

/// Reads a .prw/.prr file (`!` comments, SIMPACK style, and `%` comments, CONTACT style). Throws
/// std::runtime_error "file:line: message" on a missing file, a missing header/point block, a bad
/// number, a bad setting, or points whose y (after processing) is not strictly monotonic.
SimpackProfile read_simpack_profile(const std::filesystem::path& path);
SimpackProfile read_simpack_profile(std::istream& in, const std::string& source_name);

/// Writes a SIMPACK profile (version 1, unit mm, no processing) in this project's convention
/// converted to SIMPACK's (rail z negated). `comment` goes into the spline block.
void write_simpack_profile(std::ostream& out, const SampledProfile& profile,
                           SimpackProfileType type, const std::string& comment = "");

}  // namespace tread::profile
