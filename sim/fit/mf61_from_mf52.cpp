#include "fit/mf61_from_mf52.hpp"

#include <algorithm>
#include <cmath>

#include "fit/mf_coefficients.hpp"
#include "tir/tir_units.hpp"

namespace tread::fit {

namespace {

// Keys only MF 6.2 reads (TNO's MF 6.1 sample file has none of them).
const std::vector<std::string>& mf62_only_keys() {
  static const std::vector<std::string> keys = {"Q_FCY2", "Q_CAM1", "Q_CAM2", "Q_CAM3",
                                                "Q_FYS1", "Q_FYS2", "Q_FYS3"};
  return keys;
}

bool listed(const std::vector<std::string>& keys, const std::string& key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

std::string number(double v) {
  return tir::format_number(v);
}

}  // namespace

const std::vector<std::string>& mf52_only_keys() {
  static const std::vector<std::string> keys = {"LGAX",  "LGAY", "LGAZ", "PHY3", "PTX1",
                                                "PTX2",  "PTX3", "PTY1", "PTY2", "LSGKP",
                                                "LSGAL", "Q_A1", "Q_A2"};
  return keys;
}

mf::MfParameters<double> mf61_start_from_mf52(const mf::MfParameters<double>& p,
                                              std::vector<std::string>& notes) {
  mf::MfParameters<double> q = p;
  q.fit_type = mf::FitType::mf61;
  if (p.fit_type == mf::FitType::pac2002) {
    const std::pair<const char*, double> scalings[] = {
        {"LGAX", p.lgax}, {"LGAY", p.lgay}, {"LGAZ", p.lgaz}};
    for (const auto& [key, value] : scalings) {
      if (std::fabs(value - 1.0) > 0.0) {
        notes.push_back(std::string(key) + " = " + number(value) +
                        " (PAC2002 camber scaling) has no MF 6.1 counterpart: its effect is "
                        "left to the fit's camber stages");
      }
    }
  }
  if (std::fabs(p.phy3) > 0.0) {
    notes.push_back("PHY3 = " + number(p.phy3) +
                    " (MF 5.2 camber shift of Fy) has no MF 6.1 counterpart: the camber stiffness "
                    "PKY6/PKY7 starts at its book value");
  }
  return q;
}

std::vector<std::string> rewrite_as_mf61(tir::TirFile& file, const mf::MfParameters<double>& p) {
  std::vector<std::string> removed;
  for (const std::string& key : mf52_only_keys()) {
    for (tir::Section& s : file.sections()) {
      if (s.find(key) != nullptr && file.erase(s.name, key)) removed.push_back(key);
    }
  }
  std::string model_section = "MODEL";
  for (const tir::Section& s : file.sections()) {
    if (s.find("FITTYP") != nullptr || s.find("PROPERTY_FILE_FORMAT") != nullptr) {
      model_section = s.name;
      break;
    }
  }
  file.set(model_section, "FITTYP", 61.0);
  file.set_text(model_section, "PROPERTY_FILE_FORMAT", "USER");
  for (int i = 0; i < static_cast<int>(mf::kMfParameterCount); ++i) {
    const std::string key = coefficient_key(i);
    if (listed(mf52_only_keys(), key) || listed(mf62_only_keys(), key)) continue;
    if (file.find_any(key) != nullptr) continue;
    // In the file's own units ([UNITS] may be mm, kN, kPa): NOMPRES, the structural stiffnesses
    // and BOTTOM_OFFST are dimensional.
    tir::set_si(file, coefficient_section(i), key, coefficient(p, i));
  }
  return removed;
}

}  // namespace tread::fit
