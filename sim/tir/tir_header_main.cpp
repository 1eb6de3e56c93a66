// tread_tir_header: turn a .tir property file into a constexpr C++ header (see tir_header.hpp).
//   tread_tir_header IN.tir OUT.hpp [--name kTyre] [--namespace tyres]
// Bad input prints `file:line: what` and exits 1.
#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>

#include "tir/tir_file.hpp"
#include "tir/tir_header.hpp"

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
  CLI11_PARSE(app, argc, argv);
  try {
    const std::string text = tread::tir::generate_header(tread::tir::read_tir(input), options);
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
