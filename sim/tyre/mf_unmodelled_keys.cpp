#include "tyre/mf_unmodelled_keys.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <optional>
#include <string_view>

#include "mf/mf_parameters.hpp"

namespace tread::tyre {

namespace {

// The model's keys with the values tread takes where a file lacks them.
constexpr auto kModelKeys = std::to_array<tir::KeyDefault>({
#define TREAD_MF_KEY_DEFAULT(member, section, key, value, description) {"", key, value},
    TREAD_MF_PARAMETER_LIST(TREAD_MF_KEY_DEFAULT)
#undef TREAD_MF_KEY_DEFAULT
});

const tir::KeyDefault* model_key(std::string_view key) {
  const auto* k = std::find_if(kModelKeys.begin(), kModelKeys.end(),
                               [key](const tir::KeyDefault& d) { return d.key == key; });
  return k != kModelKeys.end() ? k : nullptr;
}

/// Keys of coefficient sections that only a transient or structural model uses, or that tread
/// derives itself: never a steady-state difference.
constexpr auto kNotSteadyState = std::to_array<std::string_view>({
    "Q_FZ1",                             // derived from VERTICAL_STIFFNESS and Q_FZ2
    "VERTICAL_DAMPING", "BOTTOM_STIFF",  // damping; bottoming beyond BOTTOM_OFFST
    "QTZ1", "MBELT", "LGYR",             // gyroscopic moment of the belt (transient)
});

/// What a known key that tread does not model does, for the message.
struct Known {
  std::string_view key;
  std::string_view what;
};
constexpr auto kKnown = std::to_array<Known>({
    {"LMUV", "friction decay with slip speed"},
    {"Q_FZ3", "vertical stiffness change with camber"},
    {"Q_CAM", "loaded radius change with camber"},
    {"MC_CONTOUR_A", "motorcycle contour ellipse"},
    {"MC_CONTOUR_B", "motorcycle contour ellipse"},
});

std::string upper(std::string_view text) {
  std::string u(text);
  for (char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return u;
}

bool contains(const auto& list, std::string_view key) {
  return std::find(list.begin(), list.end(), key) != list.end();
}

bool is_coefficient_section(const std::string& name) {
  constexpr std::string_view kSuffix = "_COEFFICIENTS";
  return name == "VERTICAL" || (name.size() > kSuffix.size() && name.ends_with(kSuffix));
}

// Keys of one Magic Formula generation that the others' equations in tread do not read (found
// by changing each key of the shipped MF 5.2, 6.1 and 6.2 files under each other FITTYP and
// comparing every output): an MF 6.1 or 6.2 file evaluated as MF 5.2 or PAC2002 still goes
// through its pressure, PKY4/PKY5, PEY5 and vertical terms, but not these.
struct OtherModelKey {
  std::string_view key;
  std::string_view model;  ///< the generation that reads it
  bool read_by_mf5x;       ///< MF 5.2 / PAC2002 equations read it
  bool read_by_mf61;       ///< MF 6.1 equations read it
  bool read_by_mf62;       ///< MF 6.2 equations read it
};
constexpr auto kOtherModelKeys = std::to_array<OtherModelKey>({
    {"PKY6", "MF 6.1/6.2", false, true, true},
    {"PKY7", "MF 6.1/6.2", false, true, true},
    {"PPY5", "MF 6.1/6.2", false, true, true},
    {"QSY5", "MF 6.1/6.2", false, true, true},
    {"QSY6", "MF 6.1/6.2", false, true, true},
    {"QSY7", "MF 6.1/6.2", false, true, true},
    {"QSY8", "MF 6.1/6.2", false, true, true},
    {"Q_FCY2", "MF 6.2", true, false, true},
    {"Q_CAM1", "MF 6.2", true, false, true},
    {"Q_CAM2", "MF 6.2", true, false, true},
    {"Q_CAM3", "MF 6.2", true, false, true},
    {"Q_FYS1", "MF 6.2", true, false, true},
    {"Q_FYS2", "MF 6.2", true, false, true},
    {"Q_FYS3", "MF 6.2", true, false, true},
    {"LGAX", "MF 5.2/PAC2002", true, false, false},
    {"LGAY", "MF 5.2/PAC2002", true, false, false},
    {"LGAZ", "MF 5.2/PAC2002", true, false, false},
    {"LSGKP", "MF 5.2/PAC2002", true, false, false},
    {"LSGAL", "MF 5.2/PAC2002", true, false, false},
    {"PTX1", "MF 5.2/PAC2002", true, false, false},
    {"PTX2", "MF 5.2/PAC2002", true, false, false},
    {"PTX3", "MF 5.2/PAC2002", true, false, false},
    {"PHY3", "MF 5.2/PAC2002", true, false, false},
    {"PTY1", "MF 5.2/PAC2002", true, false, false},
    {"PTY2", "MF 5.2/PAC2002", true, false, false},
});

}  // namespace

void warn_other_model_keys(const tir::TirFile& file, const tir::DetectedModel& model,
                           std::string& warning) {
  const bool mf5x = model.model == tir::TirModel::kMf50 || model.model == tir::TirModel::kMf52 ||
                    model.model == tir::TirModel::kPac2002;
  const bool mf61 = model.model == tir::TirModel::kMf61;
  const bool mf62 = model.model == tir::TirModel::kMf62;
  if (!mf5x && !mf61 && !mf62) return;
  std::size_t count = 0;
  std::string listed;
  std::string models;
  for (const tir::Section& section : file.sections()) {
    if (section.is_table()) continue;
    for (const tir::Entry* e : section.entries()) {
      const std::string key = upper(e->key);
      const auto* other = std::find_if(kOtherModelKeys.begin(), kOtherModelKeys.end(),
                                       [&key](const OtherModelKey& k) { return k.key == key; });
      if (other == kOtherModelKeys.end()) continue;
      if ((mf5x && other->read_by_mf5x) || (mf61 && other->read_by_mf61) ||
          (mf62 && other->read_by_mf62)) {
        continue;
      }
      const std::optional<double> v = tir::parse_number(e->value);
      if (!v || e->is_quoted()) continue;
      const tir::KeyDefault* d = model_key(key);
      const double neutral = d != nullptr ? d->value : 0.0;
      if (!(std::fabs(*v - neutral) > 0.0)) continue;  // the value tread assumes anyway
      if (models.find(other->model) == std::string::npos) {
        models += (models.empty() ? "" : ", ") + std::string(other->model);
      }
      listed += (count == 0 ? "" : ", ") + key + " (line " + std::to_string(e->line) + ")";
      ++count;
    }
  }
  if (count == 0) return;
  if (!warning.empty()) warning += "\n";
  warning += file.origin() + ": " + std::to_string(count) + " key" + (count == 1 ? "" : "s") +
             " of " + models + " with values of their own, which the " + model.name +
             " equations the file is evaluated with do not read: " + listed +
             "; is its FITTYP / PROPERTY_FILE_FORMAT right?";
}

void warn_unmodelled_keys(const tir::TirFile& file, const std::string& model_name,
                          std::string& warning) {
  for (const tir::Section& section : file.sections()) {
    const std::string section_name = upper(section.name);
    if (!is_coefficient_section(section_name) || section.is_table()) continue;
    for (const tir::Entry* e : section.entries()) {
      const std::string key = upper(e->key);
      if (model_key(key) != nullptr || contains(kNotSteadyState, key)) continue;
      const std::optional<double> v = tir::parse_number(e->value);
      if (!v || e->is_quoted()) continue;  // text: nothing to evaluate
      const bool scaling = section_name == "SCALING_COEFFICIENTS" && key != "LMUV";
      const double neutral = scaling ? 1.0 : 0.0;
      if (!(std::fabs(*v - neutral) > 0.0)) continue;
      const auto* known = std::find_if(kKnown.begin(), kKnown.end(),
                                       [&key](const Known& k) { return k.key == key; });
      std::string line = file.origin() + ":" + std::to_string(e->line) + ": " + e->key + " = " +
                         e->value + " is not in tread's " + model_name + " model";
      line += known != kKnown.end() ? " (" + std::string(known->what) + ")"
                                    : " ([" + section.name + "]: a key tread does not know)";
      line += ": the outputs are those of " + e->key + " = " + tir::format_number(neutral);
      if (!warning.empty()) warning += "\n";
      warning += line;
    }
  }
}

}  // namespace tread::tyre
