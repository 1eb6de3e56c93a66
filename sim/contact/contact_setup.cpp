#include "contact/contact_setup.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "contact/profile_csv.hpp"
#include "contact/profile_function.hpp"
#include "profile/rail_profile.hpp"
#include "profile/simpack_profile.hpp"
#include "profile/wheel_profile.hpp"

namespace tread::contact {

double parse_cant_rad(const std::string& text) {
  if (text == "none" || text == "0") {
    return 0.0;
  }
  const auto colon = text.find(':');
  if (colon != std::string::npos && text.substr(0, colon) == "1") {
    try {
      std::size_t used = 0;
      const std::string n_text = text.substr(colon + 1);
      const double n = std::stod(n_text, &used);
      if (used == n_text.size() && n > 0.0 && std::isfinite(n)) {
        return std::atan(1.0 / n);
      }
    } catch (const std::exception&) {
      // fall through to the error below
    }
  }
  throw std::invalid_argument("--cant '" + text + "': expected 1:N (e.g. 1:40), none or 0");
}

profile::WheelParameters parse_wheel_spec(const std::string& spec) {
  profile::WheelParameters p;
  const auto colon = spec.find(':');
  p.family = profile::parse_wheel_family(spec.substr(0, colon));
  if (colon != std::string::npos) {
    std::stringstream rest(spec.substr(colon + 1));
    std::string item;
    while (std::getline(rest, item, ',')) {
      const auto eq = item.find('=');
      if (eq == std::string::npos) {
        throw std::invalid_argument("--wheel " + spec + ": expected key=value, got '" + item + "'");
      }
      const std::string key = item.substr(0, eq);
      const std::string value = item.substr(eq + 1);
      try {
        if (key == "h") {
          p.flange_height_mm = std::stod(value);
        } else if (key == "e") {
          p.flange_thickness_mm = std::stod(value);
        } else if (key == "slope") {
          p.outer_slope = profile::parse_outer_slope(value);
        } else if (key == "width") {
          p.width_mm = std::stod(value);
        } else if (key == "chamfer") {
          p.chamfer = value != "0" && value != "no" && value != "false";
        } else {
          throw std::invalid_argument("unknown key '" + key + "' (h, e, slope, width, chamfer)");
        }
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("--wheel " + spec + ": " + key + ": " + e.what());
      }
    }
  }
  return p;
}

namespace {

constexpr double kBuiltinSampleStep_mm = 0.01;

profile::SampledProfile builtin_wheel(const std::string& spec) {
  return profile::WheelProfile(parse_wheel_spec(spec)).sample(kBuiltinSampleStep_mm);
}

/// 60E1 or 54E1 inclined by the cant and placed at the gauge, in the track frame (origin 750 mm
/// from the track centre; the wheelset's b2b is applied to the wheels).
profile::SampledProfile builtin_rail(const std::string& spec, const std::string& cant,
                                     double cant_rad, double gauge_mm) {
  const profile::RailSection section = profile::parse_rail_section(spec);
  profile::TrackPlacement placement;
  placement.gauge_mm = gauge_mm;
  placement.half_spacing_mm = kTrackFrameOrigin_mm;
  try {
    const profile::RailInclination inclination = profile::parse_rail_inclination(cant);
    return profile::RailProfile(section, inclination, placement).sample(kBuiltinSampleStep_mm);
  } catch (const std::invalid_argument&) {
    // Another inclination than none/1:20/1:40: rotate the sampled upright head here.
    RailPlacement any;
    any.gauge_mm = gauge_mm;
    any.inclination_rad = cant_rad;
    const auto upright = profile::RailProfile(section, profile::RailInclination::kNone)
                             .sample(kBuiltinSampleStep_mm);
    return place_rail(upright, any).track;
  }
}

/// CSV (y_mm,z_mm) or SIMPACK .prw/.prr by extension.
profile::SampledProfile read_profile_file(const std::string& file) {
  const std::filesystem::path path(file);
  const std::string ext = path.extension().string();
  if (ext == ".prw" || ext == ".prr" || ext == ".PRW" || ext == ".PRR") {
    return profile::read_simpack_profile(path).profile;
  }
  return read_profile_csv(path);
}

}  // namespace

RigidContact build_contact(const ContactSetup& setup) {
  if (setup.wheel_spec.empty() == setup.wheel_file.empty()) {
    throw std::invalid_argument("give exactly one of --wheel and --wheel-file");
  }
  if (setup.rail_spec.empty() == setup.rail_file.empty()) {
    throw std::invalid_argument("give exactly one of --rail and --rail-file");
  }
  if (setup.rail_frame != "upright" && setup.rail_frame != "track") {
    throw std::invalid_argument("--rail-frame '" + setup.rail_frame +
                                "': expected upright or track");
  }
  if (setup.rail_frame == "track" && setup.rail_file.empty()) {
    throw std::invalid_argument("--rail-frame track applies to --rail-file only");
  }
  const double cant_rad = parse_cant_rad(setup.cant);  // validated even where it does not apply
  profile::SampledProfile left = setup.wheel_file.empty() ? builtin_wheel(setup.wheel_spec)
                                                          : read_profile_file(setup.wheel_file);
  profile::SampledProfile right =
      setup.wheel_right_file.empty() ? left : read_profile_file(setup.wheel_right_file);
  const bool builtin = setup.rail_file.empty();
  profile::SampledProfile rail =
      builtin ? builtin_rail(setup.rail_spec, setup.cant, cant_rad, setup.gauge_mm)
              : read_profile_file(setup.rail_file);
  left = smooth_profile(left, setup.smooth_half_window_mm);
  right = smooth_profile(right, setup.smooth_half_window_mm);
  rail = smooth_profile(rail, setup.smooth_half_window_mm);
  if (!builtin && setup.rail_frame == "upright") {
    RailPlacement placement;
    placement.gauge_mm = setup.gauge_mm;
    placement.inclination_rad = cant_rad;
    rail = place_rail(rail, placement).track;
  }
  WheelsetSetup wheelset;
  wheelset.back_to_back_mm = setup.back_to_back_mm;
  wheelset.r0_left_mm = setup.r0_mm;
  wheelset.r0_right_mm = setup.r0_right_mm.value_or(setup.r0_mm);
  return RigidContact(left, right, rail, wheelset);
}

std::optional<double> first_profile_end_abs_y(const ContactTable& table) {
  std::optional<double> out;
  for (std::size_t k = 0; k < table.y_mm.size(); ++k) {
    if (table.at_profile_end[k] && (!out || std::abs(table.y_mm[k]) < *out)) {
      out = std::abs(table.y_mm[k]);
    }
  }
  return out;
}

}  // namespace tread::contact
