// `tread tir convert`: rewrite a .tir property file in tread's normalised form (sections, keys,
// values and table rows of the original, in its order, without its comments). A Chrono Pac89Tire
// JSON coefficient file (.json) becomes an Adams-style PAC89 property file.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "cli/commands.hpp"
#include "mf/tir_info.hpp"
#include "tir/pac_coefficients.hpp"
#include "tir/tir_file.hpp"
#include "tir/tir_normalise.hpp"

namespace tread::cli {

namespace {

/// Writes `text` to `path` through a temporary file beside it, renamed on success, so a failure
/// never leaves a partial file (or destroys an earlier one).
void write_file_atomically(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path.string() + ": cannot write");
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      throw std::runtime_error(path.string() + ": write failed");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error(path.string() + ": cannot replace: " + ec.message());
  }
}

struct ConvertArgs {
  std::string input;
  std::string output;
  std::string note;
};

// A PAC89 property file holding the coefficients of a Chrono Pac89Tire JSON file.
tir::TirFile pac89_tir_from_chrono_json(const std::string& path) {
  const tir::PacCoefficients coeff = tir::pac_from_chrono_json(path);
  tir::TirFile file(path);
  file.set_text("MDI_HEADER", "FILE_TYPE", "tir");
  file.set("MDI_HEADER", "FILE_VERSION", 3.0);
  file.set_text("MDI_HEADER", "FILE_FORMAT", "ASCII");
  file.set_text("MODEL", "PROPERTY_FILE_FORMAT", "PAC89");
  tir::pac_to_tir(coeff.params, file);
  return file;
}

void run_convert(const ConvertArgs& args) {
  const tir::TirFile file = std::filesystem::path(args.input).extension() == ".json"
                                ? pac89_tir_from_chrono_json(args.input)
                                : tir::read_tir(args.input);
  const std::string note = args.note.empty()
                               ? "normalised by tread tir convert from " +
                                     std::filesystem::path(args.input).filename().string()
                               : args.note;
  write_file_atomically(args.output, tir::write_normalised_tir(file, note));
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
  convert->add_option("input", convert_args.input, "Property file to read")
      ->required()
      ->check(CLI::ExistingFile);
  convert->add_option("output", convert_args.output, "Property file to write")->required();
  convert->add_option("--note", convert_args.note,
                      "One-line comment for the first line (default: where it came from)");
  convert->callback([] { run_convert(convert_args); });

  static std::string info_input;
  auto* info = tir_cmd->add_subcommand(
      "info",
      "What a property file is: detected model, units, FNOMIN/R0/pressures, limits, defaulted "
      "keys, figures at FNOMIN (peak μx/μy, slip and cornering stiffness, trail) and warnings");
  info->add_option("file", info_input, "Property file (.tir)")
      ->required()
      ->check(CLI::ExistingFile);
  info->callback([] { std::cout << mf::tir_info_report(info_input); });
}

}  // namespace

TREAD_REGISTER_COMMAND("tir", add_tir_command);

}  // namespace tread::cli
