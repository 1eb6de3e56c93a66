#pragma once
// Tyre-model input tables (CSV) as measurement rigs and users write them (host side: throws).
//
// One definition of the column names `tread mf eval`, `tread pac eval` and the fitter's CSV reader
// accept. Names are matched without regard to case; the unit comes from the name:
//
//   quantity          SI column     also accepted (unit the name declares)
//   wheel load        Fz_N          Fz, FZ, FZW, Load_N (N); Fz_kN (kN)
//   longitudinal slip kappa         SL, LongSlip, SlipRatio (1); kappa_pct, SL_pct (%)
//   slip angle        alpha_rad     alpha, SA_rad (rad); alpha_deg, SA, SA_deg (deg)
//   inclination       gamma_rad     gamma, IA_rad (rad); gamma_deg, IA, IA_deg, camber_deg (deg)
//   forward speed     Vx_mps        Vx, V_mps (m/s); Vx_kph, Vx_kmh, V, V_kph, V_kmh (km/h)
//   turn slip         phit_1pm      phit (1/m)
//   inflation press.  P_Pa          (Pa); P_kPa, P (kPa); P_bar (bar); P_psi (psi)
//
// The bare TTC / TYDEX-style names (FZ, SA, SL, IA, V, P) carry the units of the FSAE Tire Test
// Consortium's metric files: N, deg, 1, deg, km/h, kPa.
//
// Units row: when the line under the header holds text (or "1") in every input column (e.g. "N deg
// deg kph kPa", as FSAE TTC run files have), it names the units and overrides the ones the names
// imply: N, kN, lbf; 1, -, unitless, %; deg, rad; m/s, mps, km/h, kph, kmh, mph; 1/m; Pa, kPa, bar,
// psi (any case, optionally in [] or ()). A unit not in that list for its column is an error.
//
// Separator: ',' (default), ';' or tab, chosen with `separator` or detected from the header line
// (';' or tab when the header holds no ','). With ';' or tab a cell's decimal comma is read as a
// point ("0,05" = 0.05); a row with both a decimal comma and a '.' in its numbers is an error (is
// "4.000" beside "0,05" 4 or 4000?). A UTF-8 byte order mark (spreadsheet exports) is skipped, as
// are blank lines and lines starting with '#'. Columns that name no input (nor, with
// InputTableOptions::measured, a measured output) are ignored (and listed by ignored_columns()).
//
// Sign conventions (the file's, converted to ISO-W = TYDEX W, the axes of MFeval and of every
// tread tyre command). ISO-W: x forward in the wheel plane, y left, z up; the load Fz is positive;
// α is positive when the contact patch travels towards +y (a normal tyre then gives Fy < 0 and
// Mz > 0); γ is a right-hand rotation about x: positive when the wheel top leans towards −y (to
// the right, looking forward; camber thrust then pushes towards −y).
//  - iso-w: taken as they are.
//  - sae (SAE J670: y right, z down — the FSAE TTC data): the axes are ISO-W turned half a turn
//    about x, so Fz and α change sign (the load column holds negative numbers); κ and γ do not (γ
//    is a rotation about the shared x axis: in both, positive with the wheel top to the right).
//  - adapted-iso (Pacejka's book, the PAC89/PAC94 "adapted" axes: positive α gives positive Fy):
//    α changes sign, nothing else.
// Forces and moments measured in the file (for the fitter) change sign by the same rule: Fy, Fz,
// My, Mz for sae; Fy and Mz for adapted-iso (see output_sign()).

#include <array>
#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tread::tyre {

enum class InputQuantity { fz, kappa, alpha, gamma, vx, phit, pressure };
inline constexpr std::size_t kInputQuantityCount = 7;

/// The SI column name of `q` (Fz_N, kappa, alpha_rad, gamma_rad, Vx_mps, phit_1pm, P_Pa).
std::string_view si_name(InputQuantity q);

struct InputColumn {
  InputQuantity quantity = InputQuantity::fz;
  double to_si = 1.0;     ///< SI value = cell × to_si
  std::string_view unit;  ///< the unit the name declares ("N", "deg", "km/h", ...)
};

/// The input a column name stands for (case-insensitive, surrounding blanks ignored).
std::optional<InputColumn> recognise_input_column(std::string_view name);

/// The accepted names grouped by quantity and unit, for --help ("Fz_N|FZ|FZW|Load_N [N], Fz_kN
/// [kN]; kappa|SL|... [1], ...").
std::string input_column_help();

enum class SignConvention { iso_w, sae, adapted_iso };

/// "iso-w", "sae", "adapted-iso" (case-insensitive).
std::optional<SignConvention> parse_sign_convention(std::string_view text);
std::string_view to_string(SignConvention c);

/// Factor (±1) taking input `q` written in `c` to ISO-W.
double iso_w_sign(SignConvention c, InputQuantity q);

enum class MeasuredQuantity { fx, fy, fz, mx, my, mz };
inline constexpr std::size_t kMeasuredQuantityCount = 6;
/// Factor (±1) taking a measured force or moment written in `c` to ISO-W.
double output_sign(SignConvention c, MeasuredQuantity q);

/// A measured output's column (the fitter's): Fx_N|FX|FXW [N], Fx_kN [kN]; Fy_N|FY|FYW [N], Fy_kN
/// [kN]; Mz_Nm|MZ|MZW [N m], Mz_kNm [kN m] (case-insensitive). A units row may name N, kN, lbf for
/// the forces and N m (Nm, N-m, N·m, N*m), kN m (kNm, kN-m, kN·m), ft-lbf (lbf-ft) for Mz.
struct MeasuredColumn {
  MeasuredQuantity quantity = MeasuredQuantity::fx;
  double to_si = 1.0;
  std::string_view unit;
};
std::optional<MeasuredColumn> recognise_measured_column(std::string_view name);

/// Measured values of one row, in SI units and ISO-W signs, indexed by MeasuredQuantity: NaN where
/// the table has no column or the cell is empty (not measured there).
using MeasuredValues = std::array<double, kMeasuredQuantityCount>;

struct InputTableOptions {
  char separator = '\0';  ///< ',', ';' or '\t'; '\0': detect from the header line
  SignConvention convention = SignConvention::iso_w;
  /// Inputs that must have a column (the others default to 0).
  std::vector<InputQuantity> required = {InputQuantity::fz, InputQuantity::kappa,
                                         InputQuantity::alpha, InputQuantity::gamma,
                                         InputQuantity::vx};
  /// Also read the measured outputs' columns (recognise_measured_column; next() and parse_row()
  /// give them to a MeasuredValues). Without it they are ignored columns.
  bool measured = false;
};

/// One row, in SI units and ISO-W signs. Inputs without a column are 0.
struct InputRow {
  std::array<double, kInputQuantityCount> value{};
  int line = 0;
  double operator[](InputQuantity q) const { return value[static_cast<std::size_t>(q)]; }
};

/// Reads the header on construction and one row per next() (an optional units row is taken and
/// skipped; mapping() reports the units then). Errors: tir::TirError (a
/// std::runtime_error, `file:line: message`): no header row, a column repeated (also under two
/// names, e.g. SA and alpha_deg), a required input without a column, a row with the wrong number
/// of cells, a cell of an input column that is not a finite number, an unknown unit in a units row.
class InputTable {
 public:
  InputTable(std::istream& in, std::string name, InputTableOptions options);

  /// The next data row; std::nullopt at the end of the input. `measured`, if given, receives the
  /// row's measured values (see InputTableOptions::measured).
  std::optional<InputRow> next(MeasuredValues* measured = nullptr);

  // For a reader that takes the lines from the stream itself, after construction (`tread mf
  // eval` reads large files in chunks and parses them on several threads): next() is these two.

  /// The number of the last line read from the stream (the header's, after construction).
  int line() const { return line_; }
  /// Takes `line` (numbered `line_no`) as the units row if it is one (see the file comment): call
  /// it with the first line after the header that is not blank or a comment, and only that one.
  /// Throws as next() does (wrong number of cells, unknown unit).
  bool take_units_row(std::string_view line, int line_no);
  /// Reads a data line (without its '\n') into `row`: false for a blank or '#' line. Throws as
  /// next() does. Does not change the table: safe to call from several threads at once.
  bool parse_row(std::string_view line, int line_no, InputRow& row,
                 MeasuredValues* measured = nullptr) const;

  bool has(InputQuantity q) const { return column_[static_cast<std::size_t>(q)] >= 0; }
  bool has(MeasuredQuantity q) const { return measured_column_[static_cast<std::size_t>(q)] >= 0; }
  /// The number of the header's line.
  int header_line() const { return header_line_; }
  char separator() const { return separator_; }
  const std::string& name() const { return name_; }
  /// One line per mapped column: "SA → alpha_rad (deg → rad, sign from sae)".
  std::vector<std::string> mapping() const;
  const std::vector<std::string>& ignored_columns() const { return ignored_; }
  /// The header cell of input `q` as written (empty without a column).
  std::string column_name(InputQuantity q) const;
  /// The unit input `q`'s column is written in ("" without a column).
  std::string_view column_unit(InputQuantity q) const;
  /// The sign convention the table's values are converted from.
  SignConvention convention() const noexcept { return options_.convention; }

 private:
  std::vector<std::string> split(std::string_view line) const;
  /// Takes the units of a units row (see the file comment); false if `cells` is not one.
  bool apply_units_row(const std::vector<std::string>& cells, int line_no);
  [[noreturn]] void wrong_cell_count(std::size_t found, int line_no) const;
  /// parse_row's one pass over a ',' separated line `t` (trimmed, not a comment): each number
  /// read where it stands (host::read_csv_number_at), no cell copied or scanned twice. False
  /// wherever a cell needs read_csv_number's other rules or the row an error (a cell count, a
  /// bad number): parse_row then reads the line again cell by cell, which gives the same values
  /// for every line this accepts.
  bool read_comma_row(std::string_view t, InputRow& row) const noexcept;

  std::istream& in_;
  std::string name_;
  InputTableOptions options_;
  char separator_ = ',';
  int line_ = 0;
  bool seen_row_ = false;
  std::size_t cells_ = 0;
  std::vector<std::string> header_;
  std::array<int, kInputQuantityCount> column_{};
  std::array<InputColumn, kInputQuantityCount> spec_{};
  std::array<double, kInputQuantityCount> sign_{};  ///< iso_w_sign of each input
  std::array<int, kMeasuredQuantityCount> measured_column_{};
  std::array<MeasuredColumn, kMeasuredQuantityCount> measured_spec_{};
  std::array<double, kMeasuredQuantityCount> measured_sign_{};  ///< output_sign of each
  /// Input of each cell, kInputQuantityCount + a MeasuredQuantity for a measured output; -1: none.
  std::vector<int> quantity_of_cell_;
  int header_line_ = 0;
  std::vector<std::string> ignored_;
};

}  // namespace tread::tyre
