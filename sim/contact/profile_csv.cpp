#include "contact/profile_csv.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace tread::contact {

namespace {

bool parse_double(const std::string& text, double& value) {
  const char* first = text.data();
  const char* last = text.data() + text.size();
  while (first < last && std::isspace(static_cast<unsigned char>(*first)) != 0) {
    ++first;
  }
  while (last > first && std::isspace(static_cast<unsigned char>(last[-1])) != 0) {
    --last;
  }
  if (first < last && *first == '+') {
    ++first;
  }
  const auto [ptr, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && ptr == last && first < last;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (const char c : line) {
    if (c == ',' || c == ';' || c == '\t' || c == ' ') {
      if (!cur.empty()) {
        out.push_back(cur);
        cur.clear();
      }
    } else {
      cur.push_back(c);
    }
  }
  if (!cur.empty()) {
    out.push_back(cur);
  }
  return out;
}

}  // namespace

profile::SampledProfile read_profile_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) {
    throw std::runtime_error(file.string() + ": cannot open");
  }
  profile::SampledProfile p;
  p.name = file.stem().string();
  std::vector<std::size_t> lines;
  std::string line;
  std::size_t line_no = 0;
  bool data_started = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') {
      line.pop_back();
    }
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') {
      continue;
    }
    const auto cells = split(line);
    double y = 0.0;
    double z = 0.0;
    const bool ok = cells.size() >= 2 && parse_double(cells[0], y) && parse_double(cells[1], z);
    if (!ok) {
      if (!data_started && p.y_mm.empty()) {
        data_started = true;  // one header row is allowed before the data
        continue;
      }
      throw std::runtime_error(file.string() + ":" + std::to_string(line_no) +
                               ": expected two numbers 'y_mm,z_mm', got '" + line + "'");
    }
    data_started = true;
    p.y_mm.push_back(y);
    p.z_mm.push_back(z);
    lines.push_back(line_no);
  }
  if (p.y_mm.size() < 2) {
    throw std::runtime_error(file.string() + ": fewer than 2 profile points");
  }
  if (p.y_mm[1] < p.y_mm[0]) {
    std::reverse(p.y_mm.begin(), p.y_mm.end());
    std::reverse(p.z_mm.begin(), p.z_mm.end());
    std::reverse(lines.begin(), lines.end());
  }
  for (std::size_t i = 1; i < p.y_mm.size(); ++i) {
    if (!(p.y_mm[i] > p.y_mm[i - 1])) {
      throw std::runtime_error(file.string() + ":" + std::to_string(lines[i]) +
                               ": y is not strictly monotonic (" + std::to_string(p.y_mm[i]) +
                               " after " + std::to_string(p.y_mm[i - 1]) + ")");
    }
  }
  return p;
}

}  // namespace tread::contact
