// `tread proto dbc --layout classic|fd [--output F]`: writes the protocol's DBC file.
#include <fstream>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "dbc/dbc_writer.hpp"

namespace tread::cli {
namespace {

void add_proto_command(CLI::App& app) {
  auto* proto = app.add_subcommand("proto", "The CAN protocol: DBC files");
  proto->require_subcommand(1);
  auto* dbc =
      proto->add_subcommand("dbc", "Write the DBC of a layout (generated from the codec's tables)");
  // The layout by name only: CLI11's CheckedTransformer would also take the enum's numbers ("1")
  // and print its map as the option's type in the help.
  static std::string layout_name;
  static std::string output;
  dbc->add_option("--layout", layout_name, "classic or fd")
      ->check(CLI::IsMember({"classic", "fd"}, CLI::ignore_case))
      ->required();
  dbc->add_option("--output", output, "output file (default: standard output)");
  dbc->callback([] {
    const proto::Layout layout =
        CLI::detail::to_lower(layout_name) == "fd" ? proto::Layout::fd : proto::Layout::classic;
    const std::string text = host::write_dbc(layout);
    if (output.empty()) {
      std::cout << text;
      return;
    }
    std::ofstream file(output, std::ios::binary);
    file << text;
    if (!file) {
      throw std::runtime_error("cannot write " + output);
    }
  });
}

}  // namespace

TREAD_REGISTER_COMMAND("proto", add_proto_command);

}  // namespace tread::cli
