#include "profile/miniprof_profile.hpp"

#include "profile/text_line.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string_view>

namespace tread::profile {

namespace {

[[noreturn]] void fail(const std::string& source, std::size_t line, const std::string& message) {
  throw std::runtime_error(source + ":" + std::to_string(line) + ": " + message);
}

std::string_view trim(std::string_view s) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!s.empty() && is_space(s.front())) {
    s.remove_prefix(1);
  }
  while (!s.empty() && is_space(s.back())) {
    s.remove_suffix(1);
  }
  return s;
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  const auto is_sep = [](char c) {
    return c == ',' || c == ';' || c == '\t' || c == ' ' || c == '\r';
  };
  std::size_t start = 0;
  while (start < line.size()) {
    while (start < line.size() && is_sep(line[start])) {
      ++start;
    }
    std::size_t end = start;
    while (end < line.size() && !is_sep(line[end])) {
      ++end;
    }
    if (end > start) {
      fields.push_back(line.substr(start, end - start));
    }
    start = end;
  }
  return fields;
}

bool parse_double(std::string_view text, double& value) {
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+') {
    ++first;
  }
  const auto [ptr, ec] = std::from_chars(first, last, value);
  return ec == std::errc{} && ptr == last && first != last;
}

bool starts_with_number(std::string_view text) {
  const auto fields = split_fields(text);
  double v = 0.0;
  return !fields.empty() && parse_double(fields.front(), v);
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
    strip_utf8_bom(line, line_no);
    const std::string_view text = trim(line);
    if (!text.empty() && text.front() == '#') {
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
          fail(source_name, line_no,
               "expected a header line Key=Value or a point, got '" + std::string(text) + "'");
        }
        const std::string key(trim(text.substr(0, eq)));
        const std::string value(trim(text.substr(eq + 1)));
        out.header.emplace_back(key, value);
        const std::string k = lower(key);
        if (k == "columndef") {
          const auto names = split_fields(value);
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
            fail(source_name, line_no,
                 "ColumnDef '" + value + "' does not name the columns X and Y");
          }
        } else if (k == "points" || k == "xypoints") {
          double n = 0.0;
          if (parse_double(value, n) && n >= 0.0 && !(std::abs(n - std::round(n)) > 0.0)) {
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
    const std::string data = with_decimal_points(text);
    const auto fields = split_fields(data);
    const std::size_t need = std::max(x_col, y_col) + 1;
    if (fields.size() < need) {
      fail(source_name, line_no,
           "expected at least " + std::to_string(need) + " columns, got " +
               std::to_string(fields.size()));
    }
    double x = 0.0;
    double y = 0.0;
    if (!parse_double(fields[x_col], x) || !parse_double(fields[y_col], y) || !std::isfinite(x) ||
        !std::isfinite(y)) {
      fail(source_name, line_no, "expected a point 'X Y', got '" + std::string(text) + "'");
    }
    out.points.y_mm.push_back(x);
    out.points.z_mm.push_back(y);
    out.points.line.push_back(line_no);
  }
  if (out.points.y_mm.size() < 2) {
    fail(source_name, line_no, "fewer than 2 points after the header");
  }
  if (declared_line > 0 && declared != out.points.y_mm.size()) {
    fail(source_name, declared_line,
         "the header declares " + std::to_string(declared) + " points, the file has " +
             std::to_string(out.points.y_mm.size()));
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
