// `tread rig`: the rig side as its own process over SocketCAN (see sim/rig/rig_session.hpp).
#include <iostream>

#include "cli/commands.hpp"
#include "cli/node_options.hpp"
#include "rig/rig_session.hpp"
#include "rig/scenario_catalogue.hpp"

namespace tread::cli {
namespace {

void add_rig_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "rig", "Run the rig side against a tread node over SocketCAN (node: tread node --mode sync)");
  static host::RigSettings settings;
  static bool fd = false;
  static int wheels = 4;
  static int wheelsets = 0;
  static int wheelset_forces = 0;
  cmd->add_option("--can", settings.can, "SocketCAN interface")->capture_default_str();
  cmd->add_flag("--fd", fd, "CAN FD layout");
  cmd->add_option("--tir", settings.tir, "the node's tyre property file (the reference)");
  cmd->add_option("--use-mode", settings.use_mode, "the node's --use-mode (MFeval useMode)")
      ->capture_default_str();
  cmd->add_option("--side", settings.side, "the node's --side: as-measured, left or right")
      ->check(CLI::IsMember({"as-measured", "left", "right"}))
      ->capture_default_str();
  cmd->add_option("--wheels", wheels, "road wheels (0..4)")
      ->check(CLI::Range(0, 4))
      ->capture_default_str();
  cmd->add_option("--wheelsets", wheelsets, "rail wheelsets (0..2)")
      ->check(CLI::Range(0, 2))
      ->capture_default_str();
  cmd->add_option("--wheelset-profile", settings.wheelset_profile,
                  "the node's wheelset profile (the reference), as for tread node");
  cmd->add_option("--wheelset-forces", wheelset_forces,
                  "the node's --wheelset-forces (wheelsets it answers wheel-rail forces for)")
      ->check(CLI::Range(0, 2))
      ->capture_default_str();
  cmd->add_option("--friction", settings.friction, "the node's --friction (kalker, dry, wet)")
      ->check(CLI::IsMember({"kalker", "dry", "wet"}))
      ->capture_default_str();
  cmd->add_option("--mu", settings.mu, "the node's --mu")
      ->check(host::finite_within(0.01, 1.0, "mu0"));
  std::string known;
  for (const std::string& n : host::scenario_names()) known += (known.empty() ? "" : ", ") + n;
  cmd->add_option(
         "--scenario", settings.scenarios,
         "scenarios, in order (default: those of the channels, as for tread demo): " + known)
      ->delimiter(',');
  cmd->add_option("--sweep-duration-s", settings.sweep_duration_s, "length of 'sweep'")
      ->check(host::finite_within(0.001, 3600.0, "the sweep's length in s"))
      ->capture_default_str();
  cmd->add_option("--period-us", settings.period_us,
                  "cycle period (the simulated step; at most 5000 us but for 'sweep': the "
                  "scenarios integrate the vehicle at it)")
      ->check(CLI::Range(50, 1'000'000))
      ->capture_default_str();
  cmd->add_option("--pace-us", settings.pace_us,
                  "wall-clock time per cycle (0: the period; longer runs the lockstep slower than "
                  "real time, same trace)")
      ->check(CLI::Range(0, 10'000'000))
      ->capture_default_str();
  cmd->add_option("--answer-timeout-ms", settings.answer_timeout_ms,
                  "wait this long for the node's answer of a cycle")
      ->check(host::finite_within(0.0, 60'000.0, "the answer timeout in ms"))
      ->capture_default_str();
  cmd->add_option("--out", settings.out_dir, "directory for the traces (and plots)")
      ->capture_default_str();
  cmd->add_flag("--plot", settings.plot, "draw the scenarios' plots");
  cmd->callback([] {
    check_scenario_period(settings.scenarios, static_cast<int>(settings.period_us));
    settings.layout = fd ? proto::Layout::fd : proto::Layout::classic;
    settings.wheels = static_cast<std::uint8_t>(wheels);
    settings.wheelsets = static_cast<std::uint8_t>(wheelsets);
    settings.wheelset_forces = static_cast<std::uint8_t>(wheelset_forces);
    if (settings.wheels > 0 && settings.tir.empty()) {
      throw CLI::ValidationError("--tir", "road wheels need the node's tyre file");
    }
    if (settings.wheelsets > 0 && settings.wheelset_profile.empty()) {
      // The node has no default pair: a reference guessed here would check its answers against
      // another contact.
      throw CLI::ValidationError("--wheelset-profile",
                                 "wheelsets need the node's wheelset profile (the reference)");
    }
    if (settings.wheelset_forces > settings.wheelsets) {
      throw CLI::ValidationError("--wheelset-forces",
                                 std::to_string(wheelset_forces) +
                                     " wheelsets with forces, but --wheelsets " +
                                     std::to_string(wheelsets));
    }
    host::print_rig_report(std::cout, host::run_rig(settings));
  });
}

}  // namespace

TREAD_REGISTER_COMMAND("rig", add_rig_command);

}  // namespace tread::cli
