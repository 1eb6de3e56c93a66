#include "contact/contact_setup.hpp"

#include <cmath>
#include <stdexcept>

#include "contact/profile_csv.hpp"
#include "contact/profile_function.hpp"

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

namespace {

profile::SampledProfile builtin_wheel(const std::string& spec) {
  throw std::runtime_error("--wheel " + spec +
                           ": built-in EN 13715 wheel profiles are not wired into this build yet "
                           "(profiles part of issue 4); use --wheel-file");
}

profile::SampledProfile builtin_rail(const std::string& spec) {
  throw std::runtime_error("--rail " + spec +
                           ": built-in rail heads are not wired into this build yet (profiles "
                           "part of issue 4); use --rail-file");
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
                                                          : read_profile_csv(setup.wheel_file);
  profile::SampledProfile right =
      setup.wheel_right_file.empty() ? left : read_profile_csv(setup.wheel_right_file);
  profile::SampledProfile rail =
      setup.rail_file.empty() ? builtin_rail(setup.rail_spec) : read_profile_csv(setup.rail_file);
  left = smooth_profile(left, setup.smooth_half_window_mm);
  right = smooth_profile(right, setup.smooth_half_window_mm);
  rail = smooth_profile(rail, setup.smooth_half_window_mm);
  if (setup.rail_frame == "upright") {
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
