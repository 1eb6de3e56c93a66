#include "fit/measurement.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
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

void check_has_output(const std::map<Field, std::size_t>& columns, const std::string& name,
                      std::size_t line, const char* what) {
  if (columns.count(Field::fx) + columns.count(Field::fy) + columns.count(Field::mz) == 0) {
    host::text::fail_at(name, line, std::string("no measured ") + what);
  }
}

}  // namespace

MeasurementSet read_measurement_csv(std::istream& in, const std::string& name,
                                    tyre::SignConvention convention) {
  using tyre::InputQuantity;
  using tyre::MeasuredQuantity;
  tyre::InputTableOptions options;
  options.convention = convention;
  options.required = {InputQuantity::fz, InputQuantity::kappa, InputQuantity::alpha};
  options.measured = true;
  tyre::InputTable table(in, name, options);
  if (!table.has(MeasuredQuantity::fx) && !table.has(MeasuredQuantity::fy) &&
      !table.has(MeasuredQuantity::mz)) {
    host::text::fail_at(name, static_cast<std::size_t>(table.header_line()),
                        "no measured column (Fx_N, Fy_N or Mz_Nm, or one of their other names)");
  }
  MeasurementSet set;
  set.source = name;
  set.ignored_columns = table.ignored_columns();
  // Inputs the fit does not take (MeasurementPoint holds none of them).
  for (const InputQuantity q : {InputQuantity::phit, InputQuantity::pressure}) {
    if (table.has(q)) set.ignored_columns.push_back(table.column_name(q));
  }
  set.has_pressure = table.has(InputQuantity::pressure);
  tyre::MeasuredValues measured{};
  while (const std::optional<tyre::InputRow> row = table.next(&measured)) {
    MeasurementPoint p;
    p.line = static_cast<std::size_t>(row->line);
    p.fz_n = (*row)[InputQuantity::fz];
    p.kappa = (*row)[InputQuantity::kappa];
    p.alpha_rad = (*row)[InputQuantity::alpha];
    p.gamma_rad = (*row)[InputQuantity::gamma];
    p.vx_mps = (*row)[InputQuantity::vx];
    p.fx_n = measured[static_cast<std::size_t>(MeasuredQuantity::fx)];
    p.fy_n = measured[static_cast<std::size_t>(MeasuredQuantity::fy)];
    p.mz_nm = measured[static_cast<std::size_t>(MeasuredQuantity::mz)];
    set.points.push_back(p);
  }
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
          host::text::fail_at(
              name, line, "unknown unit '" + host::text::excerpt(unit) + "' of channel " + channel);
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
          host::text::fail_at(name, line,
                              "value " + std::to_string(i + 1) + " '" +
                                  host::text::excerpt(tokens[i]) + "' is not a finite number");
        const double si = ((*v - c.meas_offset) * c.factor + c.phys_offset) * c.scale;
        if (!std::isfinite(si)) {
          host::text::fail_at(
              name, line,
              "value " + std::to_string(i + 1) + " '" + host::text::excerpt(tokens[i]) +
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

std::size_t drop_unloaded(MeasurementSet& set, std::size_t& first_line) {
  std::size_t unloaded = 0;
  first_line = 0;
  for (const MeasurementPoint& p : set.points) {
    if (p.fz_n > 0.0) continue;
    if (unloaded++ == 0) first_line = p.line;
  }
  if (unloaded == 0) return 0;
  if (2 * unloaded >= set.points.size()) {
    const auto first = std::find_if(set.points.begin(), set.points.end(),
                                    [](const MeasurementPoint& p) { return !(p.fz_n > 0.0); });
    char fz[32];
    std::snprintf(fz, sizeof fz, "%g", first->fz_n);
    host::text::fail_at(set.source, first_line,
                        "Fz = " + std::string(fz) + " N: " + std::to_string(unloaded) + " of " +
                            std::to_string(set.points.size()) +
                            " points have a load ≤ 0; the fit takes ISO-W axes (z up, Fz > 0): "
                            "data with z down (SAE J670, e.g. FSAE TTC) need --convention sae");
  }
  set.points.erase(std::remove_if(set.points.begin(), set.points.end(),
                                  [](const MeasurementPoint& p) { return !(p.fz_n > 0.0); }),
                   set.points.end());
  return unloaded;
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
