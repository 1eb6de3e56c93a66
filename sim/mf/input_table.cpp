#include "mf/input_table.hpp"

#include <cctype>
#include <istream>

#include "tir/tir_file.hpp"

namespace tread::mf {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

struct Alias {
  std::string_view name;  // lower case
  InputQuantity quantity;
  double to_si;
  std::string_view unit;
};

// Units of the bare TTC names (FZ, SA, SL, IA, V, P): the FSAE Tire Test Consortium's metric
// run files (N, deg, 1, deg, km/h, kPa).
constexpr Alias kAliases[] = {
    {"fz_n", InputQuantity::fz, 1.0, "N"},
    {"fz", InputQuantity::fz, 1.0, "N"},
    {"fzw", InputQuantity::fz, 1.0, "N"},
    {"load_n", InputQuantity::fz, 1.0, "N"},
    {"fz_kn", InputQuantity::fz, 1000.0, "kN"},
    {"kappa", InputQuantity::kappa, 1.0, "1"},
    {"sl", InputQuantity::kappa, 1.0, "1"},
    {"longslip", InputQuantity::kappa, 1.0, "1"},
    {"slipratio", InputQuantity::kappa, 1.0, "1"},
    {"kappa_pct", InputQuantity::kappa, 0.01, "%"},
    {"sl_pct", InputQuantity::kappa, 0.01, "%"},
    {"alpha_rad", InputQuantity::alpha, 1.0, "rad"},
    {"alpha", InputQuantity::alpha, 1.0, "rad"},
    {"sa_rad", InputQuantity::alpha, 1.0, "rad"},
    {"alpha_deg", InputQuantity::alpha, kDeg, "deg"},
    {"sa", InputQuantity::alpha, kDeg, "deg"},
    {"sa_deg", InputQuantity::alpha, kDeg, "deg"},
    {"gamma_rad", InputQuantity::gamma, 1.0, "rad"},
    {"gamma", InputQuantity::gamma, 1.0, "rad"},
    {"ia_rad", InputQuantity::gamma, 1.0, "rad"},
    {"gamma_deg", InputQuantity::gamma, kDeg, "deg"},
    {"ia", InputQuantity::gamma, kDeg, "deg"},
    {"ia_deg", InputQuantity::gamma, kDeg, "deg"},
    {"camber_deg", InputQuantity::gamma, kDeg, "deg"},
    {"vx_mps", InputQuantity::vx, 1.0, "m/s"},
    {"vx", InputQuantity::vx, 1.0, "m/s"},
    {"v_mps", InputQuantity::vx, 1.0, "m/s"},
    {"vx_kph", InputQuantity::vx, 1.0 / 3.6, "km/h"},
    {"vx_kmh", InputQuantity::vx, 1.0 / 3.6, "km/h"},
    {"v", InputQuantity::vx, 1.0 / 3.6, "km/h"},
    {"v_kph", InputQuantity::vx, 1.0 / 3.6, "km/h"},
    {"v_kmh", InputQuantity::vx, 1.0 / 3.6, "km/h"},
    {"phit_1pm", InputQuantity::phit, 1.0, "1/m"},
    {"phit", InputQuantity::phit, 1.0, "1/m"},
    {"p_pa", InputQuantity::pressure, 1.0, "Pa"},
    {"p_kpa", InputQuantity::pressure, 1000.0, "kPa"},
    {"p", InputQuantity::pressure, 1000.0, "kPa"},
    {"p_bar", InputQuantity::pressure, 1.0e5, "bar"},
    {"p_psi", InputQuantity::pressure, 6894.757293168361, "psi"},  // 1 psi = 6894.757... Pa
};

constexpr std::array<std::string_view, kInputQuantityCount> kSiNames = {
    "Fz_N", "kappa", "alpha_rad", "gamma_rad", "Vx_mps", "phit_1pm", "P_Pa"};

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string trim(std::string_view s) {
  const std::size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string_view::npos) return {};
  const std::size_t b = s.find_last_not_of(" \t\r");
  return std::string(s.substr(a, b - a + 1));
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
    if (a.name == key) return InputColumn{a.quantity, a.to_si, a.unit};
  }
  return std::nullopt;
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
      return q == InputQuantity::fz || q == InputQuantity::alpha ? -1.0 : 1.0;
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
  std::string line;
  while (std::getline(in_, line)) {
    ++line_;
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
    cells_ = header_.size();
    for (std::size_t i = 0; i < header_.size(); ++i) {
      const std::optional<InputColumn> c = recognise_input_column(header_[i]);
      if (!c) {
        ignored_.push_back(header_[i]);
        continue;
      }
      const std::size_t q = index(c->quantity);
      if (column_[q] >= 0) {
        throw tir::TirError(name_, line_,
                            "columns '" + header_[static_cast<std::size_t>(column_[q])] +
                                "' and '" + header_[i] + "' both give " + std::string(kSiNames[q]));
      }
      column_[q] = static_cast<int>(i);
      spec_[q] = *c;
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

std::vector<std::string> InputTable::split(const std::string& line) const {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = line.find(separator_, start);
    cells.push_back(trim(std::string_view(line).substr(
        start, end == std::string::npos ? std::string::npos : end - start)));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return cells;
}

std::optional<InputRow> InputTable::next() {
  std::string line;
  while (std::getline(in_, line)) {
    ++line_;
    const std::string t = trim(line);
    if (t.empty() || t.front() == '#') continue;
    const std::vector<std::string> cells = split(t);
    if (cells.size() != cells_) {
      throw tir::TirError(
          name_, line_,
          "expected " + std::to_string(cells_) + " cells, found " + std::to_string(cells.size()));
    }
    InputRow row;
    row.line = line_;
    for (std::size_t q = 0; q < kInputQuantityCount; ++q) {
      if (column_[q] < 0) continue;
      std::string text = cells[static_cast<std::size_t>(column_[q])];
      if (separator_ != ',' && text.find('.') == std::string::npos) {
        for (char& c : text) {
          if (c == ',') c = '.';
        }
      }
      const std::optional<double> v = tir::parse_number(text);
      if (!v) {
        throw tir::TirError(name_, line_,
                            header_[static_cast<std::size_t>(column_[q])] + ": '" +
                                cells[static_cast<std::size_t>(column_[q])] +
                                "' is not a finite number");
      }
      row.value[q] =
          *v * spec_[q].to_si * iso_w_sign(options_.convention, static_cast<InputQuantity>(q));
    }
    return row;
  }
  return std::nullopt;
}

std::vector<std::string> InputTable::mapping() const {
  std::vector<std::string> lines;
  for (std::size_t q = 0; q < kInputQuantityCount; ++q) {
    if (column_[q] < 0) continue;
    const InputQuantity quantity = static_cast<InputQuantity>(q);
    std::string line = "'" + header_[static_cast<std::size_t>(column_[q])] + "' → " +
                       std::string(kSiNames[q]) + " (";
    const bool si = std::string_view(spec_[q].unit) == recognise_input_column(kSiNames[q])->unit;
    line += si ? "in " + std::string(spec_[q].unit)
               : std::string(spec_[q].unit) + " → " +
                     std::string(recognise_input_column(kSiNames[q])->unit);
    if (iso_w_sign(options_.convention, quantity) < 0.0) {
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

}  // namespace tread::mf
