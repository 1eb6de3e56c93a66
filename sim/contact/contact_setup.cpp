#include "contact/contact_setup.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "contact/profile_function.hpp"
#include "io/text_line.hpp"
#include "profile/profile_file.hpp"
#include "profile/rail_profile.hpp"
#include "profile/wheel_profile.hpp"

namespace tread::contact {

namespace {
constexpr double kMinCantRatio = 5.0;
}  // namespace

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
      // N from 5 (11.3°) up: rails are canted 1:20 to 1:40; "1:.40" (68°) is a typing error, not a
      // track (found by fuzzing).
      if (used == n_text.size() && n >= kMinCantRatio && std::isfinite(n)) {
        return std::atan(1.0 / n);
      }
    } catch (const std::exception&) {
      // fall through to the error below
    }
  }
  throw std::invalid_argument("--cant '" + text +
                              "': expected 1:N with N of 5 or more (e.g. 1:40), none or 0");
}

namespace {

/// The keys of a wheelset-profile spec and what each sets: one table for the parser and its
/// messages.
struct SpecKey {
  const char* key;
  void (*set)(ContactSetup& setup, const std::string& value);
};

constexpr std::array kSpecKeys{
    SpecKey{"wheel", [](ContactSetup& c, const std::string& v) { c.wheel_spec = v; }},
    SpecKey{"wheel-file", [](ContactSetup& c, const std::string& v) { c.wheel_file = v; }},
    SpecKey{"wheel-right-file",
            [](ContactSetup& c, const std::string& v) { c.wheel_right_file = v; }},
    SpecKey{"rail", [](ContactSetup& c, const std::string& v) { c.rail_spec = v; }},
    SpecKey{"rail-file", [](ContactSetup& c, const std::string& v) { c.rail_file = v; }},
    SpecKey{"rail-frame", [](ContactSetup& c, const std::string& v) { c.rail_frame = v; }},
    SpecKey{"cant", [](ContactSetup& c, const std::string& v) { c.cant = v; }},
    SpecKey{"gauge", [](ContactSetup& c,
                        const std::string& v) { c.gauge_mm = host::text::finite_number(v); }},
    SpecKey{"b2b", [](ContactSetup& c,
                      const std::string& v) { c.back_to_back_mm = host::text::finite_number(v); }},
    SpecKey{"r0",
            [](ContactSetup& c, const std::string& v) { c.r0_mm = host::text::finite_number(v); }},
    SpecKey{"r0-right", [](ContactSetup& c, const std::string& v) {
              c.r0_right_mm = host::text::finite_number(v);
            }}};

}  // namespace

ContactSetup parse_wheelset_profile(const std::string& spec) {
  ContactSetup setup;
  std::stringstream items(spec);
  std::string item;
  std::vector<std::string> seen;
  while (std::getline(items, item, ',')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) {
      throw std::invalid_argument("--wheelset-profile: '" + item + "' is not key=value");
    }
    const std::string key = item.substr(0, eq);
    if (std::find(seen.begin(), seen.end(), key) != seen.end()) {
      throw std::invalid_argument("--wheelset-profile: '" + key + "' given twice");
    }
    seen.push_back(key);
    const std::string value = item.substr(eq + 1);
    const auto* k = std::find_if(kSpecKeys.begin(), kSpecKeys.end(),
                                 [&key](const SpecKey& s) { return key == s.key; });
    try {
      if (k == kSpecKeys.end()) {
        throw std::invalid_argument("unknown key");
      }
      k->set(setup, value);
    } catch (const std::logic_error& e) {
      throw std::invalid_argument("--wheelset-profile: bad '" + item + "' (" + e.what() + ")");
    }
  }
  return setup;
}

profile::WheelParameters parse_wheel_spec(const std::string& spec) {
  return profile::parse_wheel_spec(spec, "--wheel");
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

/// A file through the one profile reader; its warnings appended.
profile::SampledProfile read_file(const std::string& file, profile::ProfileRole role,
                                  const profile::ProfileReadOptions& options,
                                  std::vector<std::string>& warnings,
                                  std::optional<double>* rail_inclination_rad = nullptr) {
  profile::ProfileFile read = profile::read_profile_file(file, role, options);
  // A wheel or rail head for contact is some 50 to 200 mm wide: one under 20 mm is a file in
  // metres or inches read as millimetres.
  constexpr double kMinWidth_mm = 20.0;
  const double width_mm = read.profile.y_mm.back() - read.profile.y_mm.front();
  if (width_mm < kMinWidth_mm) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", width_mm);
    throw std::runtime_error(file + ": the profile is only " + text +
                             " mm wide: a wheel or rail profile is some 50 to 200 mm wide (is the "
                             "file in metres or inches? name its columns with their unit, e.g. "
                             "y_m,z_m, or give them in mm)");
  }
  warnings.insert(warnings.end(), read.warnings.begin(), read.warnings.end());
  if (rail_inclination_rad != nullptr) {
    *rail_inclination_rad = read.rail_inclination_rad;
  }
  return std::move(read.profile);
}

/// Runs `step` and puts the file names in front of its message when it does not name them yet.
template <typename F>
auto naming_file(const std::string& files, F&& step) -> decltype(step()) {
  try {
    return step();
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    if (files.empty() || what.find(files) != std::string::npos) {
      throw;
    }
    throw std::invalid_argument(files + ": " + what);
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    if (files.empty() || what.find(files) != std::string::npos) {
      throw;
    }
    throw std::runtime_error(files + ": " + what);
  }
}

std::string one_in(double rad) {
  return "1:" + std::to_string(static_cast<long>(std::lround(1.0 / std::tan(rad))));
}

}  // namespace

double half_contact_base_mm(const ContactSetup& setup) {
  return 0.5 * setup.back_to_back_mm + kTapingLineFromBack_mm;
}

double nominal_r0_mm(const ContactSetup& setup) {
  return 0.5 * (setup.r0_mm + setup.r0_right_mm.value_or(setup.r0_mm));
}

void check_wheelset_dimensions(const ContactSetup& setup) {
  const auto text = [](double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return std::string(b);
  };
  // A wheel's rolling radius: from small tram and bogie wheels (some 150 mm) to the largest
  // driving wheels (about 1 m); outside this range the value is in another unit or a slip.
  constexpr double kR0Min_mm = 100.0, kR0Max_mm = 1500.0;
  const auto radius = [&](const char* option, double r0_mm) {
    if (!(r0_mm >= kR0Min_mm && r0_mm <= kR0Max_mm)) {
      throw std::invalid_argument(std::string(option) + " " + text(r0_mm) +
                                  ": a wheel's rolling radius in mm lies within " +
                                  text(kR0Min_mm) + " … " + text(kR0Max_mm) + " mm");
    }
  };
  radius("--r0", setup.r0_mm);
  if (setup.r0_right_mm) radius("--r0-right", *setup.r0_right_mm);
  if (!(setup.gauge_mm > 0.0) || !(setup.back_to_back_mm > 0.0)) {
    throw std::invalid_argument("--gauge " + text(setup.gauge_mm) + ", --b2b " +
                                text(setup.back_to_back_mm) + ": both must be > 0 (mm)");
  }
  // Track gauges: from minimum-gauge lines (381 mm) to broad gauge (1676 mm); beyond this range
  // the value is in another unit or a slip (an infinite gauge ran out of memory).
  constexpr double kGaugeMin_mm = 300.0, kGaugeMax_mm = 2000.0;
  if (!(setup.gauge_mm >= kGaugeMin_mm && setup.gauge_mm <= kGaugeMax_mm)) {
    throw std::invalid_argument("--gauge " + text(setup.gauge_mm) +
                                ": a track gauge in mm lies within " + text(kGaugeMin_mm) + " … " +
                                text(kGaugeMax_mm) + " mm");
  }
  if (setup.rail_frame == "track") return;  // the rails are placed already: --gauge not used
  if (!(setup.back_to_back_mm < setup.gauge_mm)) {
    throw std::invalid_argument("--b2b " + text(setup.back_to_back_mm) +
                                " mm is not below --gauge " + text(setup.gauge_mm) +
                                " mm: the wheels' backs would stand outside the rails");
  }
  if (!setup.wheel_spec.empty() && setup.wheel_file.empty()) {
    const double e = parse_wheel_spec(setup.wheel_spec).flange_thickness_mm;
    if (!(setup.back_to_back_mm + 2.0 * e < setup.gauge_mm)) {
      throw std::invalid_argument(
          "--b2b " + text(setup.back_to_back_mm) + " mm with two flanges of e = " + text(e) +
          " mm (" + text(setup.back_to_back_mm + 2.0 * e) + " mm) does not fit in --gauge " +
          text(setup.gauge_mm) + " mm: the wheelset has no lateral play");
    }
  }
}

RigidContact build_contact(const ContactSetup& setup) {
  std::vector<std::string> ignored;
  return build_contact(setup, ignored);
}

RigidContact build_contact(const ContactSetup& setup, std::vector<std::string>& warnings) {
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
  // How to read a file, given with a built-in profile: nothing to apply it to.
  const auto file_only = [](const profile::ProfileReadOptions& o, const std::string& file,
                            const char* side) {
    if (!file.empty()) return;
    const char* given = o.z_down                                    ? "z-down"
                        : o.mirror_y                                ? "mirror-y"
                        : o.format != profile::ProfileFormat::kAuto ? "format"
                                                                    : nullptr;
    if (given != nullptr) {
      throw std::invalid_argument(std::string("--") + side + "-" + given + " applies to --" + side +
                                  "-file only (the built-in " + side + " is in tread's own frame)");
    }
  };
  file_only(setup.wheel_read, setup.wheel_file, "wheel");
  file_only(setup.rail_read, setup.rail_file, "rail");
  check_wheelset_dimensions(setup);
  const double cant_rad = parse_cant_rad(setup.cant);  // validated even where it does not apply
  using profile::ProfileRole;
  profile::SampledProfile left =
      setup.wheel_file.empty()
          ? builtin_wheel(setup.wheel_spec)
          : read_file(setup.wheel_file, ProfileRole::kWheel, setup.wheel_read, warnings);
  profile::SampledProfile right =
      setup.wheel_right_file.empty()
          ? left
          : read_file(setup.wheel_right_file, ProfileRole::kWheel, setup.wheel_read, warnings);
  const bool builtin = setup.rail_file.empty();
  std::optional<double> file_inclination_rad;
  profile::SampledProfile rail =
      builtin ? builtin_rail(setup.rail_spec, setup.cant, cant_rad, setup.gauge_mm)
              : read_file(setup.rail_file, ProfileRole::kRail, setup.rail_read, warnings,
                          &file_inclination_rad);
  const std::string& right_file =
      setup.wheel_right_file.empty() ? setup.wheel_file : setup.wheel_right_file;
  // Smoothing is for measured profiles: the built-in ones are the standards' exact shapes.
  if (!setup.wheel_file.empty()) {
    left = naming_file(setup.wheel_file,
                       [&] { return smooth_profile(left, setup.smooth_half_window_mm); });
  }
  if (!right_file.empty()) {
    right =
        naming_file(right_file, [&] { return smooth_profile(right, setup.smooth_half_window_mm); });
  }
  if (!builtin) {
    rail = naming_file(setup.rail_file,
                       [&] { return smooth_profile(rail, setup.smooth_half_window_mm); });
  }
  constexpr double kCantedFrom_rad = 1.0 / 80.0;
  if (!builtin && setup.rail_frame == "track" && file_inclination_rad &&
      std::abs(*file_inclination_rad) < kCantedFrom_rad) {
    char gauge[32];
    std::snprintf(gauge, sizeof gauge, "%.1f",
                  naming_file(setup.rail_file, [&] { return track_frame_gauge_mm(rail); }));
    warnings.push_back(setup.rail_file +
                       ": --rail-frame track, but the rail head stands upright in the file (no "
                       "inclination; its gauge point gives a gauge of " +
                       gauge +
                       " mm): if the file is in the rail's own frame, --rail-frame upright places "
                       "it by --cant and --gauge");
  }
  if (!builtin && setup.rail_frame == "upright") {
    if (file_inclination_rad && *file_inclination_rad >= kCantedFrom_rad && cant_rad > 0.0) {
      warnings.push_back(setup.rail_file + ": the rail is inclined by " +
                         one_in(*file_inclination_rad) + " in its file already, and --cant " +
                         setup.cant + " inclines it again (" +
                         one_in(*file_inclination_rad + cant_rad) +
                         " in all): pass --cant none to place the rail as given (or "
                         "--rail-frame track if it is in the track frame already)");
    }
    if (file_inclination_rad && *file_inclination_rad <= -kCantedFrom_rad) {
      warnings.push_back(setup.rail_file + ": the rail head leans toward +y by " +
                         one_in(-*file_inclination_rad) +
                         " in its file: in the upright frame the gauge side is -y; if the file "
                         "has it at +y, pass --rail-mirror-y");
    }
    RailPlacement placement;
    placement.gauge_mm = setup.gauge_mm;
    placement.inclination_rad = cant_rad;
    rail = naming_file(setup.rail_file, [&] { return place_rail(rail, placement).track; });
  }
  WheelsetSetup wheelset;
  wheelset.back_to_back_mm = setup.back_to_back_mm;
  wheelset.r0_left_mm = setup.r0_mm;
  wheelset.r0_right_mm = setup.r0_right_mm.value_or(setup.r0_mm);
  std::string files;
  for (const std::string* f : {&setup.wheel_file, &setup.wheel_right_file, &setup.rail_file}) {
    if (!f->empty()) {
      files += (files.empty() ? "" : ", ") + *f;
    }
  }
  RigidContact contact =
      naming_file(files, [&] { return RigidContact(left, right, rail, wheelset); });
  // A wheelset without lateral play (wheel files: the built-in wheels' e is checked before): both
  // flanges on their rails with the wheelset centred.
  constexpr double kFlangeContact_rad = 0.5;
  const auto gauge_text = [&] {
    char text[160];
    if (setup.rail_frame == "track") {
      std::snprintf(text, sizeof text,
                    "--b2b %g mm on the rails of a track-frame file (gauge %.1f mm)",
                    setup.back_to_back_mm, track_frame_gauge_mm(rail));
    } else {
      std::snprintf(text, sizeof text, "--b2b %g mm, --gauge %g mm", setup.back_to_back_mm,
                    setup.gauge_mm);
    }
    return std::string(text);
  };
  ContactState centred;
  try {
    centred = contact.at(0.0);
  } catch (const std::domain_error& e) {
    // The wheels stand beside the rails: a back-to-back that does not go with the gauge.
    throw std::invalid_argument((files.empty() ? "" : files + ": ") + gauge_text() +
                                ": the centred wheelset's wheels do not stand on the rails (" +
                                e.what() +
                                "); a wheelset's back-to-back is its gauge less about 75 mm "
                                "(1360 on 1435)");
  }
  // Far too much play: 25 mm toward either rail without a flange touching it (a wheelset has
  // 3 to 10 mm each side): the tread's outer slope on the rail's gauge corner was taken for
  // the wheelset's conicity.
  constexpr double kPlayMax_mm = 25.0;
  for (const double side : {-1.0, 1.0}) {
    double largest_rad = 0.0;
    bool flange = false;
    for (double y = 0.0; y <= kPlayMax_mm && !flange; y += 0.5) {
      try {
        const ContactState moved = contact.at(side * y);
        largest_rad = std::max({largest_rad, moved.left.gamma_rad, moved.right.gamma_rad});
        flange = largest_rad >= kFlangeContact_rad;
      } catch (const std::domain_error&) {
        flange = true;  // the wheels leave the rails: the profiles end before a flange is found
      }
    }
    if (!flange) {
      char text[200];
      std::snprintf(text, sizeof text,
                    ": moved %g mm toward a rail the wheelset has no flange on it (largest "
                    "contact angle %.3f rad): far more play than a wheelset has; is --b2b right "
                    "for the gauge?",
                    kPlayMax_mm, largest_rad);
      warnings.push_back((files.empty() ? "" : files + ": ") + gauge_text() + text);
      break;
    }
  }
  if (centred.left.gamma_rad > kFlangeContact_rad && centred.right.gamma_rad > kFlangeContact_rad) {
    char text[512];
    if (setup.rail_frame == "track") {
      // --gauge does not place these rails: the file does.
      std::snprintf(text, sizeof text,
                    "--b2b %g mm on the rails of a track-frame file (its gauge point gives a "
                    "gauge of %.1f mm): both flanges touch their rails with the wheelset centred "
                    "(contact angles %.2f and %.2f rad): no lateral play; if the file is in the "
                    "rail's own upright frame, --rail-frame upright places it by --cant and "
                    "--gauge",
                    setup.back_to_back_mm, track_frame_gauge_mm(rail), centred.left.gamma_rad,
                    centred.right.gamma_rad);
    } else {
      std::snprintf(text, sizeof text,
                    "--b2b %g mm, --gauge %g mm: both flanges touch their rails with the wheelset "
                    "centred (contact angles %.2f and %.2f rad): the wheelset has no lateral play",
                    setup.back_to_back_mm, setup.gauge_mm, centred.left.gamma_rad,
                    centred.right.gamma_rad);
    }
    throw std::invalid_argument((files.empty() ? "" : files + ": ") + text);
  }
  return contact;
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
