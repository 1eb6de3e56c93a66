#pragma once
// `tread tir info`: what a tyre property file is and what it says, as text (host side).
//
// Lines: the file; the detected model (PROPERTY_FILE_FORMAT, FITTYP); [UNITS] (and that values
// are shown in SI); FNOMIN, R0, width, NOMPRES/INFLPRES; the valid ranges; the keys of the
// model that took defaults; for Magic Formula files the figures at FNOMIN (mf/mf_tyre_figures:
// peak μx drive/brake, μy, Kxκ, Kyα, pneumatic trail, Re, Rl); then warnings, among them where the
// load dependence of the peak friction changes sign inside FZMIN…FZMAX (μ(Fz) = (PDX1 + PDX2·dfz)
// ·LMUX at γ = 0 and nominal pressure, likewise PDY1/PDY2 for Fy), which real files have, and
// the curve checks of mf/mf_curve_checks.hpp (stiffness signs, friction rising with load).
// PAC89/PAC94 files get the model, radius and coefficient counts. Throws tir::TirError as the
// loaders do (e.g. "not a Magic Formula file: …").
#include <filesystem>
#include <string>

namespace tread::tyre {

std::string tir_info_report(const std::filesystem::path& path);

}  // namespace tread::tyre
