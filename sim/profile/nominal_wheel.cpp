#include "profile/nominal_wheel.hpp"
#include "io/text_line.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

namespace tread::profile {

namespace {

double rms_difference(const WheelProfile& nominal, const SampledProfile& measured) {
  double ss = 0.0;
  double n = 0.0;
  for (std::size_t i = 0; i < measured.y_mm.size(); ++i) {
    const double y = measured.y_mm[i];
    if (y >= -25.0 && y <= 25.0) {
      const double d = measured.z_mm[i] - nominal.at(y).z_mm;
      ss += d * d;
      n += 1.0;
    }
  }
  return n > 0.0 ? std::sqrt(ss / n) : 0.0;
}

}  // namespace

NominalChoice choose_nominal(const std::string& spec, const SampledProfile& measured,
                             const SampledWheelMeasures& measures) {
  NominalChoice out;
  WheelParameters& p = out.parameters;
  std::set<std::string> given;
  bool family_given = spec != "auto";  // empty: S1002
  if (!spec.empty() && spec != "auto") {
    p = parse_wheel_spec(spec, "--nominal", &given);
  }
  std::ostringstream how;
  const FlangeMeasures& f = measures.flange;
  if (!given.contains("h")) {
    // Tread wear raises Sh, a thin flange's cusp lowers it by up to 0.17 mm.
    p.flange_height_mm = f.height_mm < 29.8 ? 28.0 : (f.height_mm < 31.8 ? 30.0 : 32.0);
    how << "h from Sh; ";
  }
  if (!given.contains("e")) {
    p.flange_thickness_mm = std::clamp(std::round(2.0 * f.thickness_mm) / 2.0, 28.5, 32.5);
    how << "e from Sd; ";
  }
  if (!given.contains("slope")) {
    if (measures.outer_slope) {
      const double g = *measures.outer_slope;
      if (std::fabs(g - 1.0 / 15.0) < 1.5e-4) {
        p.outer_slope = OuterSlope::k1in15;
      } else {
        const double percent = std::clamp(std::round(1000.0 * g) / 10.0, OuterSlope::kMinPercent,
                                          OuterSlope::kMaxPercent);
        char text[32];
        std::snprintf(text, sizeof text, "%.1f", percent);
        p.outer_slope = parse_outer_slope(text);
      }
      how << "outer slope measured; ";
    } else {
      how << "outer slope 1:15, the profile does not cover y 38 ... 58; ";
    }
  }
  if (!given.contains("width")) {
    p.width_mm = measured.y_mm.back() >= 67.5 ? 140.0 : 135.0;
    how << "width from the profile's end; ";
  }
  if (!family_given) {
    double best = std::numeric_limits<double>::infinity();
    WheelFamily best_family = WheelFamily::kS1002;
    for (const WheelFamily family : {WheelFamily::kS1002, WheelFamily::kEps, WheelFamily::k1in40}) {
      WheelParameters q = p;
      q.family = family;
      const double rms = rms_difference(WheelProfile(q), measured);
      if (rms < best) {
        best = rms;
        best_family = family;
      }
    }
    p.family = best_family;
    how << "family closest on the tread, y -25 ... 25";
  } else {
    how << (spec.empty() ? "family S1002 by default" : "family given");
  }
  (void)WheelProfile(p);  // validates the parameters the user gave
  out.how = how.str();
  return out;
}

}  // namespace tread::profile
