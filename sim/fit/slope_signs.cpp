#include "fit/slope_signs.hpp"

#include <cstdio>

namespace tread::fit {

std::string slope_sign_doubt(SlopeOf which, const std::vector<LoadSlope>& slopes) {
  std::string wrong;
  for (const LoadSlope& s : slopes) {
    if (!(which == SlopeOf::fy_alpha ? s.slope > 0.0 : s.slope < 0.0)) continue;
    char at[96];
    std::snprintf(at, sizeof at, "%s%.6g at Fz = %.6g N", wrong.empty() ? "" : ", ", s.slope,
                  s.fz_n);
    wrong += at;
  }
  if (wrong.empty()) return wrong;
  const char* name = which == SlopeOf::fx_kappa   ? "dFx/dkappa"
                     : which == SlopeOf::fy_alpha ? "dFy/dalpha"
                                                  : "dMz/dalpha";
  const char* expected = which == SlopeOf::fy_alpha ? "< 0" : "> 0";
  const char* why =
      which == SlopeOf::fx_kappa
          ? "kappa or Fx is written with the other sign (braking slip positive?)"
      : which == SlopeOf::fy_alpha
          ? "alpha or Fy is written with the other sign: Pacejka's adapted axes (--convention "
            "adapted-iso), or SAE data with the load already made positive (--convention sae "
            "takes the load as written, z down)"
          : "alpha or Mz is written with the other sign (Mz in SAE axes: --convention sae)";
  return std::string("the fitted ") + name + " is " + wrong + ", but " + expected +
         " in ISO-W for every tyre: " + why + "; the result is a mirror-image tyre";
}

}  // namespace tread::fit
