#include "mf/mf_parameters_from_tir.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <span>

#include "tir/tir_keys.hpp"
#include "tir/tir_units.hpp"

namespace tread::mf {

namespace {

constexpr std::array<tir::KeyDefault, static_cast<std::size_t>(kMfParameterCount)> kKeys = {{
#define TREAD_MF_KEY_DEFAULT(member, section, key, value, description) {"", key, value},
    TREAD_MF_PARAMETER_LIST(TREAD_MF_KEY_DEFAULT)
#undef TREAD_MF_KEY_DEFAULT
}};

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

MfTirParameters mf_parameters_from_tir(const tir::TirFile& file) {
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
  result.missing = resolved.missing;
  result.warning = resolved.warning(file.origin());
  for (const auto& w : file.warnings()) {
    if (!result.warning.empty()) result.warning += "\n";
    result.warning += w;
  }

  const std::optional<double> fittyp = file.number_any("FITTYP");
  if (!fittyp) {
    result.params.fit_type = FitType::pac2002;
    if (!result.warning.empty()) result.warning += "\n";
    result.warning +=
        file.origin() +
        ": no FITTYP: evaluated as Adams PAC2002 (MF 5.2 equations with LGAX/LGAY/LGAZ)";
  } else {
    const double f = *fittyp;
    long code = std::lround(f);
    if (std::fabs(f - static_cast<double>(code)) > 1e-9) code = -1;
    if (code == 6 || code == 21) {
      result.params.fit_type = FitType::mf52;
    } else if (code == 61) {
      result.params.fit_type = FitType::mf61;
    } else if (code == 62) {
      result.params.fit_type = FitType::mf62;
    } else {
      const tir::Entry* entry = file.find_any("FITTYP");
      throw tir::TirError(
          file.origin(), entry != nullptr ? entry->line : 0,
          "FITTYP " + tir::format_number(f) +
              " is not a Magic Formula 5.2/6.1/6.2 file (expected 6, 21, 61 or 62)");
    }
  }
  const std::optional<std::string> side = file.text_any("TYRESIDE");
  result.params.tyre_side = side && upper(*side) == "RIGHT" ? TyreSide::right : TyreSide::left;
  return result;
}

MfTirParameters load_mf_parameters(const std::filesystem::path& path) {
  return mf_parameters_from_tir(tir::read_tir(path));
}

}  // namespace tread::mf
