#pragma once
// A small reader for profile CSV files (`y_mm,z_mm`, '#' comments, optional header row; comma,
// semicolon, tab or space separated). Lets the contact tools read the EN 15302 reference files and
// user profiles; the profile area's general readers (.prw/.prr) live in sim/profile/.

#include <filesystem>

#include "profile/sampled_profile.hpp"

namespace tread::contact {

/// Reads the first two numeric columns as y and z. A descending y column is reversed. Throws
/// std::runtime_error with "file:line: message" for unreadable files, malformed rows and y that is
/// not strictly monotonic.
profile::SampledProfile read_profile_csv(const std::filesystem::path& file);

}  // namespace tread::contact
