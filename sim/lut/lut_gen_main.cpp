// tread_lut_gen --profile SPEC ... --contact SPEC ... --output FILE
// Writes the lookup tables of lut/ (see lut/tread_lut.hpp) as C++ source. Runs at build time.
#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/option_checks.hpp"
#include "lut/lut_generator.hpp"

int main(int argc, char** argv) {
  CLI::App app{"tread_lut_gen: lookup tables for the real-time core, from the double definitions"};
  std::vector<std::string> profiles;
  std::vector<std::string> pairs;
  std::string output;
  double max_error_um = 1.0;
  app.add_option("--profile", profiles, "built-in wheel, e.g. S1002:h=28,e=32.5,slope=1:15");
  app.add_option("--contact", pairs, "wheel/rail pair, e.g. wheel=S1002,rail=60E1,cant=1:40");
  app.add_option("--max-error-um", max_error_um, "r(y) interpolation error bound")
      ->check(tread::host::finite_within(0.01, 1000.0, "the error bound in um"))
      ->capture_default_str();
  app.add_option("--output", output, "C++ source to write")->required();
  CLI11_PARSE(app, argc, argv);
  try {
    if (profiles.empty() && pairs.empty()) {
      throw std::runtime_error("nothing to generate: give --profile or --contact");
    }
    // Each table once, each spec named in the message of what is wrong with it (the messages of
    // the shared parsers name tread's own options: --wheel, --cant, ...).
    const auto once = [](const std::vector<std::string>& specs, const char* option) {
      for (std::size_t i = 0; i < specs.size(); ++i) {
        if (specs[i].empty()) throw std::runtime_error(std::string(option) + " '': an empty spec");
        for (std::size_t j = 0; j < i; ++j) {
          if (specs[i] == specs[j]) {
            throw std::runtime_error(std::string(option) + " '" + specs[i] + "' given twice");
          }
        }
      }
    };
    once(profiles, "--profile");
    once(pairs, "--contact");
    const auto naming = [](const char* option, const std::string& spec, const auto& make) {
      try {
        return make();
      } catch (const std::exception& e) {
        throw std::runtime_error(std::string(option) + " '" + spec + "': " + e.what());
      }
    };
    std::vector<tread::host::RadiusTableData> radius;
    for (const std::string& p : profiles) {
      radius.push_back(
          naming("--profile", p, [&] { return tread::host::make_radius_table(p, max_error_um); }));
    }
    std::vector<tread::host::ContactTableData> contact;
    for (const std::string& c : pairs) {
      contact.push_back(naming("--contact", c, [&] { return tread::host::make_contact_table(c); }));
    }
    const std::string text = tread::host::write_lut_source(radius, contact);
    std::ofstream out(output, std::ios::binary);
    out << text;
    if (!out) {
      std::cerr << "tread_lut_gen: cannot write " << output << '\n';
      return 1;
    }
  } catch (const std::exception& e) {
    std::cerr << "tread_lut_gen: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
