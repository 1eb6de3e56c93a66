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

bool truthy(const std::string& value) {
  return value != "0" && value != "no" && value != "false";
}

}  // namespace

NominalChoice choose_nominal(const std::string& spec, const SampledProfile& measured,
                             const SampledWheelMeasures& measures) {
  NominalChoice out;
  WheelParameters& p = out.parameters;
  std::set<std::string> given;
  bool family_given = spec != "auto";  // empty: S1002
  if (!spec.empty() && spec != "auto") {
    const auto colon = spec.find(':');
    p.family = parse_wheel_family(spec.substr(0, colon));
    if (colon != std::string::npos) {
      std::stringstream rest(spec.substr(colon + 1));
      std::string item;
      while (std::getline(rest, item, ',')) {
        const auto eq = item.find('=');
        if (eq == std::string::npos) {
          throw std::invalid_argument("--nominal " + spec + ": expected key=value, got '" + item +
                                      "'");
        }
        const std::string key = item.substr(0, eq);
        const std::string value = item.substr(eq + 1);
        try {
          if (key == "h") {
            p.flange_height_mm = host::text::finite_number(value);
          } else if (key == "e") {
            p.flange_thickness_mm = host::text::finite_number(value);
          } else if (key == "slope") {
            p.outer_slope = parse_outer_slope(value);
          } else if (key == "width") {
            p.width_mm = host::text::finite_number(value);
          } else if (key == "chamfer") {
            p.chamfer = truthy(value);
          } else {
            throw std::invalid_argument("unknown key (h, e, slope, width, chamfer)");
          }
        } catch (const std::logic_error& e) {
          throw std::invalid_argument("--nominal " + spec + ": " + key + ": " + e.what());
        }
        given.insert(key);
      }
    }
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
