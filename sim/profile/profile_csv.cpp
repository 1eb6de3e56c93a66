#include "profile/profile_csv.hpp"

#include "io/text_line.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tread::profile {

namespace {

std::vector<std::string_view> split_commas(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    if (comma == std::string_view::npos) {
      fields.push_back(host::text::trim_blanks(line.substr(start)));
      return fields;
    }
    fields.push_back(host::text::trim_blanks(line.substr(start, comma - start)));
    start = comma + 1;
  }
}

double parse_number(std::string_view text, const std::string& source, std::size_t line,
                    const char* column) {
  double value = 0.0;
  if (!host::text::parse_number_text(text, value)) {
    host::text::fail_at(
        source, line,
        std::string("column ") + column + ": '" + host::text::excerpt(text) + "' is not a number");
  }
  if (!std::isfinite(value)) {
    host::text::fail_at(source, line, std::string("column ") + column + ": value is not finite");
  }
  return value;
}

bool is_number_text(std::string_view text) {
  double value = 0.0;
  return host::text::parse_number_text(text, value);
}

/// A header cell naming a profile axis: 'y' or 'z', alone or with its unit after '_' or '/'
/// ("y_mm", "z/m") or in brackets ("z [m]", "Y(in)"), quotes around the name ignored. `mm_per_unit`
/// converts to millimetres; a bare "y" or "z" is in millimetres. A suffix after '_' or '/' that is
/// no unit ("y_err", "z_wheel") names no axis; a bracketed unit not known is an error.
struct AxisColumn {
  char axis = 0;  ///< 'y' or 'z'; 0: the cell names no axis
  double mm_per_unit = 1.0;
  bool other_unit = false;  ///< a unit other than mm is named
};

AxisColumn axis_column(std::string_view cell, const std::string& source, std::size_t line) {
  std::string name;
  for (const char c : cell) {
    if (c != ' ' && c != '\t' && c != '"' && c != '\'') {
      name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
  }
  if (name.empty() || (name[0] != 'y' && name[0] != 'z')) return {};
  std::string_view unit = std::string_view(name).substr(1);
  bool bracketed = false;
  if (!unit.empty()) {
    const char open = unit.front();
    if (open != '_' && open != '/' && open != '[' && open != '(') return {};  // "yaw", "zone"
    unit.remove_prefix(1);
    if (open == '[' || open == '(') {
      if (unit.empty() || unit.back() != (open == '[' ? ']' : ')')) return {};
      unit.remove_suffix(1);
      bracketed = true;
    }
  }
  static constexpr std::pair<std::string_view, double> kUnits[] = {
      {"", 1.0},      {"mm", 1.0},   {"m", 1000.0},      {"cm", 10.0},      {"in", 25.4},
      {"inch", 25.4}, {"um", 0.001}, {"\u00b5m", 0.001}, {"\u03bcm", 0.001}};
  for (const auto& [u, f] : kUnits) {
    if (unit == u) return {name[0], f, !u.empty() && u != "mm"};
  }
  // Units of length a profile is not written in: named, so not taken as mm ("y_ft").
  static constexpr std::string_view kOtherLengths[] = {"ft", "feet", "dm", "km", "nm", "yd", "mil"};
  const bool other_length = std::find(std::begin(kOtherLengths), std::end(kOtherLengths), unit) !=
                            std::end(kOtherLengths);
  if (!bracketed && !other_length) return {};
  host::text::fail_at(source, line,
                      "column '" + host::text::excerpt(cell) + "': unit '" +
                          host::text::excerpt(unit) +
                          "' not known for a profile (mm, m, cm, in, um)");
}

}  // namespace

ProfilePoints read_profile_csv_points(std::istream& in, const std::string& source_name,
                                      CsvDialect dialect) {
  const bool tolerant = dialect == CsvDialect::kTolerant;
  ProfilePoints points;
  points.name = source_name;
  std::string line;
  std::size_t line_no = 0;
  std::size_t y_col = 0;
  std::size_t z_col = 1;
  std::size_t n_cols = 0;
  double y_scale = 1.0;  // to mm, from the header's units
  double z_scale = 1.0;
  bool have_header = false;
  bool data_started = false;
  while (std::getline(in, line)) {
    ++line_no;
    host::text::strip_utf8_bom(line, line_no);
    if (tolerant) {
      line = host::text::with_decimal_points(line);
    }
    const std::string_view text = host::text::trim_blanks(line);
    if (text.empty() || text.front() == '#') {
      continue;
    }
    const auto fields = tolerant ? host::text::split_fields(text) : split_commas(text);
    if (!have_header && !data_started) {
      const auto y_it = std::find(fields.begin(), fields.end(), "y_mm");
      const auto z_it = std::find(fields.begin(), fields.end(), "z_mm");
      if (y_it != fields.end() && z_it != fields.end()) {
        y_col = static_cast<std::size_t>(y_it - fields.begin());
        z_col = static_cast<std::size_t>(z_it - fields.begin());
        points.header = {{"y", "column " + std::to_string(y_col + 1) + " 'y_mm'"},
                         {"z", "column " + std::to_string(z_col + 1) + " 'z_mm'"}};
        n_cols = fields.size();
        have_header = true;
        continue;
      }
      if (!tolerant) {
        host::text::fail_at(source_name, line_no,
                            "expected a header naming the columns y_mm and z_mm, got '" +
                                host::text::excerpt(text) + "'");
      }
      if (fields.size() < 2 || !is_number_text(fields[0]) || !is_number_text(fields[1])) {
        // One header row before the data. Where it names the y and z columns ("y,z", "z_m,y_m",
        // "Y [in]", ...), they are read from there, converted from their units to mm; a header of
        // other names ("x,y" of a drawing) leaves the first two columns as y and z in mm.
        // A unit set apart by a blank ("y [mm]") is a field of its own here: joined to its name,
        // so that the header's cells count as the data's columns.
        std::vector<std::string> cells;
        for (const std::string_view f : fields) {
          if (!cells.empty() && !f.empty() &&
              (f.front() == '[' || f.front() == '(' || f.front() == '/' ||
               (!cells.back().empty() && cells.back().back() == '/'))) {
            cells.back() += f;
          } else {
            cells.emplace_back(f);
          }
        }
        const std::size_t none = cells.size();
        std::size_t y_at = none;
        std::size_t z_at = none;
        double y_mm_per = 1.0;
        double z_mm_per = 1.0;
        bool y_unit = false;
        bool z_unit = false;
        for (std::size_t k = 0; k < cells.size(); ++k) {
          const AxisColumn c = axis_column(cells[k], source_name, line_no);
          if (c.axis == 'y' && y_at == none) {
            y_at = k;
            y_mm_per = c.mm_per_unit;
            y_unit = c.other_unit;
          } else if (c.axis == 'z' && z_at == none) {
            z_at = k;
            z_mm_per = c.mm_per_unit;
            z_unit = c.other_unit;
          }
        }
        if ((y_at < none) != (z_at < none) && (y_unit || z_unit)) {
          host::text::fail_at(source_name, line_no,
                              std::string("the header gives the unit of ") + (y_unit ? "y" : "z") +
                                  " but names no " + (y_unit ? "z" : "y") + " column: '" +
                                  host::text::excerpt(text) + "'");
        }
        if (y_at < none && z_at < none) {
          y_col = y_at;
          z_col = z_at;
          y_scale = y_mm_per;
          z_scale = z_mm_per;
          const auto used = [&](std::size_t at, bool converted, double mm_per) {
            char factor[32];
            std::snprintf(factor, sizeof factor, "%g", mm_per);
            return "column " + std::to_string(at + 1) + " '" + host::text::excerpt(cells[at]) +
                   "'" +
                   (converted ? std::string(", × ") + factor + " to mm" : std::string(", mm"));
          };
          points.header = {{"y", used(y_at, y_unit, y_mm_per)},
                           {"z", used(z_at, z_unit, z_mm_per)}};
          n_cols = std::max(y_at, z_at) + 1;
        }
        have_header = true;
        continue;
      }
    }
    data_started = true;
    if (!tolerant || n_cols > 0) {
      if (tolerant ? fields.size() < n_cols : fields.size() != n_cols) {
        host::text::fail_at(source_name, line_no,
                            "expected " + std::to_string(n_cols) + " columns, got " +
                                std::to_string(fields.size()));
      }
    } else if (fields.size() < 2) {
      host::text::fail_at(
          source_name, line_no,
          "expected two numbers 'y_mm,z_mm', got '" + host::text::excerpt(text) + "'");
    }
    const double y = parse_number(fields[y_col], source_name, line_no, "y_mm") * y_scale;
    const double z = parse_number(fields[z_col], source_name, line_no, "z_mm") * z_scale;
    if (!std::isfinite(y) || !std::isfinite(z)) {
      host::text::fail_at(source_name, line_no, "value is not finite in mm");
    }
    points.y_mm.push_back(y);
    points.z_mm.push_back(z);
    points.line.push_back(line_no);
  }
  if (!have_header && !tolerant) {
    host::text::fail_at(source_name, line_no, "no header line (y_mm,z_mm) found");
  }
  if (points.y_mm.size() < 2) {
    host::text::fail_at(source_name, line_no, "fewer than 2 points");
  }
  return points;
}

SampledProfile read_profile_csv(std::istream& in, const std::string& source_name,
                                CsvDialect dialect) {
  ProfilePoints points = read_profile_csv_points(in, source_name, dialect);
  SampledProfile profile;
  profile.name = source_name;
  profile.y_mm = std::move(points.y_mm);
  profile.z_mm = std::move(points.z_mm);
  const auto& lines = points.line;
  const bool decreasing = profile.y_mm[1] < profile.y_mm[0];
  for (std::size_t i = 1; i < profile.y_mm.size(); ++i) {
    const double dy = profile.y_mm[i] - profile.y_mm[i - 1];
    if (decreasing ? !(dy < 0.0) : !(dy > 0.0)) {
      host::text::fail_at(source_name, lines[i],
                          std::string("y_mm is not strictly ") +
                              (decreasing ? "decreasing" : "increasing") +
                              " (previous point at line " + std::to_string(lines[i - 1]) + ")");
    }
  }
  if (decreasing) {
    std::reverse(profile.y_mm.begin(), profile.y_mm.end());
    std::reverse(profile.z_mm.begin(), profile.z_mm.end());
  }
  return profile;
}

SampledProfile read_profile_csv(const std::filesystem::path& path, CsvDialect dialect) {
  std::ifstream in(path);
  if (!in) {
    throw std::runtime_error(path.string() + ": cannot open the file");
  }
  SampledProfile profile = read_profile_csv(in, path.string(), dialect);
  profile.name = path.stem().string();
  return profile;
}

void write_profile_csv(std::ostream& out, const SampledProfile& profile,
                       std::span<const double> tan, int decimals) {
  check_sampled_profile(profile);
  if (!tan.empty() && tan.size() != profile.y_mm.size()) {
    throw std::invalid_argument("write_profile_csv: tan has the wrong size for " + profile.name);
  }
  std::ostringstream buffer;
  buffer << std::fixed << std::setprecision(decimals);
  buffer << (tan.empty() ? "y_mm,z_mm\n" : "y_mm,z_mm,tan\n");
  for (std::size_t i = 0; i < profile.y_mm.size(); ++i) {
    buffer << profile.y_mm[i] << ',' << profile.z_mm[i];
    if (!tan.empty()) {
      buffer << ',' << tan[i];
    }
    buffer << '\n';
  }
  out << buffer.str();
}

void check_sampled_profile(const SampledProfile& profile) {
  const std::string who = "profile '" + profile.name + "': ";
  if (profile.y_mm.size() != profile.z_mm.size()) {
    throw std::invalid_argument(who + "y_mm and z_mm differ in size");
  }
  if (profile.y_mm.size() < 2) {
    throw std::invalid_argument(who + "fewer than 2 points");
  }
  for (std::size_t i = 0; i < profile.y_mm.size(); ++i) {
    if (!std::isfinite(profile.y_mm[i]) || !std::isfinite(profile.z_mm[i])) {
      throw std::invalid_argument(who + "point " + std::to_string(i) + " is not finite");
    }
    if (i > 0 && !(profile.y_mm[i] > profile.y_mm[i - 1])) {
      throw std::invalid_argument(who + "y is not strictly increasing at point " +
                                  std::to_string(i));
    }
  }
}

}  // namespace tread::profile
