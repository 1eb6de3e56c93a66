#pragma once
// [UNITS] of a .tir file: read the declared units, convert dimensional values to SI on read, write
// SI values back in the file's units, and rewrite a whole file in SI (host side; throws TirError).
//
// Accepted spellings (case-insensitive), after the Adams property-file unit names plus common
// abbreviations:
//   LENGTH: meter metre meters metres m, mm millimeter millimetre, cm centimeter centimetre,
//           km kilometer kilometre, inch inches in, foot feet ft, mile
//   FORCE:  newton newtons n, knewton kilonewton kn, kg_force kgf, pound_force lbf,
//           kpound_force klbf kip, dyne, ounce_force ozf
//   ANGLE:  radian radians rad, degree degrees deg
//   MASS:   kg kilogram kilograms, gram grams g, tonne tonnes, pound_mass lbm, kpound_mass,
//           slug, slinch, ounce_mass ozm
//   TIME:   second seconds sec s, millisecond milliseconds ms, minute minutes min, hour hours h
//   PRESSURE (optional; otherwise force/length²): pascal pa, kpa, mpa, bar, psi
// A missing [UNITS] section or entry means SI for that quantity. An unknown unit is a TirError
// naming the unit, the key and file:line. Which keys are dimensional: tir/tir_keys.hpp.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tir/tir_file.hpp"
#include "tir/tir_keys.hpp"

namespace tread::tir {

/// SI value of one unit of each quantity (1 for SI).
struct UnitSystem {
  double length_m = 1.0;
  double force_n = 1.0;
  double angle_rad = 1.0;
  double mass_kg = 1.0;
  double time_s = 1.0;
  std::optional<double> pressure_pa;  ///< an explicit PRESSURE unit, else force/length²

  /// Multiply a file value of that dimension by this to get SI.
  double to_si(Dimension d) const noexcept;
  bool is_si() const noexcept;
};

enum class UnitQuantity { kLength, kForce, kAngle, kMass, kTime, kPressure };

/// SI value of the unit `name` of that quantity, nullopt if the spelling is unknown.
std::optional<double> unit_factor(UnitQuantity quantity, std::string_view name) noexcept;

/// The file's [UNITS] (SI where absent). Throws TirError (file:line) for an unknown unit.
UnitSystem read_units(const TirFile& file);

/// The value of `key` (any section if `section` is empty) converted to SI by its dimension in
/// key_table() (keys outside the table are returned as written). nullopt if absent.
std::optional<double> number_si(const TirFile& file, const UnitSystem& units,
                                std::string_view section, std::string_view key);

/// What to say of a value no tyre has once [UNITS] is applied (a unit named wrongly, a value left
/// in another unit: LENGTH = 'mm' over values in metres gave R0 = 0.46 mm): "KEY = v unit in SI:
/// `what` lies within lo…hi unit; is the [UNITS] section right?", or "" for a value within them
/// or a key the file does not have (a default).
std::string implausible_value(const TirFile& file, std::string_view key, double value_si, double lo,
                              double hi, std::string_view unit, std::string_view what);

/// TirFile::set() of an SI value, written in the file's own unit for that key.
void set_si(TirFile& file, std::string_view section, std::string_view key, double value_si);

/// Rewrites `file` in SI: every numeric value of a known dimensional key is converted (so are the
/// {pen fz} rows of [DEFLECTION_LOAD_CURVE] / [BOTTOMING_CURVE]), and [UNITS] becomes meter /
/// newton / radians / kg / second. Returns the numeric keys outside key_table() that were left as
/// written (their dimension is unknown): empty when nothing was left.
std::vector<std::string> convert_to_si(TirFile& file);

}  // namespace tread::tir
