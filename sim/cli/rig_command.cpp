// `tread rig`: the rig side as its own process over SocketCAN (see sim/rig/rig_session.hpp).
#include <iostream>

#include "cli/commands.hpp"
#include "rig/rig_session.hpp"

namespace tread::cli {
namespace {

void add_rig_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("rig", "Run the rig side against a tread node over SocketCAN");
  static host::RigSettings settings;
  static bool fd = false;
  static int wheels = 4;
  cmd->add_option("--can", settings.can, "SocketCAN interface")->capture_default_str();
  cmd->add_flag("--fd", fd, "CAN FD layout");
  cmd->add_option("--tir", settings.tir, "the node's tyre property file (the reference)")
      ->required();
  cmd->add_option("--wheels", wheels, "road wheels (1..4)")
      ->check(CLI::Range(1, 4))
      ->capture_default_str();
  cmd->add_option("--duration-s", settings.duration_s, "how long to run")->capture_default_str();
  cmd->add_option("--period-us", settings.period_us, "cycle period")->capture_default_str();
  cmd->callback([] {
    settings.layout = fd ? proto::Layout::fd : proto::Layout::classic;
    settings.wheels = static_cast<std::uint8_t>(wheels);
    host::print_rig_report(std::cout, host::run_rig(settings));
  });
}

}  // namespace

TREAD_REGISTER_COMMAND("rig", add_rig_command);

}  // namespace tread::cli
