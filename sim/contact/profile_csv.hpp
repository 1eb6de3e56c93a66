#pragma once
// The contact tools read profile CSV files in the tolerant dialect of profile::read_profile_csv
// (optional header, comma, semicolon, tab or space separated); this is that reader, kept under its
// old name for the contact area. User files go through profile::read_profile_file.

#include <filesystem>

#include "profile/profile_csv.hpp"
#include "profile/sampled_profile.hpp"

namespace tread::contact {

/// profile::read_profile_csv(file, CsvDialect::kTolerant): a descending y column is reversed;
/// throws std::runtime_error "file:line: message" for unreadable files, malformed rows and y that
/// is not strictly monotonic.
inline profile::SampledProfile read_profile_csv(const std::filesystem::path& file) {
  return profile::read_profile_csv(file, profile::CsvDialect::kTolerant);
}

}  // namespace tread::contact
