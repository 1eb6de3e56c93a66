#pragma once
// MiniProf (Greenwood Engineering) profile files as exported in text form: wheel `.whl` and rail
// `.ban`. What is read (the format as public converters describe it, e.g. GENSYS's
// conv_miniprof2kpf: "the header lines, then after the first empty line the measured data", `#`
// comment lines):
// - header lines `Key=Value` up to the first blank line or the first line of numbers. The key
//   used is `ColumnDef` (the column names of the point list, e.g. `X,Y` or `X, Y, Flags`: the
//   columns named X and Y are taken; without it the first two columns). A point count given as
//   `Points=N` or `XYPoints=N` is checked against the list. `XOffset`/`YOffset` (mm; any case of
//   the O) are added to every X / Y, as the instrument's software does when it exports an
//   aligned profile with its shift kept apart. Every header line is kept as (key, value) for the
//   caller to show; a line without '=' (older exports open with plain words) is kept with an
//   empty value. Lines starting with '#', '!', '%' or '"' are comments.
// - the point list: X lateral, Y vertical, both mm, separated by spaces, tabs, commas or
//   semicolons; in measurement order (y need not be monotonic).
// The conversion to this project's convention is read_profile_file's (profile_file.hpp): a wheel's
// X is measured from the flange back (inner face of the wheel) toward the field side with the
// flange pointing down (Y up), so y = X - 70 (taping line), z = -Y referred to the taping line;
// a rail's X, Y are its upright frame (y = X, z = Y).

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "profile/sampled_profile.hpp"

namespace tread::profile {

struct MiniProfFile {
  /// Header lines as (key, value), in file order.
  std::vector<std::pair<std::string, std::string>> header;
  /// X + XOffset as y_mm, Y + YOffset as z_mm, in file order, with their lines.
  ProfilePoints points;
  /// The header's XOffset / YOffset (mm, 0 when absent) and their lines (0 when absent); already
  /// added to the points.
  double x_offset_mm = 0.0;
  double y_offset_mm = 0.0;
  std::size_t x_offset_line = 0;
  std::size_t y_offset_line = 0;
};

/// Throws std::runtime_error "file:line: message" for a header key after the points, a bad
/// offset, a ColumnDef without X and Y, a bad number, a short row or fewer than 2 points.
MiniProfFile read_miniprof(std::istream& in, const std::string& source_name);
MiniProfFile read_miniprof(const std::filesystem::path& path);

}  // namespace tread::profile
