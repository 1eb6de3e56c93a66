#pragma once
// The command-line options of ContactSetup, shared by `tread contact` and `tread conicity`
// (header-only: only the tread executable links CLI11).

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

#include "contact/contact_setup.hpp"
#include "io/option_checks.hpp"
#include "profile/profile_file.hpp"

namespace tread::contact {

/// --wheel-format/--rail-format take a profile format name (auto, csv, simpack, miniprof).
inline std::function<void(const std::string&)> profile_format_setter(profile::ProfileFormat& f) {
  return [&f](const std::string& text) { f = profile::parse_profile_format(text); };
}

inline void add_contact_setup_options(CLI::App& cmd, ContactSetup& s) {
  cmd.add_option("--wheel", s.wheel_spec,
                 "built-in EN 13715 wheel: S1002, EPS or "
                 "1/40[:h=28,e=32.5,slope=1:15|6.7…15 %|1:N,width=140,chamfer=1]");
  cmd.add_option("--wheel-file", s.wheel_file,
                 "wheel profile: CSV y_mm,z_mm, SIMPACK/CONTACT .prw or MiniProf .whl (left "
                 "wheel; also the right unless --wheel-right-file)");
  cmd.add_option("--wheel-right-file", s.wheel_right_file,
                 "right wheel profile file, for a wheelset with different wheels");
  cmd.add_option_function<std::string>("--wheel-format", profile_format_setter(s.wheel_read.format),
                                       "format of the wheel files: auto (by extension), csv, "
                                       "simpack or miniprof");
  cmd.add_flag("--wheel-z-down", s.wheel_read.z_down,
               "the wheel files' z points away from the flange tip (negated on reading)");
  cmd.add_flag("--wheel-mirror-y", s.wheel_read.mirror_y,
               "the wheel files' y points toward the flange (negated on reading)");
  cmd.add_option("--rail", s.rail_spec, "built-in rail head: 60E1 or 54E1");
  cmd.add_option("--rail-file", s.rail_file,
                 "rail profile: CSV y_mm,z_mm, SIMPACK/CONTACT .prr or MiniProf .ban");
  cmd.add_option_function<std::string>("--rail-format", profile_format_setter(s.rail_read.format),
                                       "format of the rail file: auto (by extension), csv, "
                                       "simpack or miniprof");
  cmd.add_flag("--rail-z-down", s.rail_read.z_down,
               "the rail file's z points down (negated on reading)");
  cmd.add_flag("--rail-mirror-y", s.rail_read.mirror_y,
               "the rail file's gauge side is at +y (y negated on reading)");
  cmd.add_option("--rail-frame", s.rail_frame,
                 "frame of --rail-file: upright (own frame, placed by --cant and --gauge) or track "
                 "(already in the running-circle frame; --cant/--gauge do not apply)")
      ->capture_default_str();
  cmd.add_option("--cant", s.cant, "rail inclination 1:N, or none")->capture_default_str();
  cmd.add_option("--gauge", s.gauge_mm, "track gauge (mm), 14 mm below the top of rail")
      ->capture_default_str();
  cmd.add_option("--b2b", s.back_to_back_mm, "wheel back-to-back distance (mm)")
      ->capture_default_str();
  cmd.add_option("--r0", s.r0_mm, "rolling radius at the taping line (mm), left wheel")
      ->capture_default_str();
  cmd.add_option(
      "--r0-right", s.r0_right_mm,
      "right wheel rolling radius at the taping line (mm); default --r0. delta r = r_left - "
      "r_right, y > 0 toward the left rail (EN 15302's 920/918 mm case: --r0 460 "
      "--r0-right 459)");
  cmd.add_option("--smooth", s.smooth_half_window_mm,
                 "smooth measured profiles (files; built-in profiles are exact): local quadratic "
                 "fit half window (mm, up to 10), 0 = off")
      ->capture_default_str()
      ->check(host::finite_within(0.0, 10.0, "the smoothing half window in mm"));
}

}  // namespace tread::contact
