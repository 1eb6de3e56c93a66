#include "fit/measurement.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <istream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "io/text_line.hpp"

namespace tread::fit {
namespace {

std::string trim(const std::string& s) {
  return std::string(host::text::trim_blanks(s));
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::optional<double> parse_number(const std::string& text) {
  const std::string t = trim(text);
  if (t.empty()) return std::nullopt;
  double value = 0.0;
  const char* first = t.data();
  if (*first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, t.data() + t.size(), value);
  if (ec != std::errc() || ptr != t.data() + t.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream s(line);
  while (std::getline(s, cell, sep)) cells.push_back(cell);
  if (!line.empty() && line.back() == sep) cells.emplace_back();
  return cells;
}

std::vector<std::string> split_ws(const std::string& line) {
  std::vector<std::string> tokens;
  std::istringstream s(line);
  std::string t;
  while (s >> t) tokens.push_back(t);
  return tokens;
}

enum class Field { fz, kappa, alpha, gamma, vx, fx, fy, mz };

void set_field(MeasurementPoint& p, Field f, double v) {
  switch (f) {
    case Field::fz:
      p.fz_n = v;
      break;
    case Field::kappa:
      p.kappa = v;
      break;
    case Field::alpha:
      p.alpha_rad = v;
      break;
    case Field::gamma:
      p.gamma_rad = v;
      break;
    case Field::vx:
      p.vx_mps = v;
      break;
    case Field::fx:
      p.fx_n = v;
      break;
    case Field::fy:
      p.fy_n = v;
      break;
    case Field::mz:
      p.mz_nm = v;
      break;
  }
}

bool is_output(Field f) {
  return f == Field::fx || f == Field::fy || f == Field::mz;
}

void check_has_output(const std::map<Field, std::size_t>& columns, const std::string& name,
                      std::size_t line, const char* what) {
  if (columns.count(Field::fx) + columns.count(Field::fy) + columns.count(Field::mz) == 0) {
    host::text::fail_at(name, line, std::string("no measured ") + what);
  }
}

}  // namespace

// A CSV column: the inputs by tyre::recognise_input_column (the names `tread mf eval` accepts), the
// measured outputs by the names below; the factor takes the cell to SI and ISO-W.
struct CsvColumn {
  Field field;
  double factor;
};

std::optional<CsvColumn> csv_column(const std::string& header, tyre::SignConvention convention) {
  if (const auto input = tyre::recognise_input_column(header)) {
    const double sign = tyre::iso_w_sign(convention, input->quantity);
    switch (input->quantity) {
      case tyre::InputQuantity::fz:
        return CsvColumn{Field::fz, input->to_si * sign};
      case tyre::InputQuantity::kappa:
        return CsvColumn{Field::kappa, input->to_si * sign};
      case tyre::InputQuantity::alpha:
        return CsvColumn{Field::alpha, input->to_si * sign};
      case tyre::InputQuantity::gamma:
        return CsvColumn{Field::gamma, input->to_si * sign};
      case tyre::InputQuantity::vx:
        return CsvColumn{Field::vx, input->to_si * sign};
      case tyre::InputQuantity::phit:
      case tyre::InputQuantity::pressure:
        return std::nullopt;  // not held by MeasurementPoint
    }
  }
  // Measured forces and moments: SI names, kN names, TTC names (FX, FY, MZ in N and N m), TYDEX
  // channels.
  struct Output {
    Field field;
    tyre::MeasuredQuantity quantity;
    double to_si;
  };
  static const std::map<std::string, Output> outputs = {
      {"FX_N", {Field::fx, tyre::MeasuredQuantity::fx, 1.0}},
      {"FX", {Field::fx, tyre::MeasuredQuantity::fx, 1.0}},
      {"FXW", {Field::fx, tyre::MeasuredQuantity::fx, 1.0}},
      {"FX_KN", {Field::fx, tyre::MeasuredQuantity::fx, 1000.0}},
      {"FY_N", {Field::fy, tyre::MeasuredQuantity::fy, 1.0}},
      {"FY", {Field::fy, tyre::MeasuredQuantity::fy, 1.0}},
      {"FYW", {Field::fy, tyre::MeasuredQuantity::fy, 1.0}},
      {"FY_KN", {Field::fy, tyre::MeasuredQuantity::fy, 1000.0}},
      {"MZ_NM", {Field::mz, tyre::MeasuredQuantity::mz, 1.0}},
      {"MZ", {Field::mz, tyre::MeasuredQuantity::mz, 1.0}},
      {"MZW", {Field::mz, tyre::MeasuredQuantity::mz, 1.0}},
      {"MZ_KNM", {Field::mz, tyre::MeasuredQuantity::mz, 1000.0}}};
  const auto it = outputs.find(upper(trim(header)));
  if (it == outputs.end()) return std::nullopt;
  return CsvColumn{it->second.field,
                   it->second.to_si * tyre::output_sign(convention, it->second.quantity)};
}

MeasurementSet read_measurement_csv(std::istream& in, const std::string& name,
                                    tyre::SignConvention convention) {
  MeasurementSet set;
  set.source = name;
  std::map<Field, std::size_t> columns;
  std::map<Field, double> factors;
  std::size_t header_cells = 0;
  bool have_header = false;
  std::string raw;
  std::size_t line = 0;
  while (std::getline(in, raw)) {
    ++line;
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();
    if (line == 1 && raw.rfind("\xEF\xBB\xBF", 0) == 0) raw.erase(0, 3);  // UTF-8 BOM
    const std::string t = trim(raw);
    if (t.empty() || t.front() == '#') continue;
    const std::vector<std::string> cells = split(t, ',');
    if (!have_header) {
      have_header = true;
      header_cells = cells.size();
      for (std::size_t i = 0; i < cells.size(); ++i) {
        const std::optional<CsvColumn> c = csv_column(cells[i], convention);
        if (!c) {
          set.ignored_columns.push_back(trim(cells[i]));
          const auto input = tyre::recognise_input_column(cells[i]);
          set.has_pressure =
              set.has_pressure || (input && input->quantity == tyre::InputQuantity::pressure);
          continue;
        }
        if (!columns.emplace(c->field, i).second) {
          host::text::fail_at(name, line, "repeated column '" + trim(cells[i]) + "'");
        }
        factors[c->field] = c->factor;
      }
      if (columns.count(Field::fz) == 0) host::text::fail_at(name, line, "missing column 'Fz_N'");
      if (columns.count(Field::kappa) == 0)
        host::text::fail_at(name, line, "missing column 'kappa'");
      if (columns.count(Field::alpha) == 0)
        host::text::fail_at(name, line, "missing column 'alpha_rad'");
      check_has_output(columns, name, line, "column (Fx_N, Fy_N or Mz_Nm)");
      continue;
    }
    if (cells.size() != header_cells) {
      host::text::fail_at(name, line,
                          "expected " + std::to_string(header_cells) + " cells, found " +
                              std::to_string(cells.size()));
    }
    MeasurementPoint p;
    p.line = line;
    for (const auto& [field, index] : columns) {
      const std::string& cell = cells[index];
      if (is_output(field) && trim(cell).empty()) continue;  // not measured here
      const std::optional<double> v = parse_number(cell);
      if (!v)
        host::text::fail_at(
            name, line,
            "cell " + std::to_string(index + 1) + " '" + trim(cell) + "' is not a finite number");
      const double si = *v * factors[field];
      if (!std::isfinite(si)) {
        host::text::fail_at(name, line,
                            "cell " + std::to_string(index + 1) + " '" + trim(cell) +
                                "' is out of range once converted to SI units");
      }
      set_field(p, field, si);
    }
    set.points.push_back(p);
  }
  if (!have_header) host::text::fail_at(name, line, "no header row");
  return set;
}

MeasurementSet read_tydex(std::istream& in, const std::string& name) {
  static const std::map<std::string, Field> known = {
      {"FZW", Field::fz},         {"LONGSLIP", Field::kappa}, {"SLIPANGL", Field::alpha},
      {"INCLANGL", Field::gamma}, {"LONGVEL", Field::vx},     {"FXW", Field::fx},
      {"FYW", Field::fy},         {"MZW", Field::mz}};
  struct Channel {
    std::optional<Field> field;
    double scale = 1.0;  // unit → SI
    double factor = 1.0, meas_offset = 0.0, phys_offset = 0.0;
  };
  enum class Section { other, channels, data };
  MeasurementSet set;
  set.source = name;
  std::vector<Channel> channels;
  std::map<Field, std::size_t> columns;
  Section section = Section::other;
  bool seen_data = false;
  std::size_t channels_line = 0;
  std::string raw;
  std::size_t line = 0;
  while (std::getline(in, raw)) {
    ++line;
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();
    const std::string t = trim(raw);
    if (t.rfind("**", 0) == 0) {
      const std::string key = upper(split_ws(t).front());
      if (key == "**MEASURCHANNELS") {
        section = Section::channels;
        channels_line = line;
      } else if (key == "**MEASURDATA") {
        section = Section::data;
        seen_data = true;
        if (channels.empty())
          host::text::fail_at(name, line, "**MEASURDATA before any **MEASURCHANNELS");
        if (columns.count(Field::fz) == 0)
          host::text::fail_at(name, channels_line, "missing channel FZW");
        check_has_output(columns, name, channels_line, "channel (FXW, FYW or MZW)");
      } else {
        section = Section::other;
      }
      continue;
    }
    if (t.empty() || t.front() == '!' || t.front() == '$') continue;
    const std::vector<std::string> tokens = split_ws(t);
    if (section == Section::channels) {
      // name, description (may hold spaces), unit, factor, measurement offset, physical offset
      if (tokens.size() < 5)
        host::text::fail_at(name, line,
                            "channel line needs name, description, unit, factor, "
                            "offsets");
      Channel c;
      const std::size_t n = tokens.size();
      const auto f = parse_number(tokens[n - 3]);
      const auto mo = parse_number(tokens[n - 2]);
      const auto po = parse_number(tokens[n - 1]);
      if (!f || !mo || !po)
        host::text::fail_at(name, line, "channel factor/offsets are not numbers");
      c.factor = *f;
      c.meas_offset = *mo;
      c.phys_offset = *po;
      const std::string channel = upper(tokens[0]);
      const std::string unit = tokens[n - 4];
      const auto it = known.find(channel);
      if (it != known.end()) {
        const std::string u = upper(unit);
        if (u == "DEG") {
          c.scale = std::numbers::pi / 180.0;
        } else if (u == "%") {
          c.scale = 0.01;
        } else if (u == "KN" || u == "KNM") {
          c.scale = 1000.0;
        } else if (u == "KM/H" || u == "KMH") {
          c.scale = 1.0 / 3.6;
        } else if (u == "RAD" || u == "N" || u == "NM" || u == "M/S" || u == "-" || u == "1") {
          c.scale = 1.0;
        } else {
          host::text::fail_at(name, line, "unknown unit '" + unit + "' of channel " + channel);
        }
        c.field = it->second;
        if (!columns.emplace(it->second, channels.size()).second) {
          host::text::fail_at(name, line, "repeated channel " + channel);
        }
      }
      channels.push_back(c);
    } else if (section == Section::data) {
      if (tokens.size() != channels.size()) {
        host::text::fail_at(name, line,
                            "expected " + std::to_string(channels.size()) + " values, found " +
                                std::to_string(tokens.size()));
      }
      MeasurementPoint p;
      p.line = line;
      for (std::size_t i = 0; i < tokens.size(); ++i) {
        const Channel& c = channels[i];
        if (!c.field) continue;
        const std::optional<double> v = parse_number(tokens[i]);
        if (!v)
          host::text::fail_at(
              name, line,
              "value " + std::to_string(i + 1) + " '" + tokens[i] + "' is not a finite number");
        const double si = ((*v - c.meas_offset) * c.factor + c.phys_offset) * c.scale;
        if (!std::isfinite(si)) {
          host::text::fail_at(
              name, line,
              "value " + std::to_string(i + 1) + " '" + tokens[i] +
                  "' is out of range once the channel's factor, offsets and unit are applied");
        }
        set_field(p, *c.field, si);
      }
      set.points.push_back(p);
    }
  }
  if (!seen_data) host::text::fail_at(name, line, "no **MEASURDATA section");
  return set;
}

void check_rolling(const MeasurementSet& set) {
  for (const MeasurementPoint& p : set.points) {
    if (!(std::fabs(p.vx_mps) > 0.0)) {
      host::text::fail_at(set.source, p.line,
                          "Vx = 0 (no Vx column or channel, or a wheel at standstill): the Magic "
                          "Formula's slips divide by the rolling speed, so every point needs one");
    }
  }
}

MeasurementSet load_measurements(const std::filesystem::path& path,
                                 tyre::SignConvention convention) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  std::string ext = upper(path.extension().string());
  if (ext == ".TDX") return read_tydex(in, path.string());
  return read_measurement_csv(in, path.string(), convention);
}

}  // namespace tread::fit
