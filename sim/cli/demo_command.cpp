// `tread demo`: the README's main job. Until the node (issue 5) and rig (issue 6) land it reports
// what is built and what is not, and runs the pieces that exist.
#include <array>
#include <cstdint>
#include <iostream>

#include "cli/commands.hpp"
#include "proto/crc8_j1850.hpp"

namespace tread::cli {

namespace {

void add_demo_command(CLI::App& app) {
  auto* demo =
      app.add_subcommand("demo", "Run the HIL demo: node + rig (in-process bus by default)");
  static std::string can = "stub";
  demo->add_option("--can", can,
                   "CAN interface: stub (in-process) or a SocketCAN link such as vcan0");
  demo->callback([] {
    std::cout
        << "tread demo — NOT BUILT YET: the real-time node and the rig simulator do not exist in\n"
           "this build. What exists: the build, toolchains, the vcan VM test harness and the\n"
           "E2E CRC (CRC8 SAE J1850).\n";
    const std::array<std::uint8_t, 9> check{'1', '2', '3', '4', '5', '6', '7', '8', '9'};
    std::cout << "CRC8 SAE J1850 check value over \"123456789\": 0x" << std::hex
              << static_cast<int>(proto::crc8_sae_j1850(check)) << std::dec << " (expected 0x4b)\n";
  });
}

}  // namespace

TREAD_REGISTER_COMMAND("demo", add_demo_command);

}  // namespace tread::cli
