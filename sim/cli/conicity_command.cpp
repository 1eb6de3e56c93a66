// `tread conicity`: equivalent conicity tan(gamma_e) per EN 15302 (Annex B: the nonlinear kinematic
// wheelset equation integrated with delta r(y)) at the given amplitudes, as CSV
// amplitude_mm,tan_gamma_e (plus tan_gamma_regression with --regression).
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "contact/contact_plot.hpp"
#include "contact/contact_setup_cli.hpp"
#include "contact/equivalent_conicity.hpp"
#include "contact/rigid_contact.hpp"

namespace tread::cli {
namespace {

void add_conicity_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("conicity",
                                 "Equivalent conicity per EN 15302 (Annex B) at given amplitudes");
  static contact::ContactSetup setup;
  static std::vector<double> amplitudes{1.0, 2.0, 3.0};
  static double step_mm = 0.01;
  static bool regression = false;
  static std::string plot;
  contact::add_contact_setup_options(*cmd, setup);
  cmd->add_option("--amplitudes", amplitudes, "amplitudes (mm), comma separated")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--step", step_mm, "delta r table step used for the integration (mm)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--regression", regression,
                "also print the linear-regression value (harmonic weighting) for comparison");
  cmd->add_option("--plot", plot, "PNG: delta r(y) and the contact positions (gnuplot)");
  cmd->callback([] {
    std::vector<std::string> warnings;
    const contact::RigidContact c = contact::build_contact(setup, warnings);
    for (const std::string& w : warnings) {
      std::cerr << "tread conicity: warning: " << w << '\n';
    }
    const double a_max = *std::max_element(amplitudes.begin(), amplitudes.end());
    // The motion spans +-amplitude about the centre (the root of delta r): leave a margin.
    const double y_max = std::ceil(a_max + 2.0);
    const contact::ContactTable t = c.table(-y_max, y_max, step_mm);
    if (const auto end_y = contact::first_profile_end_abs_y(t); end_y && *end_y <= a_max + 1.0) {
      std::cerr << "tread conicity: warning: from |y| = " << *end_y
                << " mm the contact lies at the end of a profile (the profiles do not cover it)\n";
    }
    std::cout << (regression ? "amplitude_mm,tan_gamma_e,tan_gamma_regression\n"
                             : "amplitude_mm,tan_gamma_e\n");
    for (const double a : amplitudes) {
      const contact::ConicityResult r = contact::equivalent_conicity(t, a);
      std::cout << std::fixed << std::setprecision(3) << a << ',' << std::setprecision(5)
                << r.tan_gamma_e;
      if (regression) {
        std::cout << ',' << contact::linearised_conicity(t, a);
      }
      std::cout << '\n';
    }
    if (!plot.empty()) {
      contact::plot_contact_table(t, "wheel-rail contact", plot);
    }
  });
}

}  // namespace

TREAD_REGISTER_COMMAND("conicity", add_conicity_command);

}  // namespace tread::cli
