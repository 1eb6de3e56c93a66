#pragma once
// Validators of command-line options that the commands (cli/) and the option sets of the areas
// (contact/contact_setup_cli.hpp) share. Header-only: CLI11 is linked only into the tread
// executable.

#include <CLI/CLI.hpp>
#include <cmath>
#include <sstream>
#include <string>

namespace tread::host {

/// A finite number within [lo, hi] (CLI::Range and CLI::PositiveNumber let NaN through).
inline CLI::Validator finite_within(double lo, double hi, const std::string& what) {
  return CLI::Validator(
      [lo, hi, what](std::string& text) -> std::string {
        double v = 0.0;
        if (!CLI::detail::lexical_cast(text, v) || !std::isfinite(v) || v < lo || v > hi) {
          std::ostringstream m;
          m << "'" << text << "': " << what << " is a number from " << lo << " to " << hi;
          return m.str();
        }
        return {};
      },
      "", "FINITE");
}

}  // namespace tread::host
