#include "tyre/tir_info.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "io/text_line.hpp"
#include "tir/pac_coefficients.hpp"
#include "tir/tir_model.hpp"
#include "tir/tir_units.hpp"
#include "tyre/mf_curve_checks.hpp"
#include "tyre/mf_parameters_from_tir.hpp"
#include "tyre/mf_tyre_figures.hpp"

namespace tread::tyre {

namespace {

std::string num(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

std::string deg(double rad) {
  return num(rad * 180.0 / std::numbers::pi) + "°";
}

std::string units_line(const tir::TirFile& file) {
  std::string out;
  for (const char* k : {"LENGTH", "FORCE", "ANGLE", "MASS", "TIME", "PRESSURE"}) {
    if (const auto t = file.text("UNITS", k)) {
      if (!out.empty()) out += ", ";
      out += std::string(k) + " '" + host::text::excerpt(*t) + "'";
    }
  }
  if (out.empty()) return "none given (SI assumed)";
  return out + (tir::read_units(file).is_si() ? "" : " (values below converted to SI)");
}

// Where μ(Fz) = (P1 + P2·dfz) changes sign inside [fzmin, fzmax], if it does.
void sign_change(std::ostream& w, const char* what, double p1, double p2, double fz0, double fzmin,
                 double fzmax) {
  if (!(p2 < 0.0 || p2 > 0.0)) return;
  const double fz = fz0 * (1.0 - p1 / p2);
  if (fz > fzmin && fz < fzmax) {
    w << "  warning: " << what << " peak changes sign at Fz = " << num(fz)
      << " N, below FZMAX = " << num(fzmax) << " N\n";
  }
}

}  // namespace

std::string tir_info_report(const std::filesystem::path& path) {
  const tir::TirFile file = tir::read_tyre_property_file(path);
  const tir::DetectedModel model = tir::detect_model(file);
  std::ostringstream out;
  out << "file: " << path.string() << '\n';
  const auto format = file.text_any("PROPERTY_FILE_FORMAT");
  const auto fittyp = file.text_any("FITTYP");
  out << "model: " << model.name << " (PROPERTY_FILE_FORMAT "
      << (format ? "'" + host::text::excerpt(*format) + "'" : "-") << ", FITTYP "
      << (fittyp ? host::text::excerpt(*fittyp) : "-") << ")\n";
  out << "units: " << units_line(file) << '\n';
  if (!model.is_magic_formula()) {
    const tir::PacCoefficients pac = tir::pac_from_tir(file);
    out << "R0: " << num(pac.params.unloaded_radius_m) << " m\n";
    out << "coefficients: "
        << pac.params.a.size() + pac.params.b.size() + pac.params.c.size() - pac.missing.size()
        << " given, " << pac.missing.size() << " taken as 0\n";
    out << "load limit: " << num(pac.params.fz_max_n) << " N\n";
    out << "warnings:";
    if (pac.warnings.empty()) out << " none";
    out << '\n';
    for (const std::string& w : pac.warnings) out << "  " << w << '\n';
    out << "evaluate with: tread pac eval --tir " << path.string() << '\n';
    return out.str();
  }
  const MfTirParameters loaded = mf_parameters_from_tir(file);
  const mf::MfParameters<double>& p = loaded.params;
  out << "FNOMIN: " << num(p.fnomin_n) << " N, R0: " << num(p.unloaded_radius_m)
      << " m, width: " << num(p.width_m) << " m\n";
  if (p.fit_type == mf::FitType::mf61 || p.fit_type == mf::FitType::mf62) {
    out << "pressure: NOMPRES " << num(p.nompres_pa) << " Pa, INFLPRES " << num(p.inflpres_pa)
        << " Pa (used when no pressure is given)\n";
  }
  out << "limits: Fz " << num(p.fzmin_n) << "…" << num(p.fzmax_n) << " N, κ " << num(p.kpumin)
      << "…" << num(p.kpumax) << ", α " << deg(p.alpmin_rad) << "…" << deg(p.alpmax_rad) << ", γ "
      << deg(p.cammin_rad) << "…" << deg(p.cammax_rad);
  if (p.fit_type == mf::FitType::mf61 || p.fit_type == mf::FitType::mf62) {
    out << ", p " << num(p.presmin_pa) << "…" << num(p.presmax_pa) << " Pa";
  }
  out << '\n';
  out << "defaulted keys (" << loaded.missing.size() << "):";
  for (const auto& k : loaded.missing) out << ' ' << k;
  out << '\n';
  mf::MfOptions o;
  const MfTyreFigures f = tyre_figures(p, o);
  out << "at FNOMIN (" << num(f.fz_n) << " N, " << num(f.vx_mps) << " m/s, γ = 0, pure slip):\n"
      << "  peak μx: drive "
      << (f.drive_in_range ? num(f.mux_drive) + " at κ = " + num(f.kappa_drive) +
                                 (f.kappa_drive_at_limit ? " (KPUMAX, the range's end)" : "")
                           : std::string("none (KPUMAX ≤ 0: no drive slip in the tyre's range)"))
      << ", brake "
      << (f.brake_in_range ? num(f.mux_brake) + " at κ = " + num(f.kappa_brake) +
                                 (f.kappa_brake_at_limit ? " (KPUMIN, the range's end)" : "")
                           : std::string("none (KPUMIN ≥ 0: no brake slip in the tyre's range)"))
      << '\n'
      << "  peak μy: " << num(f.muy) << " at α = " << deg(f.alpha_muy_rad)
      << (f.alpha_muy_at_limit ? " (ALPMIN/ALPMAX, the range's end)" : "") << '\n'
      << "  slip stiffness Kxκ: " << num(f.kxk_n) << " N\n"
      << "  cornering stiffness Kyα: " << num(f.kya_nprad)
      << " N/rad (−dFy/dα; mf eval's Kya_Nprad is dFy/dα in ISO-W, " << num(-f.kya_nprad) << ")\n"
      << "  pneumatic trail (α = 0.5°): " << num(f.trail_m) << " m\n"
      << "  Re: " << num(f.re_m) << " m, Rl: " << num(f.rl_m) << " m\n";
  std::ostringstream w;
  std::istringstream lines(loaded.warning);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.find(" missing, defaults used: ") != std::string::npos) continue;  // listed above
    w << "  " << line << '\n';
  }
  if (!f.finite) w << "  warning: some figures are not finite\n";
  const double fz0 = p.fnomin_n * p.lfzo;
  sign_change(w, "Fx", p.pdx1, p.pdx2, fz0, p.fzmin_n, p.fzmax_n);
  sign_change(w, "Fy", p.pdy1, p.pdy2, fz0, p.fzmin_n, p.fzmax_n);
  // The curves themselves (mf/mf_curve_checks): stiffness signs, friction beyond reason or rising
  // with load; the peak's sign change is said above from the coefficients.
  for (const std::string& c : curve_warnings(p, mf::MfOptions{}, {p.fnomin_n}, f.vx_mps)) {
    if (c.rfind("Fx peak changes sign", 0) != 0) w << "  warning: " << c << '\n';
  }
  out << "warnings:" << (w.str().empty() ? " none\n" : "\n" + w.str());
  return out.str();
}

}  // namespace tread::tyre
