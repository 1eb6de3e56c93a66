#include "tir/pac_coefficients.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>

#include "io/text_line.hpp"
#include "tir/tir_model.hpp"
#include "tir/tir_units.hpp"

namespace tread::tir {

namespace {

constexpr const char* kLat = "LATERAL_COEFFICIENTS";
constexpr const char* kLon = "LONGITUDINAL_COEFFICIENTS";
constexpr const char* kAli = "ALIGNING_COEFFICIENTS";

template <std::size_t N>
void read_set(const TirFile& f, const char* section, char letter, std::array<double, N>& out,
              std::vector<std::string>& missing) {
  for (std::size_t i = 0; i < N; ++i) {
    const std::string key = std::string(1, letter) + std::to_string(i);
    if (const auto v = f.number(section, key)) {
      out[i] = *v;
    } else {
      out[i] = 0.0;
      missing.push_back(std::string(section) + "." + key);
    }
  }
}

template <std::size_t N>
void write_set(TirFile& f, const char* section, char letter, const std::array<double, N>& in) {
  for (std::size_t i = 0; i < N; ++i) {
    f.set(section, std::string(1, letter) + std::to_string(i), in[i]);
  }
}

double optional_any(const TirFile& f, const char* key, std::vector<std::string>& missing) {
  if (const auto v = number_si(f, read_units(f), "", key)) return *v;
  missing.emplace_back(key);
  return 0.0;
}

// The file's own input limits where it gives them (FZMAX, KPUMIN/KPUMAX, ALPMIN/ALPMAX,
// CAMMIN/CAMMAX; else the core's defaults): inputs beyond them are clamped and said `out of range`.
// The core's limits are symmetric (|κ| ≤ κmax): an asymmetric range takes its smaller side, so
// that nothing outside the file's range is evaluated as `ok`; said in the note.
void read_limits(const TirFile& file, PacCoefficients& out) {
  const UnitSystem units = read_units(file);
  const auto value = [&](const char* key) { return number_si(file, units, "", key); };
  std::string asymmetric;
  const auto symmetric = [&](const char* min_key, const char* max_key, double& limit) {
    const std::optional<double> lo = value(min_key);
    const std::optional<double> hi = value(max_key);
    if (!lo && !hi) return;
    double m = std::numeric_limits<double>::infinity();
    if (lo) m = std::min(m, -*lo);
    if (hi) m = std::min(m, *hi);
    if (!(m > 0.0)) {
      const Entry* e = file.find_any(hi ? max_key : min_key);
      throw TirError(file.origin(), e != nullptr ? e->line : 0,
                     std::string(min_key) + "…" + max_key + " does not contain 0");
    }
    if (lo && hi && std::fabs(-*lo - *hi) > 1e-12 * m) {
      asymmetric += std::string(asymmetric.empty() ? "" : ", ") + min_key + "…" + max_key;
    }
    limit = std::min(limit, m);
  };
  if (const auto fzmax = value("FZMAX")) {
    if (!(*fzmax > 0.0)) {
      throw TirError(file.origin(), file.find_any("FZMAX")->line, "FZMAX must be > 0");
    }
    out.params.fz_max_n = std::min(out.params.fz_max_n, *fzmax);
    out.fzmax_given = true;
  }
  symmetric("KPUMIN", "KPUMAX", out.params.kappa_max);
  symmetric("ALPMIN", "ALPMAX", out.params.alpha_max_rad);
  symmetric("CAMMIN", "CAMMAX", out.params.gamma_max_rad);
  if (!asymmetric.empty()) {
    out.note += std::string(out.note.empty() ? "" : "; ") + asymmetric +
                ": PAC89/PAC94 limits are symmetric, the smaller side is taken both ways";
  }
}

// The peak factors D of Fx, Fy and Mz are Fz·(k1·Fz + k2) (Fz in kN): where k1 and k2 differ in
// sign, D changes sign at Fz = −k2/k1, and above it the curve is the mirror image of the one
// below (a driving slip giving a braking force, under ok). The load limit is brought down to the
// lowest such Fz, so that rows above it are clamped and said out of range; warned about.
void limit_load_to_unchanged_peaks(PacCoefficients& out) {
  const pac::PacParams<double>& p = out.params;
  struct Peak {
    const char* output;
    const char* keys;
    double k1, k2;
  };
  const std::array<Peak, 3> peaks{{{"Fx", "B1, B2", p.b[1], p.b[2]},
                                   {"Fy", "A1, A2", p.a[1], p.a[2]},
                                   {"Mz", "C1, C2", p.c[1], p.c[2]}}};
  const Peak* first = nullptr;
  double lowest_n = out.params.fz_max_n;
  for (const Peak& k : peaks) {
    if (!(k.k1 * k.k2 < 0.0)) continue;
    const double fz_n = -k.k2 / k.k1 * 1000.0;
    if (fz_n < lowest_n) {
      lowest_n = fz_n;
      first = &k;
    }
  }
  if (first == nullptr) return;
  std::ostringstream m;
  m.precision(6);
  m << "the peak of " << first->output << " changes sign at Fz = " << lowest_n << " N ("
    << first->keys << ": D = Fz·(" << first->k1 << "·Fz + " << first->k2
    << "), Fz in kN), below the load limit " << out.params.fz_max_n << " N"
    << (out.fzmax_given ? "" : " (the file gives no FZMAX)")
    << ": loads above it are clamped to it and said out of range";
  out.warnings.push_back(m.str());
  out.params.fz_max_n = lowest_n;
}

// The curvature factors E at γ = 0 over the load range (PAC94's on both sides of the curve): the
// core takes E above 1 as 1 (beyond it the Magic Formula's curve folds), so such a file's curves
// are not its coefficients' own; warned about with the worst load.
void warn_curvature_above_one(PacCoefficients& out) {
  const pac::PacParams<double>& p = out.params;
  struct Worst {
    double e = -1e300;
    double fz_n = 0.0;
    double from_n = 0.0;  // the lowest load where E > 1 (the loads rise)
  };
  Worst fx, fy, mz;
  const auto keep = [](Worst& w, double e, double fz_n) {
    if (e > 1.0 && !(w.from_n > 0.0)) w.from_n = fz_n;
    if (e > w.e) {
      w.e = e;
      w.fz_n = fz_n;
    }
  };
  constexpr int kSteps = 200;
  for (int i = 1; i <= kSteps; ++i) {
    const double fz_n = p.fz_max_n * i / kSteps;
    const double f = fz_n / 1000.0;
    const double ex = p.b[6] * f * f + p.b[7] * f + p.b[8];
    const double ey = p.a[6] * f + p.a[7];
    const double ez = p.c[7] * f * f + p.c[8] * f + p.c[9];
    for (const double side : {-1.0, 1.0}) {
      keep(fx, out.pac94 ? ex * (1.0 - p.b[13] * side) : ex, fz_n);
      keep(fy, out.pac94 ? ey * (1.0 - p.a[17] * side) : ey, fz_n);
      keep(mz, out.pac94 ? ez * (1.0 - p.c[20] * side) : ez, fz_n);
    }
  }
  const auto say = [&](const char* output, const char* keys, const Worst& w) {
    if (!(w.e > 1.0)) return;
    std::ostringstream m;
    m.precision(4);
    m << "the curvature E of " << output << " (" << keys << ") is above 1 from Fz = " << w.from_n
      << " N (" << w.e << " at " << w.fz_n
      << " N): E above 1 is taken as 1 (the curve would fold), so the " << output
      << " curves there are not the coefficients' own";
    out.warnings.push_back(m.str());
  };
  say("Fx", out.pac94 ? "B6…B8, B13" : "B6…B8", fx);
  say("Fy", out.pac94 ? "A6, A7, A17" : "A6, A7", fy);
  say("Mz", out.pac94 ? "C7…C9, C20" : "C7…C9", mz);
}

}  // namespace

PacCoefficients pac_from_tir(const TirFile& file) {
  const DetectedModel model = detect_model(file);
  if (model.is_magic_formula()) {
    const Entry* e = file.find_any("FITTYP");
    throw TirError(file.origin(), e != nullptr ? e->line : 0,
                   "this is " + std::string(model.name.rfind("MF", 0) == 0 ? "an " : "a ") +
                       model.name + " file, not PAC89/PAC94: use tread mf eval");
  }
  PacCoefficients out;
  out.pac94 = model.model == TirModel::kPac94;
  out.note = model.note;
  read_set(file, kLat, 'A', out.params.a, out.missing);
  read_set(file, kLon, 'B', out.params.b, out.missing);
  read_set(file, kAli, 'C', out.params.c, out.missing);
  const std::size_t total = out.params.a.size() + out.params.b.size() + out.params.c.size();
  if (out.missing.size() == total) {
    // The line that made it a PAC file, else the first section's.
    const Entry* format = file.find_any("PROPERTY_FILE_FORMAT");
    const int line = format != nullptr          ? format->line
                     : !file.sections().empty() ? file.sections().front().line
                                                : 0;
    throw TirError(file.origin(), line,
                   "no PAC coefficients: expected [LATERAL_COEFFICIENTS] A0…, "
                   "[LONGITUDINAL_COEFFICIENTS] B0…, [ALIGNING_COEFFICIENTS] C0…");
  }
  out.params.unloaded_radius_m = optional_any(file, "UNLOADED_RADIUS", out.missing);
  out.params.rolling_resistance = optional_any(file, "ROLLING_RESISTANCE", out.missing);
  out.params.lateral_stiffness_npm = optional_any(file, "LATERAL_STIFFNESS", out.missing);
  read_limits(file, out);
  // Values no tyre has once [UNITS] is applied (R0 = 0.46 mm gave Mx, My 1000 times too small
  // without a word).
  for (const auto& [key, v, lo, hi, unit, what] :
       {std::tuple{"UNLOADED_RADIUS", out.params.unloaded_radius_m, 0.05, 2.5, "m",
                   "a tyre's free radius"},
        std::tuple{"LATERAL_STIFFNESS", out.params.lateral_stiffness_npm, 1e4, 1e8, "N/m",
                   "a tyre's lateral stiffness"}}) {
    if (std::string w = implausible_value(file, key, v, lo, hi, unit, what); !w.empty()) {
      out.warnings.push_back(std::move(w));
    }
  }
  limit_load_to_unchanged_peaks(out);
  warn_curvature_above_one(out);
  if (const auto side = file.text_any("TYRESIDE")) {
    for (const char c : host::text::trim_blanks(*side))
      out.tyreside += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return out;
}

void pac_to_tir(const pac::PacParams<double>& p, TirFile& file) {
  write_set(file, kLat, 'A', p.a);
  write_set(file, kLon, 'B', p.b);
  write_set(file, kAli, 'C', p.c);
  set_si(file, "DIMENSION", "UNLOADED_RADIUS", p.unloaded_radius_m);
  file.set("PAC_EXTRA", "ROLLING_RESISTANCE", p.rolling_resistance);
  set_si(file, "PAC_EXTRA", "LATERAL_STIFFNESS", p.lateral_stiffness_npm);
}

namespace {

// The index of a Chrono JSON coefficient key ("a0", "a17" for letter 'a'): the letter, then
// digits without a leading zero; nothing for any other key.
std::optional<std::size_t> coefficient_index(const std::string& key, char letter) {
  if (key.size() < 2 || key.size() > 4 || key.front() != letter) return std::nullopt;
  if (key[1] == '0' && key.size() > 2) return std::nullopt;
  std::size_t index = 0;
  const auto [end, ec] = std::from_chars(key.data() + 1, key.data() + key.size(), index);
  if (ec != std::errc{} || end != key.data() + key.size()) return std::nullopt;
  return index;
}

}  // namespace

PacCoefficients pac_from_chrono_json(const std::filesystem::path& path) {
  const std::string origin = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw TirError(origin, 0, "cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const nlohmann::json::parse_error& e) {
    // Turn the byte offset into a line number.
    const std::size_t upto = std::min<std::size_t>(e.byte, text.size());
    const auto line =
        1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(upto), '\n');
    throw TirError(origin, static_cast<int>(line), "JSON: " + host::text::excerpt(e.what(), 240));
  } catch (const nlohmann::json::exception& e) {
    // e.g. a number beyond double's range (1e999): no position given
    throw TirError(origin, 0, "JSON: " + host::text::excerpt(e.what(), 240));
  }
  PacCoefficients out;
  auto read_obj = [&](const char* object, char letter, auto& arr) {
    if (!j.contains(object) || !j[object].is_object()) {
      throw TirError(origin, 0, std::string("missing object \"") + object + "\"");
    }
    const auto& o = j[object];
    for (std::size_t i = 0; i < arr.size(); ++i) {
      const std::string key = std::string(1, letter) + std::to_string(i);
      if (o.contains(key)) {
        if (!o[key].is_number()) {
          throw TirError(origin, 0, std::string(object) + "." + key + " is not a number");
        }
        arr[i] = o[key].template get<double>();
      } else {
        arr[i] = 0.0;
        out.missing.push_back(std::string(object) + "." + key);
      }
    }
    // A key the object holds that is none of these: misspelt ('A0', 'a 0'), or beyond the
    // model's count ('a18'). It showed only as a missing value among others, its number unused.
    for (const auto& item : o.items()) {
      const std::string& k = item.key();
      const std::optional<std::size_t> index = coefficient_index(k, letter);
      const bool read = index && *index < arr.size();
      if (read) continue;
      std::string lowered = k;
      for (char& c : lowered) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      const std::optional<std::size_t> lowered_index = coefficient_index(lowered, letter);
      const bool case_only = lowered != k && lowered_index && *lowered_index < arr.size();
      out.warnings.push_back("\"" + std::string(object) + "\" has a key tread does not read: '" +
                             host::text::excerpt(k) + "'" +
                             (case_only ? " (keys are case-sensitive: '" + lowered + "'?)"
                                        : " (it reads " + std::string(1, letter) + "0 … " +
                                              std::string(1, letter) +
                                              std::to_string(arr.size() - 1) + ")"));
    }
  };
  read_obj("Lateral Coefficients", 'a', out.params.a);
  read_obj("Longitudinal Coefficients", 'b', out.params.b);
  read_obj("Aligning Coefficients", 'c', out.params.c);
  auto design = [&](const char* key) {
    if (j.contains("Design Parameters") && j["Design Parameters"].contains(key)) {
      if (!j["Design Parameters"][key].is_number()) {
        // A value written as a string ("261065") was taken as missing: 0 under ok.
        throw TirError(origin, 0, std::string("Design Parameters.") + key + " is not a number");
      }
      return j["Design Parameters"][key].get<double>();
    }
    out.missing.push_back(std::string("Design Parameters.") + key);
    return 0.0;
  };
  out.params.unloaded_radius_m = design("Unloaded Radius");
  out.params.rolling_resistance = design("Rolling Resistance");
  out.params.lateral_stiffness_npm = design("Lateral Stiffness");
  if (j.is_object()) {
    for (const auto& [key, value] : j.items()) {
      if (key == "Name" || key == "Type" || key == "Template" || key == "Lateral Coefficients" ||
          key == "Longitudinal Coefficients" || key == "Aligning Coefficients") {
        continue;
      }
      if (key == "Design Parameters" && value.is_object()) {
        for (const auto& [k, v] : value.items()) {
          static_cast<void>(v);
          if (k != "Unloaded Radius" && k != "Rolling Resistance" && k != "Lateral Stiffness") {
            out.not_carried.push_back("Design Parameters." + host::text::excerpt(k));
          }
        }
        continue;
      }
      out.not_carried.push_back(host::text::excerpt(key));
    }
  }
  limit_load_to_unchanged_peaks(out);
  warn_curvature_above_one(out);
  return out;
}

}  // namespace tread::tir
