#pragma once
// A profile as sampled points, the common currency of profile construction, files and contact
// search. Wheel profiles use the wheel convention (y from the taping line, + toward the field side;
// z = radius increase, + toward the flange tip); rail profiles their own upright frame or the track
// frame (z up).

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace tread::profile {

struct SampledProfile {
  std::string name;
  std::vector<double> y_mm;  ///< strictly increasing
  std::vector<double> z_mm;  ///< same size as y_mm
};

/// Points as a file gives them: in file order, y not necessarily monotonic (measured profiles,
/// undercut rails), with the line each point came from for messages.
struct ProfilePoints {
  std::string name;
  std::vector<double> y_mm;
  std::vector<double> z_mm;
  std::vector<std::size_t> line;  ///< same size as y_mm
  /// What a CSV header named and the reader used: ("y", "column 'y_m', m → mm"), ...
  std::vector<std::pair<std::string, std::string>> header;
};

}  // namespace tread::profile
