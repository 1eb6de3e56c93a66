// `tread profile`: an EN 13715 wheel profile (S1002, EPS, 1/40) as the seed's ASCII table, CSV
// (y_mm,z_mm,tan) or a SIMPACK .prw file, optionally plotted (profile, slope, the three families).
// With --input, a profile file (CSV y_mm,z_mm or SIMPACK .prw/.prr) is converted instead: its
// points as read (SIMPACK processing settings applied, this project's convention) are written as
// CSV or SIMPACK.
#include <filesystem>
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
  std::string input;
};

void write_output(const ProfileOptions& o, const std::string& text) {
  if (o.output.empty()) {
    std::cout << text;
    return;
  }
  std::ofstream out(o.output);
  out << text;
  if (!out) {
    throw std::runtime_error("cannot write " + o.output);
  }
}

// --input: read a profile file and write its points in another format.
void convert_profile(const ProfileOptions& o) {
  const std::filesystem::path path = o.input;
  const std::string ext = path.extension().string();
  profile::SampledProfile s;
  profile::SimpackProfileType type = profile::SimpackProfileType::kWheel;
  std::string comment;
  if (ext == ".prw" || ext == ".prr") {
    profile::SimpackProfile read = profile::read_simpack_profile(path);
    s = std::move(read.profile);
    type = read.type;
    comment = read.comment;
  } else {
    s = profile::read_profile_csv(path);
  }
  std::ostringstream text;
  if (o.format == "csv") {
    profile::write_profile_csv(text, s, {}, 9);
  } else if (o.format == "prw" || o.format == "prr") {
    const auto out_type = o.format == "prw" ? profile::SimpackProfileType::kWheel
                                            : profile::SimpackProfileType::kRail;
    if ((ext == ".prw" || ext == ".prr") && out_type != type) {
      throw std::invalid_argument(o.input + ": a " +
                                  (type == profile::SimpackProfileType::kWheel ? "wheel" : "rail") +
                                  " profile cannot be written as --format " + o.format);
    }
    profile::write_simpack_profile(text, s, out_type, comment.empty() ? s.name : comment);
  } else {
    throw std::invalid_argument("--format with --input must be csv, prw or prr, got '" + o.format +
                                "'");
  }
  write_output(o, text.str());
}

void run_profile(const ProfileOptions& o) {
  if (!o.input.empty()) {
    convert_profile(o);
    return;
  }
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

  write_output(o, text.str());
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
  cmd->add_option("--input", options->input,
                  "convert a profile file (CSV y_mm,z_mm or SIMPACK .prw/.prr) to --format csv, "
                  "prw or prr instead of constructing an EN 13715 profile")
      ->check(CLI::ExistingFile);
  cmd->add_option("--plot", options->plot,
                  "PNG: profile, slope, and the slopes of the three families (gnuplot)");
  cmd->callback([options] { run_profile(*options); });
}

}  // namespace

TREAD_REGISTER_COMMAND("profile", add_profile_command);

}  // namespace tread::cli
