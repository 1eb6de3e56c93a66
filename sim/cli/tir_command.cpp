// `tread tir`: tyre property files (.tir).
//   convert  rewrite a file in tread's normalised form (the original's sections, keys, values and
//            table rows, in its order, without its comments), optionally in SI units; a Chrono
//            Pac89Tire JSON file (.json) becomes an Adams-style PAC89 property file.
//   info     what tread makes of a file (mf/tir_info.hpp): the detected model, units, loads,
//            pressures, limits, the keys that took a default, the figures at FNOMIN (peak μx and
//            μy, slip and cornering stiffness, pneumatic trail, radii), with warnings.
#include <cctype>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "io/replace_file.hpp"
#include "tir/pac_coefficients.hpp"
#include "tir/tir_file.hpp"
#include "tir/tir_normalise.hpp"
#include "tir/tir_units.hpp"
#include "tyre/tir_info.hpp"

namespace tread::cli {

namespace {

// A PAC89 property file holding the coefficients of a Chrono Pac89Tire JSON file.
tir::TirFile pac89_tir_from_chrono_json(const std::string& path) {
  const tir::PacCoefficients coeff = tir::pac_from_chrono_json(path);
  if (!coeff.not_carried.empty()) {
    std::cerr << "tread tir convert: warning: " << path
              << ": not in the PAC89 .tir (its coefficients and R0, rolling resistance and "
                 "lateral stiffness are):";
    for (std::size_t i = 0; i < coeff.not_carried.size(); ++i) {
      std::cerr << (i == 0 ? " " : ", ") << coeff.not_carried[i];
    }
    std::cerr << '\n';
  }
  tir::TirFile file(path);
  file.set_text("MDI_HEADER", "FILE_TYPE", "tir");
  file.set("MDI_HEADER", "FILE_VERSION", 3.0);
  file.set_text("MDI_HEADER", "FILE_FORMAT", "ASCII");
  file.set_text("MODEL", "PROPERTY_FILE_FORMAT", "PAC89");
  tir::pac_to_tir(coeff.params, file);
  return file;
}

struct ConvertArgs {
  std::string input;
  std::string output;
  std::string note;
  std::string units = "file";
};

void run_convert(const ConvertArgs& args) {
  std::string ext = std::filesystem::path(args.output).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".tir") {
    throw std::runtime_error(args.output + ": tread tir convert writes a .tir property file");
  }
  tir::TirFile file = std::filesystem::path(args.input).extension() == ".json"
                          ? pac89_tir_from_chrono_json(args.input)
                          : tir::read_tir(args.input);
  if (file.sections().empty()) {
    throw std::runtime_error(args.input + ": no [SECTION] in it: not a property file");
  }
  if (args.units == "si") {
    const std::vector<std::string> left = tir::convert_to_si(file);
    if (!left.empty()) {
      std::cerr << "tread tir convert: warning: " << left.size()
                << " numeric key(s) of unknown dimension left as written:";
      for (const auto& k : left) std::cerr << ' ' << k;
      std::cerr << '\n';
    }
  }
  const std::string note = args.note.empty()
                               ? "normalised by tread tir convert from " +
                                     std::filesystem::path(args.input).filename().string() +
                                     (args.units == "si" ? " (in SI units)" : "")
                               : args.note;
  host::ReplaceFile out(args.output);
  out.stream() << tir::write_normalised_tir(file, note);
  out.commit();
  std::cerr << "tread tir convert: " << args.input << " -> " << args.output << '\n';
}

void add_tir_command(CLI::App& app) {
  auto* tir_cmd = app.add_subcommand("tir", "Tyre property files (.tir): inspect and convert");
  tir_cmd->require_subcommand(1);
  static ConvertArgs convert_args;
  auto* convert = tir_cmd->add_subcommand(
      "convert",
      "Rewrite a .tir in normalised form: the same sections, keys, values (exact text) and table "
      "rows, without the original's comments");
  convert->add_option("input", convert_args.input, "Property file to read (.tir, or Chrono .json)")
      ->required()
      ->check(CLI::ExistingFile);
  convert->add_option("output", convert_args.output, "Property file to write")->required();
  convert->add_option("--note", convert_args.note,
                      "One-line comment for the first line (default: where it came from)");
  convert
      ->add_option("--units", convert_args.units,
                   "file: keep the file's [UNITS] and values; si: convert every dimensional value "
                   "to SI and write [UNITS] as meter/newton/radians/kg/second")
      ->check(CLI::IsMember({"file", "si"}))
      ->capture_default_str();
  convert->callback([] { run_convert(convert_args); });

  static std::string info_path;
  auto* info = tir_cmd->add_subcommand(
      "info",
      "What tread makes of a property file: model and version, units, dimensions, loads, "
      "pressures, limits, defaulted keys, and figures at FNOMIN (peak mu, stiffnesses, trail, "
      "radii) in ISO-W axes, with warnings");
  info->add_option("file", info_path, "Property file (.tir)")->required()->check(CLI::ExistingFile);
  info->callback([] { std::cout << tyre::tir_info_report(info_path); });
}

}  // namespace

TREAD_REGISTER_COMMAND("tir", add_tir_command);

}  // namespace tread::cli
