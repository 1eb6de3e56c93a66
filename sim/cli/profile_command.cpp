// `tread profile`: an EN 13715 wheel profile (S1002, EPS, 1/40) as the seed's ASCII table, CSV
// (y_mm,z_mm,tan) or a SIMPACK .prw file, optionally plotted (profile, slope, the three families).
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "profile/profile_csv.hpp"
#include "profile/profile_plot.hpp"
#include "profile/profile_table.hpp"
#include "profile/simpack_profile.hpp"
#include "profile/wheel_profile.hpp"

namespace tread::cli {

namespace {

struct ProfileOptions {
  std::string family = "S1002";
  double flange_height_mm = 28.0;
  double flange_thickness_mm = 32.5;
  std::string outer_slope = "1:15";
  double width_mm = 140.0;
  bool no_chamfer = false;
  double step_mm = 0.1;
  std::string format = "table";
  std::string output;
  std::string plot;
};

void run_profile(const ProfileOptions& o) {
  profile::WheelParameters p;
  p.family = profile::parse_wheel_family(o.family);
  p.flange_height_mm = o.flange_height_mm;
  p.flange_thickness_mm = o.flange_thickness_mm;
  p.outer_slope = profile::parse_outer_slope(o.outer_slope);
  p.width_mm = o.width_mm;
  p.chamfer = !o.no_chamfer;
  const profile::WheelProfile wheel(p);
  if (!(o.step_mm > 0.0) || o.step_mm > 10.0) {
    throw std::invalid_argument("--step must be within (0, 10] mm");
  }

  std::ostringstream text;
  if (o.format == "table") {
    profile::write_profile_table(text, wheel, o.step_mm);
  } else if (o.format == "csv" || o.format == "prw") {
    std::vector<double> ys = profile::descending_grid(wheel, o.step_mm);
    profile::SampledProfile s;
    s.name = wheel.name();
    std::vector<double> tan;
    for (auto it = ys.rbegin(); it != ys.rend(); ++it) {
      const profile::ProfileValue v = wheel.at(*it);
      s.y_mm.push_back(*it);
      s.z_mm.push_back(v.z_mm);
      tan.push_back(v.tan);
    }
    if (o.format == "csv") {
      profile::write_profile_csv(text, s, tan, 6);
    } else {
      profile::write_simpack_profile(text, s, profile::SimpackProfileType::kWheel,
                                     wheel.name() + " (EN 13715, tread)");
    }
  } else {
    throw std::invalid_argument("--format must be table, csv or prw, got '" + o.format + "'");
  }

  if (o.output.empty()) {
    std::cout << text.str();
  } else {
    std::ofstream out(o.output);
    out << text.str();
    if (!out) {
      throw std::runtime_error("cannot write " + o.output);
    }
  }
  if (!o.plot.empty()) {
    profile::plot_wheel_profile(wheel, o.step_mm, o.plot);
  }
}

void add_profile_command(CLI::App& app) {
  auto options = std::make_shared<ProfileOptions>();
  auto* cmd = app.add_subcommand(
      "profile", "EN 13715 wheel profile (S1002, EPS, 1/40) as a table, CSV or SIMPACK .prw");
  cmd->add_option("--family", options->family, "S1002, EPS or 1/40")->capture_default_str();
  cmd->add_option("--flange-height", options->flange_height_mm, "h: 28, 30 or 32 mm")
      ->capture_default_str();
  cmd->add_option("--flange-thickness", options->flange_thickness_mm,
                  "e: 28.5 … 32.5 mm (EPS: step 0.5)")
      ->capture_default_str();
  cmd->add_option("--outer-slope", options->outer_slope, "1:15, 6.7, 10 or 15 (%)")
      ->capture_default_str();
  cmd->add_option("--width", options->width_mm, "wheel width: 135 or 140 mm")
      ->capture_default_str();
  cmd->add_flag("--no-chamfer", options->no_chamfer, "no 5 x 5 mm chamfer at the outer face");
  cmd->add_option("--step", options->step_mm, "sampling step (mm)")->capture_default_str();
  cmd->add_option("--format", options->format,
                  "table (the seed's layout: y descending, z, tan, 5 decimals), csv "
                  "(y_mm,z_mm,tan) or prw (SIMPACK wheel profile)")
      ->capture_default_str();
  cmd->add_option("--output", options->output, "output file (default: standard output)");
  cmd->add_option("--plot", options->plot,
                  "PNG: profile, slope, and the slopes of the three families (gnuplot)");
  cmd->callback([options] { run_profile(*options); });
}

}  // namespace

TREAD_REGISTER_COMMAND("profile", add_profile_command);

}  // namespace tread::cli
