// `tread contact`: the rigid wheel–rail contact table over wheelset displacement y (no roll, no
// penetration; global vertical-gap minimum per wheel), as CSV
// y_mm,r_left_mm,r_right_mm,delta_r_mm,gamma_left_rad,gamma_right_rad,yc_left_mm,yc_right_mm;
// with --load, the contact mechanics at each y as further columns (contact/mechanics_columns.hpp):
// Hertz ellipses and pressures, the two-point load split, creepages and creep forces (Polach or
// FASTSIM) from the wheelset motion given, Y/Q and Nadal's margin.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "contact/contact_mechanics.hpp"
#include "contact/contact_plot.hpp"
#include "contact/contact_setup_cli.hpp"
#include "contact/mechanics_columns.hpp"
#include "contact/rail_placement.hpp"
#include "contact/rigid_contact.hpp"
#include "io/option_checks.hpp"

namespace tread::cli {
namespace {

void write_table(std::ostream& out, const contact::ContactTable& t, bool rail_positions,
                 const std::string& extra_header, const std::vector<std::string>& extra) {
  out << "y_mm,r_left_mm,r_right_mm,delta_r_mm,gamma_left_rad,gamma_right_rad,yc_left_mm,"
         "yc_right_mm"
      << (rail_positions ? ",yr_left_mm,yr_right_mm" : "") << extra_header << '\n';
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
    if (k < extra.size()) {
      out << extra[k];
    }
    out << '\n';
  }
}

/// What --load and the options beside it set.
struct MechanicsOptions {
  double load_n = 0.0;
  double load_right_n = 0.0;
  contact::WheelsetState state;
  std::string friction = "kalker";
  double mu = 0.0;
  std::string creep_law = "polach";
  contact::ContactMaterials materials;
};

/// The mechanics columns of every row of the geometry table.
std::vector<std::string> mechanics_rows(const contact::RigidContact& c,
                                        const contact::ContactTable& t, const MechanicsOptions& o,
                                        double r0_left_mm, double r0_right_mm,
                                        double half_contact_base_mm) {
  const std::vector<contact::MechanicsRow> rows =
      contact::mechanics_table(c, t.y_first_mm, t.y_mm.back(), t.y_step_mm, o.materials);
  // Nadal's limit takes the profiles' flange angle, not the largest angle this table's range
  // happens to reach (a table short of flange contact would give a tread angle).
  const contact::FlangeAngles flange =
      contact::profile_flange_angles(c, std::max(std::abs(t.y_first_mm), std::abs(t.y_mm.back())));
  contact::WheelsetState state = o.state;
  state.load_left_n = o.load_n;
  state.load_right_n = o.load_right_n > 0.0 ? o.load_right_n : o.load_n;
  const rail::PolachParameters<double> polach = contact::friction_parameters(o.friction, o.mu);
  const contact::CreepLaw law =
      o.creep_law == "fastsim" ? contact::CreepLaw::fastsim : contact::CreepLaw::polach;
  std::vector<std::string> out;
  out.reserve(rows.size());
  for (const contact::MechanicsRow& r : rows) {
    const rail::WheelForces<double> left =
        contact::evaluate_wheel(r.left, false, state, r0_left_mm, half_contact_base_mm, o.materials,
                                flange.left_rad, polach, law);
    const rail::WheelForces<double> right =
        contact::evaluate_wheel(r.right, true, state, r0_right_mm, half_contact_base_mm,
                                o.materials, flange.right_rad, polach, law);
    out.push_back(contact::mechanics_fields(left, right));
  }
  return out;
}

void add_mechanics_options(CLI::App& cmd, MechanicsOptions& o) {
  cmd.add_option("--load", o.load_n,
                 "wheel load Q (N): adds the contact mechanics columns (Hertz, creep forces, Y/Q)")
      ->check(host::finite_within(1.0, 1e7, "a wheel load in N"));
  cmd.add_option("--load-right", o.load_right_n, "right wheel load (N); default --load")
      ->check(host::finite_within(1.0, 1e7, "a wheel load in N"));
  cmd.add_option("--speed", o.state.speed_m_s, "wheelset speed V (m/s)")
      ->capture_default_str()
      ->check(host::finite_within(0.01, 200.0, "the speed in m/s"));
  cmd.add_option("--yaw", o.state.yaw_rad,
                 "wheelset yaw angle (rad, counter-clockwise from above: toward the left rail)")
      ->capture_default_str()
      ->check(host::finite_within(-0.2, 0.2, "a wheelset yaw angle in rad"));
  cmd.add_option("--lateral-velocity", o.state.lateral_velocity_m_s,
                 "wheelset lateral velocity (m/s, toward the left rail)")
      ->capture_default_str()
      ->check(host::finite_within(-10.0, 10.0, "a wheelset lateral velocity in m/s"));
  cmd.add_option("--yaw-rate", o.state.yaw_rate_rad_s, "wheelset yaw rate (rad/s)")
      ->capture_default_str()
      ->check(host::finite_within(-10.0, 10.0, "a wheelset yaw rate in rad/s"));
  cmd.add_option("--axle-spin", o.state.axle_spin_rad_s,
                 "axle angular speed (rad/s; 0: a locked wheelset); default free rolling on the "
                 "nominal radius, V / r0")
      ->check(host::finite_within(0.0, 5000.0, "an axle speed in rad/s"));
  cmd.add_option("--friction", o.friction,
                 "creep law parameters: kalker (Polach with kA = kS = 1, constant mu: Kalker's "
                 "initial slope), dry or wet (Polach 2005: mu0 0.55 / 0.30, A 0.40, B 0.60 / "
                 "0.20 s/m, kA 1.00 / 0.30, kS 0.40 / 0.10)")
      ->capture_default_str()
      ->check(CLI::IsMember({"kalker", "dry", "wet"}));
  cmd.add_option("--mu", o.mu, "static friction coefficient mu0 (default 0.36 for kalker)")
      ->check(host::finite_within(0.01, 1.0, "mu0"));
  cmd.add_option("--creep-law", o.creep_law,
                 "polach (closed form, the node's) or fastsim (Kalker's strip method, 40 x 40)")
      ->capture_default_str()
      ->check(CLI::IsMember({"polach", "fastsim"}));
  cmd.add_option("--e-wheel", o.materials.wheel_material.e_mpa, "wheel Young's modulus (MPa)")
      ->capture_default_str()
      ->check(host::finite_within(50000.0, 400000.0, "a steel\'s Young\'s modulus in MPa"));
  cmd.add_option("--nu-wheel", o.materials.wheel_material.nu, "wheel Poisson's ratio")
      ->capture_default_str()
      ->check(host::finite_within(0.0, 0.5, "a Poisson\'s ratio"));
  cmd.add_option("--e-rail", o.materials.rail_material.e_mpa, "rail Young's modulus (MPa)")
      ->capture_default_str()
      ->check(host::finite_within(50000.0, 400000.0, "a steel\'s Young\'s modulus in MPa"));
  cmd.add_option("--nu-rail", o.materials.rail_material.nu, "rail Poisson's ratio")
      ->capture_default_str()
      ->check(host::finite_within(0.0, 0.5, "a Poisson\'s ratio"));
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
  static MechanicsOptions mechanics;
  contact::add_contact_setup_options(*cmd, setup);
  add_mechanics_options(*cmd, mechanics);
  cmd->add_flag("--rail-positions", rail_positions,
                "add columns yr_left_mm,yr_right_mm: contact positions on the rails in the "
                "track frame (lateral from a line 750 mm off the track centre at any gauge, + "
                "toward the field side)");
  cmd->add_option("--ymax", y_max_mm, "table from -ymax to +ymax (mm)")
      ->capture_default_str()
      ->check(host::finite_within(0.01, 100.0, "the table's half width in mm"));
  cmd->add_option("--step", step_mm, "table step (mm)")
      ->capture_default_str()
      ->check(host::finite_within(0.001, 10.0, "the table step in mm"));
  cmd->add_option("--output", output, "CSV file (default: standard output)");
  cmd->add_option("--plot", plot, "PNG: delta r(y) and the contact positions (gnuplot)");
  cmd->callback([cmd] {
    if (!(mechanics.load_n > 0.0)) {
      // The forces' options without --load were silently ignored.
      for (const char* name : {"--load-right", "--speed", "--yaw", "--lateral-velocity",
                               "--yaw-rate", "--axle-spin", "--friction", "--mu", "--creep-law",
                               "--e-wheel", "--nu-wheel", "--e-rail", "--nu-rail"}) {
        if (cmd->count(name) > 0) {
          throw std::invalid_argument(std::string(name) +
                                      " applies to the contact forces: give --load (N) too");
        }
      }
    }
    // A whole number of steps each side, so that the table is symmetric about y = 0 and ends
    // at ±ymax (--ymax 1 --step 0.3 gave rows -1.0 … 0.8, without y = 0).
    const double steps = y_max_mm / step_mm;
    if (std::fabs(steps - std::round(steps)) > 1e-6) {
      char text[160];
      std::snprintf(text, sizeof text,
                    "--ymax %g mm is not a whole number of --step %g mm: the table would not be "
                    "symmetric about y = 0",
                    y_max_mm, step_mm);
      throw std::invalid_argument(text);
    }
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
    std::string extra_header;
    std::vector<std::string> extra;
    if (mechanics.load_n > 0.0) {
      extra_header = contact::mechanics_header();
      extra = mechanics_rows(c, t, mechanics, setup.r0_mm, setup.r0_right_mm.value_or(setup.r0_mm),
                             contact::half_contact_base_mm(setup));
    }
    if (output.empty()) {
      write_table(std::cout, t, rail_positions, extra_header, extra);
    } else {
      std::ofstream file(output);
      write_table(file, t, rail_positions, extra_header, extra);
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
