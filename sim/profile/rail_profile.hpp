#pragma once
// Rail heads 60E1 and 54E1 (EN 13674-1) built from their arcs: R300 crown, R80 shoulders, R13 gauge
// corners, 1:20 sides (the rail definitions in data/PROVENANCE.md §3), upright or inclined 1:20 /
// 1:40 toward the track centre, and placed into the track frame.
//
// Upright frame: x (here y) lateral, < 0 on the gauge side, z up, origin on the rail axis at the
// top of the upright head. Inclination rotates the head about that origin toward the track centre.
// Track frame (as the contact search uses it): y lateral from the running circle of the centred
// wheelset's wheel on this side (half_spacing_mm = b2b / 2 + 70 = 750 mm from the track centre),
// + toward the field side; the gauge point (innermost head point from the top of rail down to
// gauge_depth_mm) at gauge / 2 from the track centre; z up with the top of rail at z = 0. One
// profile serves both rails (mirrored).
//
// The profile is a function z(y) from the lowest gauge-side point where the head is still a
// function (for 1:20 the gauge side turns vertical at the end of the R13 corner) to the field side,
// the sides reaching 20 mm below the upright top.

#include <string>
#include <vector>

#include "profile/sampled_profile.hpp"
#include "profile/wheel_profile.hpp"

namespace tread::profile {

enum class RailSection { k60E1, k54E1 };
enum class RailInclination { kNone, k1in20, k1in40 };

/// 0, atan(1/20), atan(1/40).
double inclination_rad(RailInclination inclination);
const char* to_string(RailSection section);
const char* to_string(RailInclination inclination);
/// "60E1"/"UIC60", "54E1"/"UIC54"; "none"/"0", "1:20", "1:40". Throw std::invalid_argument.
RailSection parse_rail_section(const std::string& text);
RailInclination parse_rail_inclination(const std::string& text);

struct TrackPlacement {
  double gauge_mm = 1435.0;
  double half_spacing_mm = 750.0;  ///< running circle from the track centre: b2b / 2 + 70
  double gauge_depth_mm = 14.0;    ///< gauge point band below the top of rail
};

class RailProfile {
 public:
  /// The head in the upright frame, rotated by the inclination about the frame's origin.
  RailProfile(RailSection section, RailInclination inclination);
  /// The head inclined and placed into the track frame.
  RailProfile(RailSection section, RailInclination inclination, const TrackPlacement& placement);

  std::string name() const;
  double y_min_mm() const { return pieces_.front().y0; }
  double y_max_mm() const { return pieces_.back().y1; }
  /// z and dz/dy at y ∈ [y_min, y_max]; throws std::out_of_range outside.
  ProfileValue at(double y_mm) const;
  /// The highest point (top of rail).
  double top_y_mm() const { return top_y_; }
  double top_z_mm() const { return top_z_; }
  /// The innermost (smallest y) point no more than depth_mm below the top of rail.
  double gauge_point_y_mm(double depth_mm = 14.0) const;
  /// Samples from y_min to y_max at `step_mm` (both ends included).
  SampledProfile sample(double step_mm) const;

  struct Piece {
    std::string name;
    bool arc = false;
    double y0 = 0.0, y1 = 0.0;
    double cy = 0.0, cz = 0.0, r = 0.0;  // arc: upper half of the circle
    double z0 = 0.0, slope = 0.0;        // line: z = z0 + slope (y - y0)
  };

 private:
  void build(RailSection section, RailInclination inclination);
  void translate(double dy, double dz);
  ProfileValue piece_at(const Piece& p, double y) const;
  RailSection section_;
  RailInclination inclination_;
  bool track_frame_ = false;
  std::vector<Piece> pieces_;
  double top_y_ = 0.0;
  double top_z_ = 0.0;
};

}  // namespace tread::profile
