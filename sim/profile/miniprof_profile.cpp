#include "profile/miniprof_profile.hpp"

#include "io/text_line.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string_view>

namespace tread::profile {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// Lines starting with one of these are comments (MiniProf exports and the tools that read them
// use all four).
bool is_comment_marker(char c) {
  return c == '#' || c == '!' || c == '%' || c == '"';
}

bool starts_with_number(std::string_view text) {
  const auto fields = host::text::split_fields(text);
  double v = 0.0;
  return !fields.empty() && host::text::parse_number_text(fields.front(), v);
}

}  // namespace

MiniProfFile read_miniprof(std::istream& in, const std::string& source_name) {
  MiniProfFile out;
  out.points.name = source_name;
  std::size_t x_col = 0;
  std::size_t y_col = 1;
  std::size_t declared = 0;
  std::size_t declared_line = 0;
  bool in_header = true;
  std::string line;
  std::size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    host::text::strip_utf8_bom(line, line_no);
    const std::string_view text = host::text::trim_blanks(line);
    if (!text.empty() && is_comment_marker(text.front())) {
      continue;
    }
    if (in_header) {
      if (text.empty()) {
        in_header = out.header.empty();  // the first blank line after the header ends it
        continue;
      }
      if (!starts_with_number(text)) {
        const std::size_t eq = text.find('=');
        if (eq == std::string_view::npos) {
          // Older exports start with plain words ("MiniProf", a section name): kept, not used.
          out.header.emplace_back(std::string(text), std::string());
          continue;
        }
        const std::string key(host::text::trim_blanks(text.substr(0, eq)));
        const std::string value(host::text::trim_blanks(text.substr(eq + 1)));
        out.header.emplace_back(key, value);
        const std::string k = lower(key);
        if (k == "xoffset" || k == "yoffset") {
          double offset_mm = 0.0;
          std::string number = value;  // a lone decimal comma is read as a point
          if (number.find('.') == std::string::npos) {
            std::replace(number.begin(), number.end(), ',', '.');
          }
          if (!host::text::parse_number_text(number, offset_mm) || !std::isfinite(offset_mm)) {
            host::text::fail_at(source_name, line_no,
                                key + " '" + host::text::excerpt(value) + "' is not a number (mm)");
          }
          (k == "xoffset" ? out.x_offset_mm : out.y_offset_mm) = offset_mm;
          (k == "xoffset" ? out.x_offset_line : out.y_offset_line) = line_no;
        } else if (k == "columndef") {
          const auto names = host::text::split_fields(value);
          std::size_t found = 0;
          for (std::size_t i = 0; i < names.size(); ++i) {
            const std::string n = lower(names[i]);
            if (n == "x") {
              x_col = i;
              found |= 1U;
            } else if (n == "y") {
              y_col = i;
              found |= 2U;
            }
          }
          if (found != 3U) {
            host::text::fail_at(
                source_name, line_no,
                "ColumnDef '" + host::text::excerpt(value) + "' does not name the columns X and Y");
          }
        } else if (k == "points" || k == "xypoints") {
          double n = 0.0;
          if (host::text::parse_number_text(value, n) && n >= 0.0 &&
              !(std::abs(n - std::round(n)) > 0.0)) {
            declared = static_cast<std::size_t>(n);
            declared_line = line_no;
          }
        }
        continue;
      }
      in_header = false;
    }
    if (text.empty()) {
      continue;
    }
    const std::string data = host::text::with_decimal_points(text);
    const auto fields = host::text::split_fields(data);
    if (text.find('=') != std::string_view::npos) {
      host::text::fail_at(source_name, line_no,
                          "header line '" + host::text::excerpt(text) +
                              "' after the points (the header ends at the "
                              "first blank line)");
    }
    const std::size_t need = std::max(x_col, y_col) + 1;
    if (fields.size() < need) {
      host::text::fail_at(source_name, line_no,
                          "expected at least " + std::to_string(need) + " columns, got " +
                              std::to_string(fields.size()));
    }
    double x = 0.0;
    double y = 0.0;
    if (!host::text::parse_number_text(fields[x_col], x) ||
        !host::text::parse_number_text(fields[y_col], y) || !std::isfinite(x) ||
        !std::isfinite(y)) {
      host::text::fail_at(source_name, line_no,
                          "expected a point 'X Y', got '" + host::text::excerpt(text) + "'");
    }
    out.points.y_mm.push_back(x + out.x_offset_mm);
    out.points.z_mm.push_back(y + out.y_offset_mm);
    out.points.line.push_back(line_no);
  }
  if (out.points.y_mm.size() < 2) {
    host::text::fail_at(source_name, line_no, "fewer than 2 points after the header");
  }
  if (declared_line > 0 && declared != out.points.y_mm.size()) {
    host::text::fail_at(source_name, declared_line,
                        "the header declares " + std::to_string(declared) +
                            " points, the file has " + std::to_string(out.points.y_mm.size()));
  }
  return out;
}

MiniProfFile read_miniprof(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) {
    throw std::runtime_error(path.string() + ": cannot open the file");
  }
  MiniProfFile out = read_miniprof(in, path.string());
  out.points.name = path.stem().string();
  return out;
}

}  // namespace tread::profile
