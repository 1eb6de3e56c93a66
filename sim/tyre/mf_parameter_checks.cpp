#include "tyre/mf_parameter_checks.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "tir/tir_units.hpp"

namespace tread::tyre {

namespace {

int line_of(const tir::TirFile& file, const char* key) {
  const tir::Entry* e = file.find_any(key);
  return e != nullptr ? e->line : 0;
}

bool is_zero(double v) noexcept {
  return !(v < 0.0 || v > 0.0);
}

std::string value_text(double v) {
  return tir::format_number(v);
}

[[noreturn]] void fail(const tir::TirFile& file, const char* key, const std::string& what) {
  throw tir::TirError(file.origin(), line_of(file, key), what);
}

void positive(const tir::TirFile& file, const char* key, double v, const char* why) {
  if (!(v > 0.0)) {
    fail(file, key, std::string(key) + " = " + value_text(v) + " must be > 0 (" + why + ")");
  }
}

void ordered(const tir::TirFile& file, const char* min_key, double min, const char* max_key,
             double max) {
  if (!(max > min)) {
    // Name the line of a key the file has; a key it lacks took its default.
    const bool has_max = file.find_any(max_key) != nullptr;
    const bool has_min = file.find_any(min_key) != nullptr;
    const auto describe = [](const char* key, double v, bool present) {
      return std::string(key) + " = " + value_text(v) + (present ? "" : " (absent: default)");
    };
    fail(file, has_max || !has_min ? max_key : min_key,
         describe(max_key, max, has_max) + " is not above " + describe(min_key, min, has_min) +
             " (the range is empty)");
  }
}

void warn(std::string& warning, const tir::TirFile& file, const char* key,
          const std::string& what) {
  if (!warning.empty()) warning += "\n";
  warning += file.origin() + ":" + std::to_string(line_of(file, key)) + ": " + what;
}

}  // namespace

void check_mf_parameters(const mf::MfParameters<double>& p, const tir::TirFile& file,
                         std::string& warning) {
  positive(file, "FNOMIN", p.fnomin_n, "the forces are scaled by it");
  positive(file, "LFZO", p.lfzo, "it scales FNOMIN");
  positive(file, "UNLOADED_RADIUS", p.unloaded_radius_m, "the moments and radii need it");
  positive(file, "VERTICAL_STIFFNESS", p.vertical_stiffness_npm,
           "the deflection and loaded radius divide by it");
  positive(file, "LONGVL", p.longvl_mps, "speeds are taken relative to it");
  if (is_zero(p.breff) && is_zero(p.dreff) && is_zero(p.freff)) {
    fail(file, "BREFF",
         "BREFF, DREFF and FREFF are all 0: the effective rolling radius law is undefined");
  }
  positive(file, "Q_RE0", p.q_re0, "the free radius R0·Q_RE0 sets the rolling and loaded radii");
  {
    // Re at FNOMIN standing still: R0·Q_RE0 − (Fz0/Cz)·(DREFF·atan(BREFF) + FREFF). At or below
    // 0 the rolling radius and ω of every load about the nominal one are nonsense.
    const double deflection_m =
        (p.fnomin_n / p.vertical_stiffness_npm) * (p.dreff * std::atan(p.breff) + p.freff);
    const double re_m = p.unloaded_radius_m * p.q_re0 - deflection_m;
    if (!(re_m > 0.0)) {
      char re_text[32];
      std::snprintf(re_text, sizeof re_text, "%.4g", re_m);
      fail(file, file.find_any("Q_RE0") != nullptr ? "Q_RE0" : "UNLOADED_RADIUS",
           "the effective rolling radius at FNOMIN, UNLOADED_RADIUS·Q_RE0 − (FNOMIN/"
           "VERTICAL_STIFFNESS)·(DREFF·atan(BREFF) + FREFF) = " +
               std::string(re_text) + " m, is not above 0");
    }
  }
  if (is_zero(p.pcx1 * p.lcx)) {
    fail(file, "PCX1", "PCX1 · LCX = 0: the Fx stiffness factor Bx = Kx/(Cx·Dx) divides by it");
  }
  if (is_zero(p.pcy1 * p.lcy)) {
    fail(file, "PCY1", "PCY1 · LCY = 0: the Fy stiffness factor By = Ky/(Cy·Dy) divides by it");
  }
  ordered(file, "FZMIN", p.fzmin_n, "FZMAX", p.fzmax_n);
  ordered(file, "KPUMIN", p.kpumin, "KPUMAX", p.kpumax);
  ordered(file, "ALPMIN", p.alpmin_rad, "ALPMAX", p.alpmax_rad);
  ordered(file, "CAMMIN", p.cammin_rad, "CAMMAX", p.cammax_rad);
  if (p.fit_type == mf::FitType::mf61 || p.fit_type == mf::FitType::mf62) {
    positive(file, "NOMPRES", p.nompres_pa, "the pressure terms divide by it");
    positive(file, "INFLPRES", p.inflpres_pa, "it is the pressure used without a pressure input");
    ordered(file, "PRESMIN", p.presmin_pa, "PRESMAX", p.presmax_pa);
    if (!(p.width_m > 0.0)) {
      warn(warning, file, "WIDTH",
           "WIDTH = " + value_text(p.width_m) + ": the contact width will be meaningless");
    }
  }
  if (!(p.vxlow_mps > 0.0)) {
    warn(warning, file, "VXLOW",
         "VXLOW = " + value_text(p.vxlow_mps) + ": no low-speed smoothing of the slips");
  }
  // A slip range that excludes 0: every figure at zero slip (stiffnesses, the trail, the peaks'
  // search from 0) would be taken at the range's end instead, and said as if at 0.
  const auto contains_zero = [&](const char* min_key, double min, const char* max_key, double max) {
    if (min > 0.0 || max < 0.0) {
      const bool min_off = min > 0.0;
      fail(file, min_off ? min_key : max_key,
           std::string(min_key) + "…" + max_key + " = " + value_text(min) + "…" + value_text(max) +
               " does not contain 0 (zero slip would be evaluated at " +
               value_text(min_off ? min : max) + ")");
    }
  };
  contains_zero("KPUMIN", p.kpumin, "KPUMAX", p.kpumax);
  contains_zero("ALPMIN", p.alpmin_rad, "ALPMAX", p.alpmax_rad);
  if (p.cammin_rad > 0.0 || p.cammax_rad < 0.0) {
    warn(warning, file, p.cammin_rad > 0.0 ? "CAMMIN" : "CAMMAX",
         "CAMMIN…CAMMAX = " + value_text(p.cammin_rad) + "…" + value_text(p.cammax_rad) +
             " rad does not contain 0: γ = 0 is evaluated at the range's end");
  }
  // Values no tyre has, in SI after the [UNITS] conversion: a unit the section names wrongly
  // (LENGTH = 'mm' on a file in metres gave R0 = 0.39 mm without a word).
  const auto plausible = [&](const char* key, double v, double lo, double hi, const char* unit,
                             const char* what) {
    if (const std::string w = tir::implausible_value(file, key, v, lo, hi, unit, what);
        !w.empty()) {
      warn(warning, file, key, w);
    }
  };
  plausible("UNLOADED_RADIUS", p.unloaded_radius_m, 0.05, 2.5, "m", "a tyre's free radius");
  plausible("FNOMIN", p.fnomin_n, 50.0, 1e6, "N", "a tyre's nominal load");
  plausible("LONGVL", p.longvl_mps, 0.5, 150.0, "m/s", "a measuring speed");
  plausible("VXLOW", p.vxlow_mps, 0.1, 10.0, "m/s", "a low-speed limit");
  plausible("VERTICAL_STIFFNESS", p.vertical_stiffness_npm, 1e4, 1e8, "N/m",
            "a tyre's vertical stiffness");
  if (p.fit_type == mf::FitType::mf61 || p.fit_type == mf::FitType::mf62) {
    plausible("NOMPRES", p.nompres_pa, 2e4, 3e6, "Pa", "a tyre's nominal pressure");
    plausible("INFLPRES", p.inflpres_pa, 2e4, 3e6, "Pa", "a tyre's pressure");
    plausible("PRESMIN", p.presmin_pa, 1e4, 3e6, "Pa", "a tyre's pressure");
    plausible("PRESMAX", p.presmax_pa, 2e4, 1e7, "Pa", "a tyre's pressure");
    plausible("WIDTH", p.width_m, 0.02, 2.0, "m", "a tyre's width");
    // The pressure used where the input gives none is INFLPRES clamped to the range, as any
    // pressure is: said, since the file names another (500 kPa above a 400 kPa PRESMAX was
    // evaluated at 400 kPa under status ok).
    if (p.inflpres_pa < p.presmin_pa || p.inflpres_pa > p.presmax_pa) {
      const double used = p.inflpres_pa < p.presmin_pa ? p.presmin_pa : p.presmax_pa;
      warn(warning, file, "INFLPRES",
           "INFLPRES = " + value_text(p.inflpres_pa) + " Pa lies outside PRESMIN…PRESMAX (" +
               value_text(p.presmin_pa) + "…" + value_text(p.presmax_pa) +
               " Pa): without a pressure input the tyre is evaluated at " + value_text(used) +
               " Pa");
    }
    // The structural stiffnesses give Cx, Cy and the relaxation lengths σ = K/C (MF 6.x): at or
    // below 0 those are meaningless (σ printed positive from a negative C, 0 from C = 0, where
    // the node's --relaxation takes 0 for "no lag").
    for (const auto& [key, v] : {std::pair{"LONGITUDINAL_STIFFNESS", p.longitudinal_stiffness_npm},
                                 std::pair{"LATERAL_STIFFNESS", p.lateral_stiffness_npm}}) {
      if (file.find_any(key) == nullptr) continue;
      if (!(v > 0.0)) {
        warn(warning, file, key,
             std::string(key) + " = " + value_text(v) +
                 ": the relaxation lengths and the structural stiffnesses Cx, Cy computed from it "
                 "are meaningless");
      } else {
        plausible(key, v, 1e4, 1e8, "N/m", "a tyre's structural stiffness");
      }
    }
  }
  if (p.fnomin_n < p.fzmin_n || p.fnomin_n > p.fzmax_n) {
    warn(warning, file, "FNOMIN",
         "FNOMIN = " + value_text(p.fnomin_n) + " lies outside FZMIN…FZMAX (" +
             value_text(p.fzmin_n) + "…" + value_text(p.fzmax_n) + ")");
  }
}

}  // namespace tread::tyre
