// tread_tir_header: turn a .tir property file into a constexpr C++ header.
//   tread_tir_header IN.tir OUT.hpp [--name kTyre] [--namespace tyres]
//       a generic key/value table (tir_header.hpp)
//   tread_tir_header IN.tir OUT.hpp --mf [--double] [--name kTyre] [--namespace tyres]
//       a ready tread::mf::MfParameters<float> (or <double>) (mf_header.hpp)
// Bad input prints `file:line: what` and exits 1.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "tir/mf_header.hpp"
#include "tir/tir_file.hpp"
#include "tir/tir_header.hpp"
#include "tyre/mf_parameters_from_tir.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Generate a constexpr C++ header from a .tir property file"};
  std::string input;
  std::string output;
  tread::tir::HeaderOptions options;
  app.add_option("input", input, ".tir file")->required();
  app.add_option("output", output, "header to write")->required();
  app.add_option("--name", options.name, "C++ name of the entry array")->capture_default_str();
  app.add_option("--namespace", options.name_space, "namespace of the arrays")
      ->capture_default_str();
  bool mf = false;
  bool use_double = false;
  app.add_flag("--mf", mf, "emit tread::mf::MfParameters instead of a key/value table");
  app.add_flag("--double", use_double, "with --mf: mf::MfParameters<double> instead of <float>");
  bool use_fixed = false;
  app.add_flag(
      "--fixed", use_fixed,
      "with --mf: mf::MfParameters<fixed::Fixed64> (Q31.32 raw values) instead of <float>");
  CLI11_PARSE(app, argc, argv);
  try {
    const auto file = tread::tir::read_tir(input);
    std::string text;
    if (mf) {
      const auto loaded = tread::tyre::mf_parameters_from_tir(file);
      if (!loaded.warning.empty()) std::cerr << loaded.warning << '\n';
      tread::tir::MfHeaderOptions mo;
      mo.name = options.name;
      mo.name_space = options.name_space;
      mo.use_float = !use_double;
      mo.use_fixed = use_fixed;
      mo.source = std::filesystem::path(input).filename().string();
      text = tread::tir::generate_mf_header(loaded.params, mo);
    } else {
      text = tread::tir::generate_header(file, options);
    }
    std::ofstream out(output, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out) {
      std::cerr << output << ": cannot write\n";
      return 1;
    }
  } catch (const tread::tir::TirError& e) {
    std::cerr << e.what() << '\n';
    return 1;
  }
  return 0;
}
