// `tread profile`: an EN 13715 wheel profile (S1002, EPS, 1/40) as the seed's ASCII table, CSV
// (y_mm,z_mm,tan) or a SIMPACK .prw file, optionally plotted (profile, slope, the three families).
// With --input, a user's profile file (read through profile::read_profile_file for its role) is
// inspected (format, header, points, spacing, warnings, measures), measured (--measure: the
// EN 15313 style flange measures of a wheel, the top, gauge point and head width of a rail),
// plotted (--plot: profile, local slope and, for a wheel, its nominal EN 13715 profile and the
// difference) or converted (--format csv|prw|prr).
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "io/option_checks.hpp"
#include "io/text_line.hpp"
#include "profile/measured_profile_plot.hpp"
#include "profile/nominal_wheel.hpp"
#include "profile/profile_csv.hpp"
#include "profile/profile_file.hpp"
#include "profile/profile_plot.hpp"
#include "profile/profile_slope.hpp"
#include "profile/profile_table.hpp"
#include "profile/rail_measures.hpp"
#include "profile/simpack_profile.hpp"
#include "profile/wheel_measures.hpp"
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
  std::string format;  // "" = table (built-in) / inspect (--input)
  std::string output;
  std::string plot;
  std::string input;
  std::string role = "auto";
  std::string input_format = "auto";
  bool z_down = false;
  bool mirror_y = false;
  bool measure = false;
  std::string nominal;
  double slope_half_window_mm = 0.5;
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

std::string fixed(double v, int decimals) {
  if (std::fabs(v) < 0.5 * std::pow(10.0, -decimals)) {
    v = 0.0;  // no "-0.000"
  }
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}

profile::ProfileRole input_role(const ProfileOptions& o) {
  if (o.role == "wheel") {
    return profile::ProfileRole::kWheel;
  }
  if (o.role == "rail") {
    return profile::ProfileRole::kRail;
  }
  if (o.role != "auto") {
    throw std::invalid_argument("--role must be auto, wheel or rail, got '" + o.role + "'");
  }
  // auto: a SIMPACK .prr or MiniProf .ban file, or a conversion to .prr, is a rail.
  std::string ext = std::filesystem::path(o.input).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".prr" || ext == ".ban" || o.format == "prr" ? profile::ProfileRole::kRail
                                                             : profile::ProfileRole::kWheel;
}

profile::ProfileFile read_input(const ProfileOptions& o) {
  profile::ProfileReadOptions read;
  read.format = profile::parse_profile_format(o.input_format);
  read.z_down = o.z_down;
  read.mirror_y = o.mirror_y;
  return profile::read_profile_file(o.input, input_role(o), read);
}

/// One measured quantity, for the text and CSV outputs.
struct Measure {
  std::string name;
  double value;
  std::string unit;
  std::string meaning;
};

/// `file_z0_mm`: z at the taping line as the file has it (the reader refers z to it).
std::vector<Measure> wheel_measure_rows(const profile::SampledWheelMeasures& m, double file_z0_mm) {
  const profile::FlangeMeasures& f = m.flange;
  std::vector<Measure> rows = {
      {"Sh", f.height_mm, "mm", "flange height: tip above the taping line z(0)"},
      {"Sd", f.thickness_mm, "mm", "flange thickness: flange back y = -70 to the face at 10 mm"},
      {"qR", f.qr_mm, "mm", "face at 10 mm to the face 2 mm below the tip"},
      {"tip_y", f.tip_y_mm, "mm", "y of the flange tip"},
      {"taping_z", m.taping_z_mm + file_z0_mm, "mm",
       "z(0) in the file: the reference of Sh and of the 10 mm level"},
      {"face_y_10", f.face_y_at_10_mm, "mm", "y of the flange face 10 mm above the taping line"},
      {"face_y_tip_2", f.face_y_below_tip_mm, "mm", "y of the flange face 2 mm below the tip"},
      {"hollow_depth", m.hollow_depth_mm, "mm",
       "largest rise of the tread toward the field side (0 when new)"},
      {"hollow_bottom_y", m.hollow_bottom_y_mm, "mm", "y of the hollow's bottom"},
      {"false_flange_y", m.false_flange_y_mm, "mm", "y of the top of that rise"},
  };
  if (m.outer_slope) {
    rows.push_back({"outer_slope", 100.0 * *m.outer_slope, "%",
                    "least-squares gradient over y 38 ... 58, falling outward"});
    rows.push_back({"outer_slope_rms", m.outer_slope_rms_mm, "mm", "residual of that line"});
  }
  return rows;
}

std::vector<Measure> rail_measure_rows(const profile::RailMeasures& m) {
  std::vector<Measure> rows = {
      {"top_y", m.top_y_mm, "mm", "y of the top of rail (highest point)"},
      {"top_z", m.top_z_mm, "mm", "z of the top of rail"},
      {"gauge_point_y", m.gauge_point_y_mm, "mm",
       m.reaches_gauge_depth ? "innermost point 14 mm below the top"
                             : "first point (the gauge side does not reach 14 mm below the top)"},
  };
  if (m.head_width_mm) {
    rows.push_back(
        {"head_width", *m.head_width_mm, "mm", "gauge point to the field side at 14 mm"});
  }
  return rows;
}

void write_measures_text(std::ostream& out, const std::vector<Measure>& rows) {
  for (const Measure& r : rows) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, "  %-16s %10.3f %-2s  %s\n", r.name.c_str(), r.value,
                  r.unit.c_str(), r.meaning.c_str());
    out << buffer;
  }
}

void write_measures_csv(std::ostream& out, const std::vector<Measure>& rows) {
  out << "quantity,value,unit\n";
  for (const Measure& r : rows) {
    out << r.name << ',' << fixed(r.value, 6) << ',' << r.unit << '\n';
  }
}

/// --input without --measure or --format: what the file holds and what it measures.
void inspect_profile(std::ostream& out, const ProfileOptions& o, const profile::ProfileFile& f) {
  const profile::SampledProfile& p = f.profile;
  out << "file      " << o.input << "\n";
  out << "format    " << profile::format_name(f.format) << "\n";
  out << "role      " << profile::role_name(f.role)
      << (o.role == "auto" ? " (--role auto: .prr, .ban and --format prr are rails)" : "") << "\n";
  if (o.z_down || o.mirror_y) {
    out << "axes      " << (o.z_down ? "z negated (--z-down) " : "")
        << (o.mirror_y ? "y mirrored (--mirror-y)" : "") << "\n";
  }
  if (f.header.empty()) {
    out << "header    (no fields used)\n";
  } else {
    // As the file has them, but quoted short and at most 30 (a header is text no one here wrote).
    constexpr std::size_t kListed = 30;
    out << "header    fields used:\n";
    for (std::size_t i = 0; i < f.header.size() && i < kListed; ++i) {
      out << "  " << host::text::excerpt(f.header[i].first) << " = "
          << host::text::excerpt(f.header[i].second) << "\n";
    }
    if (f.header.size() > kListed) {
      out << "  … and " << f.header.size() - kListed << " more\n";
    }
  }
  out << "points    " << p.y_mm.size() << "\n";
  const auto [zmin, zmax] = std::minmax_element(p.z_mm.begin(), p.z_mm.end());
  out << "y         " << fixed(p.y_mm.front(), 3) << " ... " << fixed(p.y_mm.back(), 3) << " mm\n";
  out << "z         " << fixed(*zmin, 3) << " ... " << fixed(*zmax, 3) << " mm\n";
  std::vector<double> steps;
  for (std::size_t i = 1; i < p.y_mm.size(); ++i) {
    steps.push_back(p.y_mm[i] - p.y_mm[i - 1]);
  }
  std::sort(steps.begin(), steps.end());
  const auto g4 = [](double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", v);
    return std::string(buffer);
  };
  out << "spacing   min " << g4(steps.front()) << "  median " << g4(steps[steps.size() / 2])
      << "  max " << g4(steps.back()) << " mm\n";
  if (f.warnings.empty()) {
    out << "warnings  none\n";
  } else {
    out << "warnings  " << f.warnings.size() << ":\n";
    for (const std::string& w : f.warnings) {
      out << "  " << w << "\n";
    }
  }
  if (f.role == profile::ProfileRole::kRail) {
    out << "measures (rail, z up, gauge side at smaller y):\n";
    write_measures_text(out, rail_measure_rows(profile::measure_rail(p)));
    return;
  }
  try {
    const profile::SampledWheelMeasures m = profile::measure_wheel(p);
    out << "measures (EN 15313 style; taping line y = 0, flange back y = -70):\n";
    write_measures_text(out, wheel_measure_rows(m, f.taping_z_in_file_mm));
    const profile::NominalChoice n = profile::choose_nominal(o.nominal, p, m);
    out << "nominal   " << profile::WheelProfile(n.parameters).name() << " (" << n.how << ")\n";
  } catch (const std::runtime_error& e) {
    out << "measures  not available: " << e.what() << "\n";
  }
}

void plot_input(const ProfileOptions& o, const profile::ProfileFile& f) {
  const std::vector<double> slopes = profile::local_slopes(f.profile, o.slope_half_window_mm);
  std::string title =
      std::filesystem::path(o.input).filename().string() + " (" + profile::role_name(f.role) + ")";
  if (f.role == profile::ProfileRole::kRail) {
    profile::plot_measured_profile(f.profile, slopes, nullptr, title, o.plot);
    return;
  }
  const profile::SampledWheelMeasures m = profile::measure_wheel(f.profile);
  const profile::WheelProfile nominal(profile::choose_nominal(o.nominal, f.profile, m).parameters);
  title += ": Sh " + fixed(m.flange.height_mm, 2) + ", Sd " + fixed(m.flange.thickness_mm, 2) +
           ", qR " + fixed(m.flange.qr_mm, 2) + ", hollow " + fixed(m.hollow_depth_mm, 2) +
           " mm; against " + nominal.name();
  profile::plot_measured_profile(f.profile, slopes, &nominal, title, o.plot);
}

/// --input: inspect, measure, plot or convert a profile file.
void run_input(const ProfileOptions& o) {
  const profile::ProfileFile f = read_input(o);
  if (f.role == profile::ProfileRole::kRail && !o.nominal.empty()) {
    throw std::invalid_argument(o.input +
                                ": --nominal compares a wheel with an EN 13715 profile; this file "
                                "was read as a rail");
  }
  if (o.measure || !o.format.empty() || !o.plot.empty()) {
    // Inspecting lists them in its report; measuring, converting and plotting said nothing of
    // what the reader changed or assumed (points dropped, z re-referred, a spike, a gap).
    for (const std::string& w : f.warnings) std::cerr << "tread profile: warning: " << w << '\n';
  }
  std::ostringstream text;
  if (o.measure) {
    std::vector<Measure> rows =
        f.role == profile::ProfileRole::kRail
            ? rail_measure_rows(profile::measure_rail(f.profile))
            : wheel_measure_rows(profile::measure_wheel(f.profile), f.taping_z_in_file_mm);
    if (o.format == "csv") {
      write_measures_csv(text, rows);
    } else if (o.format.empty() || o.format == "table") {
      write_measures_text(text, rows);
    } else {
      throw std::invalid_argument("--format with --measure must be table or csv, got '" + o.format +
                                  "'");
    }
  } else if (o.format.empty()) {
    inspect_profile(text, o, f);
  } else if (o.format == "csv") {
    profile::write_profile_csv(text, f.profile, {}, 9);
  } else if (o.format == "prw" || o.format == "prr") {
    const profile::ProfileRole out_role =
        o.format == "prw" ? profile::ProfileRole::kWheel : profile::ProfileRole::kRail;
    if (out_role != f.role) {
      throw std::invalid_argument(o.input + ": a " + profile::role_name(f.role) +
                                  " profile cannot be written as --format " + o.format);
    }
    profile::write_simpack_profile(text, f.profile,
                                   out_role == profile::ProfileRole::kWheel
                                       ? profile::SimpackProfileType::kWheel
                                       : profile::SimpackProfileType::kRail,
                                   f.profile.name);
  } else {
    throw std::invalid_argument(
        "--format with --input must be csv, prw or prr (or none to inspect), got '" + o.format +
        "'");
  }
  write_output(o, text.str());
  if (!o.plot.empty()) {
    plot_input(o, f);
  }
}

void run_profile(const ProfileOptions& o) {
  if (!o.input.empty()) {
    run_input(o);
    return;
  }
  if (o.measure || !o.nominal.empty()) {
    throw std::invalid_argument("--measure and --nominal need --input");
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
  if (o.format.empty() || o.format == "table") {
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
  cmd->add_option("--outer-slope", options->outer_slope,
                  "1:15 (UIC S1002) or any slope from 6.7 to 15 %: 8.5, 8.5% or 1:12")
      ->capture_default_str();
  cmd->add_option("--width", options->width_mm, "wheel width: 135 or 140 mm")
      ->capture_default_str();
  cmd->add_flag("--no-chamfer", options->no_chamfer, "no 5 x 5 mm chamfer at the outer face");
  cmd->add_option("--step", options->step_mm, "sampling step (mm)")->capture_default_str();
  cmd->add_option("--format", options->format,
                  "table (default; the seed's layout: y descending, z, tan, 5 decimals), csv "
                  "(y_mm,z_mm,tan) or prw (SIMPACK wheel profile); with --input: csv, prw or prr "
                  "converts the file, none inspects it; with --measure: table (default) or csv");
  cmd->add_option("--output", options->output, "output file (default: standard output)");
  cmd->add_option("--input", options->input,
                  "a profile file (CSV y_mm,z_mm, SIMPACK .prw/.prr, MiniProf .whl/.ban): "
                  "inspect it (default), --measure, --plot or convert it (--format)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--role", options->role,
                  "with --input: wheel or rail (auto: .prr, .ban and --format prr are rails)")
      ->capture_default_str();
  cmd->add_option("--input-format", options->input_format, "auto, csv, simpack or miniprof")
      ->capture_default_str();
  cmd->add_flag("--z-down", options->z_down, "with --input: the file's z points down");
  cmd->add_flag("--mirror-y", options->mirror_y, "with --input: the file's y points the other way");
  cmd->add_flag("--measure", options->measure,
                "with --input: print the measures (wheel: Sh, Sd, qR, hollow depth, outer slope; "
                "rail: top, gauge point, head width)");
  cmd->add_option("--nominal", options->nominal,
                  "with --input: the nominal EN 13715 wheel to compare with, e.g. S1002 or "
                  "S1002:h=28,e=32.5,slope=1:15 (keys not given, and the family without one, are "
                  "derived from the measures)");
  cmd->add_option("--slope-window", options->slope_half_window_mm,
                  "with --input --plot: half-width of the local least-squares slope (mm)")
      ->check(host::finite_within(0.01, 20.0, "the slope window's half-width in mm"))
      ->capture_default_str();
  cmd->add_option("--plot", options->plot,
                  "PNG: profile, slope, and the slopes of the three families (gnuplot); with "
                  "--input: profile, local slope, nominal profile and measured - nominal");
  cmd->callback([options, cmd] {
    // An option of the other mode was silently ignored (a nominal wheel's shape with --input, a
    // file's reading options without one): refused, naming it.
    const bool input = !options->input.empty();
    static constexpr std::array<const char*, 7> kShape{
        "--family",     "--flange-height", "--flange-thickness", "--outer-slope", "--width",
        "--no-chamfer", "--step"};
    static constexpr std::array<const char*, 7> kReading{
        "--role", "--input-format", "--z-down", "--mirror-y", "--slope-window", "", ""};
    for (const char* name : input ? kShape : kReading) {
      if (*name == '\0') continue;
      if (cmd->count(name) > 0) {
        throw std::invalid_argument(
            std::string(name) +
            (input ? " shapes a built-in wheel: not used with --input (compare the file with "
                     "one by --nominal)"
                   : " applies to --input only"));
      }
    }
    run_profile(*options);
  });
}

}  // namespace

TREAD_REGISTER_COMMAND("profile", add_profile_command);

}  // namespace tread::cli
