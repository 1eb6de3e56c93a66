#pragma once
// Loaders for PAC89/PAC94 coefficient sets (host side; throws TirError with file:line).
//
// .tir (Adams PAC89/PAC94 property files): [LATERAL_COEFFICIENTS] A0…A17,
// [LONGITUDINAL_COEFFICIENTS] B0…B13, [ALIGNING_COEFFICIENTS] C0…C20 (keys case-insensitive);
// optional anywhere: UNLOADED_RADIUS, ROLLING_RESISTANCE, LATERAL_STIFFNESS (the first and last
// converted to SI by [UNITS]). Missing coefficients are 0 (a PAC89 file has no A14…A17, B11…B13,
// C18…C20, which makes PAC94 reduce to PAC89) and are listed in `missing`. The model comes from
// tir::detect_model(): a Magic Formula file is refused ("use tread mf eval"), and so is a file
// without a single PAC coefficient.
//
// Chrono JSON (Pac89Tire template, e.g. chrono_HMMWV_Pac89Tire.json; `//` comments allowed):
// "Lateral Coefficients" {"a0"…}, "Longitudinal Coefficients" {"b0"…}, "Aligning Coefficients"
// {"c0"…}, "Design Parameters" {"Unloaded Radius", "Rolling Resistance", "Lateral Stiffness"}.

#include <filesystem>
#include <string>
#include <vector>

#include "pac/pac_params.hpp"
#include "tir/tir_file.hpp"

namespace tread::tir {

struct PacCoefficients {
  pac::PacParams<double> params;
  std::vector<std::string> missing;  ///< keys that took their default (0)
  /// The .tir says PAC94 (PROPERTY_FILE_FORMAT, or without it a nonzero A14…/B11…/C18…).
  bool pac94 = false;
  std::string note;  ///< how the model was decided, where the file does not say (else empty)
  /// What the coefficients do that the user should know: the load limit brought down to where a
  /// peak factor changes sign.
  std::vector<std::string> warnings;
  bool fzmax_given = false;  ///< the file's FZMAX set the load limit (else the core's default)
  /// From a Chrono JSON: the values PAC89's coefficients and design values leave out (mass,
  /// inertia, width, the vertical model, ...), by name; a .tir written from it does not hold them.
  std::vector<std::string> not_carried;
  /// TYRESIDE from the .tir in upper case ('LEFT', 'RIGHT', 'SYMMETRIC'), empty if absent; apply
  /// pac::mirror_pac89/mirror_pac94 (pac/pac_mirror.hpp) for a tyre on the other side.
  std::string tyreside;
};

PacCoefficients pac_from_tir(const TirFile& file);
PacCoefficients pac_from_chrono_json(const std::filesystem::path& path);

/// Writes the coefficients into `file` (sections as read by pac_from_tir); round-trips exactly.
void pac_to_tir(const pac::PacParams<double>& params, TirFile& file);

}  // namespace tread::tir
