#include "tyre/mf_parameters_from_tir.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <span>

#include "io/text_line.hpp"
#include "tir/tir_keys.hpp"
#include "tir/tir_model.hpp"
#include "tir/tir_units.hpp"
#include "tyre/mf_parameter_checks.hpp"
#include "tyre/mf_unmodelled_keys.hpp"

namespace tread::tyre {

namespace {

constexpr std::array<tir::KeyDefault, static_cast<std::size_t>(mf::kMfParameterCount)> kKeys = {{
#define TREAD_MF_KEY_DEFAULT(member, section, key, value, description) {"", key, value},
    TREAD_MF_PARAMETER_LIST(TREAD_MF_KEY_DEFAULT)
#undef TREAD_MF_KEY_DEFAULT
}};

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

void add_line(std::string& warning, const std::string& line) {
  if (!warning.empty()) warning += "\n";
  warning += line;
}

mf::FitType fit_type_of(tir::TirModel model) {
  switch (model) {
    case tir::TirModel::kMf52:
      return mf::FitType::mf52;
    case tir::TirModel::kMf61:
      return mf::FitType::mf61;
    case tir::TirModel::kMf62:
      return mf::FitType::mf62;
    default:
      return mf::FitType::pac2002;  // PAC2002 and MF-Tyre 5.0
  }
}

}  // namespace

MfTirParameters mf_parameters_from_tir(const tir::TirFile& file) {
  const tir::DetectedModel model = tir::detect_model(file);
  if (!model.is_magic_formula()) {
    const tir::Entry* e = file.find_any("PROPERTY_FILE_FORMAT");
    throw tir::TirError(file.origin(), e != nullptr ? e->line : 0,
                        "this is a " + model.name + " file: use tread pac eval");
  }
  MfTirParameters result;
  const tir::ResolvedValues resolved = tir::resolve_numbers(file, std::span(kKeys));
  // [UNITS]: values read from the file are converted to SI (defaults are SI already).
  const tir::UnitSystem units = tir::read_units(file);
  std::vector<double> values = resolved.values;
  for (std::size_t k = 0; k < kKeys.size(); ++k) {
    const tir::KeyInfo* info = tir::find_key_info(kKeys[k].key);
    if (info != nullptr && file.find_any(kKeys[k].key) != nullptr) {
      values[k] *= units.to_si(info->dimension);
    }
  }
  std::size_t i = 0;
#define TREAD_MF_ASSIGN(member, section, key, value, description) \
  result.params.member = values[i++];
  TREAD_MF_PARAMETER_LIST(TREAD_MF_ASSIGN)
#undef TREAD_MF_ASSIGN
  result.params.fit_type = fit_type_of(model.model);
  result.model = model.name;

  // Missing keys: only those the file's own model has are worth a warning.
  for (const auto& key : resolved.missing) {
    const tir::KeyInfo* info = tir::find_key_info(key);
    if (info != nullptr && (info->models & model.keys) != 0) result.missing.push_back(key);
  }
  tir::ResolvedValues own;
  own.missing = result.missing;
  result.warning = own.warning(file.origin());
  for (const auto& w : file.warnings()) add_line(result.warning, w);
  if (!model.note.empty()) add_line(result.warning, file.origin() + ": " + model.note);

  // Pressure: without a pressure input the model runs at INFLPRES; a file that gives only one of
  // INFLPRES/NOMPRES is evaluated at that pressure (not at the book tyre's 2.2 bar default).
  if (model.model == tir::TirModel::kMf61 || model.model == tir::TirModel::kMf62) {
    const bool has_infl = file.find_any("INFLPRES") != nullptr;
    const bool has_nom = file.find_any("NOMPRES") != nullptr;
    if (has_nom && !has_infl) {
      result.params.inflpres_pa = result.params.nompres_pa;
      add_line(result.warning, file.origin() + ": no INFLPRES: evaluated at NOMPRES (" +
                                   tir::format_number(result.params.nompres_pa) +
                                   " Pa) when no pressure is given");
    } else if (has_infl && !has_nom) {
      result.params.nompres_pa = result.params.inflpres_pa;
      add_line(result.warning, file.origin() + ": no NOMPRES: INFLPRES (" +
                                   tir::format_number(result.params.inflpres_pa) +
                                   " Pa) taken as the nominal pressure");
    } else if (!has_infl && !has_nom) {
      add_line(result.warning, file.origin() +
                                   ": no INFLPRES or NOMPRES: the pressure terms are off unless "
                                   "a pressure input is given (then relative to 220000 Pa)");
    }
  }

  // MF 5.2 and PAC2002 files may list NOMPRES = 0 (no pressure terms in the model), which the
  // core's dpi = (p − NOMPRES)/NOMPRES cannot take: the pressure terms are switched off instead.
  if (model.model != tir::TirModel::kMf61 && model.model != tir::TirModel::kMf62 &&
      (!(result.params.nompres_pa > 0.0) || !(result.params.inflpres_pa > 0.0))) {
    const tir::Entry* e = file.find_any(!(result.params.nompres_pa > 0.0) ? "NOMPRES" : "INFLPRES");
    add_line(result.warning,
             file.origin() + ":" + std::to_string(e != nullptr ? e->line : 0) +
                 ": NOMPRES = " + tir::format_number(result.params.nompres_pa) + ", INFLPRES = " +
                 tir::format_number(result.params.inflpres_pa) + ": " + model.name +
                 " has no pressure terms; evaluated without them (both taken as 220000 Pa)");
    result.params.nompres_pa = 220000.0;
    result.params.inflpres_pa = 220000.0;
  }
  // MF 5.2 and PAC2002 have no pressure terms, but the core (as MFeval) applies MF 6.1's to a
  // file whose INFLPRES differs from its NOMPRES: said, with the coefficients that act.
  if (model.model != tir::TirModel::kMf61 && model.model != tir::TirModel::kMf62 &&
      file.find_any("INFLPRES") != nullptr && file.find_any("NOMPRES") != nullptr &&
      std::fabs(result.params.inflpres_pa - result.params.nompres_pa) >
          1e-9 * std::fabs(result.params.nompres_pa)) {
    std::string given;
    for (const char* key :
         {"PFZ1", "PCFX1", "PCFX2", "PCFX3", "PCFY1", "PCFY2", "PCFY3", "PPX1", "PPX2", "PPX3",
          "PPX4", "PPMX1", "PPY1", "PPY2", "PPY3", "PPY4", "PPY5", "PPZ1", "PPZ2"}) {
      const std::optional<double> v = file.number_any(key);
      if (v && std::fabs(*v) > 0.0) given += std::string(given.empty() ? "" : ", ") + key;
    }
    const tir::Entry* e = file.find_any("INFLPRES");
    add_line(result.warning,
             file.origin() + ":" + std::to_string(e->line) + ": " + model.name +
                 " has no pressure terms, but INFLPRES (" +
                 tir::format_number(result.params.inflpres_pa) + " Pa) differs from NOMPRES (" +
                 tir::format_number(result.params.nompres_pa) +
                 " Pa): evaluated with MF 6.1's pressure terms at INFLPRES, as MFeval does (" +
                 (given.empty() ? std::string("the file gives none: MF 6.1's defaults")
                                : "the file's " + given + "; MF 6.1's defaults for the rest") +
                 "); INFLPRES = NOMPRES gives the model itself");
  }

  std::optional<std::string> side = file.text_any("TYRESIDE");
  // Blanks inside the quotes ('Right ', written by some tools' fixed-width fields) are not part
  // of the side: 'Right ' was evaluated as LEFT.
  if (side) side = std::string(host::text::trim_blanks(*side));
  result.params.tyre_side =
      side && upper(*side) == "RIGHT" ? mf::TyreSide::right : mf::TyreSide::left;
  if (side && upper(*side) != "RIGHT" && upper(*side) != "LEFT" && upper(*side) != "SYMMETRIC") {
    add_line(result.warning, file.origin() + ":" + std::to_string(file.find_any("TYRESIDE")->line) +
                                 ": TYRESIDE = '" + host::text::excerpt(*side) +
                                 "' is none of LEFT, RIGHT, SYMMETRIC: evaluated as LEFT "
                                 "(the file's own axes)");
  }
  check_mf_parameters(result.params, file, result.warning);
  warn_unmodelled_keys(file, model.name, result.warning);
  warn_other_model_keys(file, model, result.warning);
  return result;
}

MfTirParameters load_mf_parameters(const std::filesystem::path& path) {
  return mf_parameters_from_tir(tir::read_tyre_property_file(path));
}

}  // namespace tread::tyre
