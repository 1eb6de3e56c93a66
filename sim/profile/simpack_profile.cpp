#include "profile/simpack_profile.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "io/text_line.hpp"
#include "profile/profile_csv.hpp"

namespace tread::profile {

namespace {

/// The text before an unquoted '!' (SIMPACK's comment character) or '%' (CONTACT's).
std::string_view strip_comment(std::string_view s) {
  bool quoted = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\'') {
      quoted = !quoted;
    } else if ((s[i] == '!' || s[i] == '%') && !quoted) {
      return s.substr(0, i);
    }
  }
  return s;
}

/// A finite number filling the whole (trimmed) field.
bool parse_double(std::string_view text, double& value) {
  return host::text::parse_number_text(host::text::trim_blanks(text), value) &&
         std::isfinite(value);
}

struct Setting {
  std::string value;
  std::size_t line = 0;
};

struct RawPoint {
  double y;
  double z;
  std::size_t line;
};

/// The file as read, before any setting is applied: "block.key" → value, and the points as written.
struct SimpackBlocks {
  std::map<std::string, Setting> settings;  // "header.type", "spline.shift.y", ...
  std::vector<RawPoint> points;
  std::size_t last_line = 0;
};

/// Reads the header, spline and point blocks; fails on a line outside them, a point that is not
/// "y z [weight]", no header or fewer than two points.
SimpackBlocks read_blocks(std::istream& in, const std::string& source_name) {
  SimpackBlocks blocks;
  std::string block;  // "", "header", "spline", "point"
  bool saw_header = false;
  bool saw_points = false;
  std::string line;
  std::size_t& line_no = blocks.last_line;
  while (std::getline(in, line)) {
    ++line_no;
    host::text::strip_utf8_bom(line, line_no);
    const std::string_view text = host::text::trim_blanks(strip_comment(line));
    if (text.empty()) {
      continue;
    }
    if (text == "header.begin" || text == "spline.begin") {
      block = std::string(text.substr(0, text.find('.')));
      saw_header = saw_header || block == "header";
      continue;
    }
    if (text == "point.begin") {
      if (block != "spline") {
        host::text::fail_at(source_name, line_no, "point.begin outside a spline block");
      }
      block = "point";
      saw_points = true;
      continue;
    }
    if (text == "point.end") {
      block = "spline";
      continue;
    }
    if (text == "header.end" || text == "spline.end") {
      block.clear();
      continue;
    }
    if (block == "point") {
      std::istringstream fields{std::string(text)};
      std::string a;
      std::string b;
      std::string w;
      fields >> a >> b >> w;
      double y = 0.0;
      double z = 0.0;
      if (!parse_double(a, y) || !parse_double(b, z)) {
        host::text::fail_at(
            source_name, line_no,
            "expected a point 'y z [weight]', got '" + host::text::excerpt(text) + "'");
      }
      blocks.points.push_back({y, z, line_no});
      continue;
    }
    const std::size_t eq = text.find('=');
    if (eq == std::string_view::npos || block.empty()) {
      host::text::fail_at(source_name, line_no,
                          "unexpected line '" + host::text::excerpt(text) + "'");
    }
    std::string value(host::text::trim_blanks(text.substr(eq + 1)));
    if (value.size() >= 2 && value.front() == '\'' && value.back() == '\'') {
      value = value.substr(1, value.size() - 2);
    }
    blocks.settings[block + "." + std::string(host::text::trim_blanks(text.substr(0, eq)))] = {
        value, line_no};
  }
  if (!saw_header) {
    host::text::fail_at(source_name, line_no, "no header.begin … header.end block");
  }
  if (!saw_points || blocks.points.size() < 2) {
    host::text::fail_at(source_name, line_no, "no point block with at least 2 points");
  }
  if (block == "point") {
    // A file cut short (a copy or download that stopped): its points end wherever it did.
    host::text::fail_at(source_name, line_no,
                        "the file ends inside a point block (no point.end): it is cut short");
  }
  return blocks;
}

/// What the settings of the blocks ask for, in millimetres and radians, with SIMPACK's defaults
/// where a key is absent.
struct SimpackSettings {
  SimpackProfileType type = SimpackProfileType::kWheel;
  std::string comment;
  double to_mm = 1.0;
  double shift_y_mm = 0.0;
  double shift_z_mm = 0.0;
  double rotate_rad = 0.0;
  double y_min_mm = 1.0, y_max_mm = 0.0;  // a range only where min < max
  double z_min_mm = 1.0, z_max_mm = 0.0;
  bool mirror_y = false;
  bool mirror_z = false;
  double point_dist_min_mm = 0.0;  ///< a point closer than this to the last kept one is dropped
  std::size_t point_dist_min_line = 0;
  std::vector<std::string> notes;
};

SimpackSettings read_settings(const SimpackBlocks& blocks, const std::string& source_name) {
  const auto line_of = [&](const std::string& key) -> std::size_t {
    const auto it = blocks.settings.find(key);
    return it == blocks.settings.end() ? 0 : it->second.line;
  };
  const auto number = [&](const std::string& key, double fallback) {
    const auto it = blocks.settings.find(key);
    if (it == blocks.settings.end()) {
      return fallback;
    }
    double v = 0.0;
    if (!parse_double(it->second.value, v)) {
      host::text::fail_at(source_name, it->second.line,
                          host::text::excerpt(key) + ": '" + host::text::excerpt(it->second.value) +
                              "' is not a number");
    }
    return v;
  };

  SimpackSettings s;
  const double type = number("header.type", -1.0);
  if (type < -0.5) {
    host::text::fail_at(source_name, blocks.last_line,
                        "header.type is missing (0 = rail, 1 = wheel)");
  }
  if (std::fabs(type - 1.0) < 0.5) {
    s.type = SimpackProfileType::kWheel;
  } else if (std::fabs(type) < 0.5) {
    s.type = SimpackProfileType::kRail;
  } else {
    host::text::fail_at(source_name, line_of("header.type"),
                        "header.type must be 0 (rail) or 1 (wheel)");
  }
  if (const auto it = blocks.settings.find("spline.comment"); it != blocks.settings.end()) {
    s.comment = it->second.value;
  }
  const double len_f = number("spline.units.len.f", 1000.0);
  const double ang_f = number("spline.units.ang.f", 1.0);
  if (!(len_f > 0.0) || !(ang_f > 0.0)) {
    host::text::fail_at(source_name, line_of("spline.units.len.f"),
                        "unit factors must be positive");
  }
  s.to_mm = 1000.0 / len_f;
  s.shift_y_mm = number("spline.shift.y", 0.0) * s.to_mm;
  s.shift_z_mm = number("spline.shift.z", 0.0) * s.to_mm;
  s.rotate_rad = number("spline.rotate", 0.0) / ang_f;
  s.y_min_mm = number("spline.bound.y.min", 1.0) * s.to_mm;
  s.y_max_mm = number("spline.bound.y.max", 0.0) * s.to_mm;
  s.z_min_mm = number("spline.bound.z.min", 1.0) * s.to_mm;
  s.z_max_mm = number("spline.bound.z.max", 0.0) * s.to_mm;
  s.mirror_y = number("spline.mirror.y", 0.0) > 0.5;
  s.mirror_z = number("spline.mirror.z", 0.0) > 0.5;
  s.point_dist_min_mm = number("spline.point.dist.min", 0.0) * s.to_mm;
  s.point_dist_min_line = line_of("spline.point.dist.min");
  if (!(s.point_dist_min_mm >= 0.0 && s.point_dist_min_mm < 10.0)) {
    host::text::fail_at(source_name, s.point_dist_min_line,
                        "point.dist.min must be from 0 to 10 mm (a distance between points)");
  }
  // What SIMPACK does with the points and tread does not: said, so that a profile that differs
  // from SIMPACK's does not do so silently.
  const auto at = [&](const std::string& key) {
    return source_name + ":" + std::to_string(line_of(key)) + ": ";
  };
  if (const double smooth = number("spline.approx.smooth", 0.0); std::fabs(smooth) > 0.0) {
    std::ostringstream m;
    m << at("spline.approx.smooth") << "approx.smooth = " << smooth
      << ": SIMPACK approximates these points by a smoothing spline; tread takes them as given "
         "(--smooth fits them locally)";
    s.notes.push_back(m.str());
  }
  if (number("spline.inversion", 0.0) > 0.5) {
    s.notes.push_back(at("spline.inversion") +
                      "inversion = 1 is not applied: the points are read as the other settings "
                      "place them");
  }
  return s;
}

/// The points as the settings place them: scaled, shifted, rotated, cut to the bounds, mirrored;
/// a rail's z turned from SIMPACK's downward axis to height.
std::vector<RawPoint> placed_points(const std::vector<RawPoint>& points, const SimpackSettings& s,
                                    std::size_t& dropped) {
  const double c = std::cos(s.rotate_rad);
  const double sn = std::sin(s.rotate_rad);
  std::vector<RawPoint> kept;
  dropped = 0;
  for (const RawPoint& p : points) {
    double y = p.y * s.to_mm + s.shift_y_mm;
    double z = p.z * s.to_mm + s.shift_z_mm;
    const double yr = c * y - sn * z;
    const double zr = sn * y + c * z;
    y = yr;
    z = zr;
    if (s.y_min_mm < s.y_max_mm && (y < s.y_min_mm || y > s.y_max_mm)) {
      continue;
    }
    if (s.z_min_mm < s.z_max_mm && (z < s.z_min_mm || z > s.z_max_mm)) {
      continue;
    }
    if (s.mirror_y) {
      y = -y;
    }
    if (s.mirror_z) {
      z = -z;
    }
    if (s.type == SimpackProfileType::kRail) {
      z = -z;  // SIMPACK z down -> height up
    }
    if (s.point_dist_min_mm > 0.0 && !kept.empty() &&
        std::hypot(y - kept.back().y, z - kept.back().z) < s.point_dist_min_mm) {
      ++dropped;
      continue;
    }
    kept.push_back({y, z, p.line});
  }
  return kept;
}

}  // namespace

SimpackPoints read_simpack_points(std::istream& in, const std::string& source_name) {
  const SimpackBlocks blocks = read_blocks(in, source_name);
  const SimpackSettings settings = read_settings(blocks, source_name);
  std::size_t dropped = 0;
  const std::vector<RawPoint> kept = placed_points(blocks.points, settings, dropped);
  if (kept.size() < 2) {
    host::text::fail_at(source_name, blocks.last_line, "fewer than 2 points left after the bounds");
  }
  SimpackPoints result;
  result.type = settings.type;
  result.comment = settings.comment;
  result.notes = settings.notes;
  if (dropped > 0) {
    std::ostringstream m;
    m << source_name << ":" << settings.point_dist_min_line
      << ": point.dist.min = " << settings.point_dist_min_mm << " mm: " << dropped
      << " points closer than that to the one before were dropped, as SIMPACK does";
    result.notes.push_back(m.str());
  }
  result.points.name = source_name;
  for (const RawPoint& p : kept) {
    result.points.y_mm.push_back(p.y);
    result.points.z_mm.push_back(p.z);
    result.points.line.push_back(p.line);
  }
  return result;
}

SimpackProfile read_simpack_profile(std::istream& in, const std::string& source_name) {
  const SimpackPoints read = read_simpack_points(in, source_name);
  struct RawPoint {
    double y;
    double z;
    std::size_t line;
  };
  std::vector<RawPoint> kept;
  for (std::size_t i = 0; i < read.points.y_mm.size(); ++i) {
    kept.push_back({read.points.y_mm[i], read.points.z_mm[i], read.points.line[i]});
  }
  SimpackProfile result;
  result.type = read.type;
  result.comment = read.comment;
  const bool decreasing = kept[1].y < kept[0].y;
  for (std::size_t i = 1; i < kept.size(); ++i) {
    const double dy = kept[i].y - kept[i - 1].y;
    if (decreasing ? !(dy < 0.0) : !(dy > 0.0)) {
      host::text::fail_at(source_name, kept[i].line,
                          "y is not strictly monotonic after processing (previous point at line " +
                              std::to_string(kept[i - 1].line) + ")");
    }
  }
  if (decreasing) {
    std::reverse(kept.begin(), kept.end());
  }
  result.profile.name = source_name;
  for (const RawPoint& p : kept) {
    result.profile.y_mm.push_back(p.y);
    result.profile.z_mm.push_back(p.z);
  }
  return result;
}

SimpackProfile read_simpack_profile(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) {
    throw std::runtime_error(path.string() + ":0: cannot open the file");
  }
  SimpackProfile result = read_simpack_profile(in, path.string());
  result.profile.name = path.stem().string();
  return result;
}

void write_simpack_profile(std::ostream& out, const SampledProfile& profile,
                           SimpackProfileType type, const std::string& comment) {
  check_sampled_profile(profile);
  const bool wheel = type == SimpackProfileType::kWheel;
  std::ostringstream o;
  o << "! *************************************************\n"
    << "! ***        SIMPACK Rail-Wheel Profile         ***\n"
    << "! *************************************************\n"
    << "! written by tread: " << profile.name << "\n\n"
    << "  header.begin\n"
    << "    version       =  1                       ! Version flag\n"
    << "    type          =  " << (wheel ? 1 : 0)
    << "                       ! 0=rail profile, 1=wheel profile\n"
    << "  header.end\n\n"
    << "  spline.begin\n"
    << "    approx.smooth  = +0.000000000000000e+00   ! Approximation smoothing value\n"
    << "    comment        = '";
  for (const char ch : comment) {
    o << (ch == '\'' || ch == '\n' ? ' ' : ch);
  }
  o << "'   ! Comment\n"
    << "    type           =  0                       ! Original data file type\n"
    << "    point.dist.min = +0.000000000000000e+00\n"
    << "    shift.y        = +0.000000000000000e+00\n"
    << "    shift.z        = +0.000000000000000e+00\n"
    << "    rotate         = +0.000000000000000e+00\n"
    << "    bound.y.min    = +1.000000000000000e+00\n"
    << "    bound.y.max    = +0.000000000000000e+00\n"
    << "    bound.z.min    = +1.000000000000000e+00\n"
    << "    bound.z.max    = +0.000000000000000e+00\n"
    << "    mirror.y       =  0                       ! 0=no mirroring\n"
    << "    mirror.z       =  0                       ! 0=no mirroring\n"
    << "    inversion      =  0                       ! 0=no inversion\n"
    << "    units.len.f    = +1.000000000000000e+03   ! lengths in mm\n"
    << "    units.ang.f    = +1.000000000000000e+00   ! angles in rad\n"
    << "    point.begin\n"
    << "    ! y value (mm)  z value (mm, SIMPACK: + down)\n";
  o << std::scientific;
  o.precision(12);
  for (std::size_t i = 0; i < profile.y_mm.size(); ++i) {
    const double z = wheel ? profile.z_mm[i] : -profile.z_mm[i];
    o << "    " << profile.y_mm[i] << "  " << z << '\n';
  }
  o << "    point.end\n"
    << "  spline.end\n";
  out << o.str();
}

}  // namespace tread::profile
