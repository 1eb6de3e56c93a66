#include "tyre/mf_unmodelled_keys.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string_view>

#include "mf/mf_parameters.hpp"

namespace tread::tyre {

namespace {

constexpr auto kModelKeys = std::to_array<std::string_view>({
#define TREAD_MF_KEY_NAME(member, section, key, value, description) key,
    TREAD_MF_PARAMETER_LIST(TREAD_MF_KEY_NAME)
#undef TREAD_MF_KEY_NAME
});

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

}  // namespace

void warn_unmodelled_keys(const tir::TirFile& file, const std::string& model_name,
                          std::string& warning) {
  for (const tir::Section& section : file.sections()) {
    const std::string section_name = upper(section.name);
    if (!is_coefficient_section(section_name) || section.is_table()) continue;
    for (const tir::Entry* e : section.entries()) {
      const std::string key = upper(e->key);
      if (contains(kModelKeys, key) || contains(kNotSteadyState, key)) continue;
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
