#pragma once
// One entry point for every profile file a user brings: CSV (y_mm,z_mm), SIMPACK/CONTACT
// .prw/.prr and MiniProf .whl/.ban. The file is read for a role (wheel or rail), checked against
// what its header says, turned into this project's convention (see sampled_profile.hpp) and
// returned with a list of warnings that say what was changed or assumed. Errors name the file
// (and the line where there is one).

#include <filesystem>
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
};

struct ProfileFile {
  SampledProfile profile;  ///< this project's convention, y strictly increasing, mm
  ProfileRole role = ProfileRole::kWheel;
  ProfileFormat format = ProfileFormat::kCsv;  ///< the format it was read as
  /// What was changed or assumed on reading, each naming the file; empty for a clean file.
  std::vector<std::string> warnings;
  /// Header fields the reader used, as (key, value), for `tread profile --input` to show.
  std::vector<std::pair<std::string, std::string>> header;
};

/// Reads `path` as a `role` profile. Throws std::runtime_error ("file:line: message" where there
/// is a line) for unreadable or malformed files and for a file whose header says it is the other
/// role.
ProfileFile read_profile_file(const std::filesystem::path& path, ProfileRole role,
                              const ProfileReadOptions& options = {});

}  // namespace tread::profile
