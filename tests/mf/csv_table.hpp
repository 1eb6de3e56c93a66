#pragma once
// Test helper: a numeric CSV with a header row, columns looked up by name. Lines starting with '#'
// are comments. Values are parsed with strtod (so "NaN", "Inf", "-Inf" read as such); other text
// cells read as NaN.

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace tread::testing {

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;

  int column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == name) return static_cast<int>(i);
    }
    return -1;
  }
  double at(std::size_t row, const std::string& name) const {
    const int c = column(name);
    if (c < 0) throw std::runtime_error("no column " + name);
    return rows.at(row).at(static_cast<std::size_t>(c));
  }
};

inline std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) {
    if (!cell.empty() && cell.back() == '\r') cell.pop_back();
    cells.push_back(cell);
  }
  return cells;
}

inline CsvTable read_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  CsvTable table;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells = split_csv_line(line);
    if (table.header.empty()) {
      table.header = cells;
      continue;
    }
    if (cells.size() != table.header.size()) {
      throw std::runtime_error(path + ":" + std::to_string(line_no) + ": wrong number of cells");
    }
    std::vector<double> row;
    for (const std::string& c : cells) {
      char* end = nullptr;
      const double v = std::strtod(c.c_str(), &end);
      // Text cells (e.g. a status column) read as NaN.
      row.push_back(end == c.c_str() ? std::nan("") : v);
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace tread::testing
