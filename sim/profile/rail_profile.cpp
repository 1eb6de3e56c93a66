#include "profile/rail_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace tread::profile {

namespace {

struct Vec {
  double y;
  double z;
};

Vec rotate(Vec p, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  return {c * p.y - s * p.z, s * p.y + c * p.z};
}

struct HeadDefinition {
  double crown_r;
  double shoulder_r;
  Vec shoulder_centre;  // field side (y > 0)
  double corner_r;
  Vec corner_centre;  // field side
  double side_slope;  // 1:20 from vertical
};

HeadDefinition head(RailSection section) {
  switch (section) {
    case RailSection::k60E1:
      return {300.0, 80.0, {7.500533, -80.127896}, 13.0, {23.016030, -14.949147}, 1.0 / 20.0};
    case RailSection::k54E1:
      return {300.0, 80.0, {7.342133, -80.122550}, 13.0, {22.016278, -14.749241}, 1.0 / 20.0};
  }
  return {};
}

constexpr double kSideDepth_mm = 20.0;

}  // namespace

double inclination_rad(RailInclination inclination) {
  switch (inclination) {
    case RailInclination::kNone:
      return 0.0;
    case RailInclination::k1in20:
      return std::atan(1.0 / 20.0);
    case RailInclination::k1in40:
      return std::atan(1.0 / 40.0);
  }
  return 0.0;
}

const char* to_string(RailSection section) {
  return section == RailSection::k60E1 ? "60E1" : "54E1";
}

const char* to_string(RailInclination inclination) {
  switch (inclination) {
    case RailInclination::kNone:
      return "upright";
    case RailInclination::k1in20:
      return "1:20";
    case RailInclination::k1in40:
      return "1:40";
  }
  return "?";
}

RailSection parse_rail_section(const std::string& text) {
  if (text == "60E1" || text == "UIC60") {
    return RailSection::k60E1;
  }
  if (text == "54E1" || text == "UIC54") {
    return RailSection::k54E1;
  }
  throw std::invalid_argument("unknown rail '" + text + "' (expected 60E1 or 54E1)");
}

RailInclination parse_rail_inclination(const std::string& text) {
  if (text == "none" || text == "0" || text == "upright") {
    return RailInclination::kNone;
  }
  if (text == "1:20" || text == "1/20") {
    return RailInclination::k1in20;
  }
  if (text == "1:40" || text == "1/40") {
    return RailInclination::k1in40;
  }
  throw std::invalid_argument("unknown rail inclination '" + text +
                              "' (expected none, 1:20 or 1:40)");
}

RailProfile::RailProfile(RailSection section, RailInclination inclination)
    : section_(section), inclination_(inclination) {
  build(section, inclination);
}

RailProfile::RailProfile(RailSection section, RailInclination inclination,
                         const TrackPlacement& placement)
    : section_(section), inclination_(inclination), track_frame_(true) {
  build(section, inclination);
  const double gp = gauge_point_y_mm(placement.gauge_depth_mm);
  translate(0.5 * placement.gauge_mm - placement.half_spacing_mm - gp, -top_z_);
}

void RailProfile::build(RailSection section, RailInclination inclination) {
  const HeadDefinition d = head(section);
  const double theta = inclination_rad(inclination);
  // Tangent points in the upright frame, field side (y > 0); the gauge side mirrors them.
  const Vec crown_c{0.0, -d.crown_r};
  const auto towards = [](Vec from, Vec to, double length) {
    const double dy = to.y - from.y;
    const double dz = to.z - from.z;
    const double n = std::hypot(dy, dz);
    return Vec{from.y + length * dy / n, from.z + length * dz / n};
  };
  const Vec crown_shoulder = towards(crown_c, d.shoulder_centre, d.crown_r);
  const Vec shoulder_corner = towards(d.shoulder_centre, d.corner_centre, d.shoulder_r);
  const double q = std::sqrt(1.0 + d.side_slope * d.side_slope);
  const Vec corner_side{d.corner_centre.y + d.corner_r / q,
                        d.corner_centre.z + d.corner_r * d.side_slope / q};
  const Vec side_end{corner_side.y + d.side_slope * (corner_side.z + kSideDepth_mm),
                     -kSideDepth_mm};
  const auto mirror = [](Vec p) { return Vec{-p.y, p.z}; };

  // Rotate everything (toward the track centre: the top moves to -y).
  const auto r = [theta](Vec p) { return rotate(p, theta); };
  pieces_.clear();
  const auto add_line = [&](const char* name, Vec a, Vec b) {
    a = r(a);
    b = r(b);
    if (!(b.y - a.y > 1e-9 * std::fabs(b.z - a.z) + 1e-12)) {
      return;  // vertical or overhanging after the rotation: not part of z(y)
    }
    Piece p;
    p.name = name;
    p.y0 = a.y;
    p.y1 = b.y;
    p.z0 = a.z;
    p.slope = (b.z - a.z) / (b.y - a.y);
    pieces_.push_back(p);
  };
  const auto add_arc = [&](const char* name, Vec c, double radius, Vec a, Vec b) {
    c = r(c);
    a = r(a);
    b = r(b);
    Piece p;
    p.name = name;
    p.arc = true;
    p.y0 = pieces_.empty() ? a.y : pieces_.back().y1;
    p.y1 = b.y;
    p.cy = c.y;
    p.cz = c.z;
    p.r = radius;
    pieces_.push_back(p);
  };
  add_line("gauge side 1:20", mirror(side_end), mirror(corner_side));
  add_arc("gauge corner R13", mirror(d.corner_centre), d.corner_r, mirror(corner_side),
          mirror(shoulder_corner));
  add_arc("gauge shoulder R80", mirror(d.shoulder_centre), d.shoulder_r, mirror(shoulder_corner),
          mirror(crown_shoulder));
  add_arc("crown R300", crown_c, d.crown_r, mirror(crown_shoulder), crown_shoulder);
  add_arc("field shoulder R80", d.shoulder_centre, d.shoulder_r, crown_shoulder, shoulder_corner);
  add_arc("field corner R13", d.corner_centre, d.corner_r, shoulder_corner, corner_side);
  add_line("field side 1:20", corner_side, side_end);
  pieces_.back().y0 = pieces_[pieces_.size() - 2].y1;
  // Top of rail: the highest arc apex inside its piece (the crown up to 1:51, then the field
  // shoulder: at 1:20 the top is on the R80).
  top_z_ = -std::numeric_limits<double>::infinity();
  for (const Piece& p : pieces_) {
    if (p.arc && p.cy >= p.y0 && p.cy <= p.y1 && p.cz + p.r > top_z_) {
      top_z_ = p.cz + p.r;
      top_y_ = p.cy;
    }
  }
}

void RailProfile::translate(double dy, double dz) {
  for (Piece& p : pieces_) {
    p.y0 += dy;
    p.y1 += dy;
    p.cy += dy;
    p.cz += dz;
    p.z0 += dz;
  }
  top_y_ += dy;
  top_z_ += dz;
}

std::string RailProfile::name() const {
  std::ostringstream o;
  o << to_string(section_) << ' ' << to_string(inclination_)
    << (track_frame_ ? " (track frame)" : " (rail frame)");
  return o.str();
}

ProfileValue RailProfile::piece_at(const Piece& p, double y) const {
  if (!p.arc) {
    return {p.z0 + p.slope * (y - p.y0), p.slope};
  }
  const double dy = y - p.cy;
  const double root = std::sqrt(std::max(0.0, p.r * p.r - dy * dy));
  const double tan = root > 0.0 ? -dy / root
                                : (dy < 0.0 ? std::numeric_limits<double>::infinity()
                                            : -std::numeric_limits<double>::infinity());
  return {p.cz + root, tan};
}

ProfileValue RailProfile::at(double y) const {
  if (!(y >= y_min_mm() - 1e-12 && y <= y_max_mm() + 1e-12)) {
    std::ostringstream msg;
    msg << name() << ": y = " << y << " mm is outside [" << y_min_mm() << ", " << y_max_mm() << "]";
    throw std::out_of_range(msg.str());
  }
  const auto it = std::lower_bound(pieces_.begin(), pieces_.end(), y,
                                   [](const Piece& p, double value) { return p.y1 < value; });
  return piece_at(it == pieces_.end() ? pieces_.back() : *it, y);
}

double RailProfile::gauge_point_y_mm(double depth_mm) const {
  const double level = top_z_ - depth_mm;
  double lo = y_min_mm();
  if (at(lo).z_mm >= level) {
    return lo;  // the head's function part ends above the band: its innermost point
  }
  double hi = top_y_;
  for (int i = 0; i < 200 && hi - lo > 1e-12; ++i) {
    const double mid = 0.5 * (lo + hi);
    (at(mid).z_mm >= level ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

SampledProfile RailProfile::sample(double step_mm) const {
  if (!(step_mm > 0.0)) {
    throw std::invalid_argument("sample step must be positive");
  }
  SampledProfile out;
  out.name = name();
  const auto n = static_cast<std::size_t>(std::floor((y_max_mm() - y_min_mm()) / step_mm + 1e-9));
  for (std::size_t i = 0; i <= n; ++i) {
    const double y = y_min_mm() + static_cast<double>(i) * step_mm;
    out.y_mm.push_back(y);
    out.z_mm.push_back(at(y).z_mm);
  }
  if (out.y_mm.back() < y_max_mm() - 1e-9) {
    out.y_mm.push_back(y_max_mm());
    out.z_mm.push_back(at(y_max_mm()).z_mm);
  }
  return out;
}

}  // namespace tread::profile
