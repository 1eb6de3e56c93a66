// `tread contact`: the rigid wheel–rail contact table over wheelset displacement y (no roll, no
// penetration; global vertical-gap minimum per wheel), as CSV
// y_mm,r_left_mm,r_right_mm,delta_r_mm,gamma_left_rad,gamma_right_rad,yc_left_mm,yc_right_mm.
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "contact/contact_plot.hpp"
#include "contact/contact_setup_cli.hpp"
#include "contact/rigid_contact.hpp"

namespace tread::cli {
namespace {

void write_table(std::ostream& out, const contact::ContactTable& t, bool rail_positions) {
  out << "y_mm,r_left_mm,r_right_mm,delta_r_mm,gamma_left_rad,gamma_right_rad,yc_left_mm,"
         "yc_right_mm"
      << (rail_positions ? ",yr_left_mm,yr_right_mm\n" : "\n");
  out << std::fixed;
  // Values that round to zero print as 0.000000, never -0.000000.
  auto v = [](double x) { return std::abs(x) < 5e-7 ? 0.0 : x; };
  for (std::size_t k = 0; k < t.y_mm.size(); ++k) {
    out << std::setprecision(4) << v(t.y_mm[k]) << ',' << std::setprecision(6) << v(t.r_left_mm[k])
        << ',' << v(t.r_right_mm[k]) << ',' << v(t.delta_r_mm[k]) << ',' << v(t.gamma_left_rad[k])
        << ',' << v(t.gamma_right_rad[k]) << ',' << v(t.yc_left_mm[k]) << ','
        << v(t.yc_right_mm[k]);
    if (rail_positions) {
      out << ',' << v(t.yr_left_mm[k]) << ',' << v(t.yr_right_mm[k]);
    }
    out << '\n';
  }
}

void add_contact_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "contact", "Rigid wheel-rail contact table over the wheelset displacement (CSV)");
  static contact::ContactSetup setup;
  static double y_max_mm = 10.0;
  static double step_mm = 0.1;
  static std::string output;
  static std::string plot;
  static bool rail_positions = false;
  contact::add_contact_setup_options(*cmd, setup);
  cmd->add_flag("--rail-positions", rail_positions,
                "add columns yr_left_mm,yr_right_mm: contact positions on the rails (track frame)");
  cmd->add_option("--ymax", y_max_mm, "table from -ymax to +ymax (mm)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--step", step_mm, "table step (mm)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--output", output, "CSV file (default: standard output)");
  cmd->add_option("--plot", plot, "PNG: delta r(y) and the contact positions (gnuplot)");
  cmd->callback([] {
    std::vector<std::string> warnings;
    const contact::RigidContact c = contact::build_contact(setup, warnings);
    for (const std::string& w : warnings) {
      std::cerr << "tread contact: warning: " << w << '\n';
    }
    const contact::ContactTable t = c.table(-y_max_mm, y_max_mm, step_mm);
    if (const auto end_y = contact::first_profile_end_abs_y(t)) {
      std::cerr << "tread contact: warning: from |y| = " << *end_y
                << " mm the contact lies at the end of a profile (the profiles do not cover it)\n";
    }
    if (output.empty()) {
      write_table(std::cout, t, rail_positions);
    } else {
      std::ofstream file(output);
      write_table(file, t, rail_positions);
      if (!file) {
        throw std::runtime_error("cannot write " + output);
      }
    }
    if (!plot.empty()) {
      contact::plot_contact_table(t, "wheel-rail contact", plot);
    }
  });
}

}  // namespace

TREAD_REGISTER_COMMAND("contact", add_contact_command);

}  // namespace tread::cli
