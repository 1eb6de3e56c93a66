#pragma once
// Profile files as CSV, in two dialects (one reader):
// - strict (what tread writes): a header naming the columns `y_mm` and `z_mm` (other columns such
//   as `tan` are allowed and ignored), comma separated, one point per line;
// - tolerant (what users bring): the header is optional (when there is one and it names y_mm and
//   z_mm, those columns are used; otherwise the first two numeric columns are y and z, and one
//   non-numeric line before the data is taken as a header), separators comma, semicolon, tab or
//   spaces.
// Both skip `#` comment lines and blank lines. Wheel profiles use the wheel convention, rail
// profiles their own upright frame or the track frame (z up); the file does not say which, the
// caller does.

#include <filesystem>
#include <iosfwd>
#include <span>
#include <string>

#include "profile/sampled_profile.hpp"

namespace tread::profile {

enum class CsvDialect { kStrict, kTolerant };

/// The points of a profile CSV in file order, y not checked for monotonicity (for
/// read_profile_file, which cleans measured profiles). Throws std::runtime_error
/// "source:line: message" for a missing column, a bad number, a non-finite value or fewer than 2
/// points.
ProfilePoints read_profile_csv_points(std::istream& in, const std::string& source_name,
                                      CsvDialect dialect);

/// Reads a profile CSV. Points may be in increasing or decreasing y order (returned increasing).
/// Throws std::runtime_error "file:line: message" for a missing file, a missing column, a bad
/// number, a non-finite value, a y that is not strictly monotonic, or fewer than 2 points.
/// The profile's name is the file stem.
SampledProfile read_profile_csv(const std::filesystem::path& path,
                                CsvDialect dialect = CsvDialect::kStrict);

/// The same from a stream; `source_name` is used in messages and as the profile name.
SampledProfile read_profile_csv(std::istream& in, const std::string& source_name,
                                CsvDialect dialect = CsvDialect::kStrict);

/// Writes `y_mm,z_mm` (and `tan` if `tan` is not empty; it must have the profile's size), with
/// `decimals` digits after the point, in the profile's (increasing) order.
void write_profile_csv(std::ostream& out, const SampledProfile& profile,
                       std::span<const double> tan = {}, int decimals = 6);

/// Throws std::invalid_argument naming the profile when sizes differ, there are fewer than 2
/// points, a value is not finite or y is not strictly increasing.
void check_sampled_profile(const SampledProfile& profile);

}  // namespace tread::profile
