#include "tir/tir_units.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <numbers>
#include <sstream>

#include "io/text_line.hpp"

namespace tread::tir {

namespace {

struct UnitName {
  UnitQuantity quantity;
  std::string_view name;
  double si;
};

// Exact definitions: inch 0.0254 m, foot 0.3048 m, mile 1609.344 m, pound 0.45359237 kg,
// standard gravity 9.80665 m/s² (kgf, lbf = 0.45359237 · 9.80665 N), slug = lbf·s²/ft,
// psi = lbf/inch².
constexpr double kLbf = 0.45359237 * 9.80665;
constexpr double kSlug = kLbf / 0.3048;
constexpr std::array kUnits = std::to_array<UnitName>({
    {UnitQuantity::kLength, "meter", 1.0},
    {UnitQuantity::kLength, "metre", 1.0},
    {UnitQuantity::kLength, "meters", 1.0},
    {UnitQuantity::kLength, "metres", 1.0},
    {UnitQuantity::kLength, "m", 1.0},
    {UnitQuantity::kLength, "mm", 1e-3},
    {UnitQuantity::kLength, "millimeter", 1e-3},
    {UnitQuantity::kLength, "millimetre", 1e-3},
    {UnitQuantity::kLength, "cm", 1e-2},
    {UnitQuantity::kLength, "centimeter", 1e-2},
    {UnitQuantity::kLength, "centimetre", 1e-2},
    {UnitQuantity::kLength, "km", 1e3},
    {UnitQuantity::kLength, "kilometer", 1e3},
    {UnitQuantity::kLength, "kilometre", 1e3},
    {UnitQuantity::kLength, "inch", 0.0254},
    {UnitQuantity::kLength, "inches", 0.0254},
    {UnitQuantity::kLength, "in", 0.0254},
    {UnitQuantity::kLength, "foot", 0.3048},
    {UnitQuantity::kLength, "feet", 0.3048},
    {UnitQuantity::kLength, "ft", 0.3048},
    {UnitQuantity::kLength, "mile", 1609.344},
    {UnitQuantity::kForce, "newton", 1.0},
    {UnitQuantity::kForce, "newtons", 1.0},
    {UnitQuantity::kForce, "n", 1.0},
    {UnitQuantity::kForce, "knewton", 1e3},
    {UnitQuantity::kForce, "kilonewton", 1e3},
    {UnitQuantity::kForce, "kn", 1e3},
    {UnitQuantity::kForce, "kg_force", 9.80665},
    {UnitQuantity::kForce, "kgf", 9.80665},
    {UnitQuantity::kForce, "pound_force", kLbf},
    {UnitQuantity::kForce, "lbf", kLbf},
    {UnitQuantity::kForce, "kpound_force", 1e3 * kLbf},
    {UnitQuantity::kForce, "klbf", 1e3 * kLbf},
    {UnitQuantity::kForce, "kip", 1e3 * kLbf},
    {UnitQuantity::kForce, "dyne", 1e-5},
    {UnitQuantity::kForce, "ounce_force", kLbf / 16.0},
    {UnitQuantity::kForce, "ozf", kLbf / 16.0},
    {UnitQuantity::kAngle, "radian", 1.0},
    {UnitQuantity::kAngle, "radians", 1.0},
    {UnitQuantity::kAngle, "rad", 1.0},
    {UnitQuantity::kAngle, "degree", std::numbers::pi / 180.0},
    {UnitQuantity::kAngle, "degrees", std::numbers::pi / 180.0},
    {UnitQuantity::kAngle, "deg", std::numbers::pi / 180.0},
    {UnitQuantity::kMass, "kg", 1.0},
    {UnitQuantity::kMass, "kilogram", 1.0},
    {UnitQuantity::kMass, "kilograms", 1.0},
    {UnitQuantity::kMass, "gram", 1e-3},
    {UnitQuantity::kMass, "grams", 1e-3},
    {UnitQuantity::kMass, "g", 1e-3},
    {UnitQuantity::kMass, "tonne", 1e3},
    {UnitQuantity::kMass, "tonnes", 1e3},
    {UnitQuantity::kMass, "pound_mass", 0.45359237},
    {UnitQuantity::kMass, "lbm", 0.45359237},
    {UnitQuantity::kMass, "kpound_mass", 453.59237},
    {UnitQuantity::kMass, "slug", kSlug},
    {UnitQuantity::kMass, "slinch", kSlug * 12.0},
    {UnitQuantity::kMass, "ounce_mass", 0.45359237 / 16.0},
    {UnitQuantity::kMass, "ozm", 0.45359237 / 16.0},
    {UnitQuantity::kTime, "second", 1.0},
    {UnitQuantity::kTime, "seconds", 1.0},
    {UnitQuantity::kTime, "sec", 1.0},
    {UnitQuantity::kTime, "s", 1.0},
    {UnitQuantity::kTime, "millisecond", 1e-3},
    {UnitQuantity::kTime, "milliseconds", 1e-3},
    {UnitQuantity::kTime, "ms", 1e-3},
    {UnitQuantity::kTime, "minute", 60.0},
    {UnitQuantity::kTime, "minutes", 60.0},
    {UnitQuantity::kTime, "min", 60.0},
    {UnitQuantity::kTime, "hour", 3600.0},
    {UnitQuantity::kTime, "hours", 3600.0},
    {UnitQuantity::kTime, "h", 3600.0},
    {UnitQuantity::kPressure, "pascal", 1.0},
    {UnitQuantity::kPressure, "pa", 1.0},
    {UnitQuantity::kPressure, "kpa", 1e3},
    {UnitQuantity::kPressure, "mpa", 1e6},
    {UnitQuantity::kPressure, "bar", 1e5},
    {UnitQuantity::kPressure, "psi", kLbf / (0.0254 * 0.0254)},
});

struct UnitKey {
  std::string_view key;
  UnitQuantity quantity;
};
constexpr std::array kUnitKeys = std::to_array<UnitKey>({
    {"LENGTH", UnitQuantity::kLength},
    {"FORCE", UnitQuantity::kForce},
    {"ANGLE", UnitQuantity::kAngle},
    {"MASS", UnitQuantity::kMass},
    {"TIME", UnitQuantity::kTime},
    {"PRESSURE", UnitQuantity::kPressure},
});

std::string trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front())) != 0) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())) != 0) s.remove_suffix(1);
  return std::string(s);
}

bool is_one(double x) noexcept {
  return !(x < 1.0 || x > 1.0);
}

double power(double base, int exponent) noexcept {
  double r = 1.0;
  for (int i = 0; i < std::abs(exponent); ++i) r *= base;
  return exponent < 0 ? 1.0 / r : r;
}

// Converts every number of a {pen fz} table row in place; false if the row is not all numbers.
bool convert_row(std::string& row, double pen_factor, double fz_factor) {
  std::istringstream in(row);
  std::string token;
  std::vector<double> values;
  while (in >> token) {
    const auto v = parse_number(token);
    if (!v) return false;
    values.push_back(*v);
  }
  if (values.size() != 2) return false;
  row = " " + format_number(values[0] * pen_factor) + "  " + format_number(values[1] * fz_factor);
  return true;
}

}  // namespace

double UnitSystem::to_si(Dimension d) const noexcept {
  double f = power(angle_rad, d.angle) * power(mass_kg, d.mass) * power(time_s, d.time);
  if (pressure_pa && d.force > 0 && d.length <= -2 * d.force) {
    // force^k / length^2k is k pressures; the rest of the length exponent stays a length.
    f *= power(*pressure_pa, d.force) * power(length_m, d.length + 2 * d.force);
  } else {
    f *= power(length_m, d.length) * power(force_n, d.force);
  }
  return f;
}

bool UnitSystem::is_si() const noexcept {
  return is_one(length_m) && is_one(force_n) && is_one(angle_rad) && is_one(mass_kg) &&
         is_one(time_s) && (!pressure_pa || is_one(*pressure_pa));
}

std::optional<double> unit_factor(UnitQuantity quantity, std::string_view name) noexcept {
  for (const auto& u : kUnits) {
    if (u.quantity == quantity && iequals(u.name, name)) return u.si;
  }
  return std::nullopt;
}

UnitSystem read_units(const TirFile& file) {
  UnitSystem units;
  for (const auto& uk : kUnitKeys) {
    const Entry* e = file.find("UNITS", uk.key);
    if (e == nullptr) continue;
    const std::string name = trimmed(e->value);
    const auto f = unit_factor(uk.quantity, name);
    if (!f) {
      throw TirError(file.origin(), e->line,
                     "unknown unit '" + host::text::excerpt(name) + "' for " + std::string(uk.key) +
                         " in [UNITS]");
    }
    switch (uk.quantity) {
      case UnitQuantity::kLength:
        units.length_m = *f;
        break;
      case UnitQuantity::kForce:
        units.force_n = *f;
        break;
      case UnitQuantity::kAngle:
        units.angle_rad = *f;
        break;
      case UnitQuantity::kMass:
        units.mass_kg = *f;
        break;
      case UnitQuantity::kTime:
        units.time_s = *f;
        break;
      case UnitQuantity::kPressure:
        units.pressure_pa = *f;
        break;
    }
  }
  return units;
}

std::optional<double> number_si(const TirFile& file, const UnitSystem& units,
                                std::string_view section, std::string_view key) {
  const auto v = section.empty() ? file.number_any(key) : file.number(section, key);
  if (!v) return v;
  const KeyInfo* info = find_key_info(key);
  return info == nullptr ? *v : *v * units.to_si(info->dimension);
}

void set_si(TirFile& file, std::string_view section, std::string_view key, double value_si) {
  const KeyInfo* info = find_key_info(key);
  const double factor = info == nullptr ? 1.0 : read_units(file).to_si(info->dimension);
  file.set(section, key, value_si / factor);
}

std::vector<std::string> convert_to_si(TirFile& file) {
  const UnitSystem units = read_units(file);
  std::vector<std::string> unknown;
  for (auto& s : file.sections()) {
    if (iequals(s.name, "UNITS")) continue;
    if (iequals(s.name, "DEFLECTION_LOAD_CURVE") || iequals(s.name, "BOTTOMING_CURVE")) {
      const double pen = units.to_si(dim::kLength);
      const double fz = units.to_si(dim::kForce);
      if (is_one(pen) && is_one(fz)) continue;
      for (auto& l : s.lines) {
        if (l.kind != Line::Kind::kTableRow) continue;
        const std::string before = l.text;
        if (!convert_row(l.text, pen, fz) && trimmed(before).rfind('{', 0) != 0) {
          throw TirError(file.origin(), l.line,
                         "[" + s.name + "] row is not two numbers (pen fz): '" +
                             host::text::excerpt(trimmed(before)) + "'");
        }
      }
      continue;
    }
    for (auto& l : s.lines) {
      if (l.kind != Line::Kind::kEntry || l.entry.is_quoted()) continue;
      const auto v = parse_number(l.entry.value);
      if (!v) continue;
      const KeyInfo* info = find_key_info(l.entry.key);
      if (info == nullptr) {
        if (!units.is_si()) unknown.push_back(s.name + "." + l.entry.key);
        continue;
      }
      const double factor = units.to_si(info->dimension);
      if (is_one(factor)) continue;
      file.set(s.name, l.entry.key, *v * factor);
    }
  }
  file.set_text("UNITS", "LENGTH", "meter");
  file.set_text("UNITS", "FORCE", "newton");
  file.set_text("UNITS", "ANGLE", "radians");
  file.set_text("UNITS", "MASS", "kg");
  file.set_text("UNITS", "TIME", "second");
  if (file.find("UNITS", "PRESSURE") != nullptr) file.set_text("UNITS", "PRESSURE", "pascal");
  return unknown;
}

std::string implausible_value(const TirFile& file, std::string_view key, double value_si, double lo,
                              double hi, std::string_view unit, std::string_view what) {
  if (file.find_any(key) == nullptr || (value_si >= lo && value_si <= hi)) return {};
  const std::string u(unit);
  return std::string(key) + " = " + format_number(value_si) + " " + u +
         " in SI: " + std::string(what) + " lies within " + format_number(lo) + "…" +
         format_number(hi) + " " + u + "; is the [UNITS] section right?";
}

}  // namespace tread::tir
