// `tread conicity`: equivalent conicity tan(gamma_e) per EN 15302 at the given amplitudes, as CSV,
// one row per amplitude:
//   amplitude_mm, tan_gamma_e (Annex B: the nonlinear kinematic equation integrated), centre_mm
//   (Annex B: midway between the turning points), wavelength_mm (Annex B), tan_gamma_regression
//   (Annex C: linear regression of delta r over a harmonic cycle), centre_regression_mm (Annex C:
//   where the mean of delta r over the cycle is 0), note ("ok", "neutral" or why a method has no
//   result at this amplitude; the value is then nan and a warning goes to stderr).
// Different wheels (--wheel-right-file) and rolling radii (--r0-right; delta r = r_left - r_right)
// are allowed: the oscillation is then not centred on 0.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "contact/contact_mechanics.hpp"
#include "contact/contact_plot.hpp"
#include "contact/contact_setup_cli.hpp"
#include "contact/equivalent_conicity.hpp"
#include "contact/rigid_contact.hpp"
#include "io/option_checks.hpp"

namespace tread::cli {
namespace {

void add_conicity_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "conicity", "Equivalent conicity per EN 15302 (Annex B and Annex C) at given amplitudes");
  static contact::ContactSetup setup;
  static std::vector<double> amplitudes{1.0, 2.0, 3.0};
  static double step_mm = 0.01;
  static double y_max_mm = 0.0;
  static std::string plot;
  contact::add_contact_setup_options(*cmd, setup);
  cmd->add_option("--amplitudes", amplitudes, "amplitudes (mm), comma separated")
      ->delimiter(',')
      ->capture_default_str()
      ->check(host::finite_within(0.01, 30.0, "an amplitude in mm"));
  cmd->add_option("--step", step_mm,
                  "delta r table step used for the integration (mm; at most a tenth of the "
                  "smallest amplitude)")
      ->capture_default_str()
      ->check(host::finite_within(0.001, 1.0, "the table step in mm"));
  cmd->add_option("--ymax", y_max_mm,
                  "delta r table from -ymax to +ymax (mm); default: largest amplitude + 3 "
                  "(an asymmetric wheelset oscillates off centre)")
      ->check(host::finite_within(0.1, 100.0, "the table's half width in mm"));
  cmd->add_option("--plot", plot, "PNG: delta r(y) and the contact positions (gnuplot)");
  cmd->callback([] {
    std::vector<std::string> warnings;
    const contact::RigidContact c = contact::build_contact(setup, warnings);
    for (const std::string& w : warnings) {
      std::cerr << "tread conicity: warning: " << w << '\n';
    }
    const double a_max = *std::max_element(amplitudes.begin(), amplitudes.end());
    const double a_min = *std::min_element(amplitudes.begin(), amplitudes.end());
    if (step_mm > 0.1 * a_min) {  // the integral over a motion of a few steps is not one
      char text[96];
      std::snprintf(text, sizeof text, "%g mm is more than a tenth of the amplitude %g mm", step_mm,
                    a_min);
      throw CLI::ValidationError("--step", text);
    }
    double y_max = y_max_mm > 0.0 ? y_max_mm : std::ceil(a_max) + 3.0;
    // A whole number of steps each side: the table's grid is symmetric about y = 0 (a grid that is
    // not put a symmetric wheelset's centre off 0).
    y_max = std::ceil(y_max / step_mm - 1e-9) * step_mm;
    contact::ContactTable t;
    for (;;) {
      try {
        t = c.table(-y_max, y_max, step_mm);
        break;
      } catch (const std::domain_error& e) {
        // The default range may reach past where wheel and rail still meet: narrow it (the
        // amplitudes whose motion then leaves the table are marked in their rows).
        if (y_max_mm > 0.0 || y_max - 1.0 < a_max) {
          throw;
        }
        y_max -= 1.0;
        std::cerr << "tread conicity: warning: " << e.what() << "; delta r table narrowed to +-"
                  << y_max << " mm\n";
      }
    }
    const std::optional<double> end_y = contact::first_profile_end_abs_y(t);
    if (end_y && *end_y <= a_max + 1.0) {
      std::cerr << "tread conicity: warning: from |y| = " << *end_y
                << " mm the contact lies at the end of a profile (the profiles do not cover it)\n";
    }
    // The wavelength (Annex B) is 2 pi sqrt(e0 r0 / tan(gamma_e)) of this wheelset.
    contact::ConicityOptions options;
    options.e0_mm = contact::half_contact_base_mm(setup);
    options.r0_mm = contact::nominal_r0_mm(setup);
    std::cout << "amplitude_mm,tan_gamma_e,centre_mm,wavelength_mm,tan_gamma_regression,"
                 "centre_regression_mm,note\n";
    auto csv_safe = [](std::string text) {
      std::replace(text.begin(), text.end(), ',', ';');
      return text;
    };
    // Where the flange takes the contact (90 % of its angle): an amplitude reaching it measures
    // flange contact or climbing, not the tread's conicity.
    // A flange is where the contact angle reaches 0.5 rad (29°; a tread's is a few degrees): the
    // largest angle of a scan that never reaches a flange (a wheelset with too much play, a
    // profile without a flange) is not one, and every row was noted as flange contact.
    constexpr double kFlangeContact_rad = 0.5;
    const contact::FlangeAngles flange = contact::profile_flange_angles(c, y_max);
    const double flange_rad = 0.9 * std::min(flange.left_rad, flange.right_rad);
    double flange_y = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < t.y_mm.size() && flange_rad >= 0.9 * kFlangeContact_rad; ++k) {
      if (std::max(t.gamma_left_rad[k], t.gamma_right_rad[k]) >= flange_rad) {
        flange_y = std::min(flange_y, std::abs(t.y_mm[k]));
      }
    }
    for (const double a : amplitudes) {
      std::string note;
      if (a >= flange_y) {
        char at[32];
        std::snprintf(at, sizeof at, "%.2f", flange_y);
        note = std::string("flange contact within the motion (from |y| = ") + at +
               " mm): a flange's slope rather than the tread's conicity";
      }
      if (end_y && a >= *end_y) {
        char at[32];
        std::snprintf(at, sizeof at, "%.2f", *end_y);
        note += std::string(note.empty() ? "" : "; ") +
                "contact at the end of a profile within the motion (from |y| = " + at +
                " mm): the profiles do not cover it";
      }
      std::cout << std::fixed << std::setprecision(3) << a << ',';
      try {
        const contact::ConicityResult r = contact::equivalent_conicity(t, a, options);
        std::cout << std::setprecision(5) << r.tan_gamma_e << ',' << std::setprecision(4)
                  << r.centre_y_mm << ',' << std::setprecision(1) << r.wavelength_mm << ',';
        if (r.neutral) {
          note += std::string(note.empty() ? "" : "; ") +
                  "neutral: delta r = 0 over the whole motion (annex B)";
        }
      } catch (const std::domain_error& e) {
        std::cout << "nan,nan,nan,";
        note += std::string(note.empty() ? "" : "; ") + "annex B: " + e.what();
        std::cerr << "tread conicity: warning: annex B: " << e.what() << "\n";
      }
      try {
        const contact::RegressionResult r = contact::linearised_conicity(t, a);
        std::cout << std::setprecision(5) << r.tan_gamma_e << ',' << std::setprecision(4)
                  << r.centre_y_mm << ',';
        if (r.tan_gamma_e < 0.0) {
          note += std::string(note.empty() ? "" : "; ") +
                  "annex C negative: delta r falls as the wheelset moves over (a hollow tread, an "
                  "unstable centre)";
        }
      } catch (const std::domain_error& e) {
        std::cout << "nan,nan,";
        note += std::string(note.empty() ? "" : "; ") + "annex C: " + e.what();
        std::cerr << "tread conicity: warning: annex C: " << e.what() << "\n";
      }
      std::cout << csv_safe(note.empty() ? "ok" : note) << '\n';
    }
    if (!plot.empty()) {
      contact::plot_contact_table(t, "wheel-rail contact", plot);
    }
  });
}

}  // namespace

TREAD_REGISTER_COMMAND("conicity", add_conicity_command);

}  // namespace tread::cli
