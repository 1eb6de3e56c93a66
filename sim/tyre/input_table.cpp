#include "tyre/input_table.hpp"

#include <cctype>
#include <cmath>
#include <cstring>
#include <istream>
#include <limits>

#include "io/csv_number.hpp"
#include "io/text_line.hpp"
#include "tir/tir_file.hpp"

namespace tread::tyre {

namespace {

// A file's text as a message quotes it (io/text_line.hpp: short, control bytes as '?').
std::string ex(std::string_view text) {
  return host::text::excerpt(text);
}

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kPoundForce = 4.4482216152605;  // 1 lbf in N (exact: 0.45359237 kg · g_n)

struct Alias {
  std::string_view name;  // as shown in help; matched without regard to case
  InputQuantity quantity;
  double to_si;
  std::string_view unit;
};

// Units of the bare TTC names (FZ, SA, SL, IA, V, P): the FSAE Tire Test Consortium's metric
// run files (N, deg, 1, deg, km/h, kPa).
constexpr Alias kAliases[] = {
    {"Fz_N", InputQuantity::fz, 1.0, "N"},
    {"FZ", InputQuantity::fz, 1.0, "N"},
    {"FZW", InputQuantity::fz, 1.0, "N"},
    {"Load_N", InputQuantity::fz, 1.0, "N"},
    {"Fz_kN", InputQuantity::fz, 1000.0, "kN"},
    {"kappa", InputQuantity::kappa, 1.0, "1"},
    {"SL", InputQuantity::kappa, 1.0, "1"},
    {"LongSlip", InputQuantity::kappa, 1.0, "1"},
    {"SlipRatio", InputQuantity::kappa, 1.0, "1"},
    {"kappa_pct", InputQuantity::kappa, 0.01, "%"},
    {"SL_pct", InputQuantity::kappa, 0.01, "%"},
    {"alpha_rad", InputQuantity::alpha, 1.0, "rad"},
    {"alpha", InputQuantity::alpha, 1.0, "rad"},
    {"SA_rad", InputQuantity::alpha, 1.0, "rad"},
    {"alpha_deg", InputQuantity::alpha, kDeg, "deg"},
    {"SA", InputQuantity::alpha, kDeg, "deg"},
    {"SA_deg", InputQuantity::alpha, kDeg, "deg"},
    {"gamma_rad", InputQuantity::gamma, 1.0, "rad"},
    {"gamma", InputQuantity::gamma, 1.0, "rad"},
    {"IA_rad", InputQuantity::gamma, 1.0, "rad"},
    {"gamma_deg", InputQuantity::gamma, kDeg, "deg"},
    {"IA", InputQuantity::gamma, kDeg, "deg"},
    {"IA_deg", InputQuantity::gamma, kDeg, "deg"},
    {"camber_deg", InputQuantity::gamma, kDeg, "deg"},
    {"Vx_mps", InputQuantity::vx, 1.0, "m/s"},
    {"Vx", InputQuantity::vx, 1.0, "m/s"},
    {"V_mps", InputQuantity::vx, 1.0, "m/s"},
    {"Vx_kph", InputQuantity::vx, 1.0 / 3.6, "km/h"},
    {"Vx_kmh", InputQuantity::vx, 1.0 / 3.6, "km/h"},
    {"V", InputQuantity::vx, 1.0 / 3.6, "km/h"},
    {"V_kph", InputQuantity::vx, 1.0 / 3.6, "km/h"},
    {"V_kmh", InputQuantity::vx, 1.0 / 3.6, "km/h"},
    {"phit_1pm", InputQuantity::phit, 1.0, "1/m"},
    {"phit", InputQuantity::phit, 1.0, "1/m"},
    {"P_Pa", InputQuantity::pressure, 1.0, "Pa"},
    {"P_kPa", InputQuantity::pressure, 1000.0, "kPa"},
    {"P", InputQuantity::pressure, 1000.0, "kPa"},
    {"P_bar", InputQuantity::pressure, 1.0e5, "bar"},
    {"P_psi", InputQuantity::pressure, 6894.757293168361, "psi"},  // 1 psi = 6894.757... Pa
};

// Units a units row (the line under the header, as in FSAE TTC run files) may name.
struct UnitName {
  std::string_view name;  // lower case
  InputQuantity quantity;
  double to_si;
  std::string_view unit;  // as shown
};

constexpr UnitName kUnits[] = {
    {"n", InputQuantity::fz, 1.0, "N"},
    {"kn", InputQuantity::fz, 1000.0, "kN"},
    {"lbf", InputQuantity::fz, kPoundForce, "lbf"},
    {"1", InputQuantity::kappa, 1.0, "1"},
    {"-", InputQuantity::kappa, 1.0, "1"},
    {"unitless", InputQuantity::kappa, 1.0, "1"},
    {"%", InputQuantity::kappa, 0.01, "%"},
    {"deg", InputQuantity::alpha, kDeg, "deg"},
    {"rad", InputQuantity::alpha, 1.0, "rad"},
    {"deg", InputQuantity::gamma, kDeg, "deg"},
    {"rad", InputQuantity::gamma, 1.0, "rad"},
    {"m/s", InputQuantity::vx, 1.0, "m/s"},
    {"mps", InputQuantity::vx, 1.0, "m/s"},
    {"km/h", InputQuantity::vx, 1.0 / 3.6, "km/h"},
    {"kph", InputQuantity::vx, 1.0 / 3.6, "km/h"},
    {"kmh", InputQuantity::vx, 1.0 / 3.6, "km/h"},
    {"mph", InputQuantity::vx, 0.44704, "mph"},  // 1 mph = 0.44704 m/s
    {"1/m", InputQuantity::phit, 1.0, "1/m"},
    {"pa", InputQuantity::pressure, 1.0, "Pa"},
    {"kpa", InputQuantity::pressure, 1000.0, "kPa"},
    {"bar", InputQuantity::pressure, 1.0e5, "bar"},
    {"psi", InputQuantity::pressure, 6894.757293168361, "psi"},
};

struct MeasuredAlias {
  std::string_view name;  // matched without regard to case
  MeasuredQuantity quantity;
  double to_si;
  std::string_view unit;
};

constexpr double kFootPound = kPoundForce * 0.3048;  // 1 ft·lbf in N m (1 ft = 0.3048 m)

constexpr MeasuredAlias kMeasuredAliases[] = {
    {"Fx_N", MeasuredQuantity::fx, 1.0, "N"},    {"FX", MeasuredQuantity::fx, 1.0, "N"},
    {"FXW", MeasuredQuantity::fx, 1.0, "N"},     {"Fx_kN", MeasuredQuantity::fx, 1000.0, "kN"},
    {"Fy_N", MeasuredQuantity::fy, 1.0, "N"},    {"FY", MeasuredQuantity::fy, 1.0, "N"},
    {"FYW", MeasuredQuantity::fy, 1.0, "N"},     {"Fy_kN", MeasuredQuantity::fy, 1000.0, "kN"},
    {"Mz_Nm", MeasuredQuantity::mz, 1.0, "N m"}, {"MZ", MeasuredQuantity::mz, 1.0, "N m"},
    {"MZW", MeasuredQuantity::mz, 1.0, "N m"},   {"Mz_kNm", MeasuredQuantity::mz, 1000.0, "kN m"},
};

// Units a units row may name for a measured output (lower case).
constexpr MeasuredAlias kMeasuredUnits[] = {
    {"n", MeasuredQuantity::fx, 1.0, "N"},
    {"kn", MeasuredQuantity::fx, 1000.0, "kN"},
    {"lbf", MeasuredQuantity::fx, kPoundForce, "lbf"},
    {"n", MeasuredQuantity::fy, 1.0, "N"},
    {"kn", MeasuredQuantity::fy, 1000.0, "kN"},
    {"lbf", MeasuredQuantity::fy, kPoundForce, "lbf"},
    {"n m", MeasuredQuantity::mz, 1.0, "N m"},
    {"nm", MeasuredQuantity::mz, 1.0, "N m"},
    {"n-m", MeasuredQuantity::mz, 1.0, "N m"},
    {"n·m", MeasuredQuantity::mz, 1.0, "N m"},
    {"n*m", MeasuredQuantity::mz, 1.0, "N m"},
    {"kn m", MeasuredQuantity::mz, 1000.0, "kN m"},
    {"knm", MeasuredQuantity::mz, 1000.0, "kN m"},
    {"kn-m", MeasuredQuantity::mz, 1000.0, "kN m"},
    {"kn·m", MeasuredQuantity::mz, 1000.0, "kN m"},
    {"ft-lbf", MeasuredQuantity::mz, kFootPound, "ft-lbf"},
    {"lbf-ft", MeasuredQuantity::mz, kFootPound, "ft-lbf"},
};

constexpr std::array<std::string_view, kMeasuredQuantityCount> kMeasuredSiNames = {
    "Fx_N", "Fy_N", "Fz_N", "Mx_Nm", "My_Nm", "Mz_Nm"};

constexpr std::array<std::string_view, kInputQuantityCount> kSiNames = {
    "Fz_N", "kappa", "alpha_rad", "gamma_rad", "Vx_mps", "phit_1pm", "P_Pa"};

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string trim(std::string_view s) {
  return std::string(host::text::trim_blanks(s));
}

std::size_t index(InputQuantity q) {
  return static_cast<std::size_t>(q);
}

}  // namespace

std::string_view si_name(InputQuantity q) {
  return kSiNames[index(q)];
}

std::optional<InputColumn> recognise_input_column(std::string_view name) {
  const std::string key = lower(trim(name));
  for (const Alias& a : kAliases) {
    if (lower(a.name) == key) return InputColumn{a.quantity, a.to_si, a.unit};
  }
  return std::nullopt;
}

std::optional<MeasuredColumn> recognise_measured_column(std::string_view name) {
  const std::string key = lower(trim(name));
  for (const MeasuredAlias& a : kMeasuredAliases) {
    if (lower(a.name) == key) return MeasuredColumn{a.quantity, a.to_si, a.unit};
  }
  return std::nullopt;
}

std::string input_column_help() {
  std::string help;
  for (std::size_t q = 0; q < kInputQuantityCount; ++q) {
    if (!help.empty()) help += "; ";
    std::string_view unit;
    for (const Alias& a : kAliases) {
      if (index(a.quantity) != q) continue;
      if (a.unit != unit) {
        if (!unit.empty()) help += " [" + std::string(unit) + "], ";
        unit = a.unit;
      } else {
        help += "|";
      }
      help += a.name;
    }
    help += " [" + std::string(unit) + "]";
  }
  return help;
}

std::optional<SignConvention> parse_sign_convention(std::string_view text) {
  const std::string t = lower(trim(text));
  if (t == "iso-w" || t == "iso_w" || t == "isow") return SignConvention::iso_w;
  if (t == "sae") return SignConvention::sae;
  if (t == "adapted-iso" || t == "adapted_iso") return SignConvention::adapted_iso;
  return std::nullopt;
}

std::string_view to_string(SignConvention c) {
  switch (c) {
    case SignConvention::sae:
      return "sae";
    case SignConvention::adapted_iso:
      return "adapted-iso";
    case SignConvention::iso_w:
      break;
  }
  return "iso-w";
}

double iso_w_sign(SignConvention c, InputQuantity q) {
  switch (c) {
    case SignConvention::sae:
      // SAE J670 is ISO-W turned 180° about x (y right, z down): Fz, α and the turn slip φt (a yaw
      // rate over the speed: a rotation about z) change sign.
      return q == InputQuantity::fz || q == InputQuantity::alpha || q == InputQuantity::phit ? -1.0
                                                                                             : 1.0;
    case SignConvention::adapted_iso:
      return q == InputQuantity::alpha ? -1.0 : 1.0;
    case SignConvention::iso_w:
      break;
  }
  return 1.0;
}

double output_sign(SignConvention c, MeasuredQuantity q) {
  switch (c) {
    case SignConvention::sae:
      return q == MeasuredQuantity::fy || q == MeasuredQuantity::fz || q == MeasuredQuantity::my ||
                     q == MeasuredQuantity::mz
                 ? -1.0
                 : 1.0;
    case SignConvention::adapted_iso:
      return q == MeasuredQuantity::fy || q == MeasuredQuantity::mz ? -1.0 : 1.0;
    case SignConvention::iso_w:
      break;
  }
  return 1.0;
}

InputTable::InputTable(std::istream& in, std::string name, InputTableOptions options)
    : in_(in), name_(std::move(name)), options_(std::move(options)) {
  column_.fill(-1);
  measured_column_.fill(-1);
  std::string line;
  while (std::getline(in_, line)) {
    ++line_;
    if (line_ == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // UTF-8 BOM
    const std::string t = trim(line);
    if (t.empty() || t.front() == '#') continue;
    separator_ = options_.separator;
    if (separator_ == '\0') {
      separator_ = ',';
      if (t.find(',') == std::string::npos) {
        if (t.find(';') != std::string::npos) {
          separator_ = ';';
        } else if (t.find('\t') != std::string::npos) {
          separator_ = '\t';
        }
      }
    }
    header_ = split(t);
    // Header cells in double quotes, as spreadsheets export text ("Fz_N"): the name inside
    // ("missing column 'Fz_N'" was the answer to a header that had it).
    for (std::string& cell : header_) {
      if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"') {
        cell = trim(std::string_view(cell).substr(1, cell.size() - 2));
      }
    }
    cells_ = header_.size();
    quantity_of_cell_.assign(cells_, -1);
    header_line_ = line_;
    for (std::size_t i = 0; i < header_.size(); ++i) {
      const std::optional<InputColumn> c = recognise_input_column(header_[i]);
      if (!c) {
        const std::optional<MeasuredColumn> m =
            options_.measured ? recognise_measured_column(header_[i]) : std::nullopt;
        if (!m) {
          ignored_.push_back(header_[i]);
          continue;
        }
        const auto mq = static_cast<std::size_t>(m->quantity);
        if (measured_column_[mq] >= 0) {
          throw tir::TirError(
              name_, line_,
              "columns '" + ex(header_[static_cast<std::size_t>(measured_column_[mq])]) +
                  "' and '" + ex(header_[i]) + "' both give " + std::string(kMeasuredSiNames[mq]));
        }
        measured_column_[mq] = static_cast<int>(i);
        measured_spec_[mq] = *m;
        quantity_of_cell_[i] = static_cast<int>(kInputQuantityCount + mq);
        continue;
      }
      const std::size_t q = index(c->quantity);
      if (column_[q] >= 0) {
        throw tir::TirError(name_, line_,
                            "columns '" + ex(header_[static_cast<std::size_t>(column_[q])]) +
                                "' and '" + ex(header_[i]) + "' both give " +
                                std::string(kSiNames[q]));
      }
      column_[q] = static_cast<int>(i);
      spec_[q] = *c;
      quantity_of_cell_[i] = static_cast<int>(q);
    }
    for (std::size_t q = 0; q < kInputQuantityCount; ++q) {
      sign_[q] = iso_w_sign(options_.convention, static_cast<InputQuantity>(q));
    }
    for (std::size_t q = 0; q < kMeasuredQuantityCount; ++q) {
      measured_sign_[q] = output_sign(options_.convention, static_cast<MeasuredQuantity>(q));
    }
    for (InputQuantity q : options_.required) {
      if (!has(q)) {
        throw tir::TirError(name_, line_,
                            "missing column '" + std::string(si_name(q)) +
                                "' (or one of its other names; see --help)");
      }
    }
    return;
  }
  throw tir::TirError(name_, line_, "no header row");
}

std::vector<std::string> InputTable::split(std::string_view line) const {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = line.find(separator_, start);
    cells.push_back(trim(
        line.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start)));
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return cells;
}

namespace {

/// A units row's cell in lower case, without surrounding [] or ().
std::string unit_of_cell(const std::string& cell) {
  std::string unit = lower(cell);
  if (unit.size() >= 2 && (unit.front() == '[' || unit.front() == '(')) {
    unit = trim(std::string_view(unit).substr(1, unit.size() - 2));
  }
  return unit;
}

}  // namespace

bool InputTable::apply_units_row(const std::vector<std::string>& cells, int line_no) {
  // A units row: every input (and measured) column holds text that is not a number (or "1").
  bool any = false;
  for (std::size_t i = 0; i < cells_; ++i) {
    if (quantity_of_cell_[i] < 0) continue;
    const std::string& cell = cells[i];
    if (cell == "1") continue;  // the unit of a ratio, or a number: decided by the others
    double number = 0.0;
    if (cell.empty() || host::read_csv_number(cell, separator_ != ',', number)) return false;
    any = true;
  }
  if (!any) return false;
  for (std::size_t q = 0; q < kMeasuredQuantityCount; ++q) {
    if (measured_column_[q] < 0) continue;
    const std::string& cell = cells[static_cast<std::size_t>(measured_column_[q])];
    const std::string unit = unit_of_cell(cell);
    const MeasuredAlias* found = nullptr;
    std::string expected;
    for (const MeasuredAlias& u : kMeasuredUnits) {
      if (static_cast<std::size_t>(u.quantity) != q) continue;
      if (u.name == unit) found = &u;
      expected += (expected.empty() ? "" : ", ") + std::string(u.name);
    }
    if (found == nullptr) {
      throw tir::TirError(name_, line_no,
                          "unit '" + ex(cell) + "' of column '" +
                              ex(header_[static_cast<std::size_t>(measured_column_[q])]) +
                              "' is not a unit of " + std::string(kMeasuredSiNames[q]) +
                              " (expected " + expected + ")");
    }
    measured_spec_[q].to_si = found->to_si;
    measured_spec_[q].unit = found->unit;
  }
  for (std::size_t q = 0; q < kInputQuantityCount; ++q) {
    if (column_[q] < 0) continue;
    const std::string unit = unit_of_cell(cells[static_cast<std::size_t>(column_[q])]);
    const UnitName* found = nullptr;
    std::string expected;
    for (const UnitName& u : kUnits) {
      if (index(u.quantity) != q) continue;
      if (u.name == unit) found = &u;
      expected += (expected.empty() ? "" : ", ") + std::string(u.name);
    }
    if (found == nullptr) {
      throw tir::TirError(name_, line_no,
                          "unit '" + ex(cells[static_cast<std::size_t>(column_[q])]) +
                              "' of column '" + ex(header_[static_cast<std::size_t>(column_[q])]) +
                              "' is not a unit of " + std::string(kSiNames[q]) + " (expected " +
                              expected + ")");
    }
    spec_[q].to_si = found->to_si;
    spec_[q].unit = found->unit;
  }
  return true;
}

std::optional<InputRow> InputTable::next(MeasuredValues* measured) {
  std::string line;
  while (std::getline(in_, line)) {
    ++line_;
    const std::string_view t = host::text::trim_blanks(line);
    if (t.empty() || t.front() == '#') continue;
    if (!seen_row_) {
      seen_row_ = true;
      if (take_units_row(t, line_)) continue;
    }
    InputRow row;
    parse_row(t, line_, row, measured);
    return row;
  }
  return std::nullopt;
}

bool InputTable::take_units_row(std::string_view line, int line_no) {
  const std::vector<std::string> cells = split(host::text::trim_blanks(line));
  if (cells.size() != cells_) wrong_cell_count(cells.size(), line_no);
  return apply_units_row(cells, line_no);
}

void InputTable::wrong_cell_count(std::size_t found, int line_no) const {
  throw tir::TirError(
      name_, line_no,
      "expected " + std::to_string(cells_) + " cells, found " + std::to_string(found));
}

bool InputTable::parse_row(std::string_view line, int line_no, InputRow& row,
                           MeasuredValues* measured) const {
  const std::string_view t = host::text::trim_blanks(line);
  if (t.empty() || t.front() == '#') return false;
  row.line = line_no;
  if (measured == nullptr && separator_ == ',' && read_comma_row(t, row)) return true;
  row.value.fill(0.0);
  MeasuredValues scratch;
  MeasuredValues& out = measured != nullptr ? *measured : scratch;
  out.fill(std::numeric_limits<double>::quiet_NaN());
  // The cell count is checked first, so the first bad cell is only noted on the way.
  std::size_t cell = 0;
  std::size_t start = 0;
  std::size_t bad_cell = cells_;
  std::string_view bad_text;
  const char* bad_why = "";
  // With ';' or tab: a cell read with a decimal comma and one with a point in the same row.
  std::string_view comma_text, point_text;
  while (true) {
    const std::size_t end = t.find(separator_, start);
    if (cell < cells_ && quantity_of_cell_[cell] >= 0) {
      const auto q = static_cast<std::size_t>(quantity_of_cell_[cell]);
      const bool is_measured = q >= kInputQuantityCount;
      const std::string_view text = host::text::trim_blanks(
          t.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
      // With ';' or tab separators a cell without a '.' may have a decimal comma.
      double v = 0.0;
      if (is_measured && text.empty()) {
        // not measured in this row: stays NaN
      } else if (host::read_csv_number(text, separator_ != ',', v)) {
        if (separator_ != ',') {
          if (text.find(',') != std::string_view::npos && comma_text.empty()) comma_text = text;
          if (text.find('.') != std::string_view::npos && point_text.empty()) point_text = text;
        }
        const double si = is_measured ? v * measured_spec_[q - kInputQuantityCount].to_si *
                                            measured_sign_[q - kInputQuantityCount]
                                      : v * spec_[q].to_si * sign_[q];
        if (!std::isfinite(si) && bad_cell == cells_) {
          bad_cell = cell;
          bad_text = text;
          bad_why = "' is out of range once converted to SI units";
        }
        (is_measured ? out[q - kInputQuantityCount] : row.value[q]) = si;
      } else if (bad_cell == cells_) {
        bad_cell = cell;
        bad_text = text;
        bad_why = "' is not a finite number";
      }
    }
    ++cell;
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  if (cell != cells_) wrong_cell_count(cell, line_no);
  if (bad_cell != cells_) {
    throw tir::TirError(name_, line_no, ex(header_[bad_cell]) + ": '" + ex(bad_text) + bad_why);
  }
  if (!comma_text.empty() && !point_text.empty()) {
    // "4.000" beside "0,05": a thousands separator (4000) or a decimal point (4)? Not guessed.
    throw tir::TirError(name_, line_no,
                        "'" + ex(comma_text) + "' has a decimal comma and '" + ex(point_text) +
                            "' a point: with both in one row the point may be a thousands "
                            "separator; write every number with one decimal separator");
  }
  return true;
}

bool InputTable::read_comma_row(std::string_view t, InputRow& row) const noexcept {
  row.value.fill(0.0);
  const char* p = t.data();
  const char* const end = p + t.size();
  for (std::size_t cell = 0; cell < cells_; ++cell) {
    if (cell > 0) {
      if (p == end || *p != ',') return false;
      ++p;
    }
    const int q = quantity_of_cell_[cell];
    if (q < 0) {  // a column not read: up to the next separator
      const void* next = std::memchr(p, ',', static_cast<std::size_t>(end - p));
      p = next != nullptr ? static_cast<const char*>(next) : end;
      continue;
    }
    while (p != end && host::text::is_blank(*p)) ++p;
    double v = 0.0;
    p = host::read_csv_number_at(p, end, v);
    if (p == nullptr) return false;
    while (p != end && host::text::is_blank(*p)) ++p;
    const auto qi = static_cast<std::size_t>(q);
    row.value[qi] = v * spec_[qi].to_si * sign_[qi];
    if (!std::isfinite(row.value[qi])) return false;  // a unit's factor overflowed: say where
  }
  return p == end;
}

std::vector<std::string> InputTable::mapping() const {
  std::vector<std::string> lines;
  for (std::size_t q = 0; q < kInputQuantityCount; ++q) {
    if (column_[q] < 0) continue;
    const InputQuantity quantity = static_cast<InputQuantity>(q);
    std::string line(1, '\'');
    line += ex(header_[static_cast<std::size_t>(column_[q])]) + "' → " + std::string(kSiNames[q]) +
            " (";
    const bool si = std::string_view(spec_[q].unit) == recognise_input_column(kSiNames[q])->unit;
    line += si ? "in " + std::string(spec_[q].unit)
               : std::string(spec_[q].unit) + " → " +
                     std::string(recognise_input_column(kSiNames[q])->unit);
    if (iso_w_sign(options_.convention, quantity) < 0.0) {
      line += ", sign changed from " + std::string(to_string(options_.convention)) + " to ISO-W";
    }
    lines.push_back(line + ")");
  }
  for (std::size_t q = 0; q < kMeasuredQuantityCount; ++q) {
    if (measured_column_[q] < 0) continue;
    const std::string_view si_unit = q < 3 ? "N" : "N m";
    std::string line(1, '\'');
    line += ex(header_[static_cast<std::size_t>(measured_column_[q])]) + "' → " +
            std::string(kMeasuredSiNames[q]) + " (";
    line += measured_spec_[q].unit == si_unit
                ? "in " + std::string(si_unit)
                : std::string(measured_spec_[q].unit) + " → " + std::string(si_unit);
    if (measured_sign_[q] < 0.0) {
      line += ", sign changed from " + std::string(to_string(options_.convention)) + " to ISO-W";
    }
    lines.push_back(line + ")");
  }
  return lines;
}

std::string InputTable::column_name(InputQuantity q) const {
  return has(q) ? header_[static_cast<std::size_t>(column_[index(q)])] : std::string();
}

std::string_view InputTable::column_unit(InputQuantity q) const {
  return has(q) ? spec_[index(q)].unit : std::string_view();
}

}  // namespace tread::tyre
